// Eq. 27 at scale (studies/eq27_at_scale.hpp): the Wilson interval against
// published and independently computed values, the verdict of each k on a
// single rectangular pulse whose collapse q is known in closed form, censored
// records counted as conservative, the map over blocks, and the bootstrap
// over records against binomial quantiles, a second implementation, and the
// narrower interval a bootstrap over cases would give.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "qfactor/closed_forms.hpp"
#include "studies/distinct_inputs.hpp"
#include "studies/eq27_at_scale.hpp"
#include "studies/resampling.hpp"

#include "test_util.hpp"

using namespace rocking;
using namespace rocking::studies;

namespace {

struct WilsonCase {
    int k, n;
    double lo, hi;
};

// Each bound by mpmath at 30 digits from the formula in eq27_at_scale.hpp
// with z = sqrt(2) erfinv(0.95) = 1.959963984540054 (the script is in the
// commit that added this test):
//   import mpmath as mp; mp.mp.dps = 30; z = mp.sqrt(2) * mp.erfinv(mp.mpf('0.95'))
//   ph = k/n; d = 1 + z^2/n; (ph + z^2/(2n) -+ z sqrt(ph(1-ph)/n + z^2/(4n^2))) / d
// The last four are Newcombe 1998 (Statistics in Medicine 17, 857-872),
// Table II, method 3, printed to 4 decimals: 0.2553-0.3662, 0.0624-0.1605,
// 0-0.1611, 0.0061-0.1718; the 17-digit values round to them.
const WilsonCase kWilson[] = {
    {0, 10, 0.0, 0.27753279986288925},
    {5, 10, 0.23659309051256398, 0.76340690948743602},
    {10, 10, 0.72246720013711075, 1.0},
    {1, 10, 0.017876213095072904, 0.4041500267952385},
    {2, 100, 0.0055019675501623481, 0.070011790728543909},
    {81, 263, 0.25528851987827423, 0.36620957698280007},
    {15, 148, 0.06238639953073628, 0.16048724172330804},
    {0, 20, 0.0, 0.16112515805281939},
    {1, 29, 0.0061132142927626605, 0.17175521879320288},
};

// A single rectangular pulse of d s overturns the linearised block from
// q* = 1/(1 - e^{-p d}) up (tests/test_ida.cpp).
double single_pulse_q(double p, double d) { return 1 / -std::expm1(-p * d); }

dynamics::PulseInput single_pulse(double d) { return dynamics::PulseInput(PulseTrain({{1.0, 1.0}}), 0.15, d); }

// x = p to_k for k = 1..11, interleaved so that a verdict filed under the
// wrong k shows.  At p = 2, d = 0.8 (q* = 1.2530) eq. 27 is 16.9, 1.077,
// 5.74, 1.010, 3.63, < 1.01, 2.45, 1.13, 1.88, 1.68, 1.53 (rocking q --case 2
// --pulses 6 --x X): above q* at x <= 1.2, below it from x = 2.5 on, each
// at least 10 % from q* (2.5: 1.128).
const double kX[kHalfPeriods] = {0.1, 3.0, 0.2, 5.0, 0.3, 8.0, 0.5, 2.5, 0.8, 1.0, 1.2};
const bool kNonConservative[kHalfPeriods] = {true, false, true, false, true, false, true, false, true, true, true};

// The smallest x with P(X <= x) >= u for X ~ Binomial(n, m/n), and how far
// the CDF's values stay from u (the empirical percentile of many resamples
// lands on that x when the margin is wide).
int binomial_quantile(int n, int m, double u, double& margin) {
    const double p = double(m) / n;
    double cdf = 0;
    int at = -1;
    margin = 1;
    for (int x = 0; x <= n; ++x) {
        double choose = 1;
        for (int i = 0; i < x; ++i) choose = choose * (n - i) / (i + 1);
        cdf += choose * std::pow(p, x) * std::pow(1 - p, n - x);
        margin = std::min(margin, std::fabs(cdf - u));
        if (at < 0 && cdf >= u - 1e-12) at = x;
    }
    return at;
}

// Points on `blocks` identical blocks (alpha 0.1, p 1 rad/s; every to_k 0.5 s:
// x = 0.5, eq. 27 = 2.451) for `records` records, the first `failing` of
// which overturn every block at q = 1.5 (non-conservative for every k), the
// others at q = 3 (conservative): all-or-nothing records.
struct AllOrNothing {
    std::vector<std::vector<IdaPoint>> points;
    std::vector<std::array<double, kHalfPeriods>> to;
    std::vector<BlockShape> blocks;
    AllOrNothing(int records, int failing, int n_blocks) : blocks(n_blocks, BlockShape{0.1, 1.0, ""}) {
        std::array<double, kHalfPeriods> t{};
        t.fill(0.5);
        for (int r = 0; r < records; ++r) {
            points.push_back(std::vector<IdaPoint>(n_blocks, IdaPoint{r < failing ? 1.5 : 3.0, true}));
            to.push_back(t);
        }
    }
};

Eq27Options one_block(double alpha, double p) {
    Eq27Options o;
    o.grid.alphas = {alpha};
    o.grid.p_min = o.grid.p_max = p;
    o.grid.p_points = 1;
    return o;
}

}  // namespace

