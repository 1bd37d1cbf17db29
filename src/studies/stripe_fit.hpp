// The multiple-stripe fragility fit (Baker 2015, "Efficient analytical
// fragility function fitting using dynamic structural analysis", Earthquake
// Spectra 31, the fit to multiple stripe analysis data), made from IDAs whose
// whole overturning set in q is known (issue 39, studies/overturning_set.hpp).
//
// A record's overturning set is a union of intervals, not a threshold: a
// stronger input can throw the block back.  So at each intensity stripe q_j a
// record contributes the share of a neighbourhood of q_j (a band in ln q) that
// its set covers, and the stripe's count of records that overturn is the sum
// of those shares over the n_j records,
//     z_j = sum_r s_rj = n_j * (mean share at stripe j).                (S1)
// The lognormal (F1 of fragility.hpp) is fitted by the binomial likelihood,
//     ln L = sum_j [ z_j ln Phi(u_j) + (n_j - z_j) ln Phi(-u_j) ],
//     u_j = ln(q_j / median) / beta,                                   (S2)
// Baker's multiple-stripe likelihood less its binomial coefficients (they do
// not depend on median and beta); with a real z_j it is Papke and
// Wooldridge's (1996) Bernoulli quasi-likelihood for a fractional response,
// whose maximum is consistent for the mean share.  The records are the same at
// every stripe, so the stripes are not independent binomial draws: the
// interval is a bootstrap over records, as fragility.hpp's.
// Derivations and the conditions for a maximum: docs/fragility.md, "Three
// capacities".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "studies/fragility.hpp"
#include "studies/intervals.hpp"
#include "studies/resampling.hpp"

namespace rocking::studies {

// One stripe: its intensity, how many records were run at it and how many
// overturned (a real number, (S1)).
struct Stripe {
    double q = 0;
    double records = 0;     // n_j
    double overturned = 0;  // z_j, in [0, n_j]
};

// The stripes of a main grid of `points` q log-spaced from q_min to q_max
// (log_grid, as the IDA's), and every record's share at each.  Stripe j
// (j = 1 .. points - 1) is the main grid's step [q_{j-1}, q_j]: its
// intensity the step's geometric midpoint sqrt(q_{j-1} q_j), its
// neighbourhood the step itself, of half-width
//     h = ln(q_max / q_min) / (2 (points - 1))  in ln q,               (S3)
// so that the stripes tile [q_min, q_max] and each record's share at a
// stripe is its IDA's overturned share of that band (Ida::bands).
struct StripeShares {
    std::vector<double> q, from, to;         // each stripe's intensity and neighbourhood
    std::vector<std::vector<double>> share;  // share[r][j]: record r's covered share of stripe j's neighbourhood
    double half_width = 0;                   // h of (S3)
};

// h of (S3).  Expects 0 < q_min < q_max, points >= 2.
double stripe_half_width(double q_min, double q_max, int points);

// The stripes of (S3) and, for each record's overturning set in q (`sets`,
// one per record, spans in increasing q), its share of each neighbourhood:
//     s_rj = |set_r intersected with [from_j, to_j]| / ln(to_j / from_j),   lengths in ln q   (S4)
// (covered_share of overturning_set.hpp).  Throws std::invalid_argument for
// no record, points < 2, or not 0 < q_min < q_max finite.
StripeShares stripe_shares(const std::vector<std::vector<Span>>& sets, double q_min, double q_max, int points);

// (S1): n_j = the number of records, z_j the sum of their shares, at each stripe.
std::vector<Stripe> stripes_of(const StripeShares& shares);

struct StripeFragility {
    double median = 0, beta = 0;
    double log_likelihood = 0;  // (S2) at the fit, without the binomial coefficients
    int stripes = 0;
};

// (S2) at median and beta.
double stripe_log_likelihood(const std::vector<Stripe>& stripes, double median, double beta);

// Why (S2) has no maximum with beta > 0, or "" when it has one.  With
// S = the stripes where z_j > 0 and F = those where z_j < n_j, none when
//   - every share is 0 (S empty): ln L rises towards 0 as the median grows;
//   - every share is 1 (F empty): ln L rises towards 0 as the median falls;
//   - there is one stripe: one share does not fix two parameters;
//   - the shares step from 0 to 1 (max F <= min S, a perfect separation):
//     ln L rises towards its supremum as beta -> 0 with the median at the step;
//   - the share does not rise with q,
//         sum_{i<j} n_i n_j (ln q_j - ln q_i)(z_j/n_j - z_i/n_i) <= 0,      (S5)
//     (the n-weighted covariance of ln q and the share, summed pairwise so
//     that equal shares give exactly 0): the maximum over (1/beta, ln median
//     / beta) in the plane, which the other conditions make exist, lies at
//     1/beta <= 0, so over beta > 0 ln L rises as beta -> infinity.
// Otherwise ln L, concave in (1/beta, ln median/beta), has one maximum with
// beta > 0 (docs/fragility.md, "Three capacities").
std::string why_no_stripe_maximum(const std::vector<Stripe>& stripes);

// The maximum of (S2) by Newton's method in a = 1/beta, b = (ln median -
// x_ref)/beta, where u_j = a (ln q_j - x_ref) - b is linear and ln L concave
// (ln Phi is), from beta = the stripes' n-weighted spread of ln q and the
// median at their mean x_ref, a step halved until ln L does not fall, to a
// step of 1e-13 relative.  Throws std::invalid_argument where
// why_no_stripe_maximum says why, for q not finite, > 0 and increasing, for
// n_j < 1 or z_j not in [0, n_j], or a median beyond a double;
// std::runtime_error where Newton's method does not converge in 200 steps.
StripeFragility fit_stripes(const std::vector<Stripe>& stripes);

// The records resampled with replacement `resamples` times by SeededRng
// (resampling.hpp; one draw per record, as fragility.hpp's bootstrap draws,
// so that the same seed resamples the same records), by their positions in
// shares.share (a study's draw order, record_order.hpp), each resample's stripes
// (S1) refitted; a resample whose (S2) has no maximum is redrawn; the
// percentile interval at `level`.  Throws std::invalid_argument where the
// shares themselves have no maximum, for resamples < 2, a level not in
// (0, 1), or fewer than 1 in 100 resamples with a maximum.
BootstrapInterval bootstrap_stripes(const StripeShares& shares, int resamples, std::uint64_t seed, double level);

}  // namespace rocking::studies
