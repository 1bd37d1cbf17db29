#include "qfactor/printed.hpp"

#include <cmath>

namespace rocking::printed {

namespace {
double sh2(double v) {
    const double s = std::sinh(v);
    return s * s;
}
}  // namespace

// theta'' = p^2 (alpha - theta) - p^2 a/g  ->  phi'' = (1 - phi) - qa
double eq03_accel(double phi, double qa) { return (1.0 - phi) - qa; }
// theta'' = -p^2 (alpha - theta) + p^2 a/g ->  phi'' = (phi - 1) + qa
double eq06_accel(double phi, double qa) { return (phi - 1.0) + qa; }
double eq03_accel_corrected(double phi, double qa) { return phi + qa - 1.0; }

double eq07_phi(double q, double x, double tau) { return (q - 1.0) * (std::cosh(x * tau) - 1.0); }
double eq08_dphi(double q, double x, double tau) { return (q - 1.0) * std::sinh(x * tau); }

double eq10_phi(double q, double x, double tau) {
    return 2.0 * (sh2(x * tau / 2.0) * (q - 1.0) - 2.0 * q * sh2(x * (tau - 1.0) / 2.0));
}

double eq12_q(double x) {
    const double c = std::cosh(x);
    return (2.0 * c * c - 1.0) / (2.0 * c * (c - 1.0));
}

double eq14_phi(double q, double x, double tau) {
    return 2.0 * sh2(x * tau / 2.0) * (q - 1.0) - 3.0 * q * sh2(x * (tau - 1.0) / 2.0);
}

double eq15_q(double x) {
    const double c = std::cosh(x);
    return (2.0 - 4.0 * c * c) / (3.0 * c - 4.0 * c * c + 1.0);
}

double eq16_phi(double q, double x, double tau) { return (q / 2.0 - 1.0) * (std::cosh(x * tau) - 1.0); }
double eq17_dphi(double q, double x, double tau) { return (q / 2.0 - 1.0) * std::sinh(x * tau); }

double eq18_phi(double q, double x, double tau) {
    return sh2(x * tau / 2.0) * (q - 2.0) - 3.0 * q * sh2(x * (tau - 1.0) / 2.0);
}

double eq19_q(double x) {
    const double c = std::cosh(x);
    return (4.0 * c * c - 2.0) / (2.0 * c * c - 3.0 * c + 1.0);
}

double eq20_phi(double q, double x, double tau) { return eq14_phi(q, x, tau); }

double eq22_q(double x) {
    return 2.0 * std::cosh(3.0 * x) / (2.0 * std::cosh(3.0 * x) - 3.0 * std::cosh(2.0 * x) + 1.0);
}

double eq23_phi(double q, double x, double tau) {
    return 2.0 * sh2(x * tau / 2.0) * (q - 1.0) - 3.0 * q * sh2(x * (tau - 2.0) / 2.0);
}
double eq23_phi_corrected(double q, double x, double tau) {
    return sh2(x * tau / 2.0) * (q - 2.0) - 3.0 * q * sh2(x * (tau - 2.0) / 2.0);
}

double eq24_q(double x) {
    return 2.0 * std::cosh(3.0 * x) / (std::cosh(3.0 * x) - 3.0 * std::cosh(x) + 2.0);
}

double eq27_q(double x) {
    const double num = 2.0 / 3.0 * sh2(3.0 * x) + 1.0 / 3.0;
    const double den = sh2(x) - sh2(x / 2.0) + sh2(2.0 * x) - sh2(2.5 * x) - sh2(1.5 * x) +
                       2.0 / 3.0 * sh2(3.0 * x);
    return num / den;
}

namespace {
double eq28_with(double c9_coefficient, double x) {
    const double den = std::cosh(3 * x) + std::cosh(6 * x) - std::cosh(2 * x) - std::cosh(8 * x) +
                       c9_coefficient * std::cosh(9 * x) - std::cosh(5 * x) + 1.0 / 3.0;
    return 2.0 / 3.0 * std::cosh(9 * x) / den;
}
}  // namespace

double eq28_q(double x) { return eq28_with(1.0, x); }
double eq28_q_corrected(double x) { return eq28_with(2.0 / 3.0, x); }

}  // namespace rocking::printed
