#include "qfactor/closed_forms.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "pulse/pulse_train.hpp"
#include "qfactor/superposition.hpp"

namespace rocking {

namespace {
// (1 - e^{-x})^2 without cancellation.
double one_minus_u_sq(double x) {
    const double d = std::expm1(-x);
    return d * d;
}
void check_x(double x) {
    if (std::isnan(x) || x < kSmallestX)
        throw std::domain_error("x = p*to must be a number >= 1e-150 (got " + std::to_string(x) + ")");
}
}  // namespace

double q1(double x) {
    check_x(x);
    const double u = std::exp(-x), u2 = u * u;
    return (1.0 + u2 * u2) / ((1.0 + u2) * one_minus_u_sq(x));
}

double q2(double x) {
    check_x(x);
    const double u = std::exp(-x), u2 = u * u;
    return 2.0 * (1.0 + u2 * u2) / ((2.0 + u + 2.0 * u2) * one_minus_u_sq(x));
}

double q3(double x) {
    check_x(x);
    const double u = std::exp(-x), u2 = u * u;
    return 2.0 * (1.0 + u2 * u2) / ((1.0 - u + u2) * one_minus_u_sq(x));
}

double q4(double x) {
    check_x(x);
    const double u = std::exp(-x), u2 = u * u, u3 = u2 * u;
    return (1.0 + u3 * u3) / ((1.0 + 0.5 * u + 0.5 * u3 + u2 * u2) * one_minus_u_sq(x));
}

double q5(double x) {
    check_x(x);
    const double u = std::exp(-x), u2 = u * u, u3 = u2 * u;
    return 2.0 * (1.0 + u3 * u3) / ((1.0 + 2.0 * u + 2.0 * u3 + u2 * u2) * one_minus_u_sq(x));
}

double q_case(int which, double x) {
    switch (which) {
        case 1: return q1(x);
        case 2: return q2(x);
        case 3: return q3(x);
        case 4: return q4(x);
        case 5: return q5(x);
        default:
            throw std::invalid_argument("case must be 1, 2, 3, 4 or 5 (got " + std::to_string(which) + ")");
    }
}

double q2_n6(double x) { return q_factor(repeated_case(2, 6), x).q; }
double q4_n6(double x) { return q_factor(repeated_case(4, 6), x).q; }

}  // namespace rocking
