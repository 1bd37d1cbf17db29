// Eq. 27 for the block the searches run (records::model_of).  The paper's
// q_27 = q2_n6(p to) holds for the symmetric block.  An imperfect block
// (issue 41) has a corner on each side with its own alpha and p: eq. 27's
// train (case 2, six pulses) then overturns it toward corner sigma at the
// PGA q2_n6(p_sigma to) alpha_sigma g (qfactor/imperfect_q.hpp), and the
// block resists the smaller.  Over the nominal alpha g, that PGA is the q a
// record's PGA/(alpha g) is checked against.  docs/findings.md, I2: eq. 27
// taken as printed (the nominal alpha and p) is non-conservative more often.
#pragma once

#include "qfactor/superposition.hpp"
#include "records/collapse.hpp"

namespace rocking::studies {

struct Eq27OfBlock {
    double q = 0;               // the collapse PGA over (alpha g), alpha the nominal
    double q_as_printed = 0;    // q2_n6(p to): the nominal block's, the paper's eq. 27
    int side = +1;              // the corner it overturns toward first (+1 or -1)
    Excursion excursion;        // eq. 27's train at q on that corner: holds while stays_positive()
};

// Throws std::domain_error where p to has no collapse q (q_factor's).
Eq27OfBlock eq27_of_block(double alpha, double p, const records::CollapseOptions& model, double to);

}  // namespace rocking::studies
