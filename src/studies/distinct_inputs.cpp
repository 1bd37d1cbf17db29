#include "studies/distinct_inputs.hpp"

#include <cstddef>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "batch/sha256.hpp"

namespace rocking::studies {

namespace {

std::string g7(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.7g", v);
    return text;
}

std::string content_digest(const dynamics::SampledInput& input) {
    batch::Sha256 digest;
    const double dt = input.dt();
    digest.update(&dt, sizeof dt);
    digest.update(input.samples().data(), input.samples().size() * sizeof(double));
    return digest.hex();
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
        const auto [first, added] = seen.emplace(content_digest(*inputs[k]), k);
        if (!added)
            throw std::invalid_argument(files[k] + ": the same record as " + files[first->second] + " (records " +
                                        std::to_string(first->second + 1) + " and " + std::to_string(k + 1) +
                                        ": the same step and samples), whose cases would count twice: give each "
                                        "record once");
    }
}

}  // namespace rocking::studies
