// The engine against a 50-digit reference: (S2) evaluated naively in
// Boost.Multiprecision, where cancellation and overflow do not matter.
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_dec_float.hpp>
#include <cmath>

#include "pulse/pulse_train.hpp"
#include "qfactor/closed_forms.hpp"
#include "qfactor/superposition.hpp"

using namespace rocking;
using Big = boost::multiprecision::cpp_dec_float_50;

namespace {

// q = cosh(xT) / sum_j dA_j (cosh(x s_j) - 1), straight from the jumps.
Big reference_q(const PulseTrain& train, double x_double) {
    const Big x(x_double);
    Big T = 0, tau = 0, previous = 0, den = 0;
    for (const Pulse& p : train.pulses()) T += Big(p.duration);
    for (const Pulse& p : train.pulses()) {
        const Big a(p.amplitude);
        den += (a - previous) * (cosh(x * (T - tau)) - 1);
        previous = a;
        tau += Big(p.duration);
    }
    return cosh(x * T) / den;
}

std::vector<double> log_grid(double from, double to, int n) {
    std::vector<double> x;
    for (int k = 0; k < n; ++k) x.push_back(from * std::pow(to / from, k / double(n - 1)));
    return x;
}

void expect_close(const PulseTrain& train, double x, double q, double tolerance) {
    const Big ref = reference_q(train, x);
    const double rel = static_cast<double>(abs(Big(q) - ref) / ref);
    EXPECT_LE(rel, tolerance) << train.name() << " at x = " << x << ": q = " << q << ", reference "
                              << ref.str(20);
}

}  // namespace

TEST(Multiprecision, EngineWithin1e12ForEveryCaseAndPulseCount) {
    const auto xs = log_grid(1e-6, 50.0, 60);
    std::vector<PulseTrain> trains;
    for (int i = 1; i <= 5; ++i) trains.push_back(pulse_case(i));
    for (int c : {1, 2, 4})
        for (int n = 2; n <= 12; ++n) trains.push_back(repeated_case(c, n));
    for (const PulseTrain& train : trains)
        for (double x : xs) expect_close(train, x, q_factor(train, x).q, 1e-12);
}

TEST(Multiprecision, EngineWithin1e12BeyondFifty) {
    for (int c : {1, 2, 4})
        for (int n : {2, 6, 12})
            for (double x : {80.0, 200.0, 1000.0}) {
                const PulseTrain train = repeated_case(c, n);
                expect_close(train, x, q_factor(train, x).q, 1e-12);
            }
}

TEST(Multiprecision, ClosedFormsWithin1e12) {
    for (int i = 1; i <= 5; ++i)
        for (double x : log_grid(1e-6, 1000.0, 80)) expect_close(pulse_case(i), x, q_case(i, x), 1e-12);
}

TEST(Multiprecision, ConditionNumberBoundsTheError) {
    // The engine's own error estimate (condition * eps) must cover the error.
    for (int c : {1, 2, 4})
        for (int n = 2; n <= 12; ++n)
            for (double x : log_grid(1e-6, 50.0, 30)) {
                const PulseTrain train = repeated_case(c, n);
                const QFactor r = q_factor(train, x);
                // Leading order sum |dA| s^2 / M1: 117.5 for case 1 with N = 12.
                EXPECT_LE(r.condition, 200.0);
                expect_close(train, x, r.q, 8.0 * r.condition * 2.2e-16);
            }
}
