// The run's rules (run_rules.hpp), each on its own: the end of the input,
// the uplift from rest, an impact and the end of its cascade, the free
// rocking's end and the decision by energy.  Both drivers (simulate.cpp's
// general path and the record kernel) run through these, so a fault here
// shows in both; these tests pin each rule against values worked out by
// hand from its definition.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "dynamics/run_rules.hpp"

using namespace rocking::dynamics;

namespace {

Model block(double alpha, double p, double restitution = 1.0) {
    Model m;
    m.block = Block::from_p(p, alpha);
    m.restitution = restitution;
    return m;
}

// A ramp a(t) = rate t (in g) sampled every dt: it first exceeds alpha at
// t = alpha / rate, where the interpolation is exact.
SampledInput ramp(double rate, double dt, int samples) {
    std::vector<double> a;
    for (int k = 0; k < samples; ++k) a.push_back(rate * k * dt);
    return SampledInput(a, dt, "ramp");
}

auto no_note = [](double, double) {};
auto no_rest = [](double) {};

}  // namespace

TEST(RunRules, TheEndOfTheInputTakesThetaAtTfinOnceAndOnlyFromTfin) {
    SimulationOptions options;
    options.initial_theta = 0.01;
    options.initial_omega = 0.02;
    rules::RunState<double> s(options, 2.0);
    SimulationResult result;
    std::vector<double> noted;
    auto note = [&](double when, double value) { noted = {when, value}; };

    s.t = 1.999;
    rules::end_of_input(s, result, 2.0, note);
    EXPECT_FALSE(s.recorded);
    EXPECT_TRUE(noted.empty());

    s.t = 2.5;
    rules::end_of_input(s, result, 2.0, note);
    ASSERT_TRUE(s.recorded);
    EXPECT_EQ(result.theta_at_tfin, 0.01);
    EXPECT_EQ(result.omega_at_tfin, 0.02);
    EXPECT_EQ(noted, (std::vector<double>{2.0, 0.01}));  // noted at t_fin itself

    s.theta = 0.3;  // a later pass does not take it again
    rules::end_of_input(s, result, 2.0, note);
    EXPECT_EQ(result.theta_at_tfin, 0.01);
}

TEST(RunRules, ARestingBlockLiftsWhereTheInputFirstExceedsAlphaOnTheCornerItPushes) {
    const Model m = block(0.1, 2.0);
    for (const double sign : {1.0, -1.0}) {
        // |a| = alpha at t = 0.1 / 0.23 = 0.4348 s, between samples; t_fin = 2 s.
        const SampledInput input = ramp(sign * 0.23, 0.01, 201);
        SimulationOptions options;
        rules::RunState<double> s(options, input.t_end());
        SimulationResult result;
        ASSERT_TRUE(s.resting);
        double rested_until = -1;
        auto at = [&](double t) { return input.accel(t); };
        ASSERT_TRUE(rules::lift_from_rest(s, result, m, input, at, input.t_end(),
                                          [&](double t) { rested_until = t; }));
        EXPECT_NEAR(s.t, 0.1 / 0.23, 1e-15);
        EXPECT_GT(std::fabs(input.accel(s.t)), 0.1);  // never lifted with the input pushing it back
        EXPECT_EQ(rested_until, s.t);
        EXPECT_EQ(s.sigma, sign > 0 ? 1 : -1);
        EXPECT_FALSE(s.resting);
        EXPECT_TRUE(result.uplifted);
        EXPECT_EQ(s.theta, 0.0);
        EXPECT_EQ(s.omega, 0.0);
    }
}

TEST(RunRules, ABlockThatTheInputNeverLiftsEndsTheRunWithThetaZeroAtTfin) {
    const Model m = block(0.3, 2.0);                 // alpha above the ramp's peak, 0.25 g
    const SampledInput input = ramp(0.125, 0.01, 201);
    SimulationOptions options;
    options.free_record_time = 1.0;
    rules::RunState<double> s(options, input.t_end());
    SimulationResult result;
    result.theta_at_tfin = 7.0;  // must be overwritten
    double rested_until = -1;
    auto at = [&](double t) { return input.accel(t); };
    EXPECT_FALSE(rules::lift_from_rest(s, result, m, input, at, input.t_end(), [&](double t) { rested_until = t; }));
    EXPECT_TRUE(s.recorded);
    EXPECT_EQ(result.theta_at_tfin, 0.0);
    EXPECT_FALSE(result.uplifted);
    EXPECT_DOUBLE_EQ(rested_until, 3.0);  // the theta(t) record is kept at rest to t_fin + free_record_time
}

