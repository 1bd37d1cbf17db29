// The block's response along the record's scale (issue 40, the plot of
// `rocking assess`): the run at each of a log-spaced set of q = PGA/(alpha g)
// of the record scaled, as the IDA takes it, with its peak |theta|/alpha
// during the input and whether it overturns (the free rocking after the
// input followed).  The IDA finds where the outcome changes; this samples
// what happens in between, for the eye: a curve, not a search.
#pragma once

#include <vector>

#include "dynamics/ground_input.hpp"
#include "records/collapse.hpp"

namespace rocking::studies {

struct ScaledRun {
    double q = 0;
    double peak_theta_over_alpha = 0;  // max |theta|/alpha on [0, t_fin]; the fall angle's where it fell in the input
    bool overturns = false;            // under the options' criterion
};

// `points` q log-spaced over [q_min, q_max] (both included), each a run of
// the input scaled to PGA = q alpha g.  Throws std::invalid_argument for
// 0 < q_min < q_max not holding, points not in [2, 100000], and whatever
// simulate() throws.
std::vector<ScaledRun> scaled_response(const dynamics::GroundInput& input, double alpha, double p,
                                       const records::CollapseOptions& model, double q_min, double q_max, int points);

}  // namespace rocking::studies
