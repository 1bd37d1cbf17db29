// The sliding scene's two premises (reproduce/scenes/sliding_scene.hpp, sliding_eq27.cpp): a friction
// run that never slipped is the same run, bit for bit, at any larger mu (the eq. 27 part takes such
// outcomes instead of running them); a block leaving the ground is told apart from other failures
// (FreeFlight); and the rule that tells a sliding effect from the rocking model's own near-ties.
#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/ground_input.hpp"
#include "dynamics/sliding/sliding_simulate.hpp"
#include "pulse/pulse_train.hpp"
#include "qfactor/closed_forms.hpp"
#include "scenes/sliding_scene.hpp"

using namespace rocking;
using namespace rocking::dynamics;
using rocking::scenes::sliding_scene::classify;
using rocking::scenes::sliding_scene::Effect;
using SceneRun = rocking::scenes::sliding_scene::Run;

namespace {

sliding::SlidingResult run(double alpha, double mu, const GroundInput& in) {
    const double R = 1.0 / std::cos(alpha);  // a block 2 m tall
    sliding::SlidingOptions o;
    return sliding::simulate_sliding(sliding::FrictionBlock{alpha, R, mu}, in, o);
}

SceneRun outcome(bool over, double peak) {
    SceneRun r;
    r.overturned = over;
    r.peak = peak;
    return r;
}

}  // namespace

TEST(SlidingScene, ARunThatNeverSlipsIsTheSameRunAtAnyLargerMu) {
    // Case 2 at x = 1 and 1.5 times the uplift: the block rocks and strikes, its corner stuck throughout.
    const double alpha = 0.2;
    const PulseInput in(pulse_case(2), 1.5 * std::tan(alpha), 0.4);
    const sliding::SlidingResult base = run(alpha, 0.6, in);
    ASSERT_FALSE(base.slid);
    ASSERT_TRUE(base.uplifted);
    ASSERT_GT(base.impacts, 0);
    for (double mu : {0.8, 1.0, 1e6}) {
        const sliding::SlidingResult r = run(alpha, mu, in);
        EXPECT_EQ(r.max_abs_theta_input, base.max_abs_theta_input) << "mu " << mu;
        EXPECT_EQ(r.theta_at_tfin, base.theta_at_tfin) << "mu " << mu;
        EXPECT_EQ(r.impacts, base.impacts) << "mu " << mu;
        EXPECT_EQ(r.steps, base.steps) << "mu " << mu;
        EXPECT_EQ(r.overturned, base.overturned) << "mu " << mu;
    }
    // A smaller mu that slips is another run: the rule runs one way only.
    const sliding::SlidingResult slips = run(alpha, 0.21, in);
    EXPECT_TRUE(slips.slid);
    EXPECT_NE(slips.max_abs_theta_input, base.max_abs_theta_input);
}

TEST(SlidingScene, ABlockThatLeavesTheGroundThrowsFreeFlight) {
    // Case 3 at x = 0.2 scaled to 0.6 q3 (6.2 g) on alpha 0.2: the pivot unloads at t = 0.0745 s.
    const double alpha = 0.2, R = 1.0 / std::cos(alpha), p = std::sqrt(3 * 9.81 / (4 * R));
    const PulseInput in(pulse_case(3), q_case(3, 0.2) * alpha * 0.6, 0.2 / p);
    try {
        run(alpha, 1e6, in);
        FAIL() << "no free flight";
    } catch (const sliding::FreeFlight& e) {
        EXPECT_NEAR(e.t, 0.0744795546, 1e-6);
        EXPECT_NE(std::string(e.what()).find("leaves the ground"), std::string::npos);
    }
    // Outside the model is outside for the scene, not a failure of it.
    const SceneRun r = rocking::scenes::sliding_scene::friction_run(in, alpha, p, 1e6, 1e-9);
    EXPECT_TRUE(r.outside);
}

TEST(SlidingScene, TheRuleTellsSlidingFromTheRockingModelsOwnTies) {
    const std::array<SceneRun, 4> safe = {outcome(false, 0.50), outcome(false, 0.501), outcome(false, 0.499),
                                     outcome(false, 0.50)};
    // The same, a peak 10 % lower at both tolerances, a peak 4 % lower, one at the 5 % line.
    EXPECT_EQ(classify(safe, {outcome(false, 0.50), outcome(false, 0.50)}), Effect::same);
    EXPECT_EQ(classify(safe, {outcome(false, 0.45), outcome(false, 0.45)}), Effect::peak);
    EXPECT_EQ(classify(safe, {outcome(false, 0.48), outcome(false, 0.48)}), Effect::same);
    EXPECT_EQ(classify(safe, {outcome(false, 0.4751), outcome(false, 0.4751)}), Effect::peak_tie);
    // Overturning where all four stand, at both tolerances; at one only.
    EXPECT_EQ(classify(safe, {outcome(true, 0), outcome(true, 0)}), Effect::outcome);
    EXPECT_EQ(classify(safe, {outcome(true, 0), outcome(false, 0.5)}), Effect::sliding_tie);
    // The rocking-only runs disagree (AQK HNN, alpha 0.1, q 1.5: dopri5 at 1e-9 stands, the rest fall):
    // whatever the friction does, not sliding's.
    const std::array<SceneRun, 4> tie = {outcome(false, 0.9), outcome(true, 0), outcome(true, 0), outcome(true, 0)};
    EXPECT_EQ(classify(tie, {outcome(true, 0), outcome(true, 0)}), Effect::rocking_tie);
    EXPECT_EQ(classify(tie, {outcome(false, 0.9), outcome(false, 0.9)}), Effect::rocking_tie);
    // Peaks of the four spread beyond 5 %: the rocking model's own sensitivity.
    const std::array<SceneRun, 4> spread = {outcome(false, 0.12), outcome(false, 0.03), outcome(false, 0.03),
                                       outcome(false, 0.03)};
    EXPECT_EQ(classify(spread, {outcome(false, 0.03), outcome(false, 0.03)}), Effect::rocking_tie);
    // Outside the model: the friction's run, or the control.
    SceneRun out;
    out.outside = true;
    EXPECT_EQ(classify(safe, {out, outcome(false, 0.5)}), Effect::outside);
    std::array<SceneRun, 4> control_out = safe;
    control_out[3] = out;
    EXPECT_EQ(classify(control_out, {outcome(false, 0.5), outcome(false, 0.5)}), Effect::outside_control);
    // A block the rocking model never lifts, lifted by friction: a change (its peak was 0).
    const std::array<SceneRun, 4> rest = {outcome(false, 0), outcome(false, 0), outcome(false, 0), outcome(false, 0)};
    EXPECT_EQ(classify(rest, {outcome(false, 0.01), outcome(false, 0.01)}), Effect::peak);
    EXPECT_EQ(classify(rest, {outcome(false, 0), outcome(false, 0)}), Effect::same);
}
