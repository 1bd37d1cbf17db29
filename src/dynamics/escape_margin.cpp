#include "dynamics/escape_margin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rocking::dynamics {

namespace {

// 1 - e^{-x} (1 + x) = e^{-x} x^2 sum_k x^k / (k + 2)!: by the series below
// x = 1 (every term positive, cut where the next is below 1e-19 of the sum),
// where the difference would cancel up to 1/x of its digits; directly above.
double one_minus_exp_times_1_plus(double x) {
    if (x > 1) return -std::expm1(-x) - x * std::exp(-x);
    double term = 0.5, sum = 0.5;
    for (int k = 1; k < 20 && term > 1e-19 * sum; ++k) {
        term *= x / (k + 2);
        sum += term;
    }
    return std::exp(-x) * x * x * sum;
}

}  // namespace

// p int_0^u e^{-p s} (a0 + c1 s) ds = a0 (1 - e^{-x}) + (c1 / p) (1 - e^{-x} (1 + x)), x = p u.
double piece_integral(double a0, double c1, double u, double p) {
    const double x = p * u;
    return a0 * -std::expm1(-x) + c1 / p * one_minus_exp_times_1_plus(x);
}

// J at the samples, backwards from J(T) = 0: over piece k,
//   J(k dt) = e^{-p dt} J((k + 1) dt) + p int_0^dt e^{-p s} a(k dt + s) ds;
// L forwards from L(0) = 0: over piece k, with s counted back from its end,
//   L((k + 1) dt) = e^{-p dt} L(k dt) + p int_0^dt e^{-p s} (a_{k+1} - c1 s) ds.
// (docs/overturning_set.md, section 1.)  Both multiply the past by e^{-p dt} < 1:
// the recursions damp their rounding.
RestOfInput::RestOfInput(const SampledInput& record, double p, bool with_past)
    : a_(record.samples().data()), n_(record.samples().size()), J_(n_), L_(with_past ? n_ : 0), dt_(record.dt()),
      with_past_(with_past) {
    if (n_ < 2) throw std::invalid_argument("RestOfInput: the record needs at least two samples");
    retune(p);
}

void RestOfInput::retune(double p) {
    if (!(p > 0 && std::isfinite(p))) throw std::invalid_argument("RestOfInput: p must be finite and > 0");
    p_ = p;
    const double x = p * dt_, decay = std::exp(-x), e1 = -std::expm1(-x), e2 = one_minus_exp_times_1_plus(x) / p;
    const std::size_t n = n_;
    J_[n - 1] = 0.0;
    for (std::size_t k = n - 1; k-- > 0;) {
        const double c1 = (a_[k + 1] - a_[k]) / dt_;
        J_[k] = decay * J_[k + 1] + (a_[k] * e1 + c1 * e2);
    }
    if (!with_past_) return;
    L_[0] = 0.0;
    for (std::size_t k = 0; k + 1 < n; ++k) {
        const double c1 = (a_[k + 1] - a_[k]) / dt_;
        L_[k + 1] = decay * L_[k] + (a_[k + 1] * e1 - c1 * e2);
    }
}

std::size_t RestOfInput::piece(double t) const {
    const double k = std::floor(t / dt_);
    return k <= 0 ? 0 : std::min(static_cast<std::size_t>(k), n_ - 2);
}

double RestOfInput::accel(double t) const {
    if (t >= t_end()) return 0.0;
    const std::size_t k = piece(t);
    return a_[k] + (a_[k + 1] - a_[k]) / dt_ * std::fma(-double(k), dt_, t);
}

double RestOfInput::slope(double t) const {
    if (t >= t_end()) return 0.0;
    const std::size_t k = piece(t);
    return (a_[k + 1] - a_[k]) / dt_;
}

// Inside piece k, from t to the piece's end, then J there carried back.
double RestOfInput::at(double t) const {
    if (t >= t_end()) return 0.0;
    const std::size_t k = piece(t);
    const double c1 = (a_[k + 1] - a_[k]) / dt_, to_end = std::fma(double(k + 1), dt_, -t);
    return piece_integral(accel(t), c1, to_end, p_) + std::exp(-p_ * to_end) * J_[k + 1];
}

// From the piece's start to t (its integral read backwards from t), and
// after the end the last value decaying.
double RestOfInput::past(double t) const {
    if (!with_past_) throw std::logic_error("RestOfInput::past: built without L");
    if (t >= t_end()) return std::exp(-p_ * (t - t_end())) * L_.back();
    const std::size_t k = piece(t);
    const double c1 = (a_[k + 1] - a_[k]) / dt_, from_start = std::fma(-double(k), dt_, t);
    return std::exp(-p_ * from_start) * L_[k] + piece_integral(accel(t), -c1, from_start, p_);
}

// In one piece: J(t0) = P(t0, d) + e^{-p d} J(t1) with P(t0, d) = p int_0^d
// e^{-p s} a(t0 + s) ds, so J(t0) e^{p d} - J(t1) = e^{p d} P(t0, d); and
// L(t1) = e^{-p d} L(t0) + p int_0^d e^{-p s} a(t1 - s) ds.  After the end
// both gains are 0 (no input).
double RestOfInput::unstable_gain(double t0, double t1) const {
    const double d = t1 - t0;
    if (t0 >= t_end()) return 0.0;
    if (t1 < t_end() && piece(t0) == piece(t1)) return std::exp(p_ * d) * piece_integral(accel(t0), slope(t0), d, p_);
    return at(t0) * std::exp(p_ * d) - at(t1);
}

