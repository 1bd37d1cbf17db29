#include "qfactor/superposition.hpp"

#include <cmath>
#include <limits>
#include <optional>
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

// 1 - e^{-u} for u >= 0, without cancellation as u -> 0.
double one_minus_exp(double u) { return -std::expm1(-u); }

// k e^u / 2 without overflow in e^u where k e^u / 2 itself is finite.  As
// (k/2 e^{u/2}) e^{u/2}, each factor to an ulp: exp(u + log(k/2)) would
// round its argument, an error of u eps (1.5e-13 at u = 700).
double half_exp_times(double k, double u) {
    if (k == 0.0) return 0.0;
    if (u < 700.0) return 0.5 * k * std::exp(u);
    const double half = std::exp(0.5 * u);
    return 0.5 * k * half * half;
}

// The denominator of (S3), sum_j dA_j e^{-x tau_j} (1 - e^{-x s_j})^2,
// = 2 e^{-xT} sum_j dA_j (cosh(x s_j) - 1), and the sum of its |terms|.
struct Denominator {
    double sum = 0.0, magnitude = 0.0;
};
Denominator denominator(const std::vector<Jump>& jumps, double x, double T) {
    Denominator d;
    for (const Jump& j : jumps) {
        const double e = std::expm1(-x * (T - j.tau));
        // e^{-x tau}: 0 for x = inf is the right limit, so x = +inf is allowed.
        const double term = j.dA * (j.tau == 0.0 ? 1.0 : std::exp(-x * j.tau)) * e * e;
        d.sum += term;
        d.magnitude += std::fabs(term);
    }
    return d;
}

}  // namespace

