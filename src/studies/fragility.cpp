#include "studies/fragility.hpp"

#include "numerics/newton_ascent.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sf_erf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace rocking::studies {

namespace {

void check_points(const std::vector<IdaPoint>& points) {
    for (const IdaPoint& p : points)
        if (!(std::isfinite(p.q) && p.q > 0))
            throw std::invalid_argument("fragility: every q must be finite and > 0 (got " + std::to_string(p.q) + ")");
}

std::string g10(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
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

// ln(q / reference) without the rounding of ln q - ln reference: near the
// reference q - reference is exact (Sterbenz), so a q that differs from it
// gives a deviation that is not 0 and holds all its digits.
double log_ratio(double q, double reference) {
    if (q >= 0.5 * reference && q <= 2 * reference) return std::log1p((q - reference) / reference);
    return std::log(q) - std::log(reference);
}

// The closed form of the likelihood's maximum on the collapsed points (with
// every point, censored ones too, where `all` is set): the mean and rms of
// ln q, taken about one of the q, so that beta is 0 exactly when every q is
// equal and otherwise their spread to rounding, never rounding alone.
void moments(const std::vector<IdaPoint>& points, bool all, double& mu, double& beta) {
    double reference = 0, sum = 0, sum2 = 0;
    int n = 0;
    for (const IdaPoint& p : points)
        if (all || p.collapsed) {
            if (n == 0) reference = p.q;
            sum += log_ratio(p.q, reference), ++n;
        }
    const double mean = sum / n;
    for (const IdaPoint& p : points)
        if (all || p.collapsed) sum2 += (log_ratio(p.q, reference) - mean) * (log_ratio(p.q, reference) - mean);
    mu = std::log(reference) + mean;
    beta = std::sqrt(sum2 / n);
}

// phi(z)/Q(z).  Below z = -37 Q is 1 to the last bit and phi underflows
// there, which GSL reports as an error (its default handler aborts):
// a censored point far below the median on Newton's way.
double normal_hazard(double z) {
    return z < -37 ? std::exp(-0.5 * z * z) / std::sqrt(2 * M_PI) : gsl_sf_hazard(z);
}

// With censored points, Newton's method in Olsen's (1978) parameters
// theta = 1/beta, gamma = mu/beta, where z_i = theta ln q_i - gamma and
//     ln L = sum_collapsed [ln theta - z_i^2/2 - ln q_i - ln(2 pi)/2] + sum_censored ln Q(z_i)
// is concave (Olsen's theorem for the censored normal), so Newton with a
// step halved until ln L does not fall reaches the one maximum from the
// collapsed points' closed form (from every point's where the collapses
// share one q; any start with beta > 0 will do).  A simplex took ~30 times as many
// evaluations of ln L, and a bootstrap fits thousands of resamples.
// Derivatives: d ln Q(z)/dz = -h(z), d^2/dz^2 = -h(z)(h(z) - z), with the
// normal hazard h = phi/Q (GSL's gsl_sf_hazard, accurate for large z).
void maximise_with_censoring(const std::vector<IdaPoint>& points, double& mu, double& beta) {
    // ln q about one collapsed q: with ln q itself, z = theta ln q - gamma
    // cancels (to 5 digits where the q lie 1e-4 apart), so that rounding hid
    // the last steps and Newton never met its 1e-13.
    double reference = 0;
    for (const IdaPoint& p : points)
        if (p.collapsed && reference == 0) reference = p.q;
    std::vector<double> y(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) y[k] = log_ratio(points[k].q, reference);
    double theta = 1 / beta, gamma = (mu - std::log(reference)) / beta;
    // ln L less the terms that do not depend on (theta, gamma).
    auto lnl = [&](double th, double ga) {
        double sum = 0;
        for (std::size_t k = 0; k < points.size(); ++k) {
            const double z = th * y[k] - ga;
            sum += points[k].collapsed ? std::log(th) - 0.5 * z * z : gsl_sf_log_erfc(z / M_SQRT2);
        }
        return sum;
    };
    const auto slopes = [&](double th, double ga) {
        numerics::Slopes2 d;
        for (std::size_t k = 0; k < points.size(); ++k) {
            const double z = th * y[k] - ga;
            if (points[k].collapsed) {
                d.g_a += 1 / th - z * y[k];
                d.g_b += z;
                d.h_aa -= 1 / (th * th) + y[k] * y[k];
                d.h_ab += y[k];
                d.h_bb -= 1;
            } else {
                const double h = normal_hazard(z), c = h * (h - z);
                d.g_a -= h * y[k];
                d.g_b += h;
                d.h_aa -= c * y[k] * y[k];
                d.h_ab += c * y[k];
                d.h_bb -= c;
            }
        }
        return d;
    };
    numerics::newton_ascent(lnl, slopes, theta, gamma, "fragility");
    mu = std::log(reference) + gamma / theta;
    beta = 1 / theta;
}

}  // namespace

double overturning_probability(const LognormalFragility& f, double q) {
    return gsl_cdf_ugaussian_P(std::log(q / f.median) / f.beta);
}

double log_likelihood(const std::vector<IdaPoint>& points, const LognormalFragility& f) {
    return log_likelihood(points, std::log(f.median), f.beta);
}

bool all_collapses_equal(const std::vector<IdaPoint>& points) {
    const IdaPoint* first = nullptr;
    for (const IdaPoint& p : points) {
        if (!p.collapsed) continue;
        if (!first) first = &p;
        else if (p.q != first->q) return false;
    }
    return first != nullptr;
}

std::string why_no_maximum(const std::vector<IdaPoint>& points) {
    double c = 0, censored_max = 0;
    bool any_collapsed = false;
    for (const IdaPoint& p : points) {
        if (p.collapsed) c = p.q, any_collapsed = true;
        else censored_max = std::max(censored_max, p.q);
    }
    if (!any_collapsed) return "no record overturned (every point is censored): ln L has no maximum";
    if (all_collapses_equal(points) && !(censored_max > c))
        return "every record that overturned did so at the same q = " + g10(c) +
               " and no censored record lies above it: ln L grows without bound as beta -> 0 (no spread to fit)";
    return "";
}

LognormalFragility fit_lognormal(const std::vector<IdaPoint>& points) {
    check_points(points);
    const std::string why = why_no_maximum(points);
    if (!why.empty()) throw std::invalid_argument("fragility: " + why);
    LognormalFragility out;
    for (const IdaPoint& p : points) (p.collapsed ? out.collapsed : out.censored) += 1;
    double mu = 0, beta = 0;
    // Equal collapses have no spread of their own: Newton starts from all
    // the points' (a censored one lies above them, so beta > 0).
    moments(points, all_collapses_equal(points), mu, beta);
    if (out.censored > 0) maximise_with_censoring(points, mu, beta);
    out.median = std::exp(mu);
    if (!std::isfinite(out.median))  // censored points far above so few collapses, at beta in the hundreds
        throw std::invalid_argument("fragility: the fitted median, e^" + g10(mu) + ", is beyond a double");
    out.beta = beta;
    out.log_likelihood = log_likelihood(points, mu, beta);
    return out;
}

BootstrapInterval bootstrap(const std::vector<IdaPoint>& points, int resamples, std::uint64_t seed, double level) {
    check_points(points);
    if (resamples < 2) throw std::invalid_argument("fragility bootstrap: at least 2 resamples");
    if (!(level > 0 && level < 1)) throw std::invalid_argument("fragility bootstrap: the level must be in (0, 1)");
    const std::string why = why_no_maximum(points);
    if (!why.empty()) throw std::invalid_argument("fragility bootstrap: " + why);
    SeededRng rng(seed);
    std::vector<double> medians, betas;
    std::vector<IdaPoint> draw(points.size());
    for (long attempts = 0; static_cast<int>(medians.size()) < resamples; ++attempts) {
        if (attempts > 100L * resamples)
            throw std::invalid_argument("fragility bootstrap: fewer than 1 in 100 resamples have a maximum of ln L within a double "
                                        "(two distinct overturning q, or one below a censored record); too few "
                                        "records overturned to resample");
        for (IdaPoint& d : draw) d = points[rng.index(points.size())];
        if (!why_no_maximum(draw).empty()) continue;
        // A resample can have a maximum no double holds (one overturning under
        // censored records far above it: a median of e^(hundreds)); the whole
        // sample's fit succeeded, so it is redrawn as one without a maximum is.
        LognormalFragility f;
        try {
            f = fit_lognormal(draw);
        } catch (const std::invalid_argument&) {
            continue;
        }
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
