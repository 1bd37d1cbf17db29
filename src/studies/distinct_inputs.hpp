// A study's cases are independent draws only when no input repeats: an alpha
// given twice, or a record given twice (one file by two paths, or two files
// with the same samples), counts the same cases twice, and every share and
// interval over them takes the copies for evidence.  Repeats are refused, not
// counted once: the study would otherwise mean something other than what it
// was asked.  Here, in the library, so that the command line and the Python
// module refuse the same repeats in the same words (each front end names the
// value as its user gave it: "--alpha", "alpha").
#pragma once

#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"

namespace rocking::studies {

// Throws std::invalid_argument naming `name` and the value given twice (as a
// number: 0.1 and 0.10 are one value).
void refuse_repeated_values(const std::string& name, const std::vector<double>& values);

// Throws std::invalid_argument naming both records when two inputs have the
// same step and the same samples (in g), whatever their paths, or when one is
// the other scaled, a flip of sign included (its samples in one ratio to the
// other's within 1e-6 of its peak): the studies that take records (fragility,
// eq27) scale each to every q, and the block is symmetric, so a scaled copy
// is the same case.  `files[k]` names `inputs[k]`.
void refuse_repeated_records(const std::vector<std::string>& files,
                             const std::vector<const dynamics::SampledInput*>& inputs);

}  // namespace rocking::studies