QFactor q_factor(const PulseTrain& train, double x) {
    // x = +inf is accepted: every e^{-x tau} is then 0 and q = 1 / A_0.
    if (std::isnan(x) || x < kSmallestX)
        throw std::domain_error("x = p*to must be >= 1e-150 (got " + describe_x(x) +
                                "): below it q ~ 2/(M1 x^2) overflows");
    const double T = train.t_fin();
    const Denominator d = denominator(jumps_of(train), x, T);
    const double sum = d.sum, magnitude = d.magnitude;
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

namespace {

// At the collapse q (phi(T) = 1), (S1) is phi = [cosh(xT) Sa(tau) - (cosh(x tau) - 1) Sa(T)] / Sa(T),
// Sa(tau) = sum_{tau_j <= tau} dA_j (cosh(x(tau - tau_j)) - 1).  Its two terms
// grow like e^{x(T + tau)} and cancel to O(e^{xT}): the old evaluation lost
// x tau / ln 10 digits (phi = -593 for case 4 at x = 15).  Per jump, with
// a = x(tau - tau_j), b = x tau, c = x(T - tau_j), t = xT (a + t = b + c), the
// product-to-sum identities cancel the e^{(t + a)} parts exactly:
//   tau_j <= tau:  cosh t (cosh a - 1) - (cosh b - 1)(cosh c - 1)
//                    = (cosh a - 1) - 4 sh(x tau_j/2) sh(x(T-tau)/2) [sh(t/2) sh(a/2) + sh(b/2) sh(c/2)]   (R1)
//   tau_j >  tau:  -(cosh b - 1)(cosh c - 1)
// and their derivatives in tau, over x and x^2:
//   tau_j <= tau:  [sinh b - sinh(x tau_j)] - sinh(x tau_j) (cosh(x(T - tau)) - 1)                     (R2)
//                  cosh b + sinh(x(T - tau)) sinh(x tau_j)                                              (R3)
//   tau_j >  tau:  -sinh b (cosh c - 1),  -cosh b (cosh c - 1).
// Each is a difference of two non-negative products (or one product): no
// term is larger than e^{xT}, and as x -> 0 the first product dominates, so
// nothing cancels there either.  Times 2 e^{-xT}, as the denominator of (S3),
// each is a product of exponentials <= 1 and of g(u) = 1 - e^{-u} in [0, 1]:
// no overflow for any x.  Summed over the jumps with dA_j and divided by that
// denominator they give phi, phi' and phi'' at the collapse q.
struct Numerators {
    double phi = 0.0, dphi = 0.0, ddphi = 0.0;
    double magnitude = 0.0;   // sum over the jumps of |dA_j| (P_j + Q_j) of phi's pieces
    double dmagnitude = 0.0;  // the same for phi'
};
Numerators collapse_numerators(const std::vector<Jump>& jumps, double x, double T, double tau) {
    const double g = one_minus_exp(x * tau), g2 = one_minus_exp(2.0 * x * tau), gt = one_minus_exp(x * T);
    const double gr = one_minus_exp(x * (T - tau)), gr2 = one_minus_exp(2.0 * x * (T - tau));
    const double e_tau = std::exp(x * (tau - T)), back = std::exp(-2.0 * x * tau);
    Numerators n;
    for (const Jump& j : jumps) {
        const double gc = one_minus_exp(x * (T - j.tau));
        if (j.tau <= tau) {
            const double a = x * (tau - j.tau), ga = one_minus_exp(a), e_j = std::exp(x * (j.tau - tau));
            const double gj = one_minus_exp(x * j.tau), gj2 = one_minus_exp(2.0 * x * j.tau);
            const double P = std::exp(-x * (T - tau + j.tau)) * ga * ga;  // (cosh a - 1), times 2 e^{-xT}
            const double Q = 0.5 * gj * gr * (gt * ga + g * gc);
            const double dP = e_tau * (1.0 + std::exp(-x * (tau + j.tau))) * ga, dQ = 0.5 * e_j * gj2 * gr * gr;
            const double ddP = e_tau * (1.0 + back), ddQ = 0.5 * e_j * gr2 * gj2;
            n.phi += j.dA * (P - Q);
            n.dphi += j.dA * (dP - dQ);
            n.ddphi += j.dA * (ddP + ddQ);
            n.magnitude += std::fabs(j.dA) * (P + Q);
            n.dmagnitude += std::fabs(j.dA) * (dP + dQ);
        } else {
            const double e_j = 0.5 * std::exp(x * (tau - j.tau)) * gc * gc;
            n.phi -= j.dA * e_j * g * g;
            n.dphi -= j.dA * e_j * g2;
            n.ddphi -= j.dA * e_j * (1.0 + back);
            n.magnitude += std::fabs(j.dA * e_j * g * g);
            n.dmagnitude += std::fabs(j.dA * e_j * g2);
        }
    }
    return n;
}

// (S1) and its derivatives summed as printed, at the given q, times
// 2 e^{-x tau} so that no term overflows ((cosh u - 1) 2 e^{-x tau} =
// e^{-x tau_j} (1 - e^{-u})^2, u = x(tau - tau_j)) and scaled back at the end:
// the response comes out as +-inf only where it is beyond the double range.
ResponseState direct_response(const std::vector<Jump>& jumps, double x, double q, double tau) {
    double phi = 0.0, dphi = 0.0, ddphi = 0.0, magnitude = 0.0, dmagnitude = 0.0;
    for (std::size_t k = 0; k < jumps.size() && jumps[k].tau <= tau; ++k) {
        const double dF = (k == 0) ? q * jumps[k].dA - 1.0 : q * jumps[k].dA;
        const double u = x * (tau - jumps[k].tau), e = std::exp(-x * jumps[k].tau), g = one_minus_exp(u);
        const double back = std::exp(-2.0 * u);
        phi += dF * e * g * g;
        dphi += dF * e * one_minus_exp(2.0 * u);
        ddphi += dF * e * (1.0 + back);
        magnitude += std::fabs(dF) * e * g * g;
        dmagnitude += std::fabs(dF) * e * one_minus_exp(2.0 * u);
    }
    const double u = x * tau;
    return {half_exp_times(phi, u), half_exp_times(dphi, u), half_exp_times(ddphi, u), half_exp_times(magnitude, u),
            half_exp_times(dmagnitude, u)};
}

// (r - 1)(cosh u - 1), (r - 1) sinh u and (r - 1) cosh u, finite wherever they can be.
ResponseState off_collapse(double r_minus_1, double u) {
    if (u < 700.0)
        return {r_minus_1 * cosh_m1(u), r_minus_1 * std::sinh(u), r_minus_1 * std::cosh(u),
                std::fabs(r_minus_1) * cosh_m1(u), std::fabs(r_minus_1 * std::sinh(u))};
    const double v = half_exp_times(r_minus_1, u);
    return {v, v, v, std::fabs(v), std::fabs(v)};
}

// The response to one train at one x, at the exact collapse q or at a given q.
class Evaluator {
public:
    Evaluator(const PulseTrain& train, double x, std::optional<double> q)
        : jumps_(jumps_of(train)), x_(x), T_(train.t_fin()), d_(denominator(jumps_, x, T_)) {
        collapse_ = !q.has_value();
        if (d_.sum > 0.0) qc_ = (1.0 + std::exp(-2.0 * x * T_)) / d_.sum;
        q_ = q.value_or(qc_);
        if (collapse_ && !(d_.sum > 0.0))
            throw std::domain_error("train '" + train.name() + "' has no collapse q at x = " + describe_x(x));
    }

    double q() const { return q_; }

    // q A_0 > 1: the first pulse lifts the block.  At the collapse q of a
    // large x, q_c A_0 - 1 ~ e^{-xT} rounds away with q_c (q = 1 exactly for
    // case 2 at x = 700); its sign is that of
    //   ((1 + e^{-2xT}) A_0 - D) / 2 = A_0 e^{-xT} - sum_{j >= 1} dA_j e^{-x tau_j} (1 - e^{-x s_j})^2 / 2,
    // taken here times e^{x tau_1} so that its terms neither overflow nor all underflow.
    bool onset() const {
        if (jumps_.empty() || jumps_.front().tau != 0.0 || !(jumps_.front().dA > 0.0)) return false;
        if (!collapse_) return q_ * jumps_.front().dA > 1.0;
        const double first = jumps_.size() > 1 ? jumps_[1].tau : T_;
        double sign = jumps_.front().dA * std::exp(-x_ * (T_ - first));
        for (std::size_t k = 1; k < jumps_.size(); ++k) {
            const double g = one_minus_exp(x_ * (T_ - jumps_[k].tau));
            sign -= 0.5 * jumps_[k].dA * std::exp(-x_ * (jumps_[k].tau - first)) * g * g;
        }
        return sign > 0.0;
    }

    ResponseState at(double tau) const {
        if (tau <= 0.0) return ResponseState{0.0, 0.0, 0.0, 0.0, 0.0};
        if (tau < T_) return up_to_t_fin(tau);
        // After t_fin the input is zero: psi = phi - 1 and phi' leave t_fin as
        //   psi = psi_T cosh u + w_T sinh u,  u = x (tau - T),
        // from u = 1 on written as (psi_T + w_T) e^u / 2 + (psi_T - w_T) e^{-u} / 2,
        // so that a large u gives the response's true (possibly infinite) size,
        // not inf - inf; below 1 as printed, where that split would cancel.
        const ResponseState end = up_to_t_fin(T_);
        const double psi = end.phi - 1.0, w = end.dphi, u = x_ * (tau - T_);
        // Beyond the double range at t_fin already: it only grows from there.
        if (!std::isfinite(psi) || !std::isfinite(w)) return end;
        ResponseState s;
        double grows, decays;  // cosh u and sinh u are (grows + decays), (grows - decays) of 1
        if (u < 1.0) {
            s.ddphi = psi * std::cosh(u) + w * std::sinh(u);
            s.dphi = psi * std::sinh(u) + w * std::cosh(u);
            grows = 0.5 * std::exp(u), decays = 0.5 * std::exp(-u);
        } else {
            const double decay = 0.5 * std::exp(-u);
            s.ddphi = half_exp_times(psi + w, u) + (psi - w) * decay;
            s.dphi = half_exp_times(psi + w, u) - (psi - w) * decay;
            grows = half_exp_times(1.0, u), decays = decay;
        }
        s.phi = 1.0 + s.ddphi;
        const double on_psi = end.magnitude + std::fabs(psi), on_w = end.dmagnitude + std::fabs(w);
        s.magnitude = 1.0 + on_psi * (grows + decays) + on_w * (grows - decays);
        s.dmagnitude = on_psi * (grows - decays) + on_w * (grows + decays);
        return s;
    }

private:
    // phi_c = N / D from (R1)-(R3): at the collapse q itself, whose rounding
    // to double would move phi by (its rounding) times cosh(x tau), 1e-16 e^{40}
    // for case 2 at x = 20.  At a given q = r q_c, (S1) is
    // r phi_c + (r - 1)(cosh(x tau) - 1) (phi is linear in q; the -1 of dF_0
    // gives the second term), where the rounding of q_c moves r - 1 by up to
    // D's condition times eps: the printed sum (S1) is better where its own
    // |terms| are smaller than that (early times, q A_0 near 1), and is taken there.
    ResponseState up_to_t_fin(double tau) const {
        if (!(d_.sum > 0.0)) return direct_response(jumps_, x_, q_, tau);
        const Numerators n = collapse_numerators(jumps_, x_, T_, tau);
        const double phi_c = n.phi / d_.sum;
        // phi_c carries the rounding of its sum and of the denominator's.
        const double magnitude_c = (n.magnitude + std::fabs(n.phi) * d_.magnitude / d_.sum) / d_.sum;
        const double dmagnitude_c = (n.dmagnitude + std::fabs(n.dphi) * d_.magnitude / d_.sum) / d_.sum;
        if (collapse_) return {phi_c, n.dphi / d_.sum, n.ddphi / d_.sum, magnitude_c, dmagnitude_c};
        const double r = q_ / qc_, u = x_ * tau;
        const ResponseState off = off_collapse((q_ - qc_) / qc_, u);
        ResponseState s{r * phi_c + off.phi, r * n.dphi / d_.sum + off.dphi, r * n.ddphi / d_.sum + off.ddphi,
                        r * magnitude_c + off.magnitude + r * (d_.magnitude / d_.sum) * std::fabs(off_collapse(1.0, u).phi),
                        r * dmagnitude_c + off.dmagnitude + r * (d_.magnitude / d_.sum) * std::fabs(off_collapse(1.0, u).dphi)};
        const ResponseState direct = direct_response(jumps_, x_, q_, tau);
        return direct.magnitude < s.magnitude ? direct : s;
    }

    std::vector<Jump> jumps_;
    double x_, T_;
    Denominator d_;
    bool collapse_ = false;
    double qc_ = NAN, q_ = NAN;
};

// The lowest phi and phi' and the highest phi (Excursion) of one evaluator.
Excursion excursion_of(const PulseTrain& train, double x, const Evaluator& response) {
    const double q = response.q();
    Excursion out{response.onset(), INFINITY, 0.0, INFINITY, -INFINITY, 0.0};
    // Within a pulse of level F = q A - 1 and length U = x d, psi = phi + F and
    // w = phi' move as psi = A e^u + B e^{-u}, w = A e^u - B e^{-u}, so
    //   psi is stationary at e^{2u} = B/A (A B > 0),
    //   w   is stationary at e^{2u} = -B/A (A B < 0).
    // A = (psi + w)/2 and B = (psi - w)/2 at the pulse's start, or A e^U and
    // B e^{-U} at its end, whichever end knows each better: near an
    // equilibrium A is far below the start's rounding (case 2 at x = 700
    // sits at theta = 1.5 alpha for most of its second pulse, A ~ e^{-700}),
    // and the end, where A e^U has grown back, still resolves it.  Logarithms
    // keep e^{+-U} out of range issues.  Both ends come from the evaluator,
    // which does not lose the digits that propagating the state pulse by pulse
    // did at large x (theta down to -1.8e9 alpha for case 2 at x = 20).
    auto consider = [&](double value, double where) {
        if (value < out.min_phi) {
            out.min_phi = value;
            out.tau_at_min = where;
        }
    };
    auto consider_max = [&](double value, double where) {
        if (value > out.max_phi) {
            out.max_phi = value;
            out.tau_at_max = where;
        }
    };
    const double eps = std::numeric_limits<double>::epsilon();
    double tau0 = 0.0;
    ResponseState s0 = response.at(0.0);
    for (std::size_t k = 0; k < train.size(); ++k) {
        const Pulse& p = train.pulses()[k];
        const bool first = k == 0, last = k + 1 == train.size();
        const double tau1 = last ? train.t_fin() : tau0 + p.duration;  // as the jumps place it
        const ResponseState s1 = response.at(tau1);
        const double F = q * p.amplitude - 1.0, U = x * p.duration;
        const double psi0 = s0.phi + F, w0 = s0.dphi, psi1 = s1.phi + F, w1 = s1.dphi;
        // log|A|, log|B| and their signs, each from the end that rounds it less.
        const double error0 = eps * (std::fabs(psi0) + std::fabs(w0)), error1 = eps * (std::fabs(psi1) + std::fabs(w1));
        const bool A_from_start = error0 <= error1 * std::exp(-U);
        const double A = A_from_start ? 0.5 * (psi0 + w0) : 0.5 * (psi1 + w1);
        const double log_A = std::log(std::fabs(A)) - (A_from_start ? 0.0 : U);
        const bool B_from_start = error0 <= error1 * std::exp(U);
        const double B = B_from_start ? 0.5 * (psi0 - w0) : 0.5 * (psi1 - w1);
        const double log_B = std::log(std::fabs(B)) + (B_from_start ? 0.0 : U);
        // The value at the stationary point from the evaluator too: 2 sgn(A)
        // sqrt(AB) - F would cancel where x is small (F ~ q ~ 1/x^2).
        if (A != 0.0 && B != 0.0) {
            const double u = 0.5 * (log_B - log_A), where = tau0 + u / x;
            if (u > 0.0 && u < U) {
                const ResponseState there = response.at(where);
                if ((A > 0.0) == (B > 0.0)) {
                    if (!first) consider(there.phi, where);
                    consider_max(there.phi, where);
                } else {
                    out.min_dphi = std::fmin(out.min_dphi, there.dphi);
                }
            }
        }
        consider(s1.phi, tau1);
        if (!last) consider_max(s1.phi, tau1);
        out.min_dphi = std::fmin(out.min_dphi, s1.dphi);
        tau0 += p.duration;
        s0 = s1;
    }
    return out;
}

}  // namespace

ResponseState response(const PulseTrain& train, double x, double q, double tau) {
    return Evaluator(train, x, q).at(tau);
}

ResponseState collapse_response(const PulseTrain& train, double x, double tau) {
    return Evaluator(train, x, std::nullopt).at(tau);
}

Excursion excursion(const PulseTrain& train, double x, double q) {
    return excursion_of(train, x, Evaluator(train, x, q));
}

Excursion collapse_excursion(const PulseTrain& train, double x) {
    return excursion_of(train, x, Evaluator(train, x, std::nullopt));
}

}  // namespace rocking
