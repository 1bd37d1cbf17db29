#include "studies/fragility.hpp"

#include <gsl/gsl_cdf.h>
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

// With censored points, Newton's method in Olsen's (1978) parameters
// theta = 1/beta, gamma = mu/beta, where z_i = theta ln q_i - gamma and
//     ln L = sum_collapsed [ln theta - z_i^2/2 - ln q_i - ln(2 pi)/2] + sum_censored ln Q(z_i)
// is concave (Olsen's theorem for the censored normal), so Newton with a
// step halved until ln L does not fall reaches the one maximum from the
// collapsed points' closed form.  A simplex took ~30 times as many
// evaluations of ln L, and a bootstrap fits thousands of resamples.
// Derivatives: d ln Q(z)/dz = -h(z), d^2/dz^2 = -h(z)(h(z) - z), with the
// normal hazard h = phi/Q (GSL's gsl_sf_hazard, accurate for large z).
void maximise_with_censoring(const std::vector<IdaPoint>& points, double& mu, double& beta) {
    double theta = 1 / beta, gamma = mu / beta;
    auto lnl = [&](double th, double ga) { return log_likelihood(points, ga / th, 1 / th); };
    double current = lnl(theta, gamma);
    for (int iteration = 0; iteration < 200; ++iteration) {
        double g_th = 0, g_ga = 0, h_thth = 0, h_thga = 0, h_gaga = 0;
        for (const IdaPoint& p : points) {
            const double y = std::log(p.q), z = theta * y - gamma;
            if (p.collapsed) {
                g_th += 1 / theta - z * y;
                g_ga += z;
                h_thth -= 1 / (theta * theta) + y * y;
                h_thga += y;
                h_gaga -= 1;
            } else {
                const double h = gsl_sf_hazard(z), c = h * (h - z);
                g_th -= h * y;
                g_ga += h;
                h_thth -= c * y * y;
                h_thga += c * y;
                h_gaga -= c;
            }
        }
        // The Newton step solves H d = -g (H negative definite).
        const double det = h_thth * h_gaga - h_thga * h_thga;
        if (!(det > 0)) break;  // not concave here: only rounding at the maximum does this
        double d_th = (-g_th * h_gaga + g_ga * h_thga) / det, d_ga = (-g_ga * h_thth + g_th * h_thga) / det;
        // Converged: Newton's last steps shrink quadratically, and one this
        // small moves ln L by less than its rounding, so the search below
        // could not tell up from down.
        if (std::fabs(d_th) <= 1e-13 * theta && std::fabs(d_ga) <= 1e-13 * std::max(1.0, std::fabs(gamma))) {
            theta += d_th;
            gamma += d_ga;
            break;
        }
        // Halve the step until ln L does not fall and theta stays > 0.
        double next = -INFINITY;
        for (int halving = 0; halving < 60; ++halving) {
            if (theta + d_th > 0) {
                next = lnl(theta + d_th, gamma + d_ga);
                if (next >= current) break;
            }
            d_th *= 0.5;
            d_ga *= 0.5;
        }
        if (!(next >= current)) break;  // no step up: at the maximum to rounding
        theta += d_th;
        gamma += d_ga;
        current = next;
    }
    mu = gamma / theta;
    beta = 1 / theta;
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
