// The sliding-rocking block (issue 41; dynamics/sliding/) against truth
// that does not come from its code: the regime a block at rest enters under
// a constant acceleration, by criteria derived here in closed form; the slip
// of a block that only slides under a rectangular pulse (Newmark's block);
// Housner's restitution from a stuck impact; the rocking-only full model of
// dynamics/simulate.hpp as mu -> infinity; the energy balance; the mirror
// image of the input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "dynamics/model.hpp"
#include "dynamics/simulate.hpp"
#include "dynamics/sliding/friction_block.hpp"
#include "dynamics/sliding/sliding_simulate.hpp"
#include "pulse/pulse_train.hpp"
#include "qfactor/closed_forms.hpp"

using namespace rocking;
using namespace rocking::dynamics;
using namespace rocking::dynamics::sliding;

namespace {

constexpr double g = kGravity;

// The regime from rest under a constant a = A/g > 0, in closed form.  At
// rest, the stuck block needs a friction a g (so a <= mu) and both corners
// pressed (the moment of a g at height h against g at arm b: a <= tan alpha).
// Beyond: with mu < tan(alpha) it slides, and cannot rock while sliding (the
// corners' normal forces, g (1 -+ mu tan... )/2, stay positive); with mu >=
// tan(alpha) it turns about its leading corner, stuck while the friction
// that needs, f/g = (3/4) cos(alpha) (a cos(alpha) - sin(alpha)) - a, lies
// within mu n/g = mu [1 + (3/4) sin(alpha) (a cos(alpha) - sin(alpha))];
// slipping as it turns otherwise.
Regime closed_form_regime(double mu, double a, double alpha) {
    const double tan_alpha = std::tan(alpha);
    if (a <= mu && a <= tan_alpha) return Regime::rest;
    if (mu < tan_alpha) return Regime::slide;
    const double c = std::cos(alpha), s = std::sin(alpha), turn = 0.75 * (a * c - s);
    const double f = c * turn - a, n = 1 + s * turn;
    return std::fabs(f) <= mu * n ? Regime::rock : Regime::slide_rock;
}

}  // namespace

TEST(Sliding, TheRegimeFromRestIsTheClosedFormsOverAGrid) {
    int counts[4] = {0, 0, 0, 0};
    for (double alpha : {0.05, 0.15, 0.3, 0.5, 0.7})
        for (double mu : {0.05, 0.1, 0.2, 0.3, 0.4, 0.6, 0.8, 1.0, 1.5})
            for (double a : {0.02, 0.08, 0.12, 0.18, 0.25, 0.35, 0.5, 0.7, 1.0, 1.5, 2.5, 5.0, 10.0}) {
                const FrictionBlock block{alpha, 1.5, mu};
                const Regime want = closed_form_regime(mu, a, alpha);
                for (int d : {1, -1}) {
                    const Start got = start_flat(block, d * a * g, 0);
                    EXPECT_EQ(regime_name(got.regime), std::string(regime_name(want)))
                        << "alpha " << alpha << " mu " << mu << " a " << d * a;
                    // It turns and slips towards the side the input pushes.
                    if (got.regime == Regime::rock || got.regime == Regime::slide_rock) {
                        EXPECT_EQ(got.sigma, d);
                    }
                    if (got.regime == Regime::slide || got.regime == Regime::slide_rock) {
                        EXPECT_EQ(got.s, d);
                    }
                }
                ++counts[static_cast<int>(want)];
            }
    // The grid reaches all four.
    for (int k = 0; k < 4; ++k) EXPECT_GT(counts[k], 5) << regime_name(static_cast<Regime>(k));
}

TEST(Sliding, StuckRockingIsTheFullEquation) {
    // theta'' = p^2 [(A/g) cos(sigma alpha - theta) - sin(sigma alpha - theta)] (dynamics/model.hpp).
    const FrictionBlock block{0.25, 1.2, 10};
    Model model;
    model.equation = Equation::full;
    model.block = Block::from_p(block.p(), block.alpha);
    for (double theta : {-0.3, -0.05, 0.0, 0.1, 0.4})
        for (int sigma : {1, -1})
            for (double a : {-0.7, 0.0, 0.3, 1.1}) {
                const Contact c = stick_rocking(block, theta, 0.7, sigma, a * g);
                EXPECT_NEAR(c.theta_dd, model.acceleration(theta, sigma, a), 1e-12 * block.p() * block.p());
            }
}

