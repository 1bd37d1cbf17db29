// rocking simulate's document: one run of a block on an input, on the
// rocking model (dynamics/simulate.hpp) or the sliding-rocking one
// (dynamics/sliding/sliding_simulate.hpp).
#pragma once

#include "dynamics/block_geometry.hpp"
#include "dynamics/ground_input.hpp"
#include "dynamics/imperfect_block.hpp"
#include "dynamics/simulate.hpp"
#include "dynamics/sliding/sliding_simulate.hpp"
#include "json/document.hpp"
#include "records/collapse.hpp"

namespace rocking::json {

// A rocking run and what it was of.
struct RockingRun {
    const dynamics::Model& model;  // with an imperfect block's corners
    const dynamics::GivenBlock& given;
    const dynamics::GroundInput& input;
    const dynamics::SimulationOptions& options;
    dynamics::Criterion criterion;
    const dynamics::SimulationResult& result;
    bool paper;                          // the paper's Section 3 setting
    double alpha_plus, alpha_minus;      // what the criteria measure theta against
    const dynamics::Imperfection& imperfection;
    double restitution_given;            // NaN: Housner's, each corner's own
};

// {"model", "preset" ("paper" or "physical"), "alpha", "p", the block's
// members (add_block), "input", "solver", "rtol", "atol_rad", "criterion",
// "collapse", "t_fin", "theta_tfin_over_alpha" (null after a fall during the
// input), "max_theta_input_over_alpha", "input_lifts_block", "impacts" (an
// integer), "overturned", "overturned_during_input", "t_overturn" (a double,
// NaN where it did not overturn or fell by its energy alone),
// "collapse_final_rotation", "collapse_peak_rotation", "collapse_overturning",
// with imperfections "imperfection" and "peak_over_own_alpha", and where the
// corners differ "peak_plus_over_alpha_plus", "peak_minus_over_alpha_minus"}.
Json rocking_run_json(const RockingRun& run);

// A sliding-rocking run and what it was of.
struct SlidingRun {
    const records::CollapseOptions& model;  // its friction, criterion and tolerance, in the searches' words
    const dynamics::GivenBlock& given;
    const dynamics::sliding::FrictionBlock& block;
    const dynamics::GroundInput& input;
    const dynamics::sliding::SlidingOptions& options;
    dynamics::Criterion criterion;
    const dynamics::sliding::SlidingResult& result;
};

// {"model", "friction", "alpha", "p", "R_from_p", the block's members,
// "input", "solver", "rtol", "atol_rad", "criterion", "collapse", "t_fin",
// "theta_tfin_over_alpha", "max_theta_input_over_alpha", "overturned",
// "overturned_during_input", "t_overturn" (NaN as rocking_run_json's),
// "impacts", "slipping_impacts", "slip_tfin_m", "max_slip_m", "final_slip_m",
// "time_in" ({"rest", "slide", "rock", "slide_rock"}, s), "energy"
// ({"input_work", "friction_loss", "impact_loss", "balance_error_over_gR"}),
// "collapse_final_rotation", "collapse_peak_rotation", "collapse_overturning"}.
Json sliding_run_json(const SlidingRun& run);

}  // namespace rocking::json
