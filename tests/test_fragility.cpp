// The fragility fit against data drawn from a known lognormal (GSL's
// seeded generators: the same draws on any machine), with and without
// censoring, its closed form, and the bootstrap's coverage.
#include <gtest/gtest.h>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include <cmath>
#include <memory>
#include <vector>

#include "studies/fragility.hpp"
#include "test_util.hpp"

using namespace rocking::studies;

namespace {

using Rng = std::unique_ptr<gsl_rng, decltype(&gsl_rng_free)>;

Rng seeded(unsigned long seed) {
    Rng r(gsl_rng_alloc(gsl_rng_mt19937), gsl_rng_free);
    gsl_rng_set(r.get(), seed);
    return r;
}

// n records whose collapse q is lognormal(median, beta); those above q_max
// did not overturn within the scan: censored at q_max.
std::vector<IdaPoint> draw(int n, double median, double beta, double q_max, unsigned long seed) {
    Rng rng = seeded(seed);
    std::vector<IdaPoint> points;
    for (int k = 0; k < n; ++k) {
        const double q = gsl_ran_lognormal(rng.get(), std::log(median), beta);
        points.push_back(q <= q_max ? IdaPoint{q, true} : IdaPoint{q_max, false});
    }
    return points;
}

}  // namespace

TEST(Fragility, AFitOnLognormalDrawsRecoversItsParameters) {
    // n = 4000 draws of median 2, beta 0.4: the fit within 5 standard errors,
    // beta / sqrt(n) on ln median and beta / sqrt(2 n) on beta.
    const int n = 4000;
    const LognormalFragility f = fit_lognormal(draw(n, 2.0, 0.4, INFINITY, 11));
    EXPECT_NEAR(std::log(f.median), std::log(2.0), 5 * 0.4 / std::sqrt(n));
    EXPECT_NEAR(f.beta, 0.4, 5 * 0.4 / std::sqrt(2.0 * n));
    EXPECT_EQ(f.collapsed, n);
    EXPECT_EQ(f.censored, 0);
}

TEST(Fragility, WithoutCensoringTheFitIsTheMomentsOfLnQ) {
    const std::vector<IdaPoint> points{{1.0, true}, {2.0, true}, {4.0, true}, {3.0, true}};
    double mean = 0, var = 0;
    for (const IdaPoint& p : points) mean += std::log(p.q) / 4;
    for (const IdaPoint& p : points) var += (std::log(p.q) - mean) * (std::log(p.q) - mean) / 4;
    const LognormalFragility f = fit_lognormal(points);
    EXPECT_NEAR(f.median, std::exp(mean), 1e-14);
    EXPECT_NEAR(f.beta, std::sqrt(var), 1e-14);
    EXPECT_NEAR(overturning_probability(f, f.median), 0.5, 1e-15);
    EXPECT_NEAR(overturning_probability(f, f.median * std::exp(f.beta)), gsl_cdf_ugaussian_P(1.0), 1e-15);
}

TEST(Fragility, CensoredRecordsAreKeptNotDropped) {
    // 40 % of the records never overturn up to q = 2.4 (median 2, beta 0.5):
    // the likelihood with their censored term recovers the parameters; fitting
    // the overturned ones alone is biased low by many standard errors (the
    // test would not tell the two apart otherwise).
    const int n = 4000;
    const std::vector<IdaPoint> points = draw(n, 2.0, 0.5, 2.4, 12);
    const LognormalFragility f = fit_lognormal(points);
    ASSERT_GT(f.censored, n / 4);
    const double se = 0.5 / std::sqrt(f.collapsed);
    EXPECT_NEAR(std::log(f.median), std::log(2.0), 6 * se);
    EXPECT_NEAR(f.beta, 0.5, 6 * se);
    std::vector<IdaPoint> overturned;
    for (const IdaPoint& p : points)
        if (p.collapsed) overturned.push_back(p);
    const LognormalFragility naive = fit_lognormal(overturned);
    EXPECT_GT(std::fabs(std::log(naive.median) - std::log(2.0)), 10 * se);
    // The fit is the likelihood's maximum: a step off it in any direction lowers it.
    for (double dm : {-1e-4, 1e-4})
        for (double db : {-1e-4, 0.0, 1e-4}) {
            LognormalFragility off = f;
            off.median *= std::exp(dm);
            off.beta *= std::exp(db);
            EXPECT_GT(f.log_likelihood, log_likelihood(points, off)) << dm << " " << db;
        }
}

