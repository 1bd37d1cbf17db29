#include "dynamics/sliding/friction_block.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "dynamics/model.hpp"

namespace rocking::dynamics::sliding {

namespace {

constexpr double g = kGravity;

int sign(double v) { return (v > 0) - (v < 0); }

double k2(const FrictionBlock& block) { return block.R * block.R / 3; }

}  // namespace

double FrictionBlock::b() const { return R * std::sin(alpha); }
double FrictionBlock::h() const { return R * std::cos(alpha); }
double FrictionBlock::p() const { return std::sqrt(3 * g / (4 * R)); }

void check_block(const FrictionBlock& block) {
    if (!(block.alpha > 0 && block.alpha < M_PI / 4))
        throw std::invalid_argument("sliding block: alpha must be in (0, pi/4) (got " + std::to_string(block.alpha) + ")");
    if (!(block.R > 0 && std::isfinite(block.R)))
        throw std::invalid_argument("sliding block: R must be finite and > 0 (got " + std::to_string(block.R) + ")");
    if (!(block.mu > 0)) throw std::invalid_argument("sliding block: mu must be > 0 (got " + std::to_string(block.mu) + ")");
}

Lever centroid_from_pivot(const FrictionBlock& block, double theta, int sigma) {
    const double b = block.b(), h = block.h(), c = std::cos(theta), s = std::sin(theta);
    return {-sigma * b * c + h * s, sigma * b * s + h * c};
}

Contact stick_rocking(const FrictionBlock& block, double theta, double omega, int sigma, double A) {
    const Lever d = centroid_from_pivot(block, theta, sigma);
    Contact c;
    c.theta_dd = 3 * (d.dx * g + d.dy * A) / (4 * block.R * block.R);
    c.f = d.dy * c.theta_dd - d.dx * omega * omega - A;
    c.n = g - d.dx * c.theta_dd - d.dy * omega * omega;
    return c;
}

Contact slip_rocking(const FrictionBlock& block, double theta, double omega, int sigma, int s, double A) {
    const Lever d = centroid_from_pivot(block, theta, sigma);
    const double c = d.dx + block.mu * s * d.dy, denominator = k2(block) + d.dx * c;
    if (!(denominator > 0))
        throw std::domain_error("slide-rock: R^2/3 + dx (dx + mu s dy) = " + std::to_string(denominator) +
                                " <= 0 (the Painleve paradox: no compressive contact force)");
    Contact out;
    out.theta_dd = c * (g - d.dy * omega * omega) / denominator;
    out.n = g - d.dx * out.theta_dd - d.dy * omega * omega;
    out.f = -block.mu * s * out.n;
    out.pivot_dd = A + out.f - d.dy * out.theta_dd + d.dx * omega * omega;
    return out;
}

double sliding_accel(const FrictionBlock& block, int s, double A) { return A - block.mu * g * s; }

double trailing_normal(const FrictionBlock& block) { return 0.5 * g * (1 - block.mu * block.h() / block.b()); }

const char* regime_name(Regime r) {
    switch (r) {
        case Regime::rest: return "rest";
        case Regime::slide: return "slide";
        case Regime::rock: return "rock";
        case Regime::slide_rock: return "slide-rock";
    }
    return "?";
}

Start start_flat(const FrictionBlock& block, double A, double v) {
    if (v != 0) {
        const int s = sign(v);
        // The trailing corner stays down only while mu <= tan(alpha).
        if (trailing_normal(block) >= 0) return {Regime::slide, 0, s};
        return {Regime::slide_rock, s, s};
    }
    // At rest while it neither turns (theta'' towards d, which is |A| > g tan(alpha)
    // as the forces round it: tan(alpha) against b/h differed by an ulp at the
    // threshold and left no regime consistent) nor slides (|A| > mu g).
    const int d = sign(A);
    const Contact rock = stick_rocking(block, 0, 0, d, A);
    const bool turns = rock.theta_dd * d > 0, slides = std::fabs(A) > block.mu * g;
    if (!turns && !slides) return {Regime::rest, 0, 0};
    if (turns && rock.n >= 0 && std::fabs(rock.f) <= block.mu * rock.n) return {Regime::rock, d, 0};
    if (slides && trailing_normal(block) >= 0) return {Regime::slide, 0, d};
    const Contact both = slip_rocking(block, 0, 0, d, d, A);
    if (both.theta_dd * d > 0 && both.pivot_dd * d > 0 && both.n >= 0) return {Regime::slide_rock, d, d};
    throw std::domain_error("a block at rest under A = " + std::to_string(A) +
                            " m/s^2: no regime of the four is consistent (mu = " + std::to_string(block.mu) + ")");
}

Start start_on_corner(const FrictionBlock& block, double theta, double omega, int sigma, double A) {
    const Contact rock = stick_rocking(block, theta, omega, sigma, A);
    if (std::fabs(rock.f) <= block.mu * rock.n) return {Regime::rock, sigma, 0};
    return {Regime::slide_rock, sigma, -sign(rock.f)};
}

Impact corner_impact(const FrictionBlock& block, int sigma, double omega, double xg_dot, double yg_dot) {
    const double dx = sigma * block.b(), dy = block.h(), K = k2(block), R2 = block.R * block.R;
    Impact out;
    out.omega = (K * omega - dx * yg_dot + dy * xg_dot) / (4 * R2 / 3);
    out.p_n = -dx * out.omega - yg_dot;
    out.p_t = dy * out.omega - xg_dot;
    if (std::fabs(out.p_t) <= block.mu * out.p_n) return out;
    const int z = sign(out.p_t);
    const double c = dx - block.mu * z * dy, denominator = K + c * dx;
    if (!(denominator > 0)) throw std::domain_error("impact: the slipping impact has no solution (R^2/3 + c' dx' <= 0)");
    out.omega = (K * omega - c * yg_dot) / denominator;
    out.p_n = -dx * out.omega - yg_dot;
    out.p_t = block.mu * z * out.p_n;
    out.pivot_v = xg_dot + out.p_t - dy * out.omega;
    out.slipped = true;
    // The friction impulse must oppose the slip it leaves, and press.
    if (out.p_n < 0 || sign(out.pivot_v) == z)
        throw std::domain_error("impact: the slipping impact is inconsistent (the slip it leaves runs with its "
                                "friction impulse, or the ground pulls)");
    return out;
}

}  // namespace rocking::dynamics::sliding
