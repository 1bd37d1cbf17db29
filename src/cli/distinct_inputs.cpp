#include "cli/distinct_inputs.hpp"

#include <stdexcept>

#include "cli/options.hpp"
#include "studies/distinct_inputs.hpp"

namespace rocking::cli {

void refuse_repeated_values(const std::string& flag, const std::vector<double>& values) {
    try {
        studies::refuse_repeated_values(flag, values);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

void refuse_repeated_records(const std::vector<std::string>& files,
                             const std::vector<const dynamics::SampledInput*>& inputs) {
    try {
        studies::refuse_repeated_records(files, inputs);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

}  // namespace rocking::cli
