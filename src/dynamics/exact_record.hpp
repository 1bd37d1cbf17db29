// The exact solver's record kernel: the event loop of simulate() fused with
// the exact solution of the linearised equation on a record's pieces, for the
// case the paper's records need (linearised equation, sampled input, no
// theta(t) kept).  Same model, same rules (uplift, rest, impact cascade,
// criteria, free rocking) and the same closed form as the general path
// (ExactStepper + the driver), both written as increments on the state so
// that the rounding is relative to theta and theta' rather than to alpha;
// what it saves is the general path's machinery: virtual steps, interpolant
// calls and bracketing root-finders.  A piece whose ends prove that nothing
// happens inside (theta' and theta'' of one sign; or theta'' of one sign and
// the one extremum of theta bounded, by the tangents at the ends, away from
// the ground, from alpha and from the largest |theta| so far) costs a few
// flops, and one that only falls through the ground, one Newton solve.
// Events are located by Newton's method on the closed form (its derivative
// is known exactly), safeguarded by bisection; rebounds that land inside the
// record piece they start in, by Newton on theta(u)/u.
//
// One rule is stricter than the general path's: a piece on which theta''
// changes sign is split where it vanishes, so that theta' is monotone on each
// part and no pair of extrema of theta (and no dip below 0 between them) can
// hide inside one piece; the general path assumes one extremum per step.
#pragma once

#include "dynamics/ground_input.hpp"
#include "dynamics/model.hpp"
#include "dynamics/simulate.hpp"

namespace rocking::dynamics {

// True when simulate() hands the run to the record kernel: exact solver with
// options.solver.record_kernel on, linearised equation, a SampledInput whose
// p dt <= 0.5 (an imperfect block: on its faster corner), and no theta(t)
// record asked for (record_dt <= 0).  An imperfect block (docs/imperfect.md)
// runs it with each corner's alpha and p on the flights rocking on it, the
// restitution of the corner landed on, each side's uplift threshold, the
// largest theta on each side (peak_plus_input, peak_minus_input) and the
// general path's free-rocking rule (Model::may_overturn).
bool record_kernel_applies(const Model& model, const GroundInput& input, const SimulationOptions& options);

// The run itself (callers normally go through simulate()).
SimulationResult simulate_record_kernel(const Model& model, const SampledInput& input, const SimulationOptions& options);

// The start of a flight: the block leaves the ground (an uplift from rest,
// theta = theta' = 0), rebounds from an impact (theta = 0, theta' the
// rebound's speed, after the restitution; not a rebound that the rest rule
// stops), or is released (options.initial_theta, initial_omega; t = 0).
// sigma: the corner rocked on from there.  The escape margin of the flight
// (escape_margin.hpp) is a function of this state.
struct FlightStart {
    double t, theta, omega;
    int sigma;
};

// Told of every flight's start, in the order of the run.
class FlightObserver {
public:
    virtual ~FlightObserver() = default;
    virtual void flight(const FlightStart& start) = 0;
};

// The same run, telling `observer` of each flight's start.  The kernel is
// instantiated twice: the run above has no observer's code in it at all
// (no test, no call), and both give the same result bit for bit
// (EscapeMargin.TheObserverChangesNoOutcome).  The caller checks
// record_kernel_applies(): the general path has no observer.
SimulationResult simulate_record_kernel(const Model& model, const SampledInput& input, const SimulationOptions& options,
                                        FlightObserver& observer);

// The same kernel in long double (64-bit significand, 11 bits more than
// double) from the same double input: the reference that measures the
// double kernel's rounding error, which the response's sensitivity can
// amplify by orders of magnitude over a long record (tests, benchmark).
SimulationResult simulate_record_kernel_extended(const Model& model, const SampledInput& input,
                                                 const SimulationOptions& options);

}  // namespace rocking::dynamics
