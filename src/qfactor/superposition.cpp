#include "qfactor/superposition.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rocking {

namespace {

struct Jump {
    double tau;  // when, in units of to
    double dA;   // jump of the amplitude, in units of PGA
};

// Jumps of A(tau) on [0, t_fin): the onset at 0 and one between pulses.
std::vector<Jump> jumps_of(const PulseTrain& train) {
    std::vector<Jump> jumps;
    double tau = 0.0, previous = 0.0;
    for (const Pulse& p : train.pulses()) {
        if (p.amplitude != previous) jumps.push_back({tau, p.amplitude - previous});
        previous = p.amplitude;
        tau += p.duration;
    }
    return jumps;
}

// cosh(u) - 1 without cancellation.
double cosh_m1(double u) {
    const double s = std::sinh(0.5 * u);
    return 2.0 * s * s;
}

std::string describe_x(double x) {
    std::ostringstream os;
    os.precision(17);
    os << x;
    return os.str();
}

}  // namespace

QFactor q_factor(const PulseTrain& train, double x) {
    // x = +inf is accepted: every e^{-x tau} is then 0 and q = 1 / A_0.
    if (std::isnan(x) || x < kSmallestX)
        throw std::domain_error("x = p*to must be >= 1e-150 (got " + describe_x(x) +
                                "): below it q ~ 2/(M1 x^2) overflows");
    const double T = train.t_fin();
    double sum = 0.0, magnitude = 0.0;
    for (const Jump& j : jumps_of(train)) {
        const double e = std::expm1(-x * (T - j.tau));
        // e^{-x tau}: 0 for x = inf is the right limit, so x = +inf is allowed.
        const double term = j.dA * (j.tau == 0.0 ? 1.0 : std::exp(-x * j.tau)) * e * e;
        sum += term;
        magnitude += std::fabs(term);
    }
    // Each term is ~ dA (x s)^2 for small x s: below (1e-150)^2 they leave
    // the normal range, the sum rounds to a denormal or to 0, and q to inf
    // or to "no q" (a pulse of x d = 1e-160 or 1e-300), as for x itself.
    if (magnitude < kSmallestX * kSmallestX)
        throw std::domain_error("train '" + train.name() + "' at x = " + describe_x(x) +
                                ": p times its pulses' durations is below 1e-150, where q ~ 2/(M1 x^2) overflows");
    if (!(sum > 0.0))
        throw std::domain_error("train '" + train.name() + "' cannot bring theta(t_fin) to alpha at x = " +
                                describe_x(x) + " for any q > 0 (denominator of (S2) is <= 0)");
    const double numerator = 1.0 + std::exp(-2.0 * x * T);
    return {numerator / sum, magnitude / sum};
}

double first_moment(const PulseTrain& train) {
    const double T = train.t_fin();
    double m = 0.0;
    for (const Jump& j : jumps_of(train)) m += j.dA * (T - j.tau) * (T - j.tau);
    return m;
}

double q_large_x_limit(const PulseTrain& train) { return 1.0 / train.pulses().front().amplitude; }

ResponseState response(const PulseTrain& train, double x, double q, double tau) {
    ResponseState s{0.0, 0.0, 0.0};
    if (tau <= 0.0) return s;
    std::vector<Jump> jumps = jumps_of(train);
    jumps.push_back({train.t_fin(), -train.pulses().back().amplitude});  // the input ends
    for (std::size_t k = 0; k < jumps.size() && jumps[k].tau <= tau; ++k) {
        const double dF = (k == 0) ? q * jumps[k].dA - 1.0 : q * jumps[k].dA;
        const double u = x * (tau - jumps[k].tau);
        s.phi += dF * cosh_m1(u);
        s.dphi += dF * std::sinh(u);
        s.ddphi += dF * std::cosh(u);
    }
    return s;
}

Excursion excursion(const PulseTrain& train, double x, double q) {
    Excursion out{q * train.pulses().front().amplitude > 1.0, INFINITY, 0.0, INFINITY, -INFINITY};
    // Propagate (psi, w) = (phi + F, phi'/x) exactly through each pulse:
    // psi(u) = psi0 cosh u + w0 sinh u, w(u) = psi0 sinh u + w0 cosh u.
    double phi = 0.0, w = 0.0, tau0 = 0.0;
    auto consider = [&](double value, double where) {
        if (value < out.min_phi) {
            out.min_phi = value;
            out.tau_at_min = where;
        }
    };
    for (const Pulse& p : train.pulses()) {
        const double F = q * p.amplitude - 1.0;
        const double psi0 = phi + F;
        const double U = x * p.duration;
        // Stationary point of phi inside the pulse: tanh u = -w0 / psi0.
        if (psi0 != 0.0) {
            const double r = -w / psi0;
            if (r > 0.0 && r < 1.0) {
                const double u = std::atanh(r);
                if (u < U) {
                    const double value = psi0 * std::cosh(u) + w * std::sinh(u) - F;
                    consider(value, tau0 + u / x);
                    out.max_phi = std::fmax(out.max_phi, value);
                }
            }
        }
        // Stationary point of phi' inside the pulse: tanh u = -psi0 / w0.
        if (w != 0.0) {
            const double r = -psi0 / w;
            if (r > 0.0 && r < 1.0) {
                const double u = std::atanh(r);
                if (u < U) out.min_dphi = std::fmin(out.min_dphi, psi0 * std::sinh(u) + w * std::cosh(u));
            }
        }
        const double c = std::cosh(U), s = std::sinh(U);
        phi = psi0 * c + w * s - F;
        w = psi0 * s + w * c;
        tau0 += p.duration;
        consider(phi, tau0);
        if (&p != &train.pulses().back()) out.max_phi = std::fmax(out.max_phi, phi);
        out.min_dphi = std::fmin(out.min_dphi, w);
    }
    return out;
}

}  // namespace rocking
