#include "studies/distinct_inputs.hpp"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "studies/record_order.hpp"

namespace rocking::studies {

namespace {

// Two shapes closer than this at every sample, relative to the peak, are one
// record: a copy printed to 7 digits and scaled differs by about 1e-7, two
// recordings of different motions by far more at most samples; and the
// studies bisect q to 1e-6.
constexpr double kSameShape = 1e-6;

std::string g7(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.7g", v);
    return text;
}

// Whether b is a times a factor, the sign included: the same step and
// length, and every sample of b / peak(b) within kSameShape of +-a / peak(a).
bool scaled_copy(const dynamics::SampledInput& a, const dynamics::SampledInput& b) {
    const std::vector<double>& x = a.samples();
    const std::vector<double>& y = b.samples();
    if (a.dt() != b.dt() || x.size() != y.size() || !(a.peak() > 0) || !(b.peak() > 0)) return false;
    for (const double sign : {1.0, -1.0}) {
        const double ratio = sign * b.peak() / a.peak();
        std::size_t k = 0;
        while (k < x.size() && std::fabs(y[k] - ratio * x[k]) <= kSameShape * b.peak()) ++k;
        if (k == x.size()) return true;
    }
    return false;
}

}  // namespace

void refuse_repeated_values(const std::string& name, const std::vector<double>& values) {
    std::map<double, std::size_t> seen;
    for (std::size_t k = 0; k < values.size(); ++k)
        if (!seen.emplace(values[k], k).second)
            throw std::invalid_argument(name + ": " + g7(values[k]) + " is given twice (values " +
                                        std::to_string(seen.at(values[k]) + 1) + " and " + std::to_string(k + 1) +
                                        "); each would count its cases again: give each value once");
}

void refuse_repeated_records(const std::vector<std::string>& files,
                             const std::vector<const dynamics::SampledInput*>& inputs) {
    if (files.size() != inputs.size())
        throw std::invalid_argument("refuse_repeated_records: " + std::to_string(files.size()) + " names for " +
                                    std::to_string(inputs.size()) + " records");
    std::map<std::string, std::size_t> seen;
    for (std::size_t k = 0; k < inputs.size(); ++k) {
        const auto [first, added] = seen.emplace(sample_digest(*inputs[k]), k);
        if (!added)
            throw std::invalid_argument(files[k] + ": the same record as " + files[first->second] + " (records " +
                                        std::to_string(first->second + 1) + " and " + std::to_string(k + 1) +
                                        ": the same step and samples), whose cases would count twice: give each "
                                        "record once");
    }
    // Pairs of one step and length only: records of a study seldom share both,
    // and two that do differ within a few samples.
    std::map<std::pair<double, std::size_t>, std::vector<std::size_t>> by_step;
    for (std::size_t k = 0; k < inputs.size(); ++k) {
        std::vector<std::size_t>& same = by_step[{inputs[k]->dt(), inputs[k]->samples().size()}];
        for (const std::size_t j : same)
            if (scaled_copy(*inputs[j], *inputs[k]))
                throw std::invalid_argument(
                    files[k] + ": the same record as " + files[j] + " scaled (records " + std::to_string(j + 1) +
                    " and " + std::to_string(k + 1) + ": the same step, and samples in one ratio to 1e-6 of the "
                    "peak, the sign aside), which the study's scaling to each q makes one case, counted twice: "
                    "give each record once");
        same.push_back(k);
    }
}

}  // namespace rocking::studies
