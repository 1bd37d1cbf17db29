// The printed formulas: those that match the engine must keep matching, and
// the errata found must stay found (a fix to the engine that made a wrong
// printed formula "match" would fail here).
#include <gtest/gtest.h>

#include <cmath>

#include "pulse/pulse_train.hpp"
#include "qfactor/closed_forms.hpp"
#include "qfactor/printed.hpp"
#include "qfactor/superposition.hpp"

using namespace rocking;
using namespace rocking::printed;

TEST(Printed, ClosedFormsForQMatchWhereThePaperIsRight) {
    for (double x = 0.05; x <= 3.0; x += 0.05) {
        EXPECT_NEAR(eq12_q(x) / q1(x), 1.0, 1e-10) << x;
        EXPECT_NEAR(eq15_q(x) / q2(x), 1.0, 1e-10) << x;
        EXPECT_NEAR(eq19_q(x) / q3(x), 1.0, 1e-10) << x;
        EXPECT_NEAR(eq22_q(x) / q4(x), 1.0, 1e-10) << x;
        EXPECT_NEAR(eq24_q(x) / q5(x), 1.0, 1e-10) << x;
        EXPECT_NEAR(eq27_q(x) / q2_n6(x), 1.0, 1e-10) << x;
        EXPECT_NEAR(eq28_q_corrected(x) / q4_n6(x), 1.0, 1e-10) << x;
    }
}

TEST(Printed, ResponseFormulasMatchWhereThePaperIsRight) {
    for (double x : {0.1, 0.7, 1.6})
        for (double tau = 0.0; tau <= 3.0; tau += 0.125) {
            const double q = 3.7;
            if (tau <= 1.0) {
                EXPECT_NEAR(eq07_phi(q, x, tau), response(pulse_case(1), x, q, tau).phi, 1e-12);
                EXPECT_NEAR(eq08_dphi(q, x, tau), response(pulse_case(2), x, q, tau).dphi, 1e-12);
                EXPECT_NEAR(eq16_phi(q, x, tau), response(pulse_case(3), x, q, tau).phi, 1e-12);
                EXPECT_NEAR(eq17_dphi(q, x, tau), response(pulse_case(3), x, q, tau).dphi, 1e-12);
            }
            if (tau >= 1.0 && tau <= 2.0) {
                EXPECT_NEAR(eq10_phi(q, x, tau), response(pulse_case(1), x, q, tau).phi, 1e-11);
                EXPECT_NEAR(eq14_phi(q, x, tau), response(pulse_case(2), x, q, tau).phi, 1e-11);
                EXPECT_NEAR(eq18_phi(q, x, tau), response(pulse_case(3), x, q, tau).phi, 1e-11);
            }
            if (tau >= 1.0) {
                EXPECT_NEAR(eq20_phi(q, x, tau), response(pulse_case(4), x, q, tau).phi, 1e-11);
            }
            if (tau >= 2.0) {
                EXPECT_NEAR(eq23_phi_corrected(q, x, tau), response(pulse_case(5), x, q, tau).phi, 1e-11);
            }
        }
}

TEST(Printed, Eq23AsPrintedIsWrong) {
    // Printed: 2 sinh^2(pt/2)(q5 - 1); the jump sum gives (q5 - 2) sinh^2(pt/2).
    // The two differ by q5 sinh^2(pt/2), at least 0.5 at t = 3 to, x = 0.5.
    const double x = 0.5, q = q5(x);
    const double printed_value = eq23_phi(q, x, 3.0), engine = response(pulse_case(5), x, q, 3.0).phi;
    EXPECT_NEAR(engine, 1.0, 1e-12);
    EXPECT_NEAR(printed_value - engine, q * std::pow(std::sinh(1.5 * x), 2), 1e-9);
    EXPECT_GT(std::fabs(printed_value - engine), 0.5);
}

TEST(Printed, Eq28AsPrintedIsWrong) {
    // As printed, q -> 2 as x -> 0 instead of growing like 1/x^2, and q -> 2/3
    // as x -> infinity instead of 1.
    EXPECT_NEAR(eq28_q(1e-3), 2.0, 1e-4);
    EXPECT_NEAR(eq28_q(20.0), 2.0 / 3.0, 1e-6);
    EXPECT_GT(std::fabs(eq28_q(0.5) / q4_n6(0.5) - 1.0), 0.1);
}

TEST(Printed, Eq3AsPrintedHasTheWrongSigns) {
    // At rest with no input the printed eq. 3 gives theta'' = +p^2 alpha
    // (gravity overturning a block at rest); the correct eq. gives -p^2 alpha.
    EXPECT_EQ(eq03_accel(0.0, 0.0), 1.0);
    EXPECT_EQ(eq03_accel_corrected(0.0, 0.0), -1.0);
    EXPECT_EQ(eq06_accel(0.0, 0.0), -1.0);
}
