// The superposition engine: invariants, the response, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pulse/pulse_train.hpp"
#include "qfactor/closed_forms.hpp"
#include "qfactor/superposition.hpp"
#include "test_util.hpp"

using namespace rocking;

TEST(Trains, CasesOfFigure3) {
    EXPECT_DOUBLE_EQ(pulse_case(1).t_fin(), 2.0);
    EXPECT_DOUBLE_EQ(pulse_case(4).t_fin(), 3.0);
    EXPECT_DOUBLE_EQ(pulse_case(5).t_fin(), 3.0);
    EXPECT_DOUBLE_EQ(repeated_case(2, 6).t_fin(), 6.0);  // eq. 27
    EXPECT_DOUBLE_EQ(repeated_case(4, 6).t_fin(), 9.0);  // eq. 28
    EXPECT_EQ(repeated_case(1, 7).size(), 7u);
    EXPECT_DOUBLE_EQ(repeated_case(2, 5).pulses().back().amplitude, 1.0);
    EXPECT_DOUBLE_EQ(pulse_case(3).amplitude_at(0.5), 0.5);
    EXPECT_DOUBLE_EQ(pulse_case(3).amplitude_at(1.5), -1.0);
    EXPECT_DOUBLE_EQ(pulse_case(3).amplitude_at(2.0), 0.0);
}

TEST(Trains, RejectBadTrains) {
    EXPECT_THROW(PulseTrain({}), std::invalid_argument);
    EXPECT_THROW(PulseTrain({{1.0, 0.0}}), std::invalid_argument);
    EXPECT_THROW(PulseTrain({{1.0, -1.0}}), std::invalid_argument);
    EXPECT_THROW(PulseTrain({{-1.0, 1.0}}), std::invalid_argument);
    EXPECT_THROW(PulseTrain({{NAN, 1.0}}), std::invalid_argument);
    EXPECT_THROW(pulse_case(0), std::invalid_argument);
    EXPECT_THROW(repeated_case(2, 0), std::invalid_argument);
    EXPECT_THROW(parse_train("1:1,-0.5"), std::invalid_argument);
    EXPECT_THROW(parse_train("1:1,abc:1"), std::invalid_argument);
    EXPECT_THROW(parse_train("1:1,-0.5:1x"), std::invalid_argument);
    EXPECT_EQ(parse_train("1:1,-0.5:2").t_fin(), 3.0);
}

TEST(Engine, RejectsBadXAndImpossibleTrains) {
    EXPECT_THROW(q_factor(pulse_case(1), 0.0), std::domain_error);
    EXPECT_THROW(q_factor(pulse_case(1), -0.5), std::domain_error);
    EXPECT_THROW(q_factor(pulse_case(1), NAN), std::domain_error);
    // A strong reverse pulse: theta(t_fin) cannot reach alpha for any q.
    try {
        q_factor(parse_train("1:1,-5:1"), 1.0);
        FAIL() << "expected domain_error";
    } catch (const std::domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot bring theta(t_fin) to alpha"), std::string::npos);
    }
}

TEST(Engine, ResponseReachesAlphaAtTFin) {
    for (int i = 1; i <= 5; ++i)
        for (double x : {0.1, 0.5, 1.0, 2.0}) {
            const PulseTrain train = pulse_case(i);
            const double q = q_factor(train, x).q;
            EXPECT_NEAR(response(train, x, q, train.t_fin()).phi, 1.0, 1e-11) << i << " " << x;
        }
}

TEST(Engine, ResponsePhiIsAccurateToTheConditionOfItsSum) {
    // (S1) summed in long double (test_util.hpp); its condition is the sum of
    // |terms|: of order 1 where x is small (q ~ 1/x^2 against cosh - 1 ~ x^2),
    // growing like e^{x tau} where it is large.  response() keeps phi within
    // 4 eps of it (measured up to 1.9 eps; 1e-16 q e^{x tau}, the bound that
    // holds for ddphi, would allow 4e-8 at x = 1e-4).
    const double eps = std::numeric_limits<double>::epsilon();
    for (int c = 1; c <= 5; ++c)
        for (double x : {1e-4, 1e-2, 1.0, 5.0}) {
            const PulseTrain train = pulse_case(c);
            const double q = q_case(c, x), T = train.t_fin();
            for (int i = 1; i <= 64; ++i) {
                const double tau = T * i / 64;
                const rocking::testing::S1Sum s1 = rocking::testing::s1_sum(
                    train, [&](std::size_t k) { return static_cast<long double>(q) * train.pulses()[k].amplitude - 1; },
                    1.0, x, tau);
                EXPECT_NEAR(response(train, x, q, tau).phi, static_cast<double>(s1.phi),
                            4 * eps * std::fmax(1.0, static_cast<double>(s1.condition)))
                    << "case " << c << " x " << x << " tau " << tau;
            }
        }
}

