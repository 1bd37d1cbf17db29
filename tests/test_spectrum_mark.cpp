// A block marked on a spectrum (studies/spectrum_mark.hpp, issue 40): its
// outcome is a run at its own p; the nearest overturning p of the set on
// each side, and the heights of eqs. 2 and 4 at them.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dynamics/block_geometry.hpp"
#include "dynamics/ground_input.hpp"
#include "records/collapse.hpp"
#include "studies/spectrum_mark.hpp"

using namespace rocking;
using namespace rocking::studies;

namespace {

Spectrum with_intervals(double alpha, std::vector<std::pair<double, double>> spans) {
    Spectrum s;
    s.alpha = alpha;
    for (const auto& [from, to] : spans) s.intervals.push_back(Interval{from, to, true, true, {}, {}});
    return s;
}

// A constant 0.3 g: the block overturns iff it lifts (0.3 > alpha) and its
// p is large enough for the 2 s record (tests/test_spectrum.cpp's closed form).
dynamics::SampledInput step() { return dynamics::SampledInput(std::vector<double>(201, 0.3), 0.01, "0.3 g for 2 s"); }

}  // namespace

TEST(SpectrumMark, TheHeightAtPIsEqs2And4Inverted) {
    for (const auto& [B, H] : {std::pair{0.6, 4.0}, {1.0, 4.0}, {0.2, 7.5}}) {
        const dynamics::GivenBlock g = dynamics::block_of_dimensions(B, H, "test");
        EXPECT_NEAR(height_at_p(g.block.alpha, g.block.p), H, 1e-13 * H) << B << "x" << H;
    }
}

TEST(SpectrumMark, TheNearestOverturningPOnEachSide) {
    const dynamics::SampledInput input = step();
    SpectrumOptions o;
    const double alpha = 0.1;
    const Spectrum s = with_intervals(alpha, {{0.5, 0.8}, {1.5, 2.0}, {3.0, 30.0}});
    const SpectrumMark between = mark_block(input, s, BlockShape{alpha, 1.0, "x"}, o);
    EXPECT_FALSE(between.in_set);
    ASSERT_TRUE(between.below.found && between.above.found);
    EXPECT_EQ(between.below.p, 0.8);
    EXPECT_EQ(between.above.p, 1.5);
    EXPECT_NEAR(between.height_above, 2 * 3 * 9.81 / (4 * 1.5 * 1.5) * std::cos(alpha), 1e-13);
    const SpectrumMark inside = mark_block(input, s, BlockShape{alpha, 1.7, ""}, o);
    EXPECT_TRUE(inside.in_set);
    // Inside [1.5, 2.0]: its ends, and the survivors beyond them reach to the neighbours' ends.
    EXPECT_EQ(inside.below.p, 1.5);
    EXPECT_EQ(inside.above.p, 2.0);
    ASSERT_TRUE(inside.survivors_below.found && inside.survivors_above.found);
    EXPECT_EQ(inside.survivors_below.p, 0.8);
    EXPECT_EQ(inside.survivors_above.p, 3.0);
    EXPECT_NEAR(inside.height_survivors_above, 2 * 3 * 9.81 / (4 * 3.0 * 3.0) * std::cos(alpha), 1e-13);
    const SpectrumMark first = mark_block(input, s, BlockShape{alpha, 0.6, ""}, o);
    EXPECT_TRUE(first.in_set && !first.survivors_below.found && first.survivors_above.p == 1.5);
    const SpectrumMark lowest = mark_block(input, s, BlockShape{alpha, 0.4, ""}, o);
    EXPECT_FALSE(lowest.below.found);
    EXPECT_EQ(lowest.above.p, 0.5);
    const SpectrumMark none = mark_block(input, with_intervals(alpha, {}), BlockShape{alpha, 2.0, ""}, o);
    EXPECT_FALSE(none.below.found || none.above.found || none.in_set);
    EXPECT_THROW(mark_block(input, s, BlockShape{0.2, 1.0, ""}, o), std::invalid_argument);
}

TEST(SpectrumMark, TheOutcomeIsARunNotTheSetsReading) {
    // The set says nothing here (no intervals), the run decides: on the
    // constant 0.3 g the alpha 0.1 block overturns at p 3, and the alpha 0.35
    // block never lifts.
    const dynamics::SampledInput input = step();
    SpectrumOptions o;
    const SpectrumMark lifted = mark_block(input, with_intervals(0.1, {}), BlockShape{0.1, 3.0, ""}, o);
    EXPECT_EQ(lifted.overturns, records::collapses_at(input, 0.1, 3.0, o.model));
    EXPECT_TRUE(lifted.overturns);
    EXPECT_NE(describe_mark(lifted).find("on an island the spectrum's method did not resolve"), std::string::npos);
    const SpectrumMark still = mark_block(input, with_intervals(0.35, {}), BlockShape{0.35, 3.0, ""}, o);
    EXPECT_FALSE(still.overturns);
}
