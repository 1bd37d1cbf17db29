#include "studies/scaled_response.hpp"

#include <cmath>
#include <stdexcept>

#include "studies/scaled_input.hpp"

namespace rocking::studies {

std::vector<ScaledRun> scaled_response(const dynamics::GroundInput& input, double alpha, double p,
                                       const records::CollapseOptions& model, double q_min, double q_max, int points) {
    if (!(q_min > 0 && q_max > q_min && std::isfinite(q_max)))
        throw std::invalid_argument("scaled_response: needs 0 < q_min < q_max, finite");
    if (points < 2 || points > 100000) throw std::invalid_argument("scaled_response: points must be in [2, 100000]");
    if (!(input.peak() > 0)) throw std::invalid_argument("scaled_response: the input never moves (peak 0)");
    std::vector<ScaledRun> out;
    out.reserve(points);
    const double step = std::log(q_max / q_min) / (points - 1);
    for (int k = 0; k < points; ++k) {
        // The ends exactly, the rest log-spaced between them.
        const double q = k == 0 ? q_min : k == points - 1 ? q_max : q_min * std::exp(step * k);
        const dynamics::SimulationResult run =
            records::simulate_block(*scaled(input, q * alpha / input.peak()), alpha, p, model);
        out.push_back({q, run.max_abs_theta_input / alpha, records::run_collapses(run, model.criterion, alpha, p, model)});
    }
    return out;
}

}  // namespace rocking::studies
