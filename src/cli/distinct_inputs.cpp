#include "cli/distinct_inputs.hpp"

#include <cstddef>
#include <map>

#include "batch/sha256.hpp"
#include "cli/options.hpp"

namespace rocking::cli {

void refuse_repeated_values(const std::string& flag, const std::vector<double>& values) {
    std::map<double, std::size_t> seen;
    for (std::size_t k = 0; k < values.size(); ++k)
        if (!seen.emplace(values[k], k).second)
            throw UsageError(flag + ": " + significant(values[k], 7) + " is given twice (values " +
                             std::to_string(seen.at(values[k]) + 1) + " and " + std::to_string(k + 1) +
                             "); each would count its cases again: give each value once");
}

namespace {

std::string content_digest(const dynamics::SampledInput& input) {
    batch::Sha256 digest;
    const double dt = input.dt();
    digest.update(&dt, sizeof dt);
    digest.update(input.samples().data(), input.samples().size() * sizeof(double));
    return digest.hex();
}

}  // namespace

void refuse_repeated_records(const std::vector<std::string>& files,
                             const std::vector<const dynamics::SampledInput*>& inputs) {
    std::map<std::string, std::size_t> seen;
    for (std::size_t k = 0; k < inputs.size(); ++k) {
        const auto [first, added] = seen.emplace(content_digest(*inputs[k]), k);
        if (!added)
            throw UsageError(files[k] + ": the same record as " + files[first->second] + " (records " +
                             std::to_string(first->second + 1) + " and " + std::to_string(k + 1) +
                             ": the same step and samples), whose cases would count twice: give each record once");
    }
}

}  // namespace rocking::cli
