// Eq. 27's non-conservative share under each capacity (issue 39, item 3;
// studies/eq27_at_scale.hpp, Eq27ByCapacity): the first overturning and the
// first robust collapse of each IDA.  Known shares from sets of overturning
// set by hand, the narrow island in q of tests/narrow_islands_truth.hpp
// (closed form) through the refine IDA, and the two bootstraps drawing the
// same records.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "narrow_islands_truth.hpp"
#include "overturning_truths.hpp"
#include "qfactor/closed_forms.hpp"
#include "studies/eq27_at_scale.hpp"
#include "studies/overturning_set.hpp"
#include "studies/resampling.hpp"
#include "test_util.hpp"

using namespace rocking;
using namespace rocking::studies;

namespace {

// x = p to_k for k = 1..11 (test_eq27_at_scale.cpp's, interleaved so that a
// verdict filed under the wrong k shows), and eq. 27 there (rocking q --case 2
// --pulses 6 --x X): 16.88, 1.077, 5.739, 1.010, 3.633, 1.0005, 2.451, 1.128,
// 1.884, 1.680, 1.533.
const double kX[kHalfPeriods] = {0.1, 3.0, 0.2, 5.0, 0.3, 8.0, 0.5, 2.5, 0.8, 1.0, 1.2};
const double kQ27[kHalfPeriods] = {16.881933597479247, 1.0765871356371945, 5.739046466293657, 1.0101410855471407,
                                   3.6327610415533256, 1.000503278357394,  2.451289040606706, 1.128397436387297,
                                   1.8839184844845542, 1.6797004690860011, 1.532770400793716};

std::array<double, kHalfPeriods> to_at(double p) {
    std::array<double, kHalfPeriods> to{};
    for (int k = 0; k < kHalfPeriods; ++k) to[k] = kX[k] / p;
    return to;
}

// An IDA on [1, 20] (100 points, robust width 5e-3) whose set of overturning
// is `spans`, summarised as the IDA summarises its intervals.
Ida ida_of(const std::vector<Span>& spans) {
    const SetSummary s = summarise_set(spans, 1.0, 20.0, 100, 5e-3);
    Ida ida;
    ida.first_overturning = {s.first_overturning, s.overturns};
    ida.first_robust_collapse = {s.first_robust_collapse, s.robustly};
    return ida;
}

}  // namespace

