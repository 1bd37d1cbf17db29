// An input scaled by a constant factor: the conditioning probe of the
// rocking spectrum (the same run with the input times 1 +- 1e-13) and, for
// the studies that scale records, their intensity.
#pragma once

#include <memory>

#include "dynamics/ground_input.hpp"

namespace rocking::studies {

// `input` times `factor` (finite, > 0).  A record comes back as a record of
// scaled samples, so that the exact solver still takes it through the record
// kernel; any other input as a view of `input`, which must outlive it.
// Throws std::invalid_argument for a factor that is not finite and > 0.
std::unique_ptr<dynamics::GroundInput> scaled(const dynamics::GroundInput& input, double factor);

}  // namespace rocking::studies