TEST(Sliding, AStuckImpactIsHousnersRestitution) {
    for (double alpha : {0.05, 0.2, 0.4}) {
        const FrictionBlock block{alpha, 2.0, 5.0};
        for (int sigma : {1, -1}) {
            // Rocking on corner sigma, theta = 0: G moves as the corner is fixed.
            const double omega = -sigma * 0.8;
            const Lever d = centroid_from_pivot(block, 0, sigma);
            const Impact hit = corner_impact(block, sigma, omega, d.dy * omega, -d.dx * omega);
            EXPECT_FALSE(hit.slipped);
            EXPECT_NEAR(hit.omega / omega, 1 - 1.5 * std::sin(alpha) * std::sin(alpha), 1e-15);
            EXPECT_GE(hit.p_n, 0);
        }
    }
}

TEST(Sliding, WithoutFrictionAnImpactKeepsTheHorizontalMomentum) {
    // mu -> 0: no tangential impulse, so x_G' is unchanged; the normal
    // impulse stops the new corner's fall: y_G'+ + dx' theta'+ = 0.
    const FrictionBlock block{0.2, 1.0, 1e-12};
    const int sigma = 1;
    const double omega = -0.6;
    const Lever d = centroid_from_pivot(block, 0, sigma);
    const double xg = d.dy * omega, yg = -d.dx * omega;
    const Impact hit = corner_impact(block, sigma, omega, xg, yg);
    EXPECT_TRUE(hit.slipped);
    EXPECT_NEAR(hit.p_t, 0, 1e-12);
    const double dx_new = sigma * block.b();
    EXPECT_NEAR(yg + hit.p_n + dx_new * hit.omega, 0, 1e-14);
    // Angular momentum about G changes by the normal impulse's moment alone.
    EXPECT_NEAR(block.R * block.R / 3 * (hit.omega - omega), dx_new * hit.p_n, 1e-11);  // less mu = 1e-12's p_t moment
}

TEST(Sliding, ASlippingImpactKeepsCoulombsLawAndTheMomentumBalance) {
    // alpha 0.3: a stuck impact needs |p_t|/p_n = 1.5 sin(a) cos(a)/(2 - 1.5 sin^2 a)
    // = 0.2265, so at mu = 0.05 and 0.15 the new corner slips.  What defines the
    // slipping impact, checked on its result: the impulse changes G's momentum
    // and its angular momentum about G; the new corner's normal velocity is 0
    // after; the tangential impulse is mu p_n, against the slip it leaves; no
    // kinetic energy is gained.
    for (double mu : {0.05, 0.15})
        for (int sigma : {1, -1}) {
            const FrictionBlock block{0.3, 1.3, mu};
            const double omega = -sigma * 0.9, K = block.R * block.R / 3;
            const Lever d = centroid_from_pivot(block, 0, sigma);
            const double xg = d.dy * omega, yg = -d.dx * omega;
            const Impact hit = corner_impact(block, sigma, omega, xg, yg);
            EXPECT_TRUE(hit.slipped) << mu;
            const double dx_new = sigma * block.b(), dy_new = block.h();
            const double xg_after = xg + hit.p_t, yg_after = yg + hit.p_n;
            EXPECT_NEAR(K * (hit.omega - omega), dx_new * hit.p_n - dy_new * hit.p_t, 1e-14) << mu;
            EXPECT_NEAR(yg_after + dx_new * hit.omega, 0, 1e-14) << mu;
            EXPECT_NEAR(hit.pivot_v, xg_after - dy_new * hit.omega, 1e-14) << mu;
            EXPECT_GT(hit.p_n, 0) << mu;
            EXPECT_NEAR(std::fabs(hit.p_t), mu * hit.p_n, 1e-15) << mu;
            EXPECT_LT(hit.p_t * hit.pivot_v, 0) << mu;
            const double before = xg * xg + yg * yg + K * omega * omega;
            const double after = xg_after * xg_after + yg_after * yg_after + K * hit.omega * hit.omega;
            EXPECT_LT(after, before) << mu;
        }
}