TEST(Engine, ResponseSatisfiesTheEquationOfMotion) {
    // phi'' = x^2 (phi + F) in tau, i.e. ddphi = phi + q A - 1, at every time.
    const PulseTrain train = repeated_case(2, 6);
    const double x = 0.7, q = q_factor(train, x).q;
    for (double tau = 0.013; tau < 8.0; tau += 0.1) {
        const ResponseState s = response(train, x, q, tau);
        EXPECT_NEAR(s.ddphi, s.phi + q * train.amplitude_at(tau) - 1.0, 1e-11 * std::fmax(1, std::fabs(s.phi)));
    }
}

TEST(Engine, StatePropagationAgreesWithSuperposition) {
    // excursion propagates (phi, phi') pulse by pulse: its lowest value
    // after the first pulse must not be above what the superposition gives on
    // a fine grid there, and must agree with it to the grid's resolution.
    const PulseTrain train = repeated_case(1, 6);
    for (double x : {0.2, 0.6, 1.5}) {
        const double q = q_factor(train, x).q;
        const Excursion e = excursion(train, x, q);
        double sampled = INFINITY;
        const double t1 = train.start(1), T = train.t_fin();
        for (int k = 0; k <= 60000; ++k) sampled = std::fmin(sampled, response(train, x, q, t1 + (T - t1) * k / 60000.0).phi);
        EXPECT_LE(e.min_phi, sampled + 1e-12);
        EXPECT_NEAR(e.min_phi, sampled, 1e-6);
        EXPECT_NEAR(response(train, x, q, e.tau_at_min).phi, e.min_phi, 1e-11);
    }
}

TEST(Engine, InvariantsOfTheLinearModel) {
    const PulseTrain base = repeated_case(4, 6);
    for (double x : {0.05, 0.4, 1.3}) {
        const double q = q_factor(base, x).q;
        // Scaling every amplitude by k scales the collapse PGA by 1/k.
        std::vector<Pulse> scaled = base.pulses(), stretched = base.pulses(), split;
        for (auto& p : scaled) p.amplitude *= 2.5;
        EXPECT_NEAR(q_factor(PulseTrain(scaled), x).q * 2.5 / q, 1.0, 1e-14);
        // Stretching time by s at x / s leaves q unchanged (only x = p to matters).
        for (auto& p : stretched) p.duration *= 4.0;
        EXPECT_NEAR(q_factor(PulseTrain(stretched), x / 4.0).q / q, 1.0, 1e-13);
        // Splitting a pulse in two of the same amplitude changes nothing.
        for (const auto& p : base.pulses()) {
            split.push_back({p.amplitude, p.duration / 2});
            split.push_back({p.amplitude, p.duration / 2});
        }
        EXPECT_NEAR(q_factor(PulseTrain(split), x).q / q, 1.0, 1e-15);
    }
}

TEST(Engine, ExcursionOfTheCasesOfFigure3) {
    // At the collapse q the rotation of case 2 grows monotonically (no impact).
    for (double x : {0.1, 0.5, 1.0, 2.0}) {
        const Excursion e = excursion(pulse_case(2), x, q2(x));
        EXPECT_TRUE(e.onset);
        EXPECT_TRUE(e.stays_positive());
        EXPECT_GT(e.min_phi, 0.0);
    }
    // A q too small to start rocking is flagged.
    EXPECT_FALSE(excursion(pulse_case(3), 0.5, 1.5).onset);
}

// The 1e-150 guard holds for p times each pulse's duration, not only for x:
// a pulse of x d = 1e-160 gave q = inf, and one of 1e-300 "no q brings
// theta(t_fin) to alpha", false for a positive pulse (the sum underflowed).
TEST(Engine, PulsesTooShortForDoubleAreRefusedNotAnsweredWrong) {
    for (const char* train : {"1:1e-160", "1:1e-300", "1:1e-151,-0.5:1e-152"}) {
        try {
            const QFactor q = q_factor(parse_train(train), 1.0);
            ADD_FAILURE() << train << " gave q = " << q.q;
        } catch (const std::domain_error& e) {
            EXPECT_NE(std::string(e.what()).find("below 1e-150"), std::string::npos) << train << ": " << e.what();
        }
    }
    // Just above the guard q is finite and right: one pulse of x d gives
    // (1 + e^{-2 x d}) / expm1(-x d)^2 = 2 / (x d)^2 (1 + O(x d)).
    for (const double d : {1e-149, 1e-120, 1e-100}) {
        const PulseTrain one({{1.0, d}});
        const QFactor q = q_factor(one, 1.0);
        EXPECT_NEAR(q.q / (2.0 / (d * d)), 1.0, 1e-14) << d;
    }
}