TEST(Eq27Capacities, EachCapacityCountsItsOwnVerdictsOnSetsMadeByHand) {
    // Four records on one block (alpha 0.1, p 2), sets of overturning in q:
    //   A: an island [1.3, 1.3001] (7.7e-5 in ln q), then [2, 20]:
    //      first overturning 1.3, first robust collapse 2;
    //   B: islands [1.75, 1.7505] and [1.95, 1.9501], then [3, 20]: 1.75 and 3;
    //   C: one island [1.2, 1.2001]: 1.2, no robust collapse (censored);
    //   D: nothing (censored under both).
    // A case is non-conservative when its capacity < eq. 27 (kQ27, each at
    // least 4 % from every capacity here).  By hand, per k:
    //   first overturning: k1, k3, k5, k7, k9: A B C (3); k10, k11: A C (2);
    //     k2, k4, k6, k8: none (C's 1.2 is above k8's 1.128);
    //   first robust collapse: k1, k3, k5: A B (2, B's 3 < 3.633); k7: A (2 <
    //     2.451); the others none (A's 2 > k9's 1.884).
    // Fails when a capacity is taken for the other, when the robust study
    // counts C as overturning, or when the censored are counted wrongly.
    const std::vector<Ida> idas = {ida_of({{1.3, 1.3001, -1, -1}, {2.0, 20.0, -1, -1}}),
                                   ida_of({{1.75, 1.7505, -1, -1}, {1.95, 1.9501, -1, -1}, {3.0, 20.0, -1, -1}}),
                                   ida_of({{1.2, 1.2001, -1, -1}}), ida_of({})};
    const double first[4] = {1.3, 1.75, 1.2, 20.0}, robust[4] = {2.0, 3.0, 20.0, 20.0};
    const bool first_found[4] = {true, true, true, false}, robust_found[4] = {true, true, false, false};
    std::vector<std::vector<Eq27Capacities>> capacities;
    for (int r = 0; r < 4; ++r) {
        const Eq27Capacities c = capacities_of(idas[r]);
        ASSERT_EQ(c.first_overturning.q, first[r]) << "record " << r;
        ASSERT_EQ(c.first_overturning.collapsed, first_found[r]) << "record " << r;
        ASSERT_EQ(c.first_robust_collapse.q, robust[r]) << "record " << r;
        ASSERT_EQ(c.first_robust_collapse.collapsed, robust_found[r]) << "record " << r;
        capacities.push_back({c});
    }
    const std::array<double, kHalfPeriods> to = to_at(2.0);
    for (int k = 0; k < kHalfPeriods; ++k) ASSERT_EQ(q2_n6(2.0 * to[k]), kQ27[k]) << "to_" << k + 1;
    const Eq27ByCapacity s = eq27_by_capacity(capacities, {to, to, to, to}, rocking::testing::listed_order(4), {{0.1, 2.0}}, 0.95, {0, 1, 0.9});
    const int want_first[kHalfPeriods] = {3, 0, 3, 0, 3, 0, 3, 0, 3, 2, 2};
    const int want_robust[kHalfPeriods] = {2, 0, 2, 0, 2, 0, 1, 0, 0, 0, 0};
    EXPECT_EQ(s.first_overturning.censored, 1);
    EXPECT_EQ(s.first_robust_collapse.censored, 2);
    EXPECT_EQ(s.first_robust_collapse.map[0].censored, 2);
    for (int k = 0; k < kHalfPeriods; ++k) {
        const Eq27Share &f = s.first_overturning.shares[k], &r = s.first_robust_collapse.shares[k];
        EXPECT_EQ(f.non_conservative, want_first[k]) << "to_" << k + 1;
        EXPECT_EQ(r.non_conservative, want_robust[k]) << "to_" << k + 1;
        EXPECT_EQ(f.cases, 4);
        EXPECT_EQ(r.cases, 4);
        EXPECT_EQ(f.share, want_first[k] / 4.0);
        EXPECT_EQ(r.share, want_robust[k] / 4.0);
        EXPECT_EQ(f.records_with_any, want_first[k]);
        EXPECT_EQ(r.records_with_any, want_robust[k]);
        const WilsonInterval wf = wilson_interval(want_first[k], 4, 0.95), wr = wilson_interval(want_robust[k], 4, 0.95);
        EXPECT_EQ(f.wilson.lo, wf.lo);
        EXPECT_EQ(f.wilson.hi, wf.hi);
        EXPECT_EQ(r.wilson.lo, wr.lo);
        EXPECT_EQ(r.wilson.hi, wr.hi);
        EXPECT_EQ(s.first_robust_collapse.map[0].non_conservative[k], want_robust[k]);
    }
    // The same through eq27_from_points, one capacity at a time.
    std::vector<std::vector<IdaPoint>> robust_points;
    for (const auto& r : capacities) robust_points.push_back({r[0].first_robust_collapse});
    const Eq27Study alone = eq27_from_points(robust_points, {to, to, to, to}, rocking::testing::listed_order(4), {{0.1, 2.0}}, 0.95, {0, 1, 0.9});
    for (int k = 0; k < kHalfPeriods; ++k)
        EXPECT_EQ(alone.shares[k].non_conservative, s.first_robust_collapse.shares[k].non_conservative);
}