TEST(Wilson, PublishedAndIndependentlyComputedBounds) {
    // Fails with z = 1.96 rounded (bounds move by ~1e-6), the normal
    // approximation phat -+ z sqrt(phat(1-phat)/n) (0 of 10 gives [0, 0]),
    // or z^2/n for z^2/(2n) in the centre.
    for (const WilsonCase& c : kWilson) {
        const WilsonInterval w = wilson_interval(c.k, c.n, 0.95);
        EXPECT_NEAR(w.lo, c.lo, 1e-14) << c.k << " of " << c.n;
        EXPECT_NEAR(w.hi, c.hi, 1e-14) << c.k << " of " << c.n;
    }
}

TEST(Wilson, ExactAtTheEndsAndRefusesNonsense) {
    // 0 and n successes: the bound at the data is exactly 0 or 1, not a
    // rounding of it (a share of 0 must not print an interval from -1e-17).
    EXPECT_EQ(wilson_interval(0, 7, 0.95).lo, 0.0);
    EXPECT_EQ(wilson_interval(7, 7, 0.95).hi, 1.0);
    EXPECT_THROW(wilson_interval(0, 0, 0.95), std::invalid_argument);
    EXPECT_THROW(wilson_interval(3, 2, 0.95), std::invalid_argument);
    EXPECT_THROW(wilson_interval(-1, 2, 0.95), std::invalid_argument);
    EXPECT_THROW(wilson_interval(1, 2, 1.0), std::invalid_argument);
}

TEST(Eq27AtScale, TheVerdictIsStrictlyBelowEq27AndNeverForACensoredPoint) {
    // Fails with <= for < (a record collapsing exactly at eq. 27's q is where
    // eq. 27 says collapse: conservative), or with censoring ignored.
    EXPECT_TRUE(non_conservative({1.5, true}, 2.0));
    EXPECT_FALSE(non_conservative({2.0, true}, 2.0));
    EXPECT_FALSE(non_conservative({2.5, true}, 2.0));
    EXPECT_FALSE(non_conservative({1.5, false}, 2.0));
}

TEST(Eq27AtScale, ASinglePulseIsNonConservativeForExactlyTheKnownDefinitions) {
    // The IDA finds q* = 1.2530 within 1e-6; each k's verdict is q* < eq. 27
    // at x = p to_k, known above.  Fails when the IDA's point is not the one
    // compared, when x is taken as to_k alone or p / to_k, or when the
    // verdicts or counts are filed under another k.
    const double alpha = 0.1, p = 2.0, d = 0.8;
    const dynamics::PulseInput pulse = single_pulse(d);
    Eq27Record r{&pulse, {}};
    for (int k = 0; k < kHalfPeriods; ++k) r.to[k] = kX[k] / p;
    const Eq27Study s = eq27_at_scale({r}, one_block(alpha, p));
    ASSERT_EQ(s.cases.size(), 1u);
    const Eq27Case& c = s.cases[0];
    ASSERT_TRUE(c.point.collapsed);
    EXPECT_NEAR(c.point.q, single_pulse_q(p, d), 1e-6 * c.point.q);
    EXPECT_EQ(s.censored, 0);
    for (int k = 0; k < kHalfPeriods; ++k) {
        EXPECT_EQ(c.q_eq27[k], q2_n6(kX[k])) << "to_" << k + 1;
        EXPECT_EQ(c.non_conservative[k], kNonConservative[k]) << "to_" << k + 1;
        EXPECT_EQ(s.shares[k].cases, 1);
        EXPECT_EQ(s.shares[k].non_conservative, kNonConservative[k] ? 1 : 0) << "to_" << k + 1;
        EXPECT_EQ(s.map[0].non_conservative[k], kNonConservative[k] ? 1 : 0) << "to_" << k + 1;
    }
}

