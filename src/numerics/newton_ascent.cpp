#include "numerics/newton_ascent.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rocking::numerics {

void newton_ascent(const std::function<double(double, double)>& lnl, const std::function<Slopes2(double, double)>& slopes,
                   double& a, double& b, const std::string& who) {
    double current = lnl(a, b);
    bool converged = false;
    for (int iteration = 0; iteration < 200 && !converged; ++iteration) {
        const Slopes2 s = slopes(a, b);
        // The Newton step solves H d = -g (H negative definite).
        const double det = s.h_aa * s.h_bb - s.h_ab * s.h_ab;
        if (!(det > 0))
            throw std::runtime_error(who + ": ln L's Hessian lost its sign to rounding at beta " + std::to_string(1 / a));
        double d_a = (-s.g_a * s.h_bb + s.g_b * s.h_ab) / det, d_b = (-s.g_b * s.h_aa + s.g_a * s.h_ab) / det;
        if (std::fabs(d_a) <= 1e-13 * a && std::fabs(d_b) <= 1e-13 * std::max(1.0, std::fabs(b))) {
            a += d_a;
            b += d_b;
            converged = true;
            break;
        }
        const double rise = 0.5 * (s.g_a * d_a + s.g_b * d_b);
        if (rise <= 1e-12 * (1 + std::fabs(current)) && a + d_a > 0) {
            a += d_a;
            b += d_b;
            current = lnl(a, b);
            continue;
        }
        double next = -INFINITY;
        for (int halving = 0; halving < 60; ++halving) {
            if (a + d_a > 0) {
                next = lnl(a + d_a, b + d_b);
                if (next >= current) break;
            }
            d_a *= 0.5;
            d_b *= 0.5;
        }
        if (!(next >= current))
            throw std::runtime_error(who + ": Newton's method found no step up although ln L should rise by " +
                                     std::to_string(rise));
        a += d_a;
        b += d_b;
        current = next;
    }
    if (!converged) throw std::runtime_error(who + ": Newton's method did not converge in 200 iterations");
}

}  // namespace rocking::numerics