TEST(Sliding, ABlockThatOnlySlidesMatchesNewmarksSlip) {
    // mu = 0.2 < tan(0.3): a 0.5 g pulse of 0.4 s slides the block and cannot
    // rock it.  Relative to the ground it accelerates at (a - mu) g for T,
    // then decelerates at mu g until it stops: slip = (a - mu) g T^2/2 +
    // v_T tau - mu g tau^2/2, v_T = (a - mu) g T, tau = v_T/(mu g).
    const double a = 0.5, mu = 0.2, T = 0.4;
    const FrictionBlock block{0.3, 1.0, mu};
    const PulseInput pulse(PulseTrain({{1.0, 1.0}}), a, T);
    SlidingOptions o;
    o.rtol = 1e-12;
    o.atol_alpha = 1e-12;
    const SlidingResult r = simulate_sliding(block, pulse, o);
    const double vT = (a - mu) * g * T, tau = vT / (mu * g);
    const double slip = 0.5 * (a - mu) * g * T * T + vT * tau - 0.5 * mu * g * tau * tau;
    EXPECT_FALSE(r.uplifted);
    EXPECT_TRUE(r.slid);
    EXPECT_NEAR(r.final_slip, slip, 1e-9 * slip);
    EXPECT_NEAR(r.slip_at_tfin, 0.5 * (a - mu) * g * T * T, 1e-9 * slip);
    EXPECT_NEAR(r.time_in[static_cast<int>(Regime::slide)], T + tau, 1e-9);
    // Energy: the input's work is spent by friction (nothing else moves at the end).
    EXPECT_NEAR(r.input_work, r.friction_loss, 1e-9 * r.input_work);
}

TEST(Sliding, AsMuGrowsItIsTheRockingOnlyFullModel) {
    // Two pulses that rock the block through an impact (0.3 g) or lift it
    // past its top during the input (0.6 g): the sliding engine at mu = 1e6
    // against simulate() on the full equation with Housner's restitution
    // (dopri5 at the same tolerance).  The fall is called at 1 rad in both:
    // nearer pi/2 the falling block's pivot unloads (n -> 0), slips even at
    // mu = 1e6 and then flies, which the rocking-only model does not see.
    const FrictionBlock block{0.15, 1.0, 1e6};
    for (double pga : {0.3, 0.6})
        for (bool free_rocking : {false, true}) {
            const PulseInput pulse(PulseTrain({{1.0, 1.0}, {-1.0, 1.0}}), pga, 0.3);
            SlidingOptions so;
            so.rtol = 1e-11;
            so.atol_alpha = 1e-11;
            so.overturn_angle = 1.0;
            so.free_rocking = free_rocking;
            const SlidingResult s = simulate_sliding(block, pulse, so);
            Model model;
            model.equation = Equation::full;
            model.block = Block::from_p(block.p(), block.alpha);
            model.restitution = housner_restitution(block.alpha);
            SimulationOptions ro;
            ro.solver.kind = SolverKind::dopri5;
            ro.solver.rtol = 1e-11;
            ro.solver.atol_alpha = 1e-11;
            ro.overturn_angle = 1.0;
            ro.free_rocking = free_rocking;
            const SimulationResult r = simulate(model, pulse, ro);
            const std::string at = "pga " + std::to_string(pga) + (free_rocking ? ", free rocking" : "");
            EXPECT_FALSE(s.slid) << at;
            EXPECT_TRUE(s.uplifted) << at;
            EXPECT_EQ(s.overturned, r.overturned) << at;
            EXPECT_EQ(s.overturned_during_input, r.overturned_during_input) << at;
            EXPECT_EQ(s.impacts, r.impacts) << at;
            EXPECT_NEAR(s.max_abs_theta_input, r.max_abs_theta_input, 1e-9 * block.alpha) << at;
            EXPECT_NEAR(s.theta_at_tfin, r.theta_at_tfin, 1e-9 * block.alpha) << at;
            if (r.overturned) {
                EXPECT_NEAR(s.t_overturn, r.t_overturn, 1e-8) << at;
            }
        }
}

