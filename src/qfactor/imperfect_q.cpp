#include "qfactor/imperfect_q.hpp"

#include <cmath>
#include <stdexcept>

namespace rocking {

double ImperfectCollapse::pga_g() const { return std::fmin(toward_plus.pga_g, toward_minus.pga_g); }

int ImperfectCollapse::weaker_side() const { return toward_minus.pga_g < toward_plus.pga_g ? -1 : 1; }

ImperfectCollapse imperfect_collapse(const PulseTrain& train, double to, CornerOfBlock plus, CornerOfBlock minus) {
    for (double v : {to, plus.alpha, plus.p, minus.alpha, minus.p})
        if (!(std::isfinite(v) && v > 0))
            throw std::invalid_argument("imperfect_collapse: to, each corner's alpha and p must be finite and > 0");
    // Toward theta < 0 the block sees the mirror image of eq. 3 on that
    // corner: the same (S2) in its own x, scaled by its own alpha.
    auto toward = [&](const CornerOfBlock& c) {
        DirectionalCollapse d;
        d.x = c.p * to;
        d.pga_g = q_factor(train, d.x).q * c.alpha;
        d.excursion = collapse_excursion(train, d.x);
        return d;
    };
    return {toward(plus), toward(minus)};
}

}  // namespace rocking
