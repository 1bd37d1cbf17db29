// The studies on an imperfect block (issue 41): eq. 27 toward each corner
// (studies/eq27_of_block.hpp), the IDA's grid from where the block lifts
// (IdaOptions::q_start) and the p from which blocks of several slendernesses
// stand.  Truth: the paper's q2_n6 scaled by the corner's alpha (a lean
// changes alpha alone: ImperfectBlock.ALeanShiftsAlphaAlone), and a push held
// for 20 s, which overturns the block toward a corner as soon as it exceeds
// that corner's threshold alpha_sigma g.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "dynamics/imperfect_block.hpp"
#include "qfactor/closed_forms.hpp"
#include "records/collapse.hpp"
#include "studies/eq27_of_block.hpp"
#include "studies/ida.hpp"

using namespace rocking;

namespace {

records::CollapseOptions leaning(double lean) {
    records::CollapseOptions o;
    o.imperfection.lean = lean;
    return o;
}

}  // namespace

TEST(Eq27OfBlock, ThePerfectBlockGetsThePapers) {
    const studies::Eq27OfBlock e = studies::eq27_of_block(0.15, 2.0, records::CollapseOptions{}, 0.4);
    EXPECT_EQ(e.q, q2_n6(0.8));
    EXPECT_EQ(e.q_as_printed, q2_n6(0.8));
    EXPECT_EQ(e.side, 1);
}

TEST(Eq27OfBlock, ALeanScalesItByTheWeakerCorner) {
    const double alpha = 0.15, psi = 0.01, p = 2.0, to = 0.4;
    for (int sign : {+1, -1}) {
        const studies::Eq27OfBlock e = studies::eq27_of_block(alpha, p, leaning(sign * psi), to);
        // Leaning toward theta > 0 lowers corner +1's alpha: the block goes that way first.
        EXPECT_EQ(e.side, sign);
        EXPECT_NEAR(e.q, q2_n6(p * to) * (alpha - psi) / alpha, 1e-13 * e.q);
        EXPECT_EQ(e.q_as_printed, q2_n6(p * to));
    }
}

TEST(ImperfectIda, AGridStartsWhereTheBlockLifts) {
    const double alpha = 0.15, psi = 0.05, p = 2.0;
    EXPECT_EQ(studies::lowest_lift_q(alpha, p, records::CollapseOptions{}), 1.0);
    EXPECT_NEAR(studies::lowest_lift_q(alpha, p, leaning(psi)), (alpha - psi) / alpha, 1e-14);
    // A push held for 20 s, either way: the block falls toward the corner pushed onto
    // as soon as the push exceeds that corner's alpha_sigma g, so the first
    // overturning lies at alpha_sigma/alpha, 2/3 toward the leaning side: below
    // q = 1, where a grid from 1 would have reported its own start.
    std::vector<double> firsts;
    for (double sign : {1.0, -1.0}) {
        const dynamics::SampledInput push(std::vector<double>(2001, sign), 0.01, "push");
        studies::IdaOptions o;
        o.model = leaning(psi);
        o.points = 40;
        const studies::Ida ida = studies::incremental_dynamic_analysis(push, alpha, p, o);
        EXPECT_NEAR(ida.q_start, (alpha - psi) / alpha, 1e-14);
        ASSERT_TRUE(ida.first_overturning.collapsed);
        firsts.push_back(ida.first_overturning.q);
    }
    std::sort(firsts.begin(), firsts.end());
    EXPECT_NEAR(firsts[0], (alpha - psi) / alpha, 1e-5);
    EXPECT_NEAR(firsts[1], (alpha + psi) / alpha, 1e-5);
}

TEST(ImperfectIda, APerfectBlocksGridStartsAtQMin) {
    const dynamics::SampledInput push(std::vector<double>(2001, 1.0), 0.01, "push");
    studies::IdaOptions o;
    o.points = 20;
    const studies::Ida ida = studies::incremental_dynamic_analysis(push, 0.15, 2.0, o);
    EXPECT_EQ(ida.q_start, 1.0);
    ASSERT_TRUE(ida.first_overturning.collapsed);
    EXPECT_NEAR(ida.first_overturning.q, 1.0, 1e-5);
}

TEST(ImperfectBlock, BlocksOfSeveralAlphasStandFromTheLargestStart) {
    dynamics::Imperfection imp;
    imp.fc = 1e6;
    const std::vector<double> alphas = {0.1, 0.15, 0.3};
    double want = 0;
    for (double a : alphas) want = std::max(want, dynamics::lowest_standing_p(a, imp));
    EXPECT_EQ(dynamics::lowest_standing_p(alphas, imp), want);
    EXPECT_GT(want, 0.3);  // the spectrum's default start: with fc 1 MPa it must move
    EXPECT_EQ(dynamics::lowest_standing_p(alphas, dynamics::Imperfection{}), 0.0);
}

TEST(Eq27OfBlock, ASetbackAloneTakesTheSetBackCorners) {
    // Symmetric, but each corner has the set-back block's own alpha and p.
    records::CollapseOptions o;
    o.imperfection.fc = 2e6;
    const double alpha = 0.15, p = 2.0, to = 0.4;
    const dynamics::ImperfectGeometry g = dynamics::imperfect_geometry(dynamics::Block::from_p(p, alpha), o.imperfection);
    ASSERT_LT(g.plus.alpha, alpha);
    const studies::Eq27OfBlock e = studies::eq27_of_block(alpha, p, o, to);
    EXPECT_NEAR(e.q, q2_n6(g.plus.p * to) * g.plus.alpha / alpha, 1e-13 * e.q);
    EXPECT_EQ(e.q_as_printed, q2_n6(p * to));
}
