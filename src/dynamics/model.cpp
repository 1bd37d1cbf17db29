#include "dynamics/model.hpp"

#include <cfloat>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rocking::dynamics {

namespace {
void require(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("block: " + what);
}
}  // namespace

Block Block::from_half_dimensions(double b, double h) {
    require(std::isfinite(b) && std::isfinite(h) && b > 0 && h > 0, "half-width and half-height must be > 0");
    const double R = std::hypot(b, h);
    return {std::atan(b / h), std::sqrt(3.0 * kGravity / (4.0 * R)), R};
}

Block Block::from_half_height(double h, double alpha) {
    require(std::isfinite(alpha) && alpha > 0 && alpha < M_PI / 4, "alpha must be in (0, pi/4)");
    require(std::isfinite(h) && h > 0, "height must be > 0");
    // At 2.3e-308 m, p = sqrt(3 g / 4 R) overflowed to inf (assess printed p and x null), and a
    // subnormal half-width lost the digits that give alpha back (0.15 became 0.15000000000000013).
    const double b = h * std::tan(alpha);
    require(b >= DBL_MIN && std::isfinite(std::sqrt(3.0 * kGravity / (4.0 * std::hypot(b, h)))),
            "height is too small for a double (the half-width h tan(alpha) or p = sqrt(3 g / 4 R) leaves its range)");
    return from_half_dimensions(b, h);
}

Block Block::from_full_height(double H, double alpha) { return from_half_height(H / 2.0, alpha); }

Block Block::from_p(double p, double alpha) {
    require(std::isfinite(alpha) && alpha > 0 && alpha < M_PI / 4, "alpha must be in (0, pi/4)");
    require(std::isfinite(p) && p > 0, "p must be > 0");
    return {alpha, p, 0.0};
}

double housner_restitution(double alpha) {
    const double s = std::sin(alpha);
    return 1.0 - 1.5 * s * s;
}

double Model::uplift_threshold() const {
    const double alpha = alpha_min();
    return equation == Equation::linearised ? alpha : std::tan(alpha);
}

double Model::uplift_threshold_on(int sigma) const {
    const double alpha = alpha_on(sigma);
    return equation == Equation::linearised ? alpha : std::tan(alpha);
}

// An imperfect block's corner rocks by the same equations with its own
// alpha and p (the equations of docs/imperfect.md).
double Model::acceleration(double theta, int sigma, double a_g) const {
    const double p = p_on(sigma), alpha = alpha_on(sigma), p2 = p * p;
    if (equation == Equation::linearised) return p2 * (a_g - sigma * alpha + theta);
    const double u = sigma * alpha - theta;
    return p2 * (a_g * std::cos(u) - std::sin(u));
}

double Model::jerk(double theta, double omega, int sigma, double a_g, double a_rate) const {
    const double p = p_on(sigma), alpha = alpha_on(sigma), p2 = p * p;
    if (equation == Equation::linearised) return p2 * (omega + a_rate);
    const double u = sigma * alpha - theta;
    return p2 * ((a_rate + omega) * std::cos(u) + a_g * omega * std::sin(u));
}

double Model::energy(double theta, double omega, int sigma) const {
    const double p = p_on(sigma), alpha = alpha_on(sigma), p2 = p * p;
    if (equation == Equation::linearised) {
        const double d = theta - sigma * alpha;
        return 0.5 * omega * omega - 0.5 * p2 * d * d;
    }
    return 0.5 * omega * omega + p2 * std::cos(sigma * alpha - theta);
}

double Model::barrier() const { return equation == Equation::linearised ? 0.0 : block.p * block.p; }

double Model::barrier_on(int sigma) const {
    const double p = p_on(sigma);
    return equation == Equation::linearised ? 0.0 : p * p;
}

bool Model::may_overturn(double theta, double omega, int sigma) const {
    if (sigma * theta > alpha_on(sigma) || energy(theta, omega, sigma) >= barrier_on(sigma)) return true;
    if (symmetric()) return false;
    // An imperfect block below its barrier comes back to theta = 0 and lands
    // on the other corner, whose barrier may be lower: the rebound decides.
    // Every later rebound is slower (each restitution <= 1, refused above).
    const double p = p_on(sigma), alpha = alpha_on(sigma);
    const double e = energy(theta, omega, sigma);
    const double omega0_sq = equation == Equation::linearised ? 2 * e + p * p * alpha * alpha
                                                              : 2 * (e - p * p * std::cos(alpha));
    const double rebound = restitution_onto(-sigma) * std::sqrt(std::max(0.0, omega0_sq));
    return energy(0.0, -sigma * rebound, -sigma) >= barrier_on(-sigma);
}

std::string Model::describe() const {
    std::ostringstream os;
    os << (equation == Equation::linearised ? "linearised eq. 3" : "full eq. 1") << ", alpha = " << block.alpha
       << ", p = " << block.p << " rad/s, restitution " << restitution;
    if (!symmetric())
        os << "; imperfect, on theta < 0: alpha = " << minus.alpha << ", p = " << minus.p
           << " rad/s, restitution onto it " << minus.restitution;
    return os.str();
}

}  // namespace rocking::dynamics
