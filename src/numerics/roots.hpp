// A root of f bracketed on [a, b] (TOMS 748,
// Boost.Math).  f(a) and f(b) must have opposite signs.
#pragma once

#include <boost/math/tools/toms748_solve.hpp>
#include <cstdint>

namespace rocking::numerics {

// From f(a) = fa and f(b) = fb already evaluated, stopping when the bracket
// is within 2^(1 - bits) of the root, relative, and returning its midpoint
// (the dynamics engine's event location and uplift crossings use 50 bits:
// within 2^-50 of the root).  Boost floors the bracket at 4 eps = 2^-50:
// bits above 51 gain nothing.
template <class F>
double root_of(F f, double a, double b, double fa, double fb, int bits) {
    std::uintmax_t iterations = 200;
    const auto r =
        boost::math::tools::toms748_solve(f, a, b, fa, fb, boost::math::tools::eps_tolerance<double>(bits), iterations);
    return 0.5 * (r.first + r.second);
}

// To Boost's floor: a bracket of 4 eps, the midpoint within 2 eps of the root.
template <class F>
double root_of(F f, double a, double b) {
    return root_of(f, a, b, f(a), f(b), 52);
}

}  // namespace rocking::numerics
