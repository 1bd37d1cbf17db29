// A train of piecewise-constant ground-acceleration pulses (the step inputs of
// Figure 3 and Section 3 of the paper).
//
// Units: amplitudes are in units of PGA (the first pulse of every case has
// |amplitude| 1 or 1/2), durations in units of the half-period to.  With
// these units the train is independent of the block; the block enters only
// through x = p*to.
#pragma once

#include <string>
#include <vector>

namespace rocking {

struct Pulse {
    double amplitude;  // in units of PGA, paper's sign (+ drives theta > 0)
    double duration;   // in units of to
};

class PulseTrain {
public:
    // Throws std::invalid_argument when the train is empty, a duration is not
    // finite and positive, an amplitude is not finite, or the first pulse is
    // not positive (rocking must start on the theta > 0 corner, as in the paper).
    explicit PulseTrain(std::vector<Pulse> pulses, std::string name = "custom");

    const std::vector<Pulse>& pulses() const { return pulses_; }
    const std::string& name() const { return name_; }
    std::size_t size() const { return pulses_.size(); }

    // t_fin / to: the end of the input, where the paper imposes theta = alpha.
    double t_fin() const;
    // Start of pulse k (k = size() gives t_fin), in units of to.
    double start(std::size_t k) const;
    // Amplitude at time tau (units of to); 0 before 0 and from t_fin on.
    double amplitude_at(double tau) const;
    // Largest |amplitude|: the train's PGA in units of the nominal PGA.
    double peak() const;

private:
    std::vector<Pulse> pulses_;
    std::string name_;
};

// The five inputs of Figure 3 (inferred from eqs. 7-24; see NOTES.md):
//   1: +1 (1), -1 (1)      2: +1 (1), -1/2 (1)     3: +1/2 (1), -1 (1)
//   4: +1 (1), -1/2 (2)    5: +1/2 (2), -1 (1)
// Throws std::invalid_argument for a case outside 1..5.
PulseTrain pulse_case(int which);

// The pattern of case `which` repeated until n_pulses pulses (Section 3).
// n_pulses = 2 (3 for none) is the case itself; case 2 with n_pulses = 6 is
// the input of eq. 27, case 4 with 6 that of eq. 28, case 1 with 6 the
// Coccia & Como train.  An odd n_pulses ends on the pattern's first pulse.
PulseTrain repeated_case(int which, int n_pulses);

// Parses "A:d,A:d,..." (amplitude:duration pairs).  Throws
// std::invalid_argument naming the offending item.
PulseTrain parse_train(const std::string& text);

}  // namespace rocking
