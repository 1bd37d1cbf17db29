// The closed-form q of an imperfect block (issue 41, docs/imperfect.md):
// a train of pulses pushes the block onto one corner and, while it does not
// come back to the ground (the paper's own condition: Excursion), it rocks
// on that corner alone by eq. 3 with the corner's own alpha and p.  The
// collapse PGA toward each corner is then that corner's (S2):
//   PGA_sigma = q(p_sigma to) alpha_sigma g,
// the train as given toward theta > 0 (its first pulse is positive), its
// mirror image toward theta < 0.  A block must resist the input from either
// side: its capacity is the smaller.
#pragma once

#include "pulse/pulse_train.hpp"
#include "qfactor/superposition.hpp"

namespace rocking {

struct CornerOfBlock {
    double alpha;  // rad
    double p;      // rad/s
};

struct DirectionalCollapse {
    double x;           // p_sigma to
    double pga_g;       // q(x) alpha_sigma: the collapse PGA in g
    Excursion excursion;  // at the collapse q: holds while stays_positive()
};

struct ImperfectCollapse {
    DirectionalCollapse toward_plus, toward_minus;
    // The smaller PGA and its side (+1 or -1).
    double pga_g() const;
    int weaker_side() const;
};

// Throws std::domain_error as q_factor where a corner's x has no collapse q,
// std::invalid_argument for a non-positive to, alpha or p.
ImperfectCollapse imperfect_collapse(const PulseTrain& train, double to, CornerOfBlock plus, CornerOfBlock minus);

}  // namespace rocking
