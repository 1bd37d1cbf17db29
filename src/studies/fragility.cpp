#include "studies/fragility.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_multimin.h>
#include <gsl/gsl_sf_erf.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace rocking::studies {

namespace {

void check_points(const std::vector<IdaPoint>& points) {
    int collapsed = 0;
    for (const IdaPoint& p : points) {
        if (!(std::isfinite(p.q) && p.q > 0))
            throw std::invalid_argument("fragility: every q must be finite and > 0 (got " + std::to_string(p.q) + ")");
        collapsed += p.collapsed;
    }
    if (collapsed < 2)
        throw std::invalid_argument("fragility: a lognormal fit needs at least 2 records that overturned (got " +
                                    std::to_string(collapsed) + ")");
}

// ln L of (F1) at (mu, beta) = (ln median, beta): Baker 2015's likelihood
// for IDA with right-censored records.
double log_likelihood(const std::vector<IdaPoint>& points, double mu, double beta) {
    const double half_log_2pi = 0.5 * std::log(2.0 * M_PI);
    double sum = 0;
    for (const IdaPoint& p : points) {
        const double z = (std::log(p.q) - mu) / beta;
        // ln(1 - Phi(z)) = ln(erfc(z / sqrt 2) / 2), without cancellation for large z.
        sum += p.collapsed ? -0.5 * z * z - half_log_2pi - std::log(beta) - std::log(p.q)
                           : gsl_sf_log_erfc(z / M_SQRT2) - M_LN2;
    }
    return sum;
}

// The closed form of the likelihood's maximum on collapsed points alone.
void moments(const std::vector<IdaPoint>& points, double& mu, double& beta) {
    double sum = 0, sum2 = 0;
    int n = 0;
    for (const IdaPoint& p : points)
        if (p.collapsed) sum += std::log(p.q), ++n;
    mu = sum / n;
    for (const IdaPoint& p : points)
        if (p.collapsed) sum2 += (std::log(p.q) - mu) * (std::log(p.q) - mu);
    beta = std::sqrt(sum2 / n);
}

struct Objective {
    const std::vector<IdaPoint>* points;
};

// -ln L in (mu, ln beta): the dispersion stays positive without a constraint.
double minus_log_likelihood(const gsl_vector* v, void* params) {
    const auto* o = static_cast<const Objective*>(params);
    return -log_likelihood(*o->points, gsl_vector_get(v, 0), std::exp(gsl_vector_get(v, 1)));
}

void maximise_with_censoring(const std::vector<IdaPoint>& points, double& mu, double& beta) {
    Objective objective{&points};
    gsl_multimin_function f{&minus_log_likelihood, 2, &objective};
    std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> x(gsl_vector_alloc(2), gsl_vector_free),
        step(gsl_vector_alloc(2), gsl_vector_free);
    gsl_vector_set(x.get(), 0, mu);
    gsl_vector_set(x.get(), 1, std::log(std::max(beta, 1e-3)));
    gsl_vector_set_all(step.get(), 0.1);
    std::unique_ptr<gsl_multimin_fminimizer, decltype(&gsl_multimin_fminimizer_free)> s(
        gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, 2), gsl_multimin_fminimizer_free);
    gsl_multimin_fminimizer_set(s.get(), &f, x.get(), step.get());
    // The simplex's size in (ln median, ln beta) down to 1e-12: relative
    // precision of median and beta far below any record set's sampling error.
    for (int k = 0; k < 10000; ++k) {
        if (gsl_multimin_fminimizer_iterate(s.get())) break;
        if (gsl_multimin_test_size(gsl_multimin_fminimizer_size(s.get()), 1e-12) == GSL_SUCCESS) break;
    }
    mu = gsl_vector_get(s->x, 0);
    beta = std::exp(gsl_vector_get(s->x, 1));
}

}  // namespace

double overturning_probability(const LognormalFragility& f, double q) {
    return gsl_cdf_ugaussian_P(std::log(q / f.median) / f.beta);
}

double log_likelihood(const std::vector<IdaPoint>& points, const LognormalFragility& f) {
    return log_likelihood(points, std::log(f.median), f.beta);
}

LognormalFragility fit_lognormal(const std::vector<IdaPoint>& points) {
    check_points(points);
    LognormalFragility out;
    for (const IdaPoint& p : points) (p.collapsed ? out.collapsed : out.censored) += 1;
    double mu = 0, beta = 0;
    moments(points, mu, beta);
    if (!(beta > 0)) throw std::invalid_argument("fragility: every record overturned at the same q; beta is 0");
    if (out.censored > 0) maximise_with_censoring(points, mu, beta);
    out.median = std::exp(mu);
    out.beta = beta;
    out.log_likelihood = log_likelihood(points, mu, beta);
    return out;
}

BootstrapInterval bootstrap(const std::vector<IdaPoint>& points, int resamples, std::uint64_t seed, double level) {
    check_points(points);
    if (resamples < 2) throw std::invalid_argument("fragility bootstrap: at least 2 resamples");
    if (!(level > 0 && level < 1)) throw std::invalid_argument("fragility bootstrap: the level must be in (0, 1)");
    SeededRng rng(seed);
    std::vector<double> medians, betas;
    std::vector<IdaPoint> draw(points.size());
    for (long attempts = 0; static_cast<int>(medians.size()) < resamples; ++attempts) {
        if (attempts > 100L * resamples)
            throw std::invalid_argument("fragility bootstrap: fewer than 1 in 100 resamples hold 2 distinct "
                                        "overturning records; too few records overturned to resample");
        int collapsed = 0;
        for (IdaPoint& d : draw) {
            d = points[rng.index(points.size())];
            collapsed += d.collapsed;
        }
        double mu = 0, beta = 0;
        if (collapsed < 2) continue;
        moments(draw, mu, beta);
        if (!(beta > 0)) continue;  // every draw of the same record: no spread to fit
        const LognormalFragility f = fit_lognormal(draw);
        medians.push_back(f.median);
        betas.push_back(f.beta);
    }
    BootstrapInterval out;
    out.median = percentile_interval(medians, level);
    out.beta = percentile_interval(betas, level);
    out.resamples = resamples;
    out.seed = seed;
    out.level = level;
    return out;
}

std::vector<EmpiricalPoint> empirical_curve(const std::vector<IdaPoint>& points) {
    std::vector<double> q;
    for (const IdaPoint& p : points)
        if (p.collapsed) q.push_back(p.q);
    std::sort(q.begin(), q.end());
    std::vector<EmpiricalPoint> out;
    for (std::size_t k = 0; k < q.size(); ++k) out.push_back({q[k], static_cast<double>(k + 1) / points.size()});
    return out;
}

}  // namespace rocking::studies