TEST(Fragility, TheCensoredFitSolvesTheScoreEquationsToRounding) {
    // At the maximum both scores vanish.  They are evaluated here in long
    // double in the fit's own parameters (mu, beta), another form than the
    // solver's (1/beta, mu/beta), with ln Q from std::erfc:
    //     d lnL/d mu   = sum_c z/beta + sum_cens h(z)/beta,
    //     d lnL/d beta = sum_c (z^2 - 1)/beta + sum_cens z h(z)/beta,  h = phi/Q.
    // Each is a sum of n terms ~1/beta; at a fit 1e-7 off (the simplex this
    // replaced stopped there) they are ~1e-5 x n, here below 1e-10 x n.
    // Also with the censored points at different q and some censored below
    // the lowest collapse, where the closed form start is far off.
    for (int set = 0; set < 3; ++set) {
        std::vector<IdaPoint> points = draw(60 + 40 * set, 1.2 + set, 0.25 + 0.2 * set, 1.5 + set, 40 + set);
        if (set == 2)
            for (std::size_t k = 0; k < points.size(); k += 9) points[k] = {0.9 + 0.01 * k, false};
        const LognormalFragility f = fit_lognormal(points);
        ASSERT_GT(f.censored, 3);
        const long double mu = std::log(static_cast<long double>(f.median)), beta = f.beta;
        long double d_mu = 0, d_beta = 0;
        for (const IdaPoint& p : points) {
            const long double z = (std::log(static_cast<long double>(p.q)) - mu) / beta;
            if (p.collapsed) {
                d_mu += z / beta;
                d_beta += (z * z - 1) / beta;
            } else {
                const long double h =
                    std::exp(-z * z / 2) / std::sqrt(2 * static_cast<long double>(M_PI)) / (std::erfc(z / std::sqrt(2.0L)) / 2);
                d_mu += h / beta;
                d_beta += z * h / beta;
            }
        }
        const double scale = points.size() / f.beta;
        EXPECT_LT(std::fabs(static_cast<double>(d_mu)), 1e-10 * scale) << "set " << set;
        EXPECT_LT(std::fabs(static_cast<double>(d_beta)), 1e-10 * scale) << "set " << set;
    }
}

TEST(Fragility, TheBootstrapIsReproducibleAndCoversTheTruth) {
    // Same seed, same interval; and over 200 experiments of 40 records the
    // 90 % interval holds the true median in 80-97 % of them (percentile
    // intervals under-cover a little at n = 40; a wrong resampling, e.g. of
    // a fixed subset, covers far less).
    const std::vector<IdaPoint> points = draw(40, 1.5, 0.3, INFINITY, 13);
    const BootstrapInterval a = bootstrap(points, 300, 99, 0.9), b = bootstrap(points, 300, 99, 0.9);
    EXPECT_EQ(a.median.lo, b.median.lo);
    EXPECT_EQ(a.beta.hi, b.beta.hi);
    EXPECT_LT(a.median.lo, a.median.hi);
    int covered = 0;
    for (int e = 0; e < 200; ++e) {
        const BootstrapInterval i = bootstrap(draw(40, 1.5, 0.3, INFINITY, 1000 + e), 200, 5000 + e, 0.9);
        covered += i.median.lo <= 1.5 && 1.5 <= i.median.hi;
    }
    EXPECT_GE(covered, 160);
    EXPECT_LE(covered, 194);
}

TEST(Fragility, TheEmpiricalCurveCountsEveryRecord) {
    const std::vector<IdaPoint> points{{3.0, true}, {1.0, true}, {5.0, false}, {2.0, true}};
    const std::vector<EmpiricalPoint> c = empirical_curve(points);
    ASSERT_EQ(c.size(), 3u);
    EXPECT_EQ(c[0].q, 1.0);
    EXPECT_EQ(c[2].q, 3.0);
    EXPECT_DOUBLE_EQ(c[2].share, 0.75);  // 3 of the 4 records, the censored one included in the count
}

TEST(Fragility, BadPointsAreRefused) {
    using rocking::testing::error_of;
    EXPECT_NE(error_of([] { fit_lognormal({{1.0, true}, {2.0, false}}); }).find("at least 2"), std::string::npos);
    EXPECT_NE(error_of([] { fit_lognormal({{1.0, true}, {-2.0, true}}); }).find("finite and > 0"), std::string::npos);
    EXPECT_NE(error_of([] { fit_lognormal({{1.0, true}, {1.0, true}}); }).find("beta is 0"), std::string::npos);
    EXPECT_NE(error_of([] { bootstrap({{1.0, true}, {2.0, true}}, 100, 1, 1.5); }).find("level"), std::string::npos);
}
