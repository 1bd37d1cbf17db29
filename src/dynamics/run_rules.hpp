// The rules of a run that the driver (simulate.cpp) and the record kernel
// (exact_record.cpp) share, templated on the kernel's working precision.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>

#include "dynamics/model.hpp"
#include "dynamics/simulate.hpp"

namespace rocking::dynamics::rules {

// After the input the ground is at rest: a block below the energy barrier
// can never overturn (impacts only take energy away), so the run stops as
// soon as the record asked for is complete (t >= t_limit); a block above it
// is followed until it falls (t_limit raised to t_fin + 200 / p).
template <class Real>
bool stop_after_input(const Model& model, const SimulationOptions& options, bool resting, Real theta, Real omega,
                      int sigma, Real t, Real t_fin, Real& t_limit) {
    if (!options.free_rocking || resting) return true;
    if (model.energy(theta, omega, sigma) < model.barrier()) return t >= t_limit;
    t_limit = std::max(t_limit, t_fin + Real(200.0) / Real(model.block.p));
    return t >= t_limit;
}

// Counts an impact at t_impact and keeps its time; throws past
// options.max_impacts (a cascade that does not end).  True when it comes
// within 1e-6 / p of the previous impact: a bounce too small to resolve,
// which ends the cascade.
template <class Real>
bool record_impact(SimulationResult& result, Real t_impact, const SimulationOptions& options, Real p) {
    if (result.impacts == 0) result.t_first_impact = t_impact;
    result.impact_times.push_back(t_impact);
    if (++result.impacts > options.max_impacts)
        throw std::runtime_error("impact cascade did not end after " + std::to_string(options.max_impacts) +
                                 " impacts (t = " + std::to_string(t_impact) + " s)");
    return result.impact_times.size() >= 2 &&
           t_impact - result.impact_times[result.impact_times.size() - 2] < 1e-6 / p;
}

}  // namespace rocking::dynamics::rules