TEST(Eq27Capacities, ARobustCollapseBelowTheFirstOverturningIsRefused) {
    // No IDA gives one: the robust collapse starts one of its intervals, the
    // first overturning the lowest.  Fails when the pairs are not checked.
    const std::array<double, kHalfPeriods> to = to_at(2.0);
    EXPECT_THROW(eq27_by_capacity({{Eq27Capacities{{1.5, true}, {1.4, true}}}}, {to}, rocking::testing::listed_order(1), {{0.1, 2.0}}, 0.95, {0, 1, 0.9}),
                 std::invalid_argument);
    EXPECT_THROW(eq27_by_capacity({{Eq27Capacities{{20, false}, {1.4, true}}}}, {to}, rocking::testing::listed_order(1), {{0.1, 2.0}}, 0.95, {0, 1, 0.9}),
                 std::invalid_argument);
    EXPECT_NO_THROW(eq27_by_capacity({{Eq27Capacities{{1.4, true}, {1.4, true}}}}, {to}, rocking::testing::listed_order(1), {{0.1, 2.0}}, 0.95, {0, 1, 0.9}));
}

TEST(Eq27Capacities, TheNarrowIslandInQIsNonConservativeWhereTheRobustCollapseIsNot) {
    // tests/narrow_islands_truth.hpp's island in q at p = 3, [1.26540733,
    // 1.26546961] in closed form (4.9e-5 in ln q): the refine IDA (w = 1e-5,
    // q in [1.2, 2]) puts the first overturning on it, the first robust
    // collapse where the grid's first collapse is (above 1.7).  Eq. 27 at
    // x = p to_k (kX): the first overturning is below eq. 27 for k1, k3, k5,
    // k7, k9, k10, k11 (eq. 27 from 1.533 up), the robust collapse only where
    // eq. 27 is above it (k1, k3, k5, k7 and, were it below 1.884, k9).  The
    // grid method's study equals the robust one.  Fails when the refine
    // method's first overturning is not the capacity, or the studies are
    // swapped.
    using Q = rocking::testing::NarrowIslandInQ;
    const dynamics::PulseInput input = Q::input();
    Eq27Options o;
    o.grid.alphas = {Q::alpha};
    o.grid.p_min = o.grid.p_max = Q::p;
    o.grid.p_points = 1;
    o.ida.model = rocking::testing::restitution_zero();
    o.ida.q_min = 1.2;
    o.ida.q_max = 2.0;
    o.bootstrap.resamples = 0;
    const Eq27Record record{&input, to_at(Q::p)};
    Eq27Options refine = o;
    refine.ida.method = IdaOptions::Method::refine;
    const Eq27ByCapacity s = eq27_at_scale_by_capacity({record}, refine);
    const Eq27ByCapacity grid = eq27_at_scale_by_capacity({record}, o);
    const IdaPoint& first = s.first_overturning.cases[0].point;
    const IdaPoint& robust = s.first_robust_collapse.cases[0].point;
    ASSERT_TRUE(first.collapsed && robust.collapsed);
    EXPECT_GE(first.q, static_cast<double>(Q::lower));
    EXPECT_LE(first.q, static_cast<double>(Q::lower) * (1 + 1e-6));
    ASSERT_GT(robust.q, 1.7);
    ASSERT_LT(robust.q, 2.0);
    EXPECT_NEAR(robust.q, grid.first_overturning.cases[0].point.q, 1e-6 * robust.q);
    for (int k = 0; k < kHalfPeriods; ++k) {
        EXPECT_EQ(s.first_overturning.shares[k].non_conservative, kQ27[k] > 1.27 ? 1 : 0) << "to_" << k + 1;
        EXPECT_EQ(s.first_robust_collapse.shares[k].non_conservative, kQ27[k] > robust.q ? 1 : 0) << "to_" << k + 1;
        EXPECT_EQ(grid.first_overturning.shares[k].non_conservative, s.first_robust_collapse.shares[k].non_conservative)
            << "to_" << k + 1;
    }
    // The premise: at to_10 and to_11 (eq. 27 1.680 and 1.533) the two capacities disagree.
    for (int k : {9, 10}) {
        EXPECT_EQ(s.first_overturning.shares[k].non_conservative, 1) << "to_" << k + 1;
        EXPECT_EQ(s.first_robust_collapse.shares[k].non_conservative, 0) << "to_" << k + 1;
    }
}