TEST(Eq27AtScale, ACensoredRecordCountsAsConservativeAndInTheDenominator) {
    // p d = 0.04: q* = 25.5 > q_max = 20, so the pulse never overturns the
    // block in the IDA.  At x = 0.005 eq. 27 is about 5900, far above q_max:
    // a study that took the censored q_max as a collapse q would call every k
    // non-conservative.  Beside it the collapsing pulse of the test above.
    // Fails when censored points are compared, left out of the cases (share
    // 7/1 for 7/2), or not counted as censored.
    const double alpha = 0.1, p = 0.5;
    const dynamics::PulseInput short_pulse = single_pulse(0.08), long_pulse = single_pulse(3.2);
    Eq27Record censored{&short_pulse, {}}, collapsing{&long_pulse, {}};
    for (int k = 0; k < kHalfPeriods; ++k) {
        censored.to[k] = 0.005 / p;
        collapsing.to[k] = kX[k] / p;  // p d = 1.6 as above: q* = 1.2530
    }
    const Eq27Study s = eq27_at_scale({censored, collapsing}, one_block(alpha, p));
    ASSERT_EQ(s.cases.size(), 2u);
    EXPECT_FALSE(s.cases[0].point.collapsed);
    EXPECT_EQ(s.cases[0].point.q, 20.0);
    EXPECT_GT(s.cases[0].q_eq27[0], 5000.0);
    EXPECT_EQ(s.censored, 1);
    EXPECT_EQ(s.map[0].censored, 1);
    EXPECT_EQ(s.map[0].records, 2);
    for (int k = 0; k < kHalfPeriods; ++k) {
        EXPECT_FALSE(s.cases[0].non_conservative[k]) << "to_" << k + 1;
        EXPECT_EQ(s.shares[k].cases, 2);
        const int want = kNonConservative[k] ? 1 : 0;
        EXPECT_EQ(s.shares[k].non_conservative, want) << "to_" << k + 1;
        EXPECT_EQ(s.shares[k].share, want / 2.0);
        const WilsonInterval w = wilson_interval(want, 2, 0.95);
        EXPECT_EQ(s.shares[k].wilson.lo, w.lo);
        EXPECT_EQ(s.shares[k].wilson.hi, w.hi);
    }
}

TEST(Eq27AtScale, TheMapCountsEachBlocksRecords) {
    // Three records on two blocks (p = 1 and 4 rad/s), every to_k = 0.5 s:
    // x = 0.5 (eq. 27 = 2.451) and x = 2 (eq. 27 = 1.218).  Points chosen
    // around those: block 0 has 2 of 3 non-conservative (q 1.5 and 2.0; 3.0
    // is above), block 1 has 1 of 3 (q 1.1; 1.3 above; one censored).  Fails
    // when the map is indexed by record instead of block, or a block's p is
    // taken from another block.
    const std::vector<BlockShape> blocks = {{0.1, 1.0}, {0.1, 4.0}};
    std::array<double, kHalfPeriods> to{};
    to.fill(0.5);
    const std::vector<std::vector<IdaPoint>> points = {
        {{1.5, true}, {1.1, true}}, {{2.0, true}, {1.3, true}}, {{3.0, true}, {20.0, false}}};
    const Eq27Study s = eq27_from_points(points, {to, to, to}, rocking::testing::listed_order(3), blocks, 0.95);
    ASSERT_EQ(s.map.size(), 2u);
    EXPECT_EQ(s.map[0].block.p, 1.0);
    EXPECT_EQ(s.map[1].block.p, 4.0);
    EXPECT_EQ(s.map[0].records, 3);
    EXPECT_EQ(s.map[1].censored, 1);
    for (int k = 0; k < kHalfPeriods; ++k) {
        EXPECT_EQ(s.map[0].non_conservative[k], 2);
        EXPECT_EQ(s.map[1].non_conservative[k], 1);
        EXPECT_EQ(s.shares[k].non_conservative, 3);
        EXPECT_EQ(s.shares[k].cases, 6);
    }
    EXPECT_THROW(eq27_from_points(points, {to, to}, rocking::testing::listed_order(3), blocks, 0.95), std::invalid_argument);
    to[3] = 0;
    EXPECT_THROW(eq27_from_points(points, {to, to, to}, rocking::testing::listed_order(3), blocks, 0.95), std::invalid_argument);
}