TEST(RunRules, AnImpactKeepsTheRestitutionsShareOfThetaDotOnTheOtherCorner) {
    const double e = housner_restitution(0.2);
    const Model m = block(0.2, 2.0, e);
    SimulationOptions options;
    rules::RunState<double> s(options, 10.0);
    s.resting = false;
    s.sigma = 1;
    s.theta = 0.05;
    s.omega = -0.3;
    SimulationResult result;
    rules::impact(s, result, m, options, 1.25, -0.3, 1e-9);
    EXPECT_EQ(s.t, 1.25);
    EXPECT_EQ(s.theta, 0.0);
    EXPECT_EQ(s.omega, e * -0.3);
    EXPECT_EQ(s.sigma, -1);
    EXPECT_FALSE(s.resting);
    EXPECT_EQ(result.impacts, 1);
    EXPECT_EQ(result.t_first_impact, 1.25);
    EXPECT_EQ(result.t_last_impact, 1.25);
    EXPECT_EQ(result.impact_times, (std::vector<double>{1.25}));
    EXPECT_EQ(result.rests, 0);
}

TEST(RunRules, ACascadeEndsAtARestOrAMicroBounce) {
    const Model m = block(0.2, 2.0, 0.5);
    SimulationOptions options;
    // The state after impacts at (t, theta' before it), under the rest rule rest.
    struct After {
        rules::RunState<double> s;
        SimulationResult result;
    };
    auto after = [&](std::vector<std::pair<double, double>> impacts, double rest) {
        After a{rules::RunState<double>(options, 10.0), {}};
        a.s.resting = false;
        for (const auto& [t, om] : impacts) rules::impact(a.s, a.result, m, options, t, om, rest);
        return a;
    };
    // A rebound below rest * alpha * p (1e-3 * 0.4 = 4e-4 rad/s) rests.
    const After slow = after({{1.0, -7.9e-4}}, 1e-3);  // rebound 3.95e-4
    EXPECT_TRUE(slow.s.resting);
    EXPECT_EQ(slow.s.omega, 0.0);
    EXPECT_EQ(slow.result.rests, 1);
    const After fast = after({{1.0, -8.1e-4}}, 1e-3);  // rebound 4.05e-4
    EXPECT_FALSE(fast.s.resting);
    EXPECT_EQ(fast.s.omega, 0.5 * -8.1e-4);
    EXPECT_EQ(fast.result.rests, 0);
    // A second impact within 1e-6 / p (5e-7 s) of the last is a bounce too
    // small to resolve: the block rests, whatever its speed.
    const After micro = after({{1.0, -1.0}, {1.0 + 4.9e-7, 1.0}}, 1e-9);
    EXPECT_TRUE(micro.s.resting);
    EXPECT_EQ(micro.result.impacts, 2);
    EXPECT_EQ(micro.result.rests, 1);
    const After apart = after({{1.0, -1.0}, {1.0 + 5.1e-7, 1.0}}, 1e-9);
    EXPECT_FALSE(apart.s.resting);
    EXPECT_EQ(apart.result.rests, 0);
}

