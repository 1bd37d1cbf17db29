// Two islands of overturning about 5e-5 wide, one in p and one in q, known in
// closed form (issue 39: the exact overturning set must find what the grid
// misses).  Both are two_pulses_truth.hpp's chain with d1 tuned a few 1e-8 s
// above the tangency at which the island is born: the block, rescued by -B,
// lands, rests and is lifted on the other corner for the rest of the pulse,
// r = d1 - u_impact, and overturns iff (B - alpha) expm1(p r) > alpha; that
// margin peaks at 6.1e-10 (p) and 9.1e-10 (q) rad.  The boundaries are
// tools/narrow_island.py's (mpmath findroot at 40 digits on the margin, with
// the doubles the library sees); tests/test_overturning_truth.cpp checks them
// against a long-double bisection of the chain and the library against both.
#pragma once

#include "dynamics/ground_input.hpp"
#include "pulse/pulse_train.hpp"
#include "two_pulses_truth.hpp"

namespace rocking::testing {

// +0.2 g for 1 s, then -0.11 g for 4.622764322 s; alpha 0.1, restitution 0.
// Overturns on p in [lower, upper] (5.06e-5 in ln p, 230 times narrower than
// the default spectrum grid's half step, ln 1.0116), and elsewhere in [0.3, 30]
// wherever the chain says (checked by the test: nowhere near the island).
struct NarrowIslandInP {
    static constexpr double A0 = 0.2, d0 = 1.0, B = 0.11, d1 = 4.622764322, alpha = 0.1;
    static constexpr long double lower = 0.913386081338839846866246253544L;
    static constexpr long double upper = 0.913432301523206330591390861903L;
    static dynamics::PulseInput input() {
        return dynamics::PulseInput(PulseTrain({{1.0, d0}, {-B / A0, d1}}), A0, 1.0);
    }
    // The chain with the doubles the library simulates: the second pulse's
    // amplitude A0 (-B / A0) and its length (d0 + d1) - d0.
    static bool overturns(long double p) {
        const long double b = -(A0 * (-B / A0)), len = static_cast<long double>(d0 + d1) - d0;
        return two_pulses_overturn(A0, d0, b, len, alpha, p);
    }
};

// +A g for 0.5 s, then -A g for 0.850945071 s at p = 3, A = q alpha (the IDA's
// q: PGA / (alpha g)); alpha 0.1, restitution 0.  Overturns on q in
// [lower, upper] (4.92e-5 in ln q, 310 times narrower than the default IDA
// grid's half step, ln 1.01524).
struct NarrowIslandInQ {
    static constexpr double d0 = 0.5, d1 = 0.850945071, p = 3.0, alpha = 0.1, pga = 0.3;
    static constexpr long double lower = 1.26540732608601336705905114935L;
    static constexpr long double upper = 1.26546961237156644479059847127L;
    static dynamics::PulseInput input() { return dynamics::PulseInput(PulseTrain({{1.0, d0}, {-1.0, d1}}), pga, 1.0); }
    static bool overturns(long double q) {
        const long double len = static_cast<long double>(d0 + d1) - d0;
        return q > 1 && two_pulses_overturn(q * alpha, d0, q * alpha, len, alpha, p);
    }
};

}  // namespace rocking::testing
