// rocking simulate --friction MU: the sliding-rocking run (simulate_friction.cpp).
#pragma once

#include "cli/geometry.hpp"
#include "cli/options.hpp"
#include "dynamics/ground_input.hpp"
#include "dynamics/simulate.hpp"

namespace rocking::cli {

// The line that gives a run's outcome under each of the three criteria.
// alpha_minus > 0: an imperfect block's corner theta < 0 (SimulationResult::collapse).
void print_criteria(const dynamics::SimulationResult& r, double alpha, double alpha_minus = 0);

// Runs the block on the input with friction mu and prints the result (text
// or --json); the tolerances from --rtol and --atol.
int simulate_friction(const Args& a, const GivenBlock& given, const dynamics::GroundInput& input,
                      dynamics::Criterion criterion, double mu, double record_dt = 0);

}  // namespace rocking::cli