TEST(Sliding, ItsErrorFollowsItsTolerance) {
    // A synthetic record (three sines under a half-sine envelope, sampled
    // every 0.01 s, linear between: a kink at every sample, where the steps
    // end) rocks a block of alpha 0.15 through 14 impacts without a rest.
    // At mu = 1e6 the engine is the full rocking-only model with Housner's
    // restitution, here simulate() under gsl-rk8pd at 1e-13 (rkf78 at 1e-13
    // gives the same impact times to 2e-13/p).  At rtol = atol = 1e-10 and
    // 1e-12 alpha every impact time is within 100 rtol/p of it, theta(t_fin)
    // within 5 rtol alpha, and the larger error shrinks at least 10 times
    // with the tolerance.  Measured: 16 and 29 rtol/p, 0.9 and 1.3 rtol
    // alpha.  With events located on the dense output (order 4) instead of
    // on true steps: 510 and 230 rtol/p, 36 and 18 rtol alpha.
    const double dt = 0.01, T = 6;
    std::vector<double> a;
    for (int k = 0; k * dt <= T + 1e-9; ++k) {
        const double t = k * dt;
        a.push_back(0.12 * std::sin(M_PI * t / T) *
                    (std::sin(2 * M_PI * 1.1 * t) + 0.6 * std::sin(2 * M_PI * 2.7 * t + 1) +
                     0.4 * std::sin(2 * M_PI * 5.3 * t + 2)));
    }
    const SampledInput input(a, dt, "three sines, 0.12 g");
    const FrictionBlock block{0.15, 1.0, 1e6};
    Model model;
    model.equation = Equation::full;
    model.block = Block::from_p(block.p(), block.alpha);
    model.restitution = housner_restitution(block.alpha);
    SimulationOptions ro;
    ro.solver.kind = SolverKind::gsl_rk8pd;
    ro.solver.rtol = ro.solver.atol_alpha = 1e-13;
    ro.overturn_angle = 1.0;
    ro.free_rocking = false;
    const SimulationResult truth = simulate(model, input, ro);
    ASSERT_EQ(truth.impacts, 14);
    ASSERT_EQ(truth.rests, 0);
    std::vector<double> worst;
    for (double rtol : {1e-10, 1e-12}) {
        SlidingOptions so;
        so.rtol = so.atol_alpha = rtol;
        so.overturn_angle = 1.0;
        so.free_rocking = false;
        const SlidingResult s = simulate_sliding(block, input, so);
        ASSERT_EQ(s.impacts, truth.impacts) << rtol;
        ASSERT_EQ(s.impact_times.size(), truth.impact_times.size()) << rtol;
        double e = 0;
        for (std::size_t k = 0; k < s.impact_times.size(); ++k)
            e = std::max(e, block.p() * std::fabs(s.impact_times[k] - truth.impact_times[k]));
        EXPECT_LE(e, 100 * rtol) << rtol;
        EXPECT_NEAR(s.theta_at_tfin, truth.theta_at_tfin, 5 * rtol * block.alpha) << rtol;
        worst.push_back(e);
    }
    EXPECT_LE(worst[1], worst[0] / 10);
}

TEST(Sliding, TheEnergyBalancesAndTheMirrorImageMirrors) {
    // A decaying sine of 0.45 g on a block of alpha 0.2: at mu = 0.1 it only
    // slides; at 0.3 and 1 it rocks through two impacts and slide-rocks as it
    // falls.  At every event, E - E(0) = W - D_friction - D_impacts to the
    // integration's tolerance (over g R), and the input negated gives the
    // same run mirrored.
    std::vector<double> a;
    const double dt = 0.01;
    for (int k = 0; k < 600; ++k) a.push_back(0.45 * std::sin(2 * M_PI * 1.3 * k * dt) * std::exp(-0.3 * k * dt));
    std::vector<double> minus = a;
    for (double& v : minus) v = -v;
    const SampledInput up(a, dt, "decaying sine"), down(minus, dt, "its mirror");
    for (double mu : {0.1, 0.3, 1.0}) {
        const FrictionBlock block{0.2, 0.8, mu};
        SlidingOptions o;
        o.rtol = 1e-11;
        o.atol_alpha = 1e-11;
        const SlidingResult r = simulate_sliding(block, up, o), m = simulate_sliding(block, down, o);
        EXPECT_TRUE(r.slid) << mu;
        EXPECT_EQ(r.uplifted, mu > 0.2) << mu;
        if (mu > 0.2) {
            EXPECT_EQ(r.impacts, 2) << mu;
            EXPECT_GT(r.time_in[static_cast<int>(Regime::slide_rock)], 0) << mu;
            EXPECT_GT(r.impact_loss, 0) << mu;
        }
        EXPECT_GT(r.friction_loss, 0) << mu;
        EXPECT_LT(r.balance_error, 1e-9) << mu;
        EXPECT_NEAR(m.max_abs_theta_input, r.max_abs_theta_input, 1e-12) << mu;
        EXPECT_NEAR(m.theta_at_tfin, -r.theta_at_tfin, 1e-12) << mu;
        EXPECT_NEAR(m.final_slip, -r.final_slip, 1e-12) << mu;
        EXPECT_EQ(m.impacts, r.impacts) << mu;
        EXPECT_EQ(m.overturned, r.overturned) << mu;
    }
}

