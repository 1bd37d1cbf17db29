// A study's cases are independent draws only when no input repeats: an alpha
// given twice, or a record given twice (one file by two paths, or two files
// with the same samples), counts the same cases twice, and every share and
// interval over them takes the copies for evidence.  Repeats are refused, not
// counted once: the command line would otherwise mean something other than
// what it says.
#pragma once

#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"

namespace rocking::cli {

// Throws UsageError naming `flag` and the value given twice (as a number:
// 0.1 and 0.10 are one value).
void refuse_repeated_values(const std::string& flag, const std::vector<double>& values);

// Throws UsageError naming both files when two inputs have the same step and
// the same samples (in g), whatever their paths: `files[k]` names `inputs[k]`.
void refuse_repeated_records(const std::vector<std::string>& files,
                             const std::vector<const dynamics::SampledInput*>& inputs);

}  // namespace rocking::cli