TEST(RunRules, ImpactTimesAreKeptUpToTheirCapAndImpactsStopTheRunPastTheGuard) {
    const Model m = block(0.2, 2.0);
    SimulationOptions options;
    options.max_impact_times = 3;
    options.max_impacts = 5;
    rules::RunState<double> s(options, 100.0);
    s.resting = false;
    SimulationResult result;
    for (int i = 1; i <= 5; ++i) rules::impact(s, result, m, options, double(i), 1.0, 1e-9);
    EXPECT_EQ(result.impacts, 5);
    EXPECT_EQ(result.impact_times, (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(result.t_last_impact, 5.0);
    EXPECT_THROW(rules::impact(s, result, m, options, 6.0, 1.0, 1e-9), std::runtime_error);
}

TEST(RunRules, TheFreeRockingEndsBelowTheBarrierAndIsFollowedAboveIt) {
    // Linearised: energy 0.5 theta'^2 - 0.5 p^2 (theta - sigma alpha)^2,
    // barrier 0: a block at theta = 0 overturns when |theta'| >= p alpha.
    const Model m = block(0.1, 2.0);  // p alpha = 0.2 rad/s
    SimulationOptions options;
    options.free_record_time = 0.5;
    const double t_fin = 10.0;
    {
        rules::RunState<double> s(options, t_fin);
        s.resting = false;
        s.t = t_fin;
        s.theta = 0.0;
        s.omega = 0.199;  // below the barrier
        EXPECT_FALSE(rules::stop_after_input(m, options, s, t_fin));  // the record asked for goes on to 10.5
        s.t = 10.5;
        EXPECT_TRUE(rules::stop_after_input(m, options, s, t_fin));
        SimulationResult result;
        s.recorded = true;
        rules::decide_by_energy(s, result, m, options, t_fin);
        EXPECT_FALSE(result.overturned);
    }
    {
        rules::RunState<double> s(options, t_fin);
        s.resting = false;
        s.t = 10.5;
        s.theta = 0.0;
        s.omega = 0.201;  // above the barrier: followed to t_fin + 200 / p
        EXPECT_FALSE(rules::stop_after_input(m, options, s, t_fin));
        EXPECT_EQ(s.t_limit, t_fin + 200.0 / 2.0);
        s.t = s.t_limit;
        EXPECT_TRUE(rules::stop_after_input(m, options, s, t_fin));
        SimulationResult result;
        s.recorded = true;
        rules::decide_by_energy(s, result, m, options, t_fin);
        EXPECT_TRUE(result.overturned);  // still able to overturn after 200 / p: taken to
    }
    {
        // Past the top (sigma theta > alpha) a block falls whatever its energy.
        rules::RunState<double> s(options, t_fin);
        s.resting = false;
        s.sigma = 1;
        s.theta = 0.1001;
        s.omega = 0.0;
        SimulationResult result;
        s.t = t_fin + 200.0 / 2.0;
        s.recorded = true;
        rules::decide_by_energy(s, result, m, options, t_fin);
        EXPECT_TRUE(result.overturned);
    }
}

// A record whose sample equals the threshold exactly, rising through it,
// lifts the block at that sample: the input exceeds alpha at once after it.
// The scan took only crossings strictly after a piece's start and |a| > thr
// at the start itself, so it lifted the block a sample later (0.41 s), with
// theta(t_fin)/alpha 0.38646 where the closed form gives 0.38683.
TEST(RunRules, ARecordReachingAlphaExactlyAtASampleLiftsTheBlockThere) {
    const SampledInput input = ramp(0.25, 0.01, 101);  // a = 0.1 g at sample 40, t_fin = 1 s
    ASSERT_EQ(input.samples()[40], 0.1);
    const Model m = block(0.1, 2.0);
    SimulationOptions options;
    rules::RunState<double> s(options, input.t_end());
    SimulationResult lifted;
    auto at = [&](double t) { return input.accel(t); };
    ASSERT_TRUE(rules::lift_from_rest(s, lifted, m, input, at, input.t_end(), no_rest));
    EXPECT_NEAR(s.t, 0.4, 1e-15);
    EXPECT_GT(input.accel(s.t), 0.1);
    // The whole run against theta = c (sinh(p u)/p - u), u = t - 0.4 (c = 0.25 g/s):
    // theta'' = p^2 (theta + c u) from rest.
    const double u = 1.0 - 0.4, truth = 0.25 * (std::sinh(2.0 * u) / 2.0 - u);
    for (const bool kernel : {true, false}) {
        options.free_rocking = false;
        options.solver.record_kernel = kernel;
        const SimulationResult r = simulate(m, input, options);
        EXPECT_NEAR(r.theta_at_tfin / truth, 1.0, 1e-12) << (kernel ? "record kernel" : "general path");
    }
}
