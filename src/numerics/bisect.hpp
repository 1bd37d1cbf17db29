// Bisection of a bracket [lo, hi] that may span decades: geometric while
// its ends are positive and differ by more than a factor 4 (each step then
// halves the ratio's logarithm), arithmetic otherwise.  The root finders'
// fallback where their own steps stall on such a bracket (roots.hpp,
// dynamics/closed_piece.hpp).
#pragma once

#include <cmath>

namespace rocking::numerics {

// Shrinks [lo, hi] while !done(lo, hi), at most 2200 steps (enough for any
// pair of doubles); on_lo_side(x) says whether x replaces lo (f(x) has
// f(lo)'s sign).  The bracket is left in lo and hi.
template <class Real, class OnLoSide, class Done>
void bisect_decades(Real& lo, Real& hi, OnLoSide on_lo_side, Done done) {
    for (int i = 0; i < 2200 && !done(lo, hi); ++i) {
        const Real x = lo > 0 && hi > 4 * lo ? std::sqrt(lo) * std::sqrt(hi) : lo + (hi - lo) / 2;
        if (!(x > lo && x < hi)) return;
        if (on_lo_side(x)) lo = x;
        else hi = x;
    }
}

}  // namespace rocking::numerics
