#include "studies/stripe_fit.hpp"

#include "numerics/newton_ascent.hpp"

#include <gsl/gsl_sf_erf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "studies/overturning_set.hpp"

namespace rocking::studies {

namespace {

std::string g10(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
}

void check_stripes(const std::vector<Stripe>& stripes) {
    for (std::size_t j = 0; j < stripes.size(); ++j) {
        const Stripe& s = stripes[j];
        if (!(std::isfinite(s.q) && s.q > 0) || (j > 0 && !(s.q > stripes[j - 1].q)))
            throw std::invalid_argument("stripe fit: the stripes' q must be finite, > 0 and increasing (stripe " +
                                        std::to_string(j + 1) + " at q = " + g10(s.q) + ")");
        if (!(std::isfinite(s.records) && s.records >= 1))
            throw std::invalid_argument("stripe fit: stripe " + std::to_string(j + 1) + " has " + g10(s.records) +
                                        " records, not at least 1");
        if (!(s.overturned >= 0 && s.overturned <= s.records))
            throw std::invalid_argument("stripe fit: stripe " + std::to_string(j + 1) + " has " + g10(s.overturned) +
                                        " of " + g10(s.records) + " records overturned, not in [0, " +
                                        g10(s.records) + "]");
    }
}

// ln Phi(u) = ln(erfc(-u / sqrt 2) / 2), without cancellation in either tail.
double log_phi(double u) { return gsl_sf_log_erfc(-u / M_SQRT2) - M_LN2; }

// lambda(u) = phi(u) / Phi(u) (the inverse Mills ratio) = GSL's hazard at
// -u.  Beyond u = 37 Phi is 1 to the last bit and phi underflows, which GSL
// reports as an error its default handler turns into an abort.
double mills(double u) { return u > 37 ? std::exp(-0.5 * u * u) / std::sqrt(2 * M_PI) : gsl_sf_hazard(-u); }

// One stripe's term of (S2) at u: z ln Phi(u) + (n - z) ln Phi(-u); a
// term whose weight is 0 is left out (0 ln 0 is 0 here).
double term(const Stripe& s, double u) {
    double sum = 0;
    if (s.overturned > 0) sum += s.overturned * log_phi(u);
    if (s.records - s.overturned > 0) sum += (s.records - s.overturned) * log_phi(-u);
    return sum;
}

}  // namespace

double stripe_half_width(double q_min, double q_max, int points) {
    return std::log(q_max / q_min) / (2.0 * (points - 1));
}

StripeShares stripe_shares(const std::vector<std::vector<Span>>& sets, double q_min, double q_max, int points) {
    if (sets.empty()) throw std::invalid_argument("stripes: no record");
    if (points < 2) throw std::invalid_argument("stripes: the grid needs at least 2 points");
    if (!(q_min > 0 && std::isfinite(q_max) && q_max > q_min))
        throw std::invalid_argument("stripes: the grid needs 0 < q_min < q_max, finite");
    StripeShares out;
    const std::vector<GridPoint> grid = log_grid(q_min, q_max, points, false, {});
    for (std::size_t k = 1; k < grid.size(); ++k) {
        out.from.push_back(grid[k - 1].x);
        out.to.push_back(grid[k].x);
        out.q.push_back(std::sqrt(grid[k - 1].x * grid[k].x));
    }
    out.half_width = stripe_half_width(q_min, q_max, points);
    for (const std::vector<Span>& set : sets) {
        std::vector<double> row;
        for (std::size_t j = 0; j < out.q.size(); ++j) row.push_back(covered_share(set, out.from[j], out.to[j]));
        out.share.push_back(std::move(row));
    }
    return out;
}

std::vector<Stripe> stripes_of(const StripeShares& shares) {
    std::vector<Stripe> out;
    for (std::size_t j = 0; j < shares.q.size(); ++j) {
        double z = 0;
        for (const std::vector<double>& row : shares.share) z += row[j];
        out.push_back({shares.q[j], static_cast<double>(shares.share.size()), z});
    }
    return out;
}

double stripe_log_likelihood(const std::vector<Stripe>& stripes, double median, double beta) {
    double sum = 0;
    for (const Stripe& s : stripes) sum += term(s, std::log(s.q / median) / beta);
    return sum;
}

std::string why_no_stripe_maximum(const std::vector<Stripe>& stripes) {
    check_stripes(stripes);
    bool any_overturned = false, any_safe = false;
    double max_f = -INFINITY, min_s = INFINITY;  // the highest stripe not wholly overturned, the lowest overturned at all
    for (const Stripe& s : stripes) {
        if (s.overturned > 0) any_overturned = true, min_s = std::min(min_s, s.q);
        if (s.overturned < s.records) any_safe = true, max_f = std::max(max_f, s.q);
    }
    if (!any_overturned)
        return "no record overturns anywhere in the stripes' neighbourhoods (every share 0): ln L rises towards 0 as "
               "the median grows";
    if (!any_safe)
        return "every record overturns over every stripe's whole neighbourhood (every share 1): ln L rises towards 0 "
               "as the median falls";
    if (stripes.size() == 1)
        return "one stripe (at q = " + g10(stripes.front().q) + "): its share fixes one point of the curve, not the "
               "median and beta";
    if (max_f <= min_s)
        return "the shares step from 0 to 1 at q = " + g10(max_f) + (max_f < min_s ? " to " + g10(min_s) : "") +
               " (every stripe below overturns nowhere, every stripe above everywhere): ln L rises as beta -> 0 "
               "with the median at the step (a perfect separation)";
    double trend = 0;  // (S5)
    for (std::size_t i = 0; i < stripes.size(); ++i)
        for (std::size_t j = i + 1; j < stripes.size(); ++j) {
            const Stripe &a = stripes[i], &b = stripes[j];
            const double rise = b.overturned / b.records - a.overturned / a.records;
            if (rise != 0) trend += a.records * b.records * std::log(b.q / a.q) * rise;
        }
    if (!(trend > 0))
        return "the overturned share does not rise with q (the records-weighted covariance of ln q and the share is "
               "not > 0): ln L rises as beta -> infinity, towards one share at every q";
    return "";
}

StripeFragility fit_stripes(const std::vector<Stripe>& stripes) {
    const std::string why = why_no_stripe_maximum(stripes);
    if (!why.empty()) throw std::invalid_argument("stripe fit: " + why);
    // ln q about the records-weighted mean: u_j = a y_j - b then holds its
    // digits where the stripes lie close together.
    double n = 0, x_ref = 0;
    for (const Stripe& s : stripes) n += s.records, x_ref += s.records * std::log(s.q);
    x_ref /= n;
    std::vector<double> y;
    double spread = 0;
    for (const Stripe& s : stripes) {
        y.push_back(std::log(s.q) - x_ref);
        spread += s.records * y.back() * y.back();
    }
    double a = 1 / std::sqrt(spread / n), b = 0;
    const auto lnl = [&](double aa, double bb) {
        double sum = 0;
        for (std::size_t j = 0; j < stripes.size(); ++j) sum += term(stripes[j], aa * y[j] - bb);
        return sum;
    };
    // d ln L/du_j = z lambda(u) - (n - z) lambda(-u);
    // d^2 ln L/du_j^2 = -z lambda(u)(u + lambda(u)) - (n - z) lambda(-u)(lambda(-u) - u) < 0;
    // du/da = y_j, du/db = -1.
    const auto slopes = [&](double aa, double bb) {
        numerics::Slopes2 d;
        for (std::size_t j = 0; j < stripes.size(); ++j) {
            const Stripe& s = stripes[j];
            const double u = aa * y[j] - bb;
            double g = 0, h = 0;
            if (s.overturned > 0) {
                const double l = mills(u);
                g += s.overturned * l;
                h -= s.overturned * l * (u + l);
            }
            if (s.records - s.overturned > 0) {
                const double l = mills(-u);
                g -= (s.records - s.overturned) * l;
                h -= (s.records - s.overturned) * l * (l - u);
            }
            d.g_a += g * y[j];
            d.g_b -= g;
            d.h_aa += h * y[j] * y[j];
            d.h_ab -= h * y[j];
            d.h_bb += h;
        }
        return d;
    };
    numerics::newton_ascent(lnl, slopes, a, b, "stripe fit");
    StripeFragility out;
    out.beta = 1 / a;
    out.median = std::exp(x_ref + b / a);
    if (!(std::isfinite(out.median) && out.median > 0 && std::isfinite(out.beta)))
        throw std::invalid_argument("stripe fit: the fitted median, e^" + g10(x_ref + b / a) +
                                    ", is beyond a double");
    out.log_likelihood = lnl(a, b);
    out.stripes = static_cast<int>(stripes.size());
    return out;
}

BootstrapInterval bootstrap_stripes(const StripeShares& shares, int resamples, std::uint64_t seed, double level) {
    if (resamples < 2) throw std::invalid_argument("stripe bootstrap: at least 2 resamples");
    if (!(level > 0 && level < 1)) throw std::invalid_argument("stripe bootstrap: the level must be in (0, 1)");
    const std::string why = why_no_stripe_maximum(stripes_of(shares));
    if (!why.empty()) throw std::invalid_argument("stripe bootstrap: " + why);
    const std::size_t records = shares.share.size();
    SeededRng rng(seed);
    std::vector<double> medians, betas;
    StripeShares draw = shares;
    for (long attempts = 0; static_cast<int>(medians.size()) < resamples; ++attempts) {
        if (attempts > 100L * resamples)
            throw std::invalid_argument("stripe bootstrap: fewer than 1 in 100 resamples have a maximum of ln L within a double; too "
                                        "few records overturn, or overturn alike, to resample");
        for (std::size_t r = 0; r < records; ++r) draw.share[r] = shares.share[rng.index(records)];
        const std::vector<Stripe> stripes = stripes_of(draw);
        if (!why_no_stripe_maximum(stripes).empty()) continue;
        // A resample can have a maximum no double holds: its median e^(hundreds)
        // out (fit_stripes refuses it), or further, where Newton's steps stall
        // on the flat ln L.  The whole sample's fit succeeded, so such a
        // resample is redrawn as one without a maximum is, not the study lost.
        StripeFragility f;
        try {
            f = fit_stripes(stripes);
        } catch (const std::exception&) {
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

}  // namespace rocking::studies