TEST(Eq27AtScale, TheDefaultGridIsTheIssues) {
    // alpha 0.05..0.25 by 0.05, p 0.5..10 rad/s, 10 points log-spaced: 50
    // blocks, alpha outermost, both ends of p exact.  Fails with linear
    // spacing in p or p_max missed.
    const Eq27Grid g;
    const std::vector<double> p = g.ps();
    ASSERT_EQ(p.size(), 10u);
    EXPECT_EQ(p.front(), 0.5);
    EXPECT_EQ(p.back(), 10.0);
    for (std::size_t i = 1; i < p.size(); ++i) EXPECT_NEAR(p[i] / p[i - 1], std::pow(20.0, 1.0 / 9), 1e-12);
    const std::vector<BlockShape> b = g.blocks();
    ASSERT_EQ(b.size(), 50u);
    EXPECT_EQ(b[0].alpha, 0.05);
    EXPECT_EQ(b[9].alpha, 0.05);
    EXPECT_EQ(b[10].alpha, 0.10);
    EXPECT_EQ(b[10].p, 0.5);
}

namespace {

// The message of the std::invalid_argument f throws, or "" when it throws none.
template <class F>
std::string refusal(F f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(Eq27AtScale, AGridThatSaysOtherThanItCountsIsRefusedInTheFrontEndsWords) {
    // Issue 38: one p with a range was cut to p_min (ps() returned {p_min}),
    // and an alpha given twice counted its cases twice; the command line and
    // the Python module refuse both here, each in its own names.
    const Eq27GridNames cli{"--alpha", "--p-min", "--p-max", "--p-points", " "};
    Eq27Grid g;
    g.p_points = 1;
    g.p_min = 1, g.p_max = 4;
    EXPECT_EQ(refusal([&] { g.check(cli); }),
              "--p-points 1: one p, but the range runs from 1 to 4 rad/s: give the p as --p-min P alone, or more points");
    EXPECT_EQ(refusal([&] { g.check(); }),
              "p_points=1: one p, but the range runs from 1 to 4 rad/s: give the p as p_min=P alone, or more points");
    EXPECT_NE(refusal([&] { g.ps(); }), "");
    EXPECT_NE(refusal([&] { g.blocks(); }), "");
    g.p_max = 1;
    EXPECT_EQ(g.ps(), std::vector<double>{1.0});
    EXPECT_EQ(g.blocks().size(), 5u);
    g.alphas = {0.1, 0.2, 0.10};
    EXPECT_EQ(refusal([&] { g.check(cli); }),
              "--alpha: 0.1 is given twice (values 1 and 3); each would count its cases again: give each value once");
    EXPECT_EQ(refusal([&] { g.blocks(); }),
              "alpha: 0.1 is given twice (values 1 and 3); each would count its cases again: give each value once");
    g.alphas = {0.1};
    g.p_points = 1000, g.p_max = 1.0000000000001;
    EXPECT_EQ(refusal([&] { g.check(); }),
              "p_points: 1000 points from 1 to 1 rad/s repeat p = 1: widen the range or take fewer points");
    g.p_points = 3, g.p_max = 1;
    EXPECT_EQ(refusal([&] { g.check(cli); }), "--p-points: more than 1 needs --p-max above --p-min");
}

TEST(DistinctInputs, ARecordIsItsStepAndSamplesWhateverItsName) {
    const dynamics::SampledInput a({0.1, -0.2, 0.3}, 0.01, "a"), b({0.1, -0.2, 0.3}, 0.01, "b"),
        slower({0.1, -0.2, 0.3}, 0.02, "slower"), other({0.1, -0.2, 0.3000031}, 0.01, "other");
    EXPECT_EQ(refusal([&] { refuse_repeated_records({"a.txt", "slower.txt", "other.txt"}, {&a, &slower, &other}); }), "");
    // Scaled, the sign flipped, or off by a rounding: one record to a study that scales each to every q.
    const dynamics::SampledInput scaled({-0.15, 0.3, -0.45}, 0.01, "scaled"),
        rounded({0.1, -0.2, 0.30000000000000004}, 0.01, "rounded");
    for (const dynamics::SampledInput* copy : {&scaled, &rounded})
        EXPECT_NE(refusal([&] { refuse_repeated_records({"a.txt", "copy.txt"}, {&a, copy}); })
                      .find("copy.txt: the same record as a.txt scaled (records 1 and 2"),
                  std::string::npos)
            << copy->samples()[2];
    EXPECT_EQ(refusal([&] { refuse_repeated_records({"a.txt", "slower.txt", "b.txt"}, {&a, &slower, &b}); }),
              "b.txt: the same record as a.txt (records 1 and 3: the same step and samples), whose cases would count "
              "twice: give each record once");
    EXPECT_EQ(refusal([] { refuse_repeated_values("p", {2, 3, 2.0}); }),
              "p: 2 is given twice (values 1 and 3); each would count its cases again: give each value once");
    EXPECT_EQ(refusal([] { refuse_repeated_values("p", {2, 3, 2.0000000000000004}); }), "");
}

TEST(Eq27Bootstrap, AllOrNothingRecordsGiveTheBinomialQuantiles) {
    // 20 records of 5 blocks each; for k, m_k records are non-conservative on
    // every block, the rest on none.  A resample's share is then X/20 with
    // X ~ Binomial(20, m_k/20), so the 80 % percentile interval of 20000
    // resamples is the binomial's 10 % and 90 % quantiles over 20 (each m_k
    // chosen with the CDF at least 0.018 from 0.1 and 0.9, 8 standard errors
    // of the empirical CDF at 20000).  Fails when a resample draws cases
    // (the quantiles of a binomial over 100 cases, 2.2 times narrower), when
    // the share is over the drawn records' count alone, or when the counts of
    // one k are filed under another.
    const int records = 20, blocks = 5;
    const int m[kHalfPeriods] = {10, 3, 17, 0, 8, 20, 1, 12, 19, 9, 18};
    std::vector<std::array<int, kHalfPeriods>> counts(records);
    for (int r = 0; r < records; ++r)
        for (int k = 0; k < kHalfPeriods; ++k) counts[r][k] = r < m[k] ? blocks : 0;
    const std::array<Range, kHalfPeriods> got = record_bootstrap(counts, blocks, {20000, 5, 0.8});
    for (int k = 0; k < kHalfPeriods; ++k) {
        double margin_lo = 0, margin_hi = 0;
        const int lo = binomial_quantile(records, m[k], 0.1, margin_lo), hi = binomial_quantile(records, m[k], 0.9, margin_hi);
        ASSERT_GT(std::min(margin_lo, margin_hi), 0.018) << "m = " << m[k] << ": the test's premise";
        EXPECT_EQ(got[k].lo, double(lo) / records) << "to_" << k + 1 << ", m = " << m[k];
        EXPECT_EQ(got[k].hi, double(hi) / records) << "to_" << k + 1 << ", m = " << m[k];
    }
    // Two of them written out: m = 10 gives [7, 13]/20, m = 1 gives [0, 2]/20.
    EXPECT_EQ(got[0].lo, 0.35);
    EXPECT_EQ(got[0].hi, 0.65);
    EXPECT_EQ(got[6].lo, 0.0);
    EXPECT_EQ(got[6].hi, 0.1);
}

TEST(Eq27Bootstrap, ResamplingRecordsIsWiderThanResamplingCasesOnCorrelatedData) {
    // 20 records on 10 blocks, 10 records non-conservative on all of them:
    // 200 cases, 100 non-conservative, but only 20 independent records.
    // Through eq27_from_points, the 80 % interval is Binomial(20, 1/2)'s
    // [7, 13]/20 (the test above); resampling the 200 cases instead gives
    // about 0.5 -+ 1.28 sqrt(0.25/200) = [0.455, 0.545], computed here with
    // the same generator.  Fails when the study's bootstrap draws cases, or
    // draws records but keeps only one block of each.
    const AllOrNothing d(20, 10, 10);
    const Eq27Bootstrap b{20000, 3, 0.8};
    const Eq27Study s = eq27_from_points(d.points, d.to, rocking::testing::listed_order(d.points.size()), d.blocks, 0.95, b);
    EXPECT_EQ(s.bootstrap.resamples, 20000);
    EXPECT_EQ(s.bootstrap.seed, 3u);
    EXPECT_EQ(s.bootstrap.level, 0.8);

    std::vector<int> cases;  // the 200 verdicts, record-major
    for (const Eq27Case& c : s.cases) cases.push_back(c.non_conservative[0]);
    SeededRng rng(3);
    std::vector<double> shares;
    for (int i = 0; i < b.resamples; ++i) {
        int sum = 0;
        for (std::size_t j = 0; j < cases.size(); ++j) sum += cases[rng.index(cases.size())];
        shares.push_back(double(sum) / cases.size());
    }
    const Range by_case = percentile_interval(shares, b.level);
    ASSERT_LT(by_case.hi - by_case.lo, 0.12) << "the test's premise: resampling cases is narrow";

    for (int k = 0; k < kHalfPeriods; ++k) {
        const Eq27Share& sh = s.shares[k];
        EXPECT_EQ(sh.share, 0.5);
        EXPECT_EQ(sh.bootstrap.lo, 0.35) << "to_" << k + 1;
        EXPECT_EQ(sh.bootstrap.hi, 0.65) << "to_" << k + 1;
        EXPECT_GT(sh.bootstrap.hi - sh.bootstrap.lo, 2.5 * (by_case.hi - by_case.lo)) << "to_" << k + 1;
        // Wilson at the same level takes the 200 cases as independent: as narrow as the case bootstrap.
        const WilsonInterval w = wilson_interval(100, 200, 0.8);
        EXPECT_LT(w.hi - w.lo, 0.1);
        EXPECT_EQ(sh.records_with_any, 10);
        EXPECT_EQ(sh.records, 20);
    }
}

TEST(Eq27Bootstrap, TheSameSeedGivesTheSameIntervalAsASecondImplementation) {
    // 6 records of 4 blocks, counts[r][k] = (3r + 2k + r k^2) mod 5: 300
    // resamples, seed 43, 90 %.  The bounds are those of a second
    // implementation in Python (expected/fragility/independent.py's GSL
    // mt19937 and gsl_rng_uniform_int rebuilt on Python's Mersenne Twister,
    // its percentile interpolation), to the last bit: the shares are counts
    // over 24, the interpolation one subtraction, product and sum.  Seed 42
    // gives other bounds.  Fails when the seed is not used, when the draws
    // differ from GSL's mt19937 (another generator, a modulo for the rejection
    // rule), or when the interpolation or the tails differ.
    const int records = 6, blocks = 4;
    std::vector<std::array<int, kHalfPeriods>> counts(records);
    for (int r = 0; r < records; ++r)
        for (int k = 0; k < kHalfPeriods; ++k) counts[r][k] = (3 * r + 2 * k + r * k * k) % (blocks + 1);
    const Range want[5] = {{0.16666666666666666, 0.625},
                           {0.2916666666666667, 0.7083333333333334},
                           {0.375, 0.8333333333333334},
                           {0.25, 0.6687500000000004},
                           {0.3333333333333333, 0.7520833333333338}};
    const std::array<Range, kHalfPeriods> a = record_bootstrap(counts, blocks, {300, 43, 0.9});
    const std::array<Range, kHalfPeriods> again = record_bootstrap(counts, blocks, {300, 43, 0.9});
    const std::array<Range, kHalfPeriods> other = record_bootstrap(counts, blocks, {300, 42, 0.9});
    int differs = 0;
    for (int k = 0; k < kHalfPeriods; ++k) {
        EXPECT_EQ(a[k].lo, want[k % 5].lo) << "to_" << k + 1;
        EXPECT_EQ(a[k].hi, want[k % 5].hi) << "to_" << k + 1;
        EXPECT_EQ(again[k].lo, a[k].lo);
        EXPECT_EQ(again[k].hi, a[k].hi);
        differs += other[k].lo != a[k].lo || other[k].hi != a[k].hi;
    }
    EXPECT_GT(differs, 0);
}

TEST(Eq27Bootstrap, RecordsWithAnyCaseAndNoBootstrapUnlessAsked) {
    // The map test's points (3 records on 2 blocks): record 0 is
    // non-conservative on both blocks, record 1 on block 0 only, record 2 on
    // neither: 3 non-conservative cases in 2 records.  With 0 resamples the
    // interval is not run and says so.  Fails when records_with_any counts
    // cases or blocks.
    const std::vector<BlockShape> blocks = {{0.1, 1.0}, {0.1, 4.0}};
    std::array<double, kHalfPeriods> to{};
    to.fill(0.5);
    // Block 0 (eq. 27 = 2.451): q 1.5, 2.0 below; block 1 (eq. 27 = 1.218): q 1.1 below.
    const std::vector<std::vector<IdaPoint>> points = {
        {{1.5, true}, {1.1, true}}, {{2.0, true}, {1.3, true}}, {{3.0, true}, {20.0, false}}};
    const Eq27Study s = eq27_from_points(points, {to, to, to}, rocking::testing::listed_order(3), blocks, 0.95, {0, 1, 0.9});
    EXPECT_EQ(s.records, 3);
    EXPECT_EQ(s.bootstrap.resamples, 0);
    for (int k = 0; k < kHalfPeriods; ++k) {
        EXPECT_EQ(s.shares[k].non_conservative, 3);
        EXPECT_EQ(s.shares[k].records_with_any, 2);
        EXPECT_EQ(s.shares[k].records, 3);
        EXPECT_EQ(s.shares[k].bootstrap.lo, 0.0);
        EXPECT_EQ(s.shares[k].bootstrap.hi, 0.0);
    }
    // The default runs it: 1000 resamples, seed 1, 90 % (the fragility fit's level).
    const Eq27Study d = eq27_from_points(points, {to, to, to}, rocking::testing::listed_order(3), blocks, 0.95);
    EXPECT_EQ(d.bootstrap.resamples, 1000);
    EXPECT_EQ(d.bootstrap.seed, 1u);
    EXPECT_EQ(d.bootstrap.level, 0.9);
    EXPECT_LE(d.shares[0].bootstrap.lo, d.shares[0].share);
    EXPECT_GE(d.shares[0].bootstrap.hi, d.shares[0].share);
}

TEST(Eq27Bootstrap, RefusesNonsense) {
    const std::vector<std::array<int, kHalfPeriods>> counts(3);
    EXPECT_THROW(record_bootstrap({}, 2, {10, 1, 0.9}), std::invalid_argument);
    EXPECT_THROW(record_bootstrap(counts, 0, {10, 1, 0.9}), std::invalid_argument);
    EXPECT_THROW(record_bootstrap(counts, 2, {1, 1, 0.9}), std::invalid_argument);
    EXPECT_THROW(record_bootstrap(counts, 2, {10, 1, 1.0}), std::invalid_argument);
    EXPECT_THROW(record_bootstrap(counts, 2, {10, 1, 0.0}), std::invalid_argument);
    std::vector<std::array<int, kHalfPeriods>> over(2);
    over[1][4] = 3;
    EXPECT_THROW(record_bootstrap(over, 2, {10, 1, 0.9}), std::invalid_argument);
    const AllOrNothing d(3, 1, 2);
    EXPECT_THROW(eq27_from_points(d.points, d.to, rocking::testing::listed_order(d.points.size()), d.blocks, 0.95, {-1, 1, 0.9}), std::invalid_argument);
}
