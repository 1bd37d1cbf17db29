// The overturning of the linearised block under +A0 g for d0 then -B g for d1,
// with restitution 0, by a chain of closed forms: a truth for the rocking
// spectrum's island (tests/test_spectrum.cpp, over p) and the IDA's two
// intervals in q (tests/test_ida.cpp).
//   1. theta = (A0 - alpha)(cosh pt - 1) on corner +, falling over if it
//      reaches pi/2 within d0;
//   2. under -B, y = theta - alpha - B = y0 cosh pu + v0 sinh pu.  With
//      y0 + v0 >= 0 it only rises, and falls over (after the pulse, with the
//      equilibrium lowered to alpha, still more so); otherwise it peaks at
//      alpha + B - sqrt(y0^2 - v0^2) (over if >= pi/2) and comes back to 0
//      at E = e^{pu}, the root > 1 of (y0 + v0) E^2 + 2 (alpha + B) E + (y0 - v0);
//   3. no impact within d1: free rocking from the state at d1, over iff
//      (theta - alpha) + theta'/p > 0;
//   4. an impact at u < d1: at rest, then lifted on corner - by the rest of
//      the pulse, r = d1 - u, over iff (B - alpha)(cosh pr - 1) >= pi/2 or
//      (B - alpha)(e^{pr} - 1) > alpha (a single pulse's criterion).
// Valid for A0 > alpha (the first pulse lifts the block).
#pragma once

#include <cmath>

namespace rocking::testing {

inline bool two_pulses_overturn(long double A0, long double d0, long double B, long double d1, long double alpha,
                                long double p) {
    constexpr long double kHalfPi = 1.57079632679489661923132169163975144L;
    const long double c = A0 - alpha;
    const long double th1 = c * (std::cosh(p * d0) - 1);
    if (th1 >= kHalfPi) return true;
    const long double y0 = th1 - alpha - B, v0 = c * std::sinh(p * d0);
    if (y0 + v0 >= 0) return true;
    const long double u_peak = std::atanh(-v0 / y0) / p;
    const long double peak =
        u_peak < d1 ? alpha + B - std::sqrt(y0 * y0 - v0 * v0) : alpha + B + y0 * std::cosh(p * d1) + v0 * std::sinh(p * d1);
    if (peak >= kHalfPi) return true;
    const long double qa = y0 + v0, qb = 2 * (alpha + B), qc = y0 - v0;
    const long double u_impact = std::log((-qb - std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)) / p;
    if (u_impact >= d1) {
        const long double th = alpha + B + y0 * std::cosh(p * d1) + v0 * std::sinh(p * d1);
        const long double om_p = y0 * std::sinh(p * d1) + v0 * std::cosh(p * d1);
        return (th - alpha) + om_p > 0;
    }
    const long double r = d1 - u_impact, cb = B - alpha;
    return cb * (std::cosh(p * r) - 1) >= kHalfPi || cb * std::expm1(p * r) > alpha;
}

}  // namespace rocking::testing
