// The collapse search of Table 1: for a record and a slenderness alpha, the
// smallest pulsation p at which the record overturns the block.  Collapse is
// not monotone in p, so p is raised geometrically from p_min until the first
// collapse, then the boundary inside that last step is refined by bisection.
#pragma once

#include <string>

#include "dynamics/ground_input.hpp"
#include "dynamics/imperfect_block.hpp"
#include "dynamics/simulate.hpp"

namespace rocking::records {

struct CollapseOptions {
    dynamics::Equation equation = dynamics::Equation::linearised;
    bool housner_restitution = true;  // e = 1 - 1.5 sin^2 alpha; false: restitution below
    double restitution = 1.0;
    dynamics::Criterion criterion = dynamics::Criterion::overturning;
    dynamics::SolverOptions solver{};  // exact by default
    double p_min = 0.3, p_max = 30.0;  // rad/s
    double growth = 1.01;              // scan step: p *= growth
    double rel_tol = 1e-4;             // bisection until (p_hi - p_lo) / p_hi < rel_tol
    // > 0: the base on Coulomb friction (issue 41, dynamics/sliding/): the
    // sliding-rocking model, with its full equations, its impact law and its
    // event-driven solver at sliding_rtol, in place of equation, restitution
    // and solver.  0: the block that never slides.
    double friction = 0;
    double sliding_rtol = 1e-9;        // rtol and atol (in alpha) of the sliding-rocking runs
    // A search's check of a boundary: the sliding engine 1000 times tighter
    // (it has no second method in C++ yet: tools/siconos_block.py is one).
    static constexpr double kSlidingCheckRtol = 1e-12;
    // An imperfect block (issue 41, dynamics/imperfect_block.hpp): each
    // block (alpha, p) of a search leans, stands out of plumb or pivots set
    // back as this says; Housner's restitution is then each corner's own
    // from the geometry.  Not with friction (the sliding block is perfect).
    dynamics::Imperfection imperfection{};
    // The model in words: the equation, the restitution (or the friction
    // and its impact law), the criterion and the solver.
    std::string describe_model() const;
    std::string describe() const;
};

struct CollapseResult {
    bool found = false;
    double p = 0;            // smallest collapsing p found (the upper end of the final bracket)
    double p_safe = 0;       // the largest p below it known not to collapse; 0 when none was seen
    int simulations = 0;

    // Collapse already at p_min, the search's lowest p: the smallest
    // collapsing p lies at or below p_min, outside the search (p = p_min,
    // and no p was seen to be safe).
    bool below_range() const { return found && !(p_safe > 0); }
};

// The model these options describe for the block (alpha, p): the equation,
// the restitution (Housner's 1 - 1.5 sin^2 alpha of eq. 9, or the fixed
// one) and the block of pulsation p, with its imperfections.  One place, so
// that every search runs the model its options print.
dynamics::Model model_of(double alpha, double p, const CollapseOptions& options);

// Whether run r of the block (alpha, p) collapses under criterion c: theta
// against the nominal alpha, or an imperfect block's against its own
// corners' (model_of).
bool run_collapses(const dynamics::SimulationResult& r, dynamics::Criterion c, double alpha, double p,
                   const CollapseOptions& options);

CollapseResult smallest_collapse_p(const dynamics::GroundInput& input, double alpha, const CollapseOptions& options);

// Whether the input collapses the block of slenderness alpha and pulsation p,
// under the model, restitution, criterion and solver of `options`.
bool collapses_at(const dynamics::GroundInput& input, double alpha, double p, const CollapseOptions& options);

// Whether the input lifts, at rest, any block of slenderness alpha that a
// search from p_min runs: the perfect block's threshold (alpha, or tan alpha
// on eq. 1, whatever p), or an imperfect block's lowest, on the weakest
// block of the range (the lowest p that stands: the largest setback).
bool input_lifts_any(const dynamics::GroundInput& input, double alpha, double p_min, const CollapseOptions& options);

// The same block's whole run, with the free rocking after the input followed
// whatever the criterion, so that all three criteria are decided at once (the
// rocking spectrum's grid, studies/spectrum.hpp).
dynamics::SimulationResult simulate_block(const dynamics::GroundInput& input, double alpha, double p,
                                          const CollapseOptions& options);

}  // namespace rocking::records
