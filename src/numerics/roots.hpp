// A root of f bracketed on [a, b] (TOMS 748,
// Boost.Math).  f(a) and f(b) must have opposite signs.
#pragma once

#include <boost/math/tools/toms748_solve.hpp>
#include <cstdint>

#include "numerics/bisect.hpp"

namespace rocking::numerics {

// From f(a) = fa and f(b) = fb already evaluated, stopping when the bracket
// is within 2^(1 - bits) of the root, relative, and returning its midpoint
// (the dynamics engine's event location and uplift crossings use 50 bits:
// within 2^-50 of the root).  Boost floors the bracket at 4 eps = 2^-50:
// bits above 51 gain nothing.
//
// TOMS 748 can run out of its 200 iterations on a bracket spanning decades
// (a fall 1e-34 s into a step of 0.01 s, under an input of 1e100 g: it
// stopped at [7e-52, 8e-26] and returned 4e-26).  The bracket it hands back
// then goes on by bisect_decades (bisect.hpp) to the same tolerance.
template <class F>
double root_of(F f, double a, double b, double fa, double fb, int bits) {
    const std::uintmax_t max_iterations = 200;
    std::uintmax_t iterations = max_iterations;
    boost::math::tools::eps_tolerance<double> tolerance(bits);
    auto r = boost::math::tools::toms748_solve(f, a, b, fa, fb, tolerance, iterations);
    if (iterations >= max_iterations) {
        const bool lo_negative = f(r.first) < 0;
        bisect_decades(r.first, r.second, [&](double x) { return (f(x) < 0) == lo_negative; },
                       [&](double lo, double hi) { return tolerance(lo, hi); });
    }
    return 0.5 * (r.first + r.second);
}

// To Boost's floor: a bracket of 4 eps, the midpoint within 2 eps of the root.
template <class F>
double root_of(F f, double a, double b) {
    return root_of(f, a, b, f(a), f(b), 52);
}

}  // namespace rocking::numerics
