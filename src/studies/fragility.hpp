// Fragility from incremental dynamic analysis (IDA): for each record, the
// intensity q = PGA/(alpha g) at which it first overturns a block; across
// records, the lognormal curve
//     P(overturn | q) = Phi(ln(q / median) / beta)                      (F1)
// fitted by maximum likelihood (Baker 2015, "Efficient analytical fragility
// function fitting using dynamic structural analysis", Earthquake Spectra 31,
// for IDA data), with the records that never overturned up to the largest q
// scanned kept as right-censored points, a bootstrap interval over records,
// and the empirical curve beside it.  The batch that produces the points
// (scaling each record until it overturns the block) lives above dynamics and
// records; this file knows only the points.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "studies/resampling.hpp"

namespace rocking::studies {

// One record's outcome: overturned at q (collapsed), or not up to q (censored).
struct IdaPoint {
    double q;
    bool collapsed;
};

struct LognormalFragility {
    double median = 0;          // q with P = 1/2
    double beta = 0;            // dispersion, the standard deviation of ln q
    double log_likelihood = 0;  // at the fit
    int collapsed = 0, censored = 0;
};

// (F1) at q.
double overturning_probability(const LognormalFragility& f, double q);

// ln L of (F1) with median and beta of f on the points (the quantity
// fit_lognormal maximises).
double log_likelihood(const std::vector<IdaPoint>& points, const LognormalFragility& f);

// Whether every collapsed point has the same q, compared as doubles (bit for
// bit), with no tolerance: the IDA bisects every record's boundary by the same
// halvings of the same grid, so two records whose first collapse falls in one
// final bracket already get the same double, and two that do not differ by a
// bracket (1e-6 relative by default); a tolerance here would have to know the
// IDA's.  False without collapsed points.
bool all_collapses_equal(const std::vector<IdaPoint>& points);

// Why ln L of (F1) on the points has no maximum, or "" when it has one.  It
// has none when no point collapsed (ln L rises towards 0 as the median grows),
// or when every collapse is at one q = c and no censored point lies above c:
// at median c, ln L grows like -n ln beta as beta -> 0.  A censored point
// above c makes ln L -> -inf there instead (its ln[1 - Phi] falls like
// -1/beta^2), and so do two distinct collapses; then ln L, continuous and
// -inf at every edge, has its maximum, one collapse being enough
// (docs/fragility.md, "Equal and censored collapse values").
std::string why_no_maximum(const std::vector<IdaPoint>& points);

// Maximum likelihood of (F1) on the points: with every point collapsed it is
// the closed form ln median = mean of ln q_i, beta^2 = mean of (ln q_i - ln median)^2
// (Baker 2015's moment estimates, with 1/n where Baker's sample deviation has
// 1/(n - 1)); with censored points it maximises
//     sum_collapsed ln[phi(z_i) / (beta q_i)] + sum_censored ln[1 - Phi(z_i)],  z_i = ln(q_i / median) / beta
// by Newton's method in Olsen's concave parameters (1/beta, ln median / beta),
// from the collapsed points' closed form (from all points' when the collapses
// share one q), to a step of 1e-13 relative.
// Throws std::invalid_argument where why_no_maximum says why, or for a q
// that is not finite and > 0.
LognormalFragility fit_lognormal(const std::vector<IdaPoint>& points);

struct BootstrapInterval {
    Range median, beta;  // percentile intervals at the given level
    int resamples = 0;   // resamples fitted (those whose ln L has no maximum, by why_no_maximum, are redrawn)
    std::uint64_t seed = 0;
    double level = 0;
};

// The records resampled with replacement `resamples` times (GSL's mt19937,
// seeded: the same seed gives the same interval on any machine;
// studies/resampling.hpp), drawn by their positions in `points`, which a
// study gives in its draw order (record_order.hpp) so that the interval does
// not depend on the order the records were listed in; each resample
// refitted; the percentile interval at `level` (e.g. 0.9).  A resample
// whose ln L has no maximum (why_no_maximum:
// say every draw of one record) is redrawn, so the interval is over resamples
// that have a fit.  Throws std::invalid_argument where the points have none.
BootstrapInterval bootstrap(const std::vector<IdaPoint>& points, int resamples, std::uint64_t seed, double level);

// The empirical curve: at each collapsed point's q, in increasing order, the
// share of all records that overturned at or below it.
struct EmpiricalPoint {
    double q, share;
};
std::vector<EmpiricalPoint> empirical_curve(const std::vector<IdaPoint>& points);

}  // namespace rocking::studies