TEST(Sliding, AnImpactCascadeEndsAtRest) {
    // A tall block rocked by one pulse rocks on after it with each impact
    // taking 1 - (1 - 1.5 sin^2 alpha)^2 of its energy, until the rest rule
    // lays it flat.  A residue of 1e-13 m/s of slip left by the last impact
    // set it slide-rocking, stopping and striking again without end (on the
    // Norcia record at p = 1 rad/s, mu 0.6): the cascade must end, at rest.
    // The input goes on, at 0, for 60 s after the pulse: a run stops after
    // the input once the block cannot fall, before the cascade ends.
    std::vector<double> a(6051, 0.0);
    for (int k = 0; k <= 50; ++k) a[k] = 0.3;
    const SampledInput pulse(a, 0.01, "0.3 g for 0.5 s, then 60 s at rest");
    const FrictionBlock block{0.15, 8.0, 0.6};
    const SlidingResult r = simulate_sliding(block, pulse, SlidingOptions{});
    EXPECT_FALSE(r.overturned);
    EXPECT_GT(r.impacts, 100);
    EXPECT_FALSE(r.slid);
    EXPECT_EQ(r.final_slip, 0);
    EXPECT_LT(r.balance_error, 1e-7);
}

// The end of an impact cascade, as the rocking-only driver's.  On a ground
// at rest, at amplitudes far below alpha (theta'' = -p^2 sin(alpha - theta)
// ~ -p^2 sin alpha: a projectile's arc), an arc leaving theta = 0 at omega
// lands 2 omega / (p^2 sin alpha) later at omega, so with Housner's e the
// intervals are a geometric series, T_{k+1} = e T_k; the rocking-only
// driver ends the cascade at the first impact within 1e-6/p of the last
// (run_rules.hpp, the micro-bounce rule), the block at rest.  The sliding
// driver had no such rule and went on to its rest rate (1e-8 alpha p),
// 114 more impacts here (530 against 416), each a segment of its own (issue 41's
// worst cost, NRC 2016-10-26 19:18: 131 impacts against 86, 3.4 times the
// time).  Laid flat after a micro-bounce with G's velocity as its slip (the
// rotation's share h theta'+, as the rest rule keeps it), a stuck block
// slide-rocked into Painleve's case at mu = 1e6: the base keeps its own.
TEST(Sliding, AnImpactCascadeEndsAsTheRockingOnlyOne) {
    std::vector<double> a(6051, 0.0);
    for (int k = 0; k <= 50; ++k) a[k] = 0.3;
    const SampledInput pulse(a, 0.01, "0.3 g for 0.5 s, then 60 s at rest");
    const double alpha = 0.15, e = housner_restitution(alpha);
    Model model;
    model.equation = Equation::full;
    model.block = Block::from_p(FrictionBlock{alpha, 8.0, 1e6}.p(), alpha);
    model.restitution = e;
    SimulationOptions ro;
    ro.solver.kind = SolverKind::dopri5;
    ro.solver.rtol = ro.solver.atol_alpha = SlidingOptions{}.rtol;  // the rest rate, 10 atol alpha p, the same
    const SimulationResult r = simulate(model, pulse, ro);
    ASSERT_EQ(r.rests, 1);
    for (double mu : {1e6, 0.6}) {
        const FrictionBlock block{alpha, 8.0, mu};
        const double p = block.p();
        const SlidingResult s = simulate_sliding(block, pulse, SlidingOptions{});
        const std::vector<double>& t = s.impact_times;
        ASSERT_GT(t.size(), 100u) << mu;
        EXPECT_FALSE(s.slid) << mu;
        EXPECT_EQ(s.final_slip, 0) << mu;
        // The tail, from the first interval below 1e-3/p (theta there below
        // 2e-8 rad: the arc's time off the projectile's by that over tan alpha).
        std::size_t j = 1;
        while (j < t.size() && t[j] - t[j - 1] >= 1e-3 / p) ++j;
        ASSERT_LT(j + 1, t.size()) << mu;
        const double Tj = t[j] - t[j - 1];
        for (std::size_t k = j + 1; k < t.size(); ++k)
            EXPECT_NEAR((t[k] - t[k - 1]) / (Tj * std::pow(e, double(k - j))), 1, 1e-4) << mu << ", impact " << k;
        // The series' first interval below 1e-6/p is the last impact's.
        int m = 0;
        while (Tj * std::pow(e, m) >= 1e-6 / p) ++m;
        ASSERT_GT(1e-6 / p / (Tj * std::pow(e, m)), 1 + 1e-3) << "too near the rule's threshold to tell";
        ASSERT_GT(Tj * std::pow(e, m - 1) / (1e-6 / p), 1 + 1e-3) << "too near the rule's threshold to tell";
        EXPECT_EQ(t.size(), j + 1 + m) << mu;
        EXPECT_EQ(s.impacts, r.impacts) << mu;
        ASSERT_EQ(t.size(), r.impact_times.size()) << mu;
        EXPECT_NEAR(t.back(), r.impact_times.back(), 1e-6) << mu;
    }
}

