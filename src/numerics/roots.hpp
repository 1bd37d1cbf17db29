// A root of f bracketed on [a, b], to full double precision (TOMS 748,
// Boost.Math).  f(a) and f(b) must have opposite signs.
#pragma once

#include <boost/math/tools/toms748_solve.hpp>
#include <cstdint>

namespace rocking::numerics {

template <class F>
double root_of(F f, double a, double b) {
    std::uintmax_t iterations = 200;
    const auto r = boost::math::tools::toms748_solve(f, a, b, boost::math::tools::eps_tolerance<double>(52), iterations);
    return 0.5 * (r.first + r.second);
}

}  // namespace rocking::numerics