TEST(Eq27Capacities, BothBootstrapsDrawTheSameRecords) {
    // 10 records on 10 identical blocks (alpha 0.1, p 1, every to_k 0.5 s:
    // eq. 27 = 2.451): record r overturns r blocks below it at its first
    // overturning (q 1.5, else 3) and r / 2 of them at its robust collapse,
    // so that a resampled share takes many values and the interval shows the
    // draws.  The two bootstraps must draw the same records: then in every
    // resample the first overturning's share is at least the robust one's,
    // and each interval is that of the paired draws recomputed here with the
    // same generator.  The same seed gives the same bits; another seed other
    // bounds (the premise that the intervals show the draws).  Fails when the
    // second bootstrap takes another seed.
    const int n = 10, blocks = 10;
    std::vector<std::vector<Eq27Capacities>> capacities(n);
    for (int r = 0; r < n; ++r)
        for (int b = 0; b < blocks; ++b)
            capacities[r].push_back(Eq27Capacities{{b < r ? 1.5 : 3.0, true}, {b < r / 2 ? 1.5 : 3.0, true}});
    std::array<double, kHalfPeriods> to{};
    to.fill(0.5);
    const std::vector<std::array<double, kHalfPeriods>> tos(n, to);
    const std::vector<BlockShape> bl(blocks, BlockShape{0.1, 1.0, ""});
    const Eq27Bootstrap b{400, 17, 0.9};
    const Eq27ByCapacity s = eq27_by_capacity(capacities, tos, rocking::testing::listed_order(n), bl, 0.95, b);
    const Eq27ByCapacity again = eq27_by_capacity(capacities, tos, rocking::testing::listed_order(n), bl, 0.95, b);
    const Eq27ByCapacity other = eq27_by_capacity(capacities, tos, rocking::testing::listed_order(n), bl, 0.95, {400, 18, 0.9});
    // The paired draws, recomputed.
    SeededRng rng(b.seed);
    std::vector<double> first, robust;
    for (int i = 0; i < b.resamples; ++i) {
        int f = 0, r = 0;
        for (int j = 0; j < n; ++j) {
            const int drawn = static_cast<int>(rng.index(n));
            f += drawn, r += drawn / 2;
        }
        ASSERT_GE(f, r);
        first.push_back(double(f) / (n * blocks)), robust.push_back(double(r) / (n * blocks));
    }
    const Range want_first = percentile_interval(first, b.level), want_robust = percentile_interval(robust, b.level);
    for (int k = 0; k < kHalfPeriods; ++k) {
        const Range &f = s.first_overturning.shares[k].bootstrap, &r = s.first_robust_collapse.shares[k].bootstrap;
        EXPECT_EQ(f.lo, want_first.lo) << "to_" << k + 1;
        EXPECT_EQ(f.hi, want_first.hi) << "to_" << k + 1;
        EXPECT_EQ(r.lo, want_robust.lo) << "to_" << k + 1;
        EXPECT_EQ(r.hi, want_robust.hi) << "to_" << k + 1;
        EXPECT_GE(f.lo, r.lo);
        EXPECT_GE(f.hi, r.hi);
        EXPECT_EQ(again.first_robust_collapse.shares[k].bootstrap.lo, r.lo);
        EXPECT_EQ(again.first_robust_collapse.shares[k].bootstrap.hi, r.hi);
        EXPECT_EQ(again.first_overturning.shares[k].bootstrap.lo, f.lo);
        EXPECT_EQ(again.first_overturning.shares[k].bootstrap.hi, f.hi);
        EXPECT_TRUE(other.first_robust_collapse.shares[k].bootstrap.lo != r.lo ||
                    other.first_robust_collapse.shares[k].bootstrap.hi != r.hi)
            << "to_" << k + 1;
    }
    EXPECT_EQ(s.first_overturning.shares[0].share, 0.45);
    EXPECT_EQ(s.first_robust_collapse.shares[0].share, 0.2);
}
