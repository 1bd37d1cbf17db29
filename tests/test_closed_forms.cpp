// q1..q5 and eqs. 27-28: agreement with the engine, limits at both ends of the
// x axis, and the properties the paper relies on.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pulse/pulse_train.hpp"
#include "qfactor/closed_forms.hpp"
#include "qfactor/superposition.hpp"

using namespace rocking;

namespace {
std::vector<double> log_grid(double from, double to, int n) {
    std::vector<double> x;
    for (int k = 0; k < n; ++k) x.push_back(from * std::pow(to / from, k / double(n - 1)));
    return x;
}
}  // namespace

TEST(ClosedForms, AgreeWithTheSuperpositionEngine) {
    // Two different formulas (factored rational in e^{-x}, and the jump sum
    // (S3)): agreement to a few ulps over twelve decades of x.
    for (int i = 1; i <= 5; ++i)
        for (double x : log_grid(1e-6, 1e3, 400)) {
            const double engine = q_factor(pulse_case(i), x).q;
            EXPECT_NEAR(q_case(i, x) / engine, 1.0, 4e-15) << "case " << i << " x " << x;
        }
}

TEST(ClosedForms, SmallXLimitIsTwoOverM1XSquared) {
    // q x^2 -> 2/M1 with a relative correction O(x^2): at x = 1e-8 exact to rounding.
    const double expected[] = {0, 1.0, 0.8, 4.0, 2.0 / 3.0, 2.0 / 3.0};
    for (int i = 1; i <= 5; ++i) {
        EXPECT_NEAR(2.0 / first_moment(pulse_case(i)), expected[i], 1e-15);
        for (double x : {1e-8, 1e-20, 1e-100, 1e-150}) {
            EXPECT_NEAR(q_case(i, x) * x * x / expected[i], 1.0, 1e-14) << "case " << i << " x " << x;
        }
    }
    // The engine's sum for eq. 28 has condition 288/9 = 32 as x -> 0 (see
    // QFactor::condition): 32 eps = 7e-15 relative.
    EXPECT_NEAR(q2_n6(1e-8) * 1e-16 / (4.0 / 27.0), 1.0, 1e-14);
    EXPECT_NEAR(q4_n6(1e-8) * 1e-16 / (2.0 / 9.0), 1.0, 1e-14);
}

TEST(ClosedForms, LargeXLimitIsOneOverFirstAmplitude) {
    const double limit[] = {0, 1, 1, 2, 1, 2};
    for (int i = 1; i <= 5; ++i) {
        for (double x : {50.0, 1e3, 1e300, std::numeric_limits<double>::max(),
                         std::numeric_limits<double>::infinity()}) {
            const double q = q_case(i, x);
            EXPECT_TRUE(std::isfinite(q));
            EXPECT_NEAR(q, limit[i], 1e-15) << "case " << i << " x " << x;
            EXPECT_EQ(q_large_x_limit(pulse_case(i)), limit[i]);
        }
        // Approach from above (q - limit ~ e^{-x}, e^{-2x} for case 5), never
        // below the limit; beyond x = 15 the difference is below rounding.
        for (double x : log_grid(1e-3, 15.0, 200)) EXPECT_GT(q_case(i, x), limit[i]) << i << " " << x;
    }
}

TEST(ClosedForms, NeverNaNOrInfiniteOnTheWholeAxis) {
    for (int i = 1; i <= 5; ++i)
        for (double x : log_grid(kSmallestX, 1e300, 3000)) {
            const double q = q_case(i, x);
            ASSERT_TRUE(std::isfinite(q) && q > 0) << "case " << i << " x " << x;
        }
}

TEST(ClosedForms, DecreaseMonotonicallyWithX) {
    for (int i = 1; i <= 5; ++i) {
        double previous = INFINITY;
        // Strictly while q - 1/A_0 is above rounding (x <= 15, see above).
        for (double x : log_grid(1e-4, 15.0, 2000)) {
            const double q = q_case(i, x);
            EXPECT_LT(q, previous) << "case " << i << " x " << x;
            previous = q;
        }
    }
}

TEST(ClosedForms, CasesThreeAndFiveNeedNoExtraBoundBecauseTheyStayAboveTwo) {
    // q3 - 2 = (6c - 4)/((2c - 1)(c - 1)) > 0 exactly; checked while above rounding.
    for (double x : log_grid(1e-4, 15.0, 2000)) {
        EXPECT_GT(q3(x), 2.0);
        EXPECT_GT(q5(x), 2.0);
    }
}

TEST(ClosedForms, RejectBadX) {
    EXPECT_THROW(q1(0.0), std::domain_error);
    EXPECT_THROW(q2(-1.0), std::domain_error);
    EXPECT_THROW(q3(std::nan("")), std::domain_error);
    EXPECT_THROW(q4(1e-200), std::domain_error);
    EXPECT_THROW(q_case(6, 1.0), std::invalid_argument);
}

TEST(ClosedForms, KnownValues) {
    // Independent spot values (mpmath, 30 digits, from the printed eqs. 12 and 15).
    EXPECT_NEAR(q1(0.5), 5.36110753101780071918040568478, 1e-14);
    EXPECT_NEAR(q2(0.5), 4.38821872331181020112064109452, 1e-14);
}
