// The block as an engineer gives it (dynamics/block_geometry.hpp, issue 40)
// against eqs. 2 and 4 evaluated here in long double, and every refusal.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "dynamics/block_geometry.hpp"

using namespace rocking::dynamics;

namespace {

std::string plain(const std::string& a) { return a; }

BlockSpec dims(double B, double H) {
    BlockSpec s;
    s.thickness = B;
    s.height = H;
    return s;
}

std::string refusal(const BlockSpec& s) {
    try {
        given_block(s, plain);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(BlockGeometry, ThicknessAndHeightGiveEqs2And4) {
    // alpha = atan(B/H), R = sqrt(B^2 + H^2)/2, p = sqrt(3 g/(4 R)), g = 9.81.
    for (const auto& [B, H] : {std::pair{0.6, 4.0}, {0.45, 3.0}, {0.25, 1.2}, {1e-3, 50.0}, {2.9, 3.0}}) {
        const GivenBlock g = given_block(dims(B, H), plain);
        const long double R = std::sqrt((long double)B * B + (long double)H * H) / 2;
        const long double p = std::sqrt(3 * 9.81L / (4 * R));
        EXPECT_NEAR(g.block.alpha, std::atan((long double)B / H), 4e-16 * g.block.alpha) << B << "x" << H;
        EXPECT_NEAR(g.block.R, R, 4e-16 * R);
        EXPECT_NEAR(g.block.p, p, 4e-16 * p);
        EXPECT_EQ(g.given, GivenBlock::Given::dimensions);
        EXPECT_EQ(g.thickness, B);
        EXPECT_EQ(g.height, H);
    }
    // The half-height instead of the height: the same block.
    BlockSpec half;
    half.thickness = 0.6;
    half.half_height = 2.0;
    EXPECT_EQ(given_block(half, plain).block.p, given_block(dims(0.6, 4.0), plain).block.p);
}

TEST(BlockGeometry, AlphaWithAHeightGivesTheThickness) {
    BlockSpec s;
    s.alpha = std::atan(0.15);
    s.height = 4.0;
    const GivenBlock g = given_block(s, plain);
    EXPECT_EQ(g.given, GivenBlock::Given::alpha_and_size);
    EXPECT_NEAR(g.thickness, 0.6, 1e-14);
    EXPECT_NEAR(g.height, 4.0, 1e-14);
    EXPECT_NEAR(g.block.p, given_block(dims(0.6, 4.0), plain).block.p, 1e-14);
    BlockSpec byp;
    byp.alpha = 0.1;
    byp.p = 2.0;
    const GivenBlock q = given_block(byp, plain);
    EXPECT_FALSE(q.sized());
    EXPECT_EQ(q.block.p, 2.0);
}

TEST(BlockGeometry, BothWaysMustAgreeToOnePerMille) {
    const double alpha = std::atan(0.15), p = given_block(dims(0.6, 4.0), plain).block.p;
    BlockSpec s = dims(0.6, 4.0);
    s.alpha = alpha * (1 + 0.9e-3);
    s.p = p * (1 - 0.9e-3);
    EXPECT_NO_THROW(given_block(s, plain));
    s.alpha = alpha * (1 + 1.1e-3);
    EXPECT_NE(refusal(s).find("give alpha = atan(B/H) = 0.14889 rad, but alpha is"), std::string::npos) << refusal(s);
    s.alpha = alpha;
    s.p = p * (1 + 1.1e-3);
    EXPECT_NE(refusal(s).find("give p = sqrt(3 g / (4 R)) = 1.90737 rad/s, but p is"), std::string::npos) << refusal(s);
}

TEST(BlockGeometry, WhatIsNotARockingBlockIsRefused) {
    EXPECT_NE(refusal(dims(4.0, 4.0)).find("is not below pi/4"), std::string::npos);
    EXPECT_NE(refusal(dims(5.0, 4.0)).find("is not below pi/4"), std::string::npos);
    for (double bad : {0.0, -1.0, double(NAN), double(INFINITY)})
        EXPECT_NE(refusal(dims(bad, 4.0)).find("must be finite and > 0"), std::string::npos) << bad;
    EXPECT_NE(refusal(dims(0.6, INFINITY)).find("must be finite and > 0"), std::string::npos);
    // B/H below the normal doubles: alpha would keep none of its digits.
    EXPECT_NE(refusal(dims(1e-300, 1e10)).find("gives no usable alpha and p"), std::string::npos);
    BlockSpec s;
    s.thickness = 0.6;
    EXPECT_NE(refusal(s).find("thickness B goes with exactly one of height H and half_height h"), std::string::npos);
    s.height = 4;
    s.half_height = 2;
    EXPECT_FALSE(refusal(s).empty());
    EXPECT_NE(refusal(BlockSpec{}).find("give the block as thickness B height H"), std::string::npos);
    BlockSpec two;
    two.alpha = 0.1;
    two.p = 2;
    two.height = 3;
    EXPECT_NE(refusal(two).find("alpha A goes with exactly one of p, half_height and height"), std::string::npos);
}

TEST(BlockGeometry, AListOfBlocksIsReadAndChecked) {
    const auto list = block_list("0.6x4,0.45x3,2.5e-1x1.2", "--block");
    ASSERT_EQ(list.size(), 3u);
    EXPECT_EQ(list[1].label, "0.45x3");
    EXPECT_EQ(list[2].thickness, 0.25);
    EXPECT_EQ(list[0].block.p, given_block(dims(0.6, 4.0), plain).block.p);
    for (const char* bad : {"", "0.6", "0.6x", "x4", "0.6x4x2", "0.6x4,", "0.6 x4", "0.6x4m", "0.6X4", "axb", "0.6x4,,1x2"}) {
        EXPECT_THROW(block_list(bad, "--block"), std::invalid_argument) << "'" << bad << "'";
    }
    EXPECT_THROW(block_list("0.6x4,0.6x4", "--block"), std::invalid_argument);
    EXPECT_THROW(block_list("5x4", "--block"), std::invalid_argument);
    std::string many;
    for (int k = 1; k <= 51; ++k) many += (k > 1 ? "," : "") + std::to_string(k) + "x100";
    EXPECT_THROW(block_list(many, "--block"), std::invalid_argument);
    try {
        block_list("0.6x4,0.6y4", "--block");
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "--block: each block is THICKNESSxHEIGHT in m, e.g. 0.6x4 (got '0.6y4')");
    }
}