double RestOfInput::stable_gain(double t0, double t1) const {
    const double d = t1 - t0;
    if (t0 >= t_end()) return 0.0;
    if (t1 < t_end() && piece(t0) == piece(t1)) return -piece_integral(accel(t1), -slope(t1), d, p_);
    return past(t0) * std::exp(-p_ * d) - past(t1);
}

// Xi = (y + y'/p + sigma J) / alpha, y = sigma theta - alpha (section 1).
double escape_margin(const Model& model, const RestOfInput& rest, double scale, double t, double theta, double omega,
                     int sigma) {
    const double alpha = model.block.alpha, p = model.block.p;
    return (sigma * theta - alpha + sigma * omega / p + sigma * scale * rest.at(t)) / alpha;
}

FlightMargins::FlightMargins(const Model& model, const RestOfInput& rest, double scale, bool slopes)
    : model_(model), rest_(rest), scale_(scale), slopes_(slopes) {
    if (model.equation != Equation::linearised)
        throw std::invalid_argument("FlightMargins: the escape margin is eq. 3's (the linearised equation)");
    // An imperfect block's flights would each need their own corner's alpha,
    // p and J (docs/imperfect.md, "Solvers"): not derived here.
    if (!model.symmetric())
        throw std::invalid_argument("FlightMargins: the escape margin is the symmetric block's (Model::minus unset)");
    if (model.block.p != rest.p()) throw std::invalid_argument("FlightMargins: the RestOfInput is at another p");
    if (slopes && !rest.has_past()) throw std::invalid_argument("FlightMargins: the slopes need the RestOfInput's L");
}

void FlightMargins::clear() {
    flights_.clear();
    tangent_ = Tangent{};
}

double FlightMargins::max_margin() const {
    double m = -std::numeric_limits<double>::infinity();
    for (const FlightMargin& f : flights_) m = std::max(m, f.xi);
    return m;
}

// The tangent from its last start to t, no impact between: u + qJ grows as
// e^{p t}, v + qL decays as e^{-p t} (u = theta_q + theta_q'/p, v =
// theta_q - theta_q'/p; theta_q'' = p^2 (theta_q + q a/g)).
FlightMargins::Tangent FlightMargins::carried_to(double t) const {
    const double p = model_.block.p, q = scale_, d = t - tangent_.t;
    const double u0 = tangent_.theta + tangent_.omega / p, v0 = tangent_.theta - tangent_.omega / p;
    const double u1 = u0 * std::exp(p * d) + q * rest_.unstable_gain(tangent_.t, t);
    const double v1 = v0 * std::exp(-p * d) + q * rest_.stable_gain(tangent_.t, t);
    return {t, (u1 + v1) / 2, p * (u1 - v1) / 2};
}

// The flight's margin and its slope: dXi/d ln q = (the derivative at a fixed
// time) + Xi' t_q, with Xi' = p Xi on the flight and t_q the start's move.
void FlightMargins::flight(const FlightStart& s) {
    const double alpha = model_.block.alpha, p = model_.block.p, q = scale_;
    if (!slopes_) {
        flights_.push_back({s.t, s.sigma, escape_margin(model_, rest_, q, s.t, s.theta, s.omega, s.sigma),
                            std::numeric_limits<double>::quiet_NaN()});
        return;
    }
    const bool uplift = s.theta == 0.0 && s.omega == 0.0;
    const bool rebound = !uplift && !flights_.empty() && s.theta == 0.0;
    double t_q = 0.0;
    if (rebound) {
        // The impact just before: theta' = omega- there, on corner -sigma.
        const double e = model_.restitution, om_minus = s.omega / e;
        const Tangent before = carried_to(s.t);
        const double a = q * rest_.accel(s.t);
        const double dd_minus = p * p * (a + s.sigma * alpha), dd_plus = p * p * (a - s.sigma * alpha);
        t_q = -before.theta / om_minus;
        tangent_ = {s.t, e * before.theta, e * (before.omega + dd_minus * t_q) - dd_plus * t_q};
    } else {
        // From rest (or released): the tangent is 0.  An uplift moves with
        // where q a reaches the threshold sigma alpha: t_q = -a / a'.  At
        // t = 0 the record starts above it (a jump from rest, for every q
        // near): the start does not move.
        if (uplift && s.t > 0) t_q = -s.sigma * model_.uplift_threshold() / (q * rest_.slope(s.t));
        tangent_ = {s.t, 0.0, 0.0};
    }
    const double xi = escape_margin(model_, rest_, q, s.t, s.theta, s.omega, s.sigma);
    const double at_fixed_time = s.sigma * (tangent_.theta + tangent_.omega / p + q * rest_.at(s.t)) / alpha;
    flights_.push_back({s.t, s.sigma, xi, at_fixed_time + p * xi * t_q});
}

SimulationResult simulate_with_margins(const Model& model, const SampledInput& input, const SimulationOptions& options,
                                       FlightMargins& margins) {
    if (!record_kernel_applies(model, input, options))
        throw std::invalid_argument("simulate_with_margins: the record kernel does not apply to this run");
    return simulate_record_kernel(model, input, options, margins);
}

}  // namespace rocking::dynamics
