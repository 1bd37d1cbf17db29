// The overturning set over a log range of a parameter x (the IDA's q), to a
// width w in ln x, by near-miss refinement on each flight's escape margin
// (issue 39; the method, its guarantee and its measurements:
// docs/overturning_set.md, section 3).  Parameter-agnostic like intervals.hpp:
// the caller's sampler runs the model at x and reports the outcome and each
// flight's margin Xi_j with its slope dXi_j / d ln x
// (dynamics/escape_margin.hpp).
//
// An interval between two samples of the same outcome is accepted (no change
// of outcome assumed inside) when
//   - both carry margins, the same number of flights, and all Xi_j < 0 (safe)
//     or the falling (last) flight's Xi > 0 (overturning) at both ends;
//   - the tangents reach no zero: reach * ln(b/a) <= r_a + r_b, with
//     r = min_j |Xi_j| / |dXi_j/d ln x| (all flights if safe, the falling one
//     if overturning);
//   - the tangents are borne out: for those flights, Xi_j(a) + Xi_j'(a) ln(b/a)
//     is within `consistency` of min(|Xi_j(a)|, |Xi_j(b)|) of Xi_j(b), and the
//     same from b back to a.
// Two safe samples without any flight (the block never lifts) are accepted
// too: whether the block lifts depends on the input's peak alone, monotone in
// q and independent of p.  Otherwise the interval is split at its log midpoint,
// down to a spacing <= w; every change of outcome between neighbours is then
// bisected to rel_tol with the plain outcome.
//
// Guaranteed by construction: every island of overturning or of safety wider
// than w in ln x inside a range that was split down to w holds a sample.
// Assumed in an accepted interval: each Xi_j is as regular across it as its
// values and slopes at both ends show.  Not covered: islands narrower than w;
// above `guarantee_below` (the IDA's turn-back bound q > (pi/2 - alpha)/alpha)
// an overturning run need not have a flight with Xi > 0, so acceptance there
// proves less (the result says where that range starts).
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "studies/intervals.hpp"

namespace rocking::studies {

// One run at x: its outcome and, where the run's flights are known, each
// flight's escape margin at its start and its derivative in ln x.
struct MarginSample {
    bool collapse = false;
    bool has_margins = false;  // false: the outcome only (the search splits to w around it)
    std::vector<double> xi, slope;
};

struct RefineOptions {
    double width = 1e-5;        // w, in ln x: the spacing down to which unaccepted intervals are split
    int coarse = 100;           // the first log grid, both ends included
    double reach = 2;           // c: the tangents' reach must exceed c ln(b/a)
    double consistency = 0.5;   // tangents borne out within this share of the smaller margin
    double rel_tol = 1e-6;      // each change of outcome bisected to this, relative
    double guarantee_below = std::numeric_limits<double>::infinity();
    // Stop at the first sample that collapses: where only the first
    // overturning is wanted (Table 1's p), the range above it is not searched.
    // The last span then ends at that sample, not where the set ends.
    bool first_only = false;
};

struct RefinedSet {
    std::vector<double> xs;         // every sample, increasing
    std::vector<bool> collapse;     // the outcome at each
    std::vector<Bracket> brackets;  // each change of outcome between neighbours, bisected
    std::vector<Span> spans;        // the set of collapse (spans_of)
    long samples = 0;               // runs with margins
    long bisection_runs = 0;        // runs of the plain outcome
    long accepted = 0;              // intervals accepted by the margins
    long at_width = 0;              // intervals left at spacing <= w, same outcome at both ends
    bool stopped = false;           // first_only: stopped at a sample that collapses
    // Where the guarantee stops (guarantee_below within the range), else +inf.
    double unguaranteed_from = std::numeric_limits<double>::infinity();
};

// Whether [a, b] (ln(b/a) = d) is accepted between samples A at a and B at b.
bool accept_interval(const MarginSample& A, const MarginSample& B, double d, const RefineOptions& o);

// The search over [lo, hi] (0 < lo < hi).  `sample` is one run with
// margins; `collapses` the plain outcome (the same model), for the bisection.
// Throws std::invalid_argument for a bad range, width not in (0, 1),
// coarse < 2, reach <= 0, consistency not in (0, 1], rel_tol not in
// [1e-15, 0.1].
RefinedSet refine_set(const std::function<MarginSample(double)>& sample, const std::function<bool(double)>& collapses,
                      double lo, double hi, const RefineOptions& o);

// The widths every front end (command line, batch row, Python) takes for the
// refine method, in ln of the study's parameter: w in [1e-7, 0.1] (below,
// ~1e7 samples per unit of ln x; above, a coarser search than the grid's
// half step) and the robust width in [1e-7, 1].
constexpr const char* kWidthRange = "[1e-7, 0.1]";  // as the messages print them
constexpr const char* kRobustWidthRange = "[1e-7, 1]";
inline bool in_width_range(double w) { return w >= 1e-7 && w <= 0.1; }
inline bool in_robust_width_range(double r) { return r >= 1e-7 && r <= 1; }

// The share of [from, to] (in ln x) that the spans cover.
double covered_share(const std::vector<Span>& spans, double from, double to);

// A band of x (a step of a study's main grid) and the share of it, in ln x,
// that the set of collapse covers: how much of the neighbourhood overturns.
struct Band {
    double from = 0, to = 0, share = 0;
};

// The three numbers of issue 39 for a set of collapse over [lo, hi] whose
// main grid has `points` log-spaced points: the first overturning (the first
// span's start), the first robust collapse (the start of the first span wider
// than robust_width in ln x), each at hi and not found without one, and every
// step's band.  Spans in increasing x.
struct SetSummary {
    double first_overturning = 0, first_robust_collapse = 0;
    bool overturns = false, robustly = false;
    std::vector<Band> bands;
};
SetSummary summarise_set(const std::vector<Span>& spans, double lo, double hi, int points, double robust_width);

}  // namespace rocking::studies
