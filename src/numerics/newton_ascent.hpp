// The maximum of a concave log-likelihood of two parameters (a, b), a > 0, by
// Newton's method with the step halved until ln L does not fall: the censored
// lognormal fit (studies/fragility.cpp, Olsen's theta = 1/beta, gamma =
// mu/beta) and the multiple-stripe fit (studies/stripe_fit.cpp, a = 1/beta,
// b = mu/beta about a reference) share it.
#pragma once

#include <functional>
#include <string>

namespace rocking::numerics {

// ln L's gradient and Hessian at (a, b).
struct Slopes2 {
    double g_a = 0, g_b = 0, h_aa = 0, h_ab = 0, h_bb = 0;
};

// From (a, b), until both Newton steps are below 1e-13 relative (of a, and
// of max(1, |b|)), at most 200 iterations.  A step whose predicted rise
// g.d/2 is below ln L's rounding (1e-12 (1 + |ln L|)) is taken whole: ln L
// can no longer judge it, and stopping there left fits 1e-8 off.  Farther
// off the step is halved (at most 60 times) until ln L does not fall and a
// stays > 0.  Throws std::runtime_error, its message led by `who`, where the
// Hessian is not negative definite (only rounding gets there for the callers'
// concave ln L), no halved step rises, or 200 iterations do not converge.
void newton_ascent(const std::function<double(double, double)>& lnl, const std::function<Slopes2(double, double)>& slopes,
                   double& a, double& b, const std::string& who);

}  // namespace rocking::numerics
