// What the synthetic generators share (synthetic.cpp, synthetic_stochastic.cpp):
// how a value is written in a header or a message, the sampling checks of a
// generator's frequencies (issue 38: refused at or above 1/(2 dt), warned of
// below 10 samples a period) and the count of samples.  Internal: not among
// the public headers.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "records/record.hpp"

namespace rocking::records::synthetic_detail {

constexpr double kGravity = 9.81;  // m/s^2, as Record::in_g
// Above this many samples the stochastic sum (quadratic in the samples within
// the filter's memory) and the files get out of hand; real records sit far below.
constexpr std::size_t kMaxSamples = 10'000'000;

// The shortest %g text that reads back as v (0.213 rather than 0.21299999999999999).
std::string text_of(double v);
// v to a few digits, for messages.
std::string short_text(double v);
// Throws std::invalid_argument "NAME must be RULE (got GOT)".
[[noreturn]] void refuse(const std::string& name, const std::string& rule, double got);

// A frequency of a generator, as the sampling checks name it.
struct Frequency {
    std::string name;                     // as the message writes it: "fp", "fc", ...
    std::string role;                     // what it is, after the value
    double hz;
    std::vector<std::string> parameters;  // the keys whose values set it
    std::string remedy;                   // the change of those that lowers it
};

// Throws a SamplingError for the first frequency at or above 1/(2 dt).
void refuse_unsampled(const std::vector<Frequency>& frequencies, double dt);
// A warning for each frequency with fewer than 10 samples a period.
std::vector<std::string> sampling_warnings(const std::vector<Frequency>& frequencies, double dt);
// The warnings into the record's header ("warning"), where warnings_of finds them.
void state_warnings(Record& r, const std::vector<std::string>& warnings);
// n - 1 = floor(duration/dt), refused beyond kMaxSamples or below 4 samples.
std::size_t sample_count(double dt, double duration);

}  // namespace rocking::records::synthetic_detail