// An event is applied where it has happened.  Located by Newton on the true
// steps, a slip's start had been taken at the closest approach, at times on
// the near side, where the stuck corner's friction still held: the slip
// stopped at once and started again, 10^6 regime changes in 0.1 s (Figure
// 5's case 3, alpha 0.1, x 0.3, Rd 0.5, mu 0.4: the sliding scene stopped).
// The run now ends, with few regime changes, at both tolerances.
TEST(Sliding, AStickSlipChangeIsNotRepeatedWithoutEnd) {
    const double alpha = 0.1, R = 1.0 / std::cos(alpha), p = std::sqrt(3 * g / (4 * R)), x = 0.3;
    const double pga = q_case(3, x) * alpha * 0.5;
    const PulseInput input(pulse_case(3), pga, x / p);
    for (double rtol : {1e-9, 1e-11}) {
        SlidingOptions o;
        o.rtol = o.atol_alpha = rtol;
        o.max_events = 10000;
        const SlidingResult r = simulate_sliding({alpha, R, 0.4}, input, o);
        EXPECT_LT(r.regime_changes, 200) << rtol;
        EXPECT_TRUE(r.slid) << rtol;
    }
}

// The micro-bounce rule's speed bound.  A slipping impact can reverse
// theta': then the old corner, driven into the ground, strikes at once (the
// next impact within 1e-6/p, at full speed), which the time test alone took
// for a micro-bounce and laid the block flat.  By hand, from the impulse
// (P_t, P_n) per unit mass at the striking corner (K = R^2/3, b, h as in
// friction_block.hpp, theta' clockwise, the block on corner +b at theta = 0,
// theta' = w0 < 0, that pivot slipping at v0 > 0):
//   1. corner -b strikes.  G from it (b, h): x_G' = v0 + h w0, y_G' = b w0;
//      x_G'+ = x_G' + P_t, y_G'+ = y_G' + P_n, K (w1 - w0) = b P_n - h P_t;
//      no rebound, y_G'+ + b w1 = 0: P_n = -b (w0 + w1); its slip after
//      u1 = x_G'+ - h w1.  Slipping (u1 > 0, P_t = -mu P_n):
//        w1 = w0 (K - b^2 - mu b h)/(K + b^2 + mu b h),
//      against w0 where mu b h > K - b^2: the block turns back onto corner +b.
//   2. corner +b strikes, the block on -b with w1 > 0, slipping at u1.  G
//      from it (-b, h): K (w2 - w1) = -b P_n - h P_t, P_n = b (w1 + w2),
//      u2 = u1 + h w1 + P_t - h w2.  Slipping (u2 > 0, P_t = -mu P_n):
//        w2 = w1 (K - b^2 + mu b h)/(K + b^2 - mu b h).
//   Together: w2/w0 = [(K - b^2)^2 - (mu b h)^2]/[(K + b^2)^2 - (mu b h)^2],
// -0.33305 at alpha 0.6, R 1, mu 0.7 (> tan alpha = 0.684, so it rocks):
// the block rebounds on corner +b at a third of its speed, not flat.  The
// test checks on the run's own v0 that the stuck impulse of impact 1 breaks
// Coulomb's law (|P_t| > mu P_n, the stuck w1 = [(K - b^2 + h^2) w0 + h v0]/(4K))
// and that u1, u2 > 0, so that this is the law's case.  The input is
// synthetic: 0.8 g for 0.2 s lifts the block, 0.08 s at rest lets it fall
// back, and 2 g from 0.28 s sets its pivot slipping at 0.5 m/s as it
// lands (slide-rock's theta'' does not depend on A).
TEST(Sliding, AReversingSlipIsNoMicroBounce) {
    const FrictionBlock block{0.6, 1.0, 0.7};
    const double b = block.b(), h = block.h(), mu = block.mu, K = block.R * block.R / 3, p = block.p();
    const PulseInput input(PulseTrain({{1.0, 0.2}, {0.0, 0.08}, {2.5, 0.05}, {0.0, 0.1}}), 0.8, 1.0);
    SlidingOptions o;
    o.rtol = o.atol_alpha = 1e-11;
    o.free_rocking = false;
    const double dt = 1e-5;
    o.record_dt = dt;
    const SlidingResult r = simulate_sliding(block, input, o);
    const std::vector<double>& t = r.impact_times;
    ASSERT_GE(t.size(), 2u);
    ASSERT_LT(t[1] - t[0], 1e-6 / p) << "the pair must fall under the rule's time test";
    EXPECT_GE(r.slipping_impacts, 2);
    // The samples around the pair, read back to it linearly from two on each
    // side: off by at most |theta'''| dt^2, about 6 rad/s^3 here (slide-rock:
    // d theta''/d theta ~ (dy - mu dx) g/K ~ 36 s^-2, times |theta'| < 0.2),
    // 6e-10 rad/s, with the integration's 1e-11 alpha (measured: 1.9e-10).
    const std::vector<SlidingSample>& s = r.samples;
    std::size_t k = 1;
    while (k + 2 < s.size() && s[k + 1].t < t[0]) ++k;
    ASSERT_TRUE(k + 2 < s.size() && s[k].t < t[0] && t[1] < s[k + 1].t);
    ASSERT_EQ(s[k - 1].regime, Regime::slide_rock);
    ASSERT_EQ(s[k].regime, Regime::slide_rock);
    ASSERT_EQ(s[k + 1].regime, s[k + 2].regime);
    ASSERT_GT(s[k].theta, 0);
    const double w0 = s[k].omega + (s[k].omega - s[k - 1].omega) * (t[0] - s[k].t) / dt;
    const double v0 = s[k].slip_rate + (s[k].slip_rate - s[k - 1].slip_rate) * (t[0] - s[k].t) / dt;
    const double w2 = s[k + 1].omega - (s[k + 2].omega - s[k + 1].omega) * (s[k + 1].t - t[1]) / dt;
    ASSERT_LT(w0, -0.1);
    // Impact 1 by hand: stuck breaks Coulomb's law, slipping onwards holds.
    const double w1s = ((K - b * b + h * h) * w0 + h * v0) / (4 * K);
    EXPECT_GT(std::fabs(h * w1s - v0 - h * w0), mu * std::fabs(b * (w0 + w1s)));
    const double mbh = mu * b * h, w1 = w0 * (K - b * b - mbh) / (K + b * b + mbh);
    const double pn1 = -b * (w0 + w1), u1 = v0 + h * w0 - mu * pn1 - h * w1;
    EXPECT_GT(w1, 0);
    EXPECT_GT(pn1, 0);
    EXPECT_GT(u1, 0.1);
    const double want = w1 * (K - b * b + mbh) / (K + b * b - mbh);
    EXPECT_GT(u1 + h * w1 - mu * b * (w1 + want) - h * want, 0.1);
    EXPECT_NEAR(want / w0, ((K - b * b) * (K - b * b) - mbh * mbh) / ((K + b * b) * (K + b * b) - mbh * mbh), 1e-14);
    // Not laid flat: rocking on corner +b again, at w2.
    EXPECT_GT(s[k + 1].theta, 0);
    EXPECT_NEAR(w2, want, 2e-9) << "before " << w0 << " rad/s";
}
