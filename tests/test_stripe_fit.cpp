// The multiple-stripe fit (studies/stripe_fit.hpp) against independent truth:
// closed forms where the fit reproduces its data exactly (two stripes; shares
// on a lognormal), tools/stripe_mle.py (mpmath, 40 digits, the score equations
// in (ln median, ln beta)) on hand-made stripes and on synthetic overturning
// sets whose shares are exact, every case without a maximum, the bootstrap's
// determinism and its re-run by the tool; and the fragility of a block three
// ways (studies::block_fragility with the refine method) on synthetic IDAs and
// on rectangular pulses whose overturning set is known in closed form.
#include <gtest/gtest.h>

#include <gsl/gsl_cdf.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "studies/ida.hpp"
#include "studies/stripe_fit.hpp"
#include "synthetic_ida.hpp"
#include "test_util.hpp"

using namespace rocking;
using namespace rocking::studies;
using rocking::testing::synthetic_ida;

namespace {

// Expects `what` to be refused by why_no_stripe_maximum with words holding
// `words`, and fit_stripes to throw std::invalid_argument with them.
void expect_no_maximum(const std::vector<Stripe>& stripes, const std::string& words) {
    const std::string why = why_no_stripe_maximum(stripes);
    EXPECT_NE(why.find(words), std::string::npos) << "why: '" << why << "', expected words: " << words;
    try {
        fit_stripes(stripes);
        ADD_FAILURE() << "fit_stripes fitted a set without a maximum (" << words << ")";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
}

// A record's overturning set as spans.
std::vector<Span> set_of(const std::vector<std::pair<double, double>>& intervals) {
    std::vector<Span> out;
    for (const auto& [from, to] : intervals) out.push_back(Span{from, to, -1, -1});
    return out;
}

// tools/stripe_mle.py's synthetic case: five records' sets, a grid of 20 q from 1 to 20.
const std::vector<std::vector<std::pair<double, double>>> kSynthetic = {
    {{1.3, 20}},
    {{1.15, 1.18}, {1.6, 2.4}, {3.0, 20}},
    {{2.2, 20}},
    {{1.05, 1.0501}, {4.5, 20}},
    {{1.9, 2.6}, {5.5, 7}, {9, 20}},
};

}  // namespace

TEST(StripeFit, TwoStripesAreFittedExactly) {
    // Two stripes, two parameters: the maximum reproduces both shares,
    // Phi(u_j) = s_j, so beta = ln(q2/q1) / (Phi^-1(s2) - Phi^-1(s1)) and
    // ln median = ln q1 - beta Phi^-1(s1), whatever n.  Shares 0.3, 0.7 at
    // 1.5 and 3: median sqrt(4.5) by symmetry.
    for (double n : {1.0, 4.0, 25.0}) {
        const StripeFragility f = fit_stripes({{1.5, n, 0.3 * n}, {3.0, n, 0.7 * n}});
        const double z1 = gsl_cdf_ugaussian_Pinv(0.3), z2 = gsl_cdf_ugaussian_Pinv(0.7);
        const double beta = std::log(2.0) / (z2 - z1);
        EXPECT_NEAR(f.beta, beta, 1e-13 * beta) << n;
        EXPECT_NEAR(f.median, std::exp(std::log(1.5) - beta * z1), 1e-13) << n;
        EXPECT_NEAR(f.median, std::sqrt(4.5), 1e-13) << n;
        EXPECT_EQ(f.stripes, 2);
    }
    // tools/stripe_mle.py --stripe 1.5 4 1.2 --stripe 3 4 2.8: median 2.1213203435596426851,
    // beta 0.66089483492348723961, ln L -4.8869144164391478171.
    const StripeFragility f = fit_stripes({{1.5, 4, 1.2}, {3.0, 4, 2.8}});
    EXPECT_NEAR(f.log_likelihood, -4.8869144164391478171, 1e-13);
}

TEST(StripeFit, SharesOnALognormalGiveItsParameters) {
    // Every stripe's share on Phi(ln(q/2)/0.4): each term of (S2) is at its
    // own maximum there, so the fit is (2, 0.4) to rounding.
    std::vector<Stripe> stripes;
    for (int j = 0; j < 12; ++j) {
        const double q = std::exp(std::log(0.9) + j * std::log(5.0) / 11);
        stripes.push_back({q, 7, 7 * gsl_cdf_ugaussian_P(std::log(q / 2) / 0.4)});
    }
    const StripeFragility f = fit_stripes(stripes);
    EXPECT_NEAR(f.median, 2.0, 1e-12);
    EXPECT_NEAR(f.beta, 0.4, 1e-12);
    // ln L there is the sum of the terms' own maxima: no (median, beta) does better.
    for (double dm : {-1e-4, 1e-4})
        for (double db : {-1e-4, 0.0, 1e-4}) EXPECT_LT(stripe_log_likelihood(stripes, 2 + dm, 0.4 + db), f.log_likelihood);
}

TEST(StripeFit, HandMadeStripesMatchAnIndependentFit) {
    // tools/stripe_mle.py (mpmath, 40 digits, by the score equations in
    // (ln median, ln beta)), its 20 digits: `--stripe Q N Z` per stripe.
    struct Case {
        const char* name;
        std::vector<Stripe> stripes;
        double median, beta, log_likelihood;
    };
    const std::vector<Case> cases = {
        // Equal n, a share that falls between two rises.
        {"A", {{1.2, 5, 0}, {1.5, 5, 1}, {2, 5, 1.5}, {2.5, 5, 3.25}, {3.2, 5, 2.5}, {4, 5, 5}},
         2.4241784355946594336, 0.41205334419337555933, -14.071244669125662052},
        // Unequal n, a q below 1, the last stripe wholly overturned.
        {"B", {{0.8, 3, 0.3}, {1, 7, 1.4}, {1.25, 2, 1.9}, {1.6, 10, 6.05}, {2, 4, 4}},
         1.2911118487114977978, 0.36098285583315155977, -13.546655866616115278},
        // Nearly separated: beta 0.038.
        {"C", {{1, 10, 0}, {1.1, 10, 0.2}, {1.2, 10, 5.5}, {1.3, 10, 9.9}, {1.4, 10, 10}},
         1.1931651038895409934, 0.038442647073646052196, -8.4292712811096507159},
        // A rise on balance only (shares 0.5, 0.25, 0.75).
        {"D", {{1, 4, 2}, {2, 4, 1}, {3, 4, 3}}, 1.8121171422389664547, 2.4077958505844092904,
         -8.1838432614860549325},
        // Small shares: the median far above the stripes.
        {"E", {{2, 40, 0.001}, {8, 40, 0.25}, {30, 40, 1.5}}, 607.09798157328369376, 1.6960043953890538606,
         -7.9406782240920128478},
    };
    for (const Case& c : cases) {
        ASSERT_EQ(why_no_stripe_maximum(c.stripes), "") << c.name;
        const StripeFragility f = fit_stripes(c.stripes);
        EXPECT_NEAR(f.median, c.median, 1e-11 * c.median) << c.name;
        EXPECT_NEAR(f.beta, c.beta, 1e-11 * c.beta) << c.name;
        EXPECT_NEAR(f.log_likelihood, c.log_likelihood, 1e-12 * std::fabs(c.log_likelihood)) << c.name;
        EXPECT_NEAR(stripe_log_likelihood(c.stripes, c.median, c.beta), c.log_likelihood,
                    1e-12 * std::fabs(c.log_likelihood))
            << c.name;
    }
}

TEST(StripeFit, EveryCaseWithoutAMaximumIsRefusedAndSaysWhy) {
    expect_no_maximum({{1, 3, 0}, {2, 3, 0}}, "every share 0");
    expect_no_maximum({{1, 3, 3}, {2, 3, 3}}, "every share 1");
    expect_no_maximum({{1.5, 3, 1}}, "one stripe (at q = 1.5)");
    // Perfect separation: with a stripe in between, and without.
    expect_no_maximum({{1, 3, 0}, {2, 3, 1.2}, {3, 3, 3}}, "the shares step from 0 to 1 at q = 2 (every");
    expect_no_maximum({{1, 3, 0}, {2, 3, 0}, {3, 3, 3}, {4, 3, 3}}, "the shares step from 0 to 1 at q = 2 to 3");
    // No rise: equal shares (the pairwise sum (S5) is 0 exactly, not a
    // rounding residue that would fit beta ~ 1e16), falling shares, a
    // separation the other way, and a rise outweighed by falls.
    expect_no_maximum({{1, 4, 1}, {2, 4, 1}, {3, 4, 1}}, "does not rise with q");
    expect_no_maximum({{1.1, 7, 0.7}, {1.7, 7, 0.7}, {2.3, 7, 0.7}, {9.1, 7, 0.7}}, "does not rise with q");
    expect_no_maximum({{1, 4, 3}, {2, 4, 2}, {3, 4, 1}}, "does not rise with q");
    expect_no_maximum({{1, 4, 4}, {2, 4, 0}}, "does not rise with q");
    expect_no_maximum({{1, 4, 2}, {2, 4, 3}, {3, 4, 1}}, "does not rise with q");
    // The same data just past each edge have a maximum.
    EXPECT_EQ(why_no_stripe_maximum({{1, 3, 0.001}, {2, 3, 1.2}, {3, 3, 3}}), "");
    EXPECT_EQ(why_no_stripe_maximum({{1, 4, 1}, {2, 4, 1}, {3, 4, 1.001}}), "");
    EXPECT_EQ(why_no_stripe_maximum({{1, 4, 2}, {2, 4, 1}, {3, 4, 3}}), "");
    // Bad data are errors, not reasons.
    EXPECT_THROW(why_no_stripe_maximum({{2, 3, 1}, {1, 3, 2}}), std::invalid_argument);
    EXPECT_THROW(why_no_stripe_maximum({{1, 3, 1}, {2, 3, 3.5}}), std::invalid_argument);
    EXPECT_THROW(why_no_stripe_maximum({{1, 0, 0}, {2, 3, 1}}), std::invalid_argument);
    EXPECT_THROW(why_no_stripe_maximum({{1, 3, -0.1}, {2, 3, 1}}), std::invalid_argument);
    EXPECT_THROW(why_no_stripe_maximum({{0, 3, 1}, {2, 3, 1}}), std::invalid_argument);
}

TEST(StripeFit, SharesOfSyntheticSetsAreExactAndTheirFitIsTheIndependentOne) {
    std::vector<std::vector<Span>> sets;
    for (const auto& s : kSynthetic) sets.push_back(set_of(s));
    const StripeShares shares = stripe_shares(sets, 1, 20, 20);
    ASSERT_EQ(shares.q.size(), 19u);
    EXPECT_NEAR(shares.half_width, std::log(20.0) / 38, 1e-16);
    const double r = std::pow(20.0, 1.0 / 19);  // the grid's ratio
    for (std::size_t j = 0; j < 19; ++j) {
        EXPECT_NEAR(shares.from[j], std::pow(r, j), 1e-14 * shares.to[j]);
        EXPECT_NEAR(shares.q[j], std::pow(r, j + 0.5), 1e-14 * shares.q[j]);
        EXPECT_NEAR(std::log(shares.to[j] / shares.from[j]), 2 * shares.half_width, 1e-14);
    }
    // By hand (r = 1.17084, r^2 = 1.37086): record 0 ([1.3, 20]) covers
    // ln(r^2 / 1.3) / ln r of step 1 ([r, r^2]) and every step above wholly;
    // record 3's island [1.05, 1.0501] is ln(1.0501/1.05) / ln r of step 0.
    EXPECT_NEAR(shares.share[0][1], std::log(r * r / 1.3) / std::log(r), 1e-14);
    EXPECT_EQ(shares.share[0][0], 0.0);
    for (std::size_t j = 2; j < 19; ++j) EXPECT_EQ(shares.share[0][j], 1.0) << j;
    EXPECT_NEAR(shares.share[3][0], std::log(1.0501 / 1.05) / std::log(r), 1e-14);
    // Record 1: [1.15, 1.18] spans steps 0 and 1 (r = 1.1708 between).
    EXPECT_NEAR(shares.share[1][0], std::log(r / 1.15) / std::log(r), 1e-14);
    EXPECT_NEAR(shares.share[1][1], std::log(1.18 / r) / std::log(r), 1e-14);
    const std::vector<Stripe> stripes = stripes_of(shares);
    for (std::size_t j = 0; j < 19; ++j) {
        double z = 0;
        for (const auto& row : shares.share) z += row[j];
        EXPECT_EQ(stripes[j].overturned, z);
        EXPECT_EQ(stripes[j].records, 5.0);
        EXPECT_EQ(stripes[j].q, shares.q[j]);
    }
    // tools/stripe_mle.py --intervals on the same sets, its shares at 40
    // digits: median 2.5684239613393341192, beta 0.7369487032306905568,
    // ln L -37.747546642784967782.
    const StripeFragility f = fit_stripes(stripes);
    EXPECT_NEAR(f.median, 2.5684239613393341192, 1e-12 * 2.57);
    EXPECT_NEAR(f.beta, 0.7369487032306905568, 1e-12);
    EXPECT_NEAR(f.log_likelihood, -37.747546642784967782, 1e-12 * 37.7);
}

TEST(StripeFit, TheBootstrapIsTheIndependentOneAndTheSameUnderItsSeed) {
    std::vector<std::vector<Span>> sets;
    for (const auto& s : kSynthetic) sets.push_back(set_of(s));
    const StripeShares shares = stripe_shares(sets, 1, 20, 20);
    const BootstrapInterval b = bootstrap_stripes(shares, 200, 7, 0.9);
    // tools/stripe_mle.py --intervals with "bootstrap": {"resamples": 200,
    // "seed": 7, "level": 0.9}: GSL's mt19937 rebuilt in Python, the same
    // draws, each resample fitted at 40 digits.
    EXPECT_NEAR(b.median.lo, 1.7889056872993272, 1e-11);
    EXPECT_NEAR(b.median.hi, 3.6989235148907023, 1e-11);
    EXPECT_NEAR(b.beta.lo, 0.33642644273558175, 1e-11);
    EXPECT_NEAR(b.beta.hi, 0.9899419154261698, 1e-11);
    EXPECT_EQ(b.resamples, 200);
    EXPECT_EQ(b.seed, 7u);
    EXPECT_EQ(b.level, 0.9);
    // The same seed: the same interval, bit for bit; another seed: another.
    const BootstrapInterval again = bootstrap_stripes(shares, 200, 7, 0.9);
    EXPECT_EQ(again.median.lo, b.median.lo);
    EXPECT_EQ(again.median.hi, b.median.hi);
    EXPECT_EQ(again.beta.lo, b.beta.lo);
    EXPECT_EQ(again.beta.hi, b.beta.hi);
    const BootstrapInterval other = bootstrap_stripes(shares, 200, 8, 0.9);
    EXPECT_NE(other.median.lo, b.median.lo);
    // Refusals: shares without a maximum, too few resamples, a bad level.
    StripeShares flat = shares;
    for (auto& row : flat.share)
        for (double& s : row) s = 0;
    EXPECT_THROW(bootstrap_stripes(flat, 200, 7, 0.9), std::invalid_argument);
    EXPECT_THROW(bootstrap_stripes(shares, 1, 7, 0.9), std::invalid_argument);
    EXPECT_THROW(bootstrap_stripes(shares, 200, 7, 1.0), std::invalid_argument);
}

TEST(StripeFit, TheBootstrapRedrawsResamplesWithoutAMaximum) {
    // One record overturns from q = 1.3 on (its shares alone step from 0 to
    // 1: no maximum), one never (every share 0): a resample of two copies of
    // either has no maximum; only resamples holding both are fitted, and they
    // are the data themselves, so the interval is one point, the fit.
    std::vector<std::vector<Span>> sets = {set_of({{1.3, 20}}), set_of({})};
    const StripeShares shares = stripe_shares(sets, 1, 20, 20);
    const StripeFragility f = fit_stripes(stripes_of(shares));
    const BootstrapInterval b = bootstrap_stripes(shares, 50, 3, 0.9);
    EXPECT_NEAR(b.median.lo, f.median, 1e-14 * f.median);
    EXPECT_NEAR(b.median.hi, f.median, 1e-14 * f.median);
    EXPECT_NEAR(b.beta.lo, f.beta, 1e-14 * f.beta);
    EXPECT_NEAR(b.beta.hi, f.beta, 1e-14 * f.beta);
}

TEST(StripeFit, TheBootstrapRedrawsResamplesWhoseMedianIsBeyondADouble) {
    // Record A steps from share 0 to 1, records B rise from 1e-3 to `rise`: a
    // resample of B's alone has a maximum of ln L (the shares rise), but its
    // median lies e^(hundreds) out (at 1.008e-3, e^905: beyond a double; at
    // 1.005e-3, further, where Newton's steps stall); of A's alone it has
    // none.  Either is redrawn, so every fitted resample holds 1 or 2 copies
    // of A, and the interval lies between the fits of those two mixtures.
    for (double rise : {1.008e-3, 1.005e-3}) {
        StripeShares shares;
        shares.q = {1, 2};
        shares.from = {0.9, 1.8};
        shares.to = {1.1, 2.2};
        shares.half_width = 0.1;
        shares.share = {{0, 1}, {1e-3, rise}, {1e-3, rise}};
        StripeShares only_b = shares;
        only_b.share = {shares.share[1], shares.share[2]};
        EXPECT_EQ(why_no_stripe_maximum(stripes_of(only_b)), "");
        EXPECT_ANY_THROW(fit_stripes(stripes_of(only_b)));
        std::vector<StripeFragility> mixtures;
        for (int copies_of_a : {1, 2}) {
            StripeShares mix = shares;
            mix.share.clear();
            for (int k = 0; k < 3; ++k) mix.share.push_back(shares.share[k < copies_of_a ? 0 : 1]);
            mixtures.push_back(fit_stripes(stripes_of(mix)));
        }
        const BootstrapInterval b = bootstrap_stripes(shares, 50, 3, 0.9);
        // The percentile interval interpolates between the resamples' fits.
        auto within = [&](double v, double StripeFragility::*field) {
            const double x = mixtures[0].*field, y = mixtures[1].*field;
            return std::isfinite(v) && std::min(x, y) <= v && v <= std::max(x, y);
        };
        EXPECT_TRUE(within(b.median.lo, &StripeFragility::median)) << rise << ": " << b.median.lo;
        EXPECT_TRUE(within(b.median.hi, &StripeFragility::median)) << rise << ": " << b.median.hi;
        EXPECT_TRUE(within(b.beta.lo, &StripeFragility::beta)) << rise << ": " << b.beta.lo;
        EXPECT_TRUE(within(b.beta.hi, &StripeFragility::beta)) << rise << ": " << b.beta.hi;
        EXPECT_LT(b.median.lo, b.median.hi) << rise;  // both mixtures drawn
    }
}

TEST(StripeFit, StripeSharesRefuseBadGrids) {
    const std::vector<std::vector<Span>> one = {set_of({{2, 3}})};
    EXPECT_THROW(stripe_shares({}, 1, 20, 20), std::invalid_argument);
    EXPECT_THROW(stripe_shares(one, 1, 20, 1), std::invalid_argument);
    EXPECT_THROW(stripe_shares(one, 0, 20, 20), std::invalid_argument);
    EXPECT_THROW(stripe_shares(one, 2, 2, 20), std::invalid_argument);
}

namespace {

FragilityStudyOptions refined_options(double q_max, int points, int resamples) {
    FragilityStudyOptions o;
    o.ida.method = IdaOptions::Method::refine;
    o.ida.q_max = q_max;
    o.ida.points = points;
    o.resamples = resamples;
    o.seed = 7;
    o.level = 0.9;
    return o;
}

void expect_same(const BootstrapInterval& a, const BootstrapInterval& b) {
    EXPECT_EQ(a.median.lo, b.median.lo);
    EXPECT_EQ(a.median.hi, b.median.hi);
    EXPECT_EQ(a.beta.lo, b.beta.lo);
    EXPECT_EQ(a.beta.hi, b.beta.hi);
    EXPECT_EQ(a.resamples, b.resamples);
}

}  // namespace

TEST(FragilityThreeWays, SyntheticIdasGiveEachCapacityItsFit) {
    // kSynthetic's sets, with the first robust collapse of a robust width of
    // 0.05 in ln q: [1.15, 1.18] (0.026) and [1.05, 1.0501] are islands.
    const std::vector<double> robust = {1.3, 1.6, 2.2, 4.5, 1.9};
    std::vector<Ida> idas;
    for (std::size_t r = 0; r < kSynthetic.size(); ++r) idas.push_back(synthetic_ida(kSynthetic[r], {robust[r], true}));
    const FragilityStudyOptions o = refined_options(20, 20, 200);
    const BlockFragility f = block_fragility({0.1, 2}, idas, rocking::testing::listed_order(idas.size()), o);
    ASSERT_TRUE(f.three_ways);
    // (a) the first overturning: today's fit and bootstrap of the points.
    std::vector<IdaPoint> first;
    for (const auto& s : kSynthetic) first.push_back({s.front().first, true});
    ASSERT_TRUE(f.fitted);
    EXPECT_EQ(f.fit.median, fit_lognormal(first).median);
    EXPECT_EQ(f.fit.beta, fit_lognormal(first).beta);
    expect_same(f.interval, bootstrap(first, 200, 7, 0.9));
    // (b) the first robust collapse: no record censored, so the closed form
    // (mean and rms of ln q), and the bootstrap of those points.
    ASSERT_TRUE(f.robust.fitted) << f.robust.no_fit;
    double mean = 0, var = 0;
    for (double q : robust) mean += std::log(q) / 5;
    for (double q : robust) var += (std::log(q) - mean) * (std::log(q) - mean) / 5;
    EXPECT_NEAR(f.robust.fit.median, std::exp(mean), 1e-14 * std::exp(mean));
    EXPECT_NEAR(f.robust.fit.beta, std::sqrt(var), 1e-14);
    ASSERT_TRUE(f.robust.bootstrapped);
    std::vector<IdaPoint> robust_points;
    for (double q : robust) robust_points.push_back({q, true});
    expect_same(f.robust.interval, bootstrap(robust_points, 200, 7, 0.9));
    // The first overturning lies at or below the robust collapse record by
    // record, so (a)'s median (the mean of ln q here) lies below (b)'s.
    EXPECT_LT(f.fit.median, f.robust.fit.median);
    // (c) the stripes: tools/stripe_mle.py's fit and bootstrap (above).
    ASSERT_TRUE(f.stripes.fitted) << f.stripes.no_fit;
    EXPECT_NEAR(f.stripes.fit.median, 2.5684239613393341192, 1e-12 * 2.57);
    EXPECT_NEAR(f.stripes.fit.beta, 0.7369487032306905568, 1e-12);
    ASSERT_TRUE(f.stripes.bootstrapped);
    EXPECT_NEAR(f.stripes.interval.median.lo, 1.7889056872993272, 1e-11);
    EXPECT_NEAR(f.stripes.interval.beta.hi, 0.9899419154261698, 1e-11);
    // Each stripe's mean share is at most the share of records whose first
    // overturning lies at or below the stripe's top: a record inside its set
    // at q has overturned at or below q.
    for (std::size_t j = 0; j < f.stripes.stripes.size(); ++j) {
        int below = 0;
        for (const IdaPoint& p : first) below += p.q <= f.stripes.shares.to[j];
        EXPECT_LE(f.stripes.stripes[j].overturned, below) << j;
    }
    // The grid method: the same first-overturning fit, nothing more.
    FragilityStudyOptions grid = o;
    grid.ida.method = IdaOptions::Method::grid;
    const BlockFragility g = block_fragility({0.1, 2}, idas, rocking::testing::listed_order(idas.size()), grid);
    EXPECT_FALSE(g.three_ways);
    EXPECT_FALSE(g.robust.fitted);
    EXPECT_TRUE(g.robust.points.empty());
    EXPECT_FALSE(g.stripes.fitted);
    EXPECT_TRUE(g.stripes.stripes.empty());
    EXPECT_EQ(g.fit.median, f.fit.median);
    expect_same(g.interval, f.interval);
}

TEST(FragilityThreeWays, EachFitSaysWhyNotAlone) {
    // Two records, one overturning from 1.5 on with a robust collapse at 3,
    // one never: (a) and (b) have one collapse below a censored point, a
    // maximum; the stripes step from 0 to 1/2 and stay: a fit.  One record
    // alone: (a) and (b) one collapse, nothing censored above (no maximum),
    // the stripes step from 0 to 1 (no maximum).
    const FragilityStudyOptions o = refined_options(4, 10, 0);
    const BlockFragility one = block_fragility({0.1, 2}, {synthetic_ida({{1.5, 4}}, {3, true})},
                                                rocking::testing::listed_order(1), o);
    EXPECT_FALSE(one.fitted);
    EXPECT_FALSE(one.robust.fitted);
    EXPECT_NE(one.robust.no_fit.find("no censored record lies above it"), std::string::npos) << one.robust.no_fit;
    EXPECT_FALSE(one.stripes.fitted);
    EXPECT_NE(one.stripes.no_fit.find("step from 0 to 1"), std::string::npos) << one.stripes.no_fit;
    const BlockFragility two =
        block_fragility({0.1, 2}, {synthetic_ida({{1.5, 4}}, {3, true}), synthetic_ida({}, {4, false})}, rocking::testing::listed_order(2), o);
    EXPECT_TRUE(two.fitted);
    EXPECT_TRUE(two.robust.fitted);
    EXPECT_FALSE(two.robust.bootstrapped);
    EXPECT_TRUE(two.stripes.fitted) << two.stripes.no_fit;
    EXPECT_FALSE(two.stripes.bootstrapped);
    // No record overturns: none of the three.
    const BlockFragility none = block_fragility({0.1, 2}, {synthetic_ida({}, {4, false}), synthetic_ida({}, {4, false})}, rocking::testing::listed_order(2), o);
    EXPECT_FALSE(none.fitted || none.robust.fitted || none.stripes.fitted);
    EXPECT_NE(none.stripes.no_fit.find("every share 0"), std::string::npos) << none.stripes.no_fit;
}

TEST(FragilityThreeWays, RectangularPulsesGiveTheStripesOfTheirClosedForm) {
    // A record of constant samples is a rectangular pulse of duration d: it
    // overturns the block for every q above q* = 1 / (1 - e^{-p d})
    // (test_overturning_search.cpp), so each record's shares are known in
    // closed form: 0 below q*, 1 above, ln(to / q*) / ln(to / from) in the
    // step holding q*.  Five durations, refine IDAs at w = 1e-3.
    const double alpha = 0.1, p = 2, dt = 0.01;
    const std::vector<int> samples = {31, 41, 51, 81, 121};  // d = 0.3 .. 1.2 s
    FragilityStudyOptions o = refined_options(4, 15, 0);
    o.ida.width = 1e-3;
    std::vector<Ida> idas;
    std::vector<double> known;
    for (int n : samples) {
        const dynamics::SampledInput record(std::vector<double>(n, 0.15), dt, "pulse");
        idas.push_back(incremental_dynamic_analysis(record, alpha, p, o.ida));
        known.push_back(1 / -std::expm1(-p * (n - 1) * dt));
    }
    const BlockFragility f = block_fragility({alpha, p}, idas, rocking::testing::listed_order(idas.size()), o);
    ASSERT_TRUE(f.three_ways);
    std::vector<Stripe> exact = f.stripes.stripes;
    for (std::size_t j = 0; j < exact.size(); ++j) {
        const double from = f.stripes.shares.from[j], to = f.stripes.shares.to[j];
        double z = 0;
        for (std::size_t r = 0; r < known.size(); ++r) {
            ASSERT_EQ(f.idas[r].intervals.size(), 1u) << r;
            const double s = known[r] <= from ? 1 : known[r] >= to ? 0 : std::log(to / known[r]) / std::log(to / from);
            EXPECT_NEAR(f.stripes.shares.share[r][j], s, 2e-6 / std::log(to / from)) << r << " " << j;
            // The stripes' shares are the IDA's bands, bit for bit.
            EXPECT_EQ(f.stripes.shares.share[r][j], f.idas[r].bands[j].share) << r << " " << j;
            z += s;
        }
        exact[j].overturned = z;
    }
    // The fit on the IDAs' stripes against the fit on the closed form's: the
    // brackets (1e-6 relative) move each share by at most 1e-6 / 0.105.
    ASSERT_TRUE(f.stripes.fitted) << f.stripes.no_fit;
    const StripeFragility truth = fit_stripes(exact);
    EXPECT_NEAR(f.stripes.fit.median, truth.median, 1e-5 * truth.median);
    EXPECT_NEAR(f.stripes.fit.beta, truth.beta, 1e-5 * truth.beta);
    // Every set is one interval: the robust collapse is the first overturning.
    ASSERT_TRUE(f.robust.fitted);
    EXPECT_EQ(f.robust.fit.median, f.fit.median);
    EXPECT_EQ(f.robust.fit.beta, f.fit.beta);
}
