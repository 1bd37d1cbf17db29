// The full equation's own truth: times of its motion under a constant ground
// acceleration A g (A = 0: free rocking), from its first integral, by
// quadrature in long double.  Nothing here comes from src/: the tests use it
// to check the ODE solvers on the full equation against something other than
// each other.
//
// On corner sigma = +1 (model.hpp), theta'' = p^2 [A cos phi - sin phi] with
// phi = alpha - theta, so
//   theta'^2 / 2 + p^2 (cos phi + A sin phi) = const,
//   cos phi + A sin phi = r cos(phi - beta),  r = sqrt(1 + A^2),  beta = atan A.
// Between two rests of theta' (or a rest and theta = 0), with
// psi = |phi - beta| moving away from psi0 (where theta' = 0),
//   theta'^2 = 2 p^2 r (cos psi0 - cos psi) = 4 p^2 r (sin^2(psi/2) - k^2),  k = sin(psi0/2),
// and sin(psi/2) = k cosh v turns dt = dpsi / |theta'| into
//   dt = dv / (p sqrt(r) sqrt(1 - k^2 cosh^2 v)),
// smooth on the whole range (the 1/sqrt(sin^2 - k^2) of the rest point is gone):
//   t(psi0 -> psi1) = (1 / (p sqrt r)) * integral_0^V dv / sqrt(1 - k^2 cosh^2 v),
//   V = acosh(sin(psi1/2) / k),  for psi0 < psi1 < pi.
// Its linearised limit is (1/p) acosh(alpha / (alpha - theta0)) (the free
// rocking quarter period of the issue).
#pragma once

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rocking::testing {

// (1 / p_eff) integral_0^acosh(s1/k) dv / sqrt(1 - k^2 cosh^2 v), 0 < k < s1 < 1.
// Gauss-Kronrod in long double; its error estimate must stay below 1e-15 of
// the value (tanh-sinh agreed to 1e-19 on k 1e-8 to 0.1, s1 0.2 to 0.95).
inline long double rise_time(long double k, long double s1, long double p_eff) {
    if (!(k > 0 && k < s1 && s1 < 1)) throw std::invalid_argument("rise_time: needs 0 < k < s1 < 1");
    const long double V = std::acosh(s1 / k);
    auto f = [k](long double v) {
        const long double c = k * std::cosh(v);
        return 1 / std::sqrt(1 - c * c);
    };
    long double error = 0;
    const long double t =
        boost::math::quadrature::gauss_kronrod<long double, 31>::integrate(f, 0.0L, V, 15, 1e-16L, &error);
    if (!(error <= 1e-15L * t)) throw std::runtime_error("rise_time: quadrature did not converge");
    return t / p_eff;
}

// The first n impact times of the full equation released from rest at
// theta0 (0 < theta0 < alpha), ground at rest, restitution e on theta'.
// Each half-cycle from theta = 0 to its peak and back takes twice the time
// from the peak down; at an impact theta'^2 becomes e^2 theta'^2, so with
// k = sin((alpha - |theta_peak|)/2), s = sin(alpha/2):
//   4 p^2 (s^2 - k1^2) = e^2 4 p^2 (s^2 - k0^2),  k1^2 = (1 - e^2) s^2 + e^2 k0^2
// (a sum of positive terms: no cancellation near the top).
inline std::vector<long double> free_rocking_impact_times(long double alpha, long double p, long double e,
                                                          long double theta0, int n) {
    const long double s = std::sin(alpha / 2), e2 = e * e;
    long double k = std::sin((alpha - theta0) / 2);
    long double t = rise_time(k, s, p);
    std::vector<long double> times{t};
    while (static_cast<int>(times.size()) < n) {
        k = std::sqrt((1 - e2) * s * s + e2 * k * k);
        t += 2 * rise_time(k, s, p);
        times.push_back(t);
    }
    return times;
}

// The time a block at rest at theta = 0 takes to reach theta1 under a
// constant ground acceleration A g, A > tan alpha (it uplifts at once, on
// corner +): psi = beta - alpha + theta from psi0 = beta - alpha.
inline long double step_time_to(long double alpha, long double p, long double A, long double theta1) {
    const long double beta = std::atan(A), r = std::sqrt(1 + A * A);
    if (!(beta > alpha) || !(beta - alpha + theta1 < M_PI)) throw std::invalid_argument("step_time_to: out of range");
    return rise_time(std::sin((beta - alpha) / 2), std::sin((beta - alpha + theta1) / 2), p * std::sqrt(r));
}

}  // namespace rocking::testing
