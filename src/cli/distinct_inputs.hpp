// The command line's words for studies/distinct_inputs.hpp: a repeated
// value or record is a bad command line (UsageError, exit 2).
#pragma once

#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"

namespace rocking::cli {

// Throws UsageError naming `flag` and the value given twice.
void refuse_repeated_values(const std::string& flag, const std::vector<double>& values);

// Throws UsageError naming both files when two inputs are one record.
void refuse_repeated_records(const std::vector<std::string>& files,
                             const std::vector<const dynamics::SampledInput*>& inputs);

}  // namespace rocking::cli
