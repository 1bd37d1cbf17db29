// The rules of a run that the driver (simulate.cpp) and the record kernel
// (exact_record.cpp) share, templated on the kernel's working precision:
// the run's state between segments, what happens at the top of each pass
// (the state at t_fin, rest and uplift, the stop after the input), the
// impact book-keeping, and the closing decision by energy.  Each caller
// keeps only its own way of integrating a segment.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dynamics/ground_input.hpp"
#include "dynamics/model.hpp"
#include "dynamics/simulate.hpp"

namespace rocking::dynamics::rules {

// The state a run carries from one segment to the next.
template <class Real>
struct RunState {
    Real t = 0, theta = 0, omega = 0;
    int sigma = 1;          // the corner rocked on (sgn theta)
    bool resting = false;   // on the ground, waiting for the input to lift it
    bool recorded = false;  // theta(t_fin) taken
    Real t_limit = 0;       // end of the free rocking followed after t_fin

    RunState(const SimulationOptions& options, Real t_fin)
        : theta(options.initial_theta),
          omega(options.initial_omega),
          sigma(options.initial_theta > 0 || (options.initial_theta == 0 && options.initial_omega > 0) ? 1 : -1),
          resting(options.initial_theta == 0.0 && options.initial_omega == 0.0),
          t_limit(t_fin + options.free_record_time) {}
};

// A run's result before the run: the input's end, and room for a record's
// impacts (Norcia's block has 221) so that impact_times does not grow by
// doubling, a reallocation and a copy each time (0.3 us of the record
// kernel's 18, bench/).
inline SimulationResult new_result(const SimulationOptions& options, double t_fin) {
    SimulationResult result;
    result.t_fin = t_fin;
    result.impact_times.reserve(std::min<std::size_t>(options.max_impact_times, 256));
    return result;
}

// After the input the ground is at rest: a block that can no longer
// overturn (Model::may_overturn: below the energy barrier on the near side
// of the top) stops as soon as the record asked for is complete (t >=
// t_limit); any other is followed until it falls (t_limit raised to t_fin +
// 200 / p).
template <class Real>
bool stop_after_input(const Model& model, const SimulationOptions& options, RunState<Real>& s, Real t_fin) {
    if (!options.free_rocking || s.resting) return true;
    if (!model.may_overturn(static_cast<double>(s.theta), static_cast<double>(s.omega), s.sigma))
        return s.t >= s.t_limit;
    s.t_limit = std::max(s.t_limit, t_fin + Real(kFreeRockingTimesP) / Real(model.p_min()));
    return s.t >= s.t_limit;
}

// The end of the input: theta(t_fin) and theta'(t_fin) taken the first time
// t reaches t_fin (note_theta(t, theta) keeps the largest |theta|).
template <class Real, class NoteTheta>
void end_of_input(RunState<Real>& s, SimulationResult& result, Real t_fin, NoteTheta note_theta) {
    if (s.recorded || s.t < t_fin) return;
    result.theta_at_tfin = static_cast<double>(s.theta);
    result.omega_at_tfin = static_cast<double>(s.omega);
    s.recorded = true;
    note_theta(t_fin, s.theta);
}

// The uplift from rest: a resting block leaves the ground when the input, as
// the caller evaluates it (at(t), see uplift_time), first exceeds the uplift
// threshold, on the corner the input pushes it to.  False when it does not
// before t_fin: the block rests to the end (theta(t_fin) = 0) and the run is
// over.  rest_until(t) lets the caller keep its theta(t) record of the rest.
template <class Real, class At, class RestUntil>
bool lift_from_rest(RunState<Real>& s, SimulationResult& result, const Model& model, const GroundInput& input, At at,
                    Real t_fin, RestUntil rest_until) {
    const Real tu = s.t >= t_fin ? Real(INFINITY)
                    : model.symmetric()
                        ? Real(uplift_time(input, static_cast<double>(s.t), static_cast<double>(t_fin),
                                           model.uplift_threshold(), at))
                        : Real(uplift_time(input, static_cast<double>(s.t), static_cast<double>(t_fin),
                                           model.uplift_threshold_on(1), model.uplift_threshold_on(-1), at));
    if (tu >= t_fin) {
        rest_until(std::max(t_fin, s.t_limit));
        if (!s.recorded) {
            result.theta_at_tfin = result.omega_at_tfin = 0.0;
            s.recorded = true;
        }
        return false;
    }
    rest_until(tu);
    s.t = tu;
    s.theta = s.omega = 0.0;
    s.sigma = at(static_cast<double>(tu)) > 0 ? 1 : -1;
    s.resting = false;
    result.uplifted = true;
    return true;
}

// The top of each pass of a run's loop, the phases in their order: the end
// of the input, the uplift of a resting block, and after the input the free
// rocking's end (stop_after_input).  False: the run is over.
template <class Real, class At, class NoteTheta, class RestUntil>
bool begin_pass(RunState<Real>& s, SimulationResult& result, const Model& model, const GroundInput& input, At at,
                const SimulationOptions& options, Real t_fin, NoteTheta note_theta, RestUntil rest_until) {
    end_of_input(s, result, t_fin, note_theta);
    if (s.resting && !lift_from_rest(s, result, model, input, at, t_fin, rest_until)) return false;
    return !(s.t >= t_fin && stop_after_input(model, options, s, t_fin));
}

// record_impact's throw, out of line: with its message built inline,
// record_impact was not inlined into the kernel's cascade (a call on every rebound).
[[noreturn]] inline __attribute__((noinline, cold)) void too_many_impacts(int max_impacts, double t_impact) {
    throw std::runtime_error("more than " + std::to_string(max_impacts) + " impacts by t = " + std::to_string(t_impact) +
                             " s: the run is stopped (SimulationOptions::max_impacts, a guard on run time)");
}

// Counts an impact at t_impact and keeps its time (the first
// options.max_impact_times); throws past options.max_impacts.  True when it
// comes within 1e-6 / p of the previous impact: a bounce too small to
// resolve, which ends the cascade.
template <class Real>
bool record_impact(SimulationResult& result, Real t_impact, const SimulationOptions& options, Real p) {
    const bool micro = result.impacts > 0 && t_impact - result.t_last_impact < 1e-6 / p;
    if (result.impacts == 0) result.t_first_impact = static_cast<double>(t_impact);
    result.t_last_impact = static_cast<double>(t_impact);
    if (result.impact_times.size() < options.max_impact_times) result.impact_times.push_back(result.t_last_impact);
    if (++result.impacts > options.max_impacts) too_many_impacts(options.max_impacts, static_cast<double>(t_impact));
    return micro;
}

// The impact itself: theta = 0, the angular velocity om_i before it times
// the restitution factor, the other corner; a rebound slower than
// rest * alpha * p, or a micro-bounce (record_impact), leaves the block at rest.
template <class Real>
void apply_impact(RunState<Real>& s, SimulationResult& result, const Model& model, Real t_impact, Real om_i,
                  bool micro, Real rest) {
    s.t = t_impact;
    s.theta = 0.0;
    s.sigma = -s.sigma;
    s.omega = Real(model.restitution_onto(s.sigma)) * om_i;
    if (micro || std::fabs(s.omega) < rest * Real(model.alpha_on(s.sigma)) * Real(model.p_on(s.sigma))) {
        s.omega = 0.0;
        s.resting = true;
        ++result.rests;
    }
}

// An impact at t_impact with angular velocity om_i before it: counted
// (record_impact), then applied (apply_impact) with the rest rule rest.
// Always inline: a call on every rebound of the kernel's cascades.
template <class Real>
__attribute__((always_inline)) inline void impact(RunState<Real>& s, SimulationResult& result, const Model& model,
                                                  const SimulationOptions& options, Real t_impact, Real om_i, Real rest) {
    const bool micro = record_impact(result, t_impact, options, Real(model.p_max()));
    apply_impact(s, result, model, t_impact, om_i, micro, rest);
}

// Overturning decided by energy when the run stopped in free rocking
// without simulating the fall: a block that may still overturn after 200 / p
// of free rocking is taken to (Model::may_overturn).
template <class Real>
void decide_by_energy(const RunState<Real>& s, SimulationResult& result, const Model& model,
                      const SimulationOptions& options, Real t_fin) {
    if (options.free_rocking && !result.overturned && !s.resting && s.recorded && s.t >= t_fin &&
        model.may_overturn(static_cast<double>(s.theta), static_cast<double>(s.omega), s.sigma))
        result.overturned = true;
}

}  // namespace rocking::dynamics::rules
