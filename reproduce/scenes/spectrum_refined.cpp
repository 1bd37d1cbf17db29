// The refine method's view of the Norcia spectra (issue 39, item 4), beside
// the grid method's of spectrum.cpp: the first overturning and the first
// robust collapse against the grids' lowest p, and how much of the range
// between them overturns.
#include "spectrum_refined.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "harness/table.hpp"
#include "records_analysis.hpp"

namespace rocking::scenes {

namespace {

using studies::Boundary;
using studies::Confirmation;
using studies::Interval;
using studies::Spectrum;

// w = 1e-3 in ln p keeps the view under a minute of CPU for the 50 pairs
// (57 s measured, a third of it the checks of ~2,350 boundaries); 1e-4 costs
// 4x that (expected/spectrum/PROVENANCE.md).  Islands narrower than w may be
// missed: the first overturning here is an upper bound.
constexpr double kWidth = 1e-3;
constexpr double kRobustWidth = 5e-3;  // the library's default, stated here because the file states it
// The stated band below the grids' lowest p: what the grids call safe there.
constexpr double kBelowGrid = 1.05;

// A well-conditioned bracket (confirmed, or seen otherwise by the second
// solver) is held to the bisection's 1e-6; an ill-conditioned one, placed by
// rounding, only to the spacing of the samples around it (<= w: an interval
// whose ends differ in outcome is always split down to w).
bool well_conditioned(const Boundary& b) {
    return b.confirmation == Confirmation::confirmed || b.confirmation == Confirmation::disagrees;
}

std::vector<studies::Span> spans_of(const Spectrum& s) {
    std::vector<studies::Span> spans;
    for (const Interval& in : s.intervals) spans.push_back({in.from, in.to, -1, -1});
    return spans;
}

// The library's band (a step of the main grid) holding p.
const studies::Band* band_at(const Spectrum& s, double p) {
    for (const studies::Band& b : s.bands)
        if (p >= b.from && p < b.to) return &b;
    return s.bands.empty() || p < s.bands.back().to ? nullptr : &s.bands.back();
}

// The interval that starts the first robust collapse.
const Interval* robust_interval(const Spectrum& s) {
    if (!s.first_robust_collapse.found) return nullptr;
    for (const Interval& in : s.intervals)
        if (in.from == s.first_robust_collapse.p) return &in;
    return nullptr;
}

// Where the intervals file stops for a pair: every interval starting at or
// below this p is listed, enough to recompute each of the row's numbers
// (the share up to the first robust collapse, the band below the grids'
// lowest p, the band at the first overturning); all of them without a robust
// collapse.
double listed_up_to(const Spectrum& r, const Spectrum& g, double p_max) {
    if (!r.first_robust_collapse.found) return p_max;
    double cut = r.first_robust_collapse.p;
    if (!g.intervals.empty()) cut = std::max(cut, g.intervals.front().from);
    if (const studies::Band* b = band_at(r, r.first_overturning.p)) cut = std::max(cut, b->to);
    return cut;
}

// A boundary's check and its bracket in the columns of its kind.
void add_bracket(harness::Table& t, const Boundary& b, bool lower) {
    const double first = lower ? b.p_safe : b.p_collapse, second = lower ? b.p_collapse : b.p_safe;
    t.add(studies::confirmation_name(b.confirmation));
    if (well_conditioned(b)) t.add(first).add(second).add("-").add("-");
    else t.add("-").add("-").add(first).add(second);
}

void add_percent_below(harness::Table& t, double p, bool has_grid, double grid_p) {
    if (has_grid) t.add(100 * (1 - p / grid_p));
    else t.add("-");
}

}  // namespace

studies::SpectrumOptions refined_spectrum_options() {
    studies::SpectrumOptions o;  // the grid method's p range and main grid: 200 p from 0.3 to 30 rad/s
    o.model = table1_search();
    o.method = studies::SpectrumOptions::Method::refine;
    o.width = kWidth;
    o.robust_width = kRobustWidth;
    return o;
}

void write_spectrum_refined(SceneContext& ctx, const std::vector<RefinedPair>& pairs, const std::string& inputs) {
    const studies::SpectrumOptions o = refined_spectrum_options();
    const std::string solver = "refine search: " + o.describe_grid() + "; " + o.describe_refinement();
    const std::string width = "w = " + g_text(kWidth) + " in ln p (every island and gap wider than w found; "
                              "narrower ones may be missed), robust width " + g_text(kRobustWidth) + " in ln p";

    harness::Table t({"record", "alpha", "grid_lowest_p", "grid_intervals", "first_overturning_p",
                      "first_overturning_safe", "first_overturning_check", "first_below_grid_percent", "first_robust_p",
                      "first_robust_safe", "first_robust_check", "robust_below_grid_percent", "intervals",
                      "intervals_listed", "share_first_to_robust", "share_5pc_below_grid", "band_share_at_first",
                      "guarantee"});
    t.note("scene", "spectrum: the refine method's overturning set beside the grid method's, per Norcia record and "
                    "alpha (issue 39): its first overturning and first robust collapse against the grids' lowest p");
    t.note("model", o.describe_model());
    t.note("solver", solver);
    t.note("width", width);
    t.note("inputs", inputs);
    t.note("columns",
           "p in rad/s. grid_lowest_p, grid_intervals: the grid method's lowest overturning p and number of intervals "
           "(spectrum_summary.csv); first_overturning_p: the refine method's lowest overturning p, with the safe end "
           "of its bracket and its check; first_robust_p: the start of its first interval wider than the robust "
           "width in ln p, likewise ('none up to 30' without one); *_below_grid_percent: 100 (1 - p / grid_lowest_p); "
           "intervals: the refine method's intervals up to 30 rad/s; intervals_listed: those of "
           "spectrum_refined_intervals.csv; share_first_to_robust: the share of ln p from first_overturning_p to "
           "first_robust_p that overturns ('-' where they coincide); share_5pc_below_grid: the share of ln p from "
           "grid_lowest_p / 1.05 to grid_lowest_p that overturns (where the grids see no overturning); "
           "band_share_at_first: the library's overturned share of the main-grid step holding first_overturning_p; "
           "guarantee: no where the record's q = PGA/(alpha g) is above (pi/2 - alpha)/alpha (the escape margin's "
           "guarantee does not hold)");

    harness::Table iv({"record", "alpha", "interval", "from", "to", "from_check", "from_safe", "from_collapse",
                       "from_ill_safe", "from_ill_collapse", "to_check", "to_collapse", "to_safe", "to_ill_collapse",
                       "to_ill_safe"});
    iv.note("scene", "spectrum: the refine method's overturning intervals in p from which spectrum_refined.csv's "
                     "numbers are computed (issue 39)");
    iv.note("model", o.describe_model());
    iv.note("solver", solver);
    iv.note("width", width);
    iv.note("inputs", inputs);
    iv.note("listed", "per record and alpha, every interval starting at or below the largest of the first robust "
                      "collapse, the grids' lowest p and the end of the main-grid step holding the first overturning; "
                      "every interval where there is no robust collapse");
    iv.note("columns",
            "p in rad/s; an interval overturns the block from 'from' to 'to'; each end a boundary (safe at *_safe, "
            "overturning at *_collapse, 1e-6 relative apart) or the grid's own end; *_check: confirmed (the input "
            "times 1 +- 1e-13 flips nothing, rk8pd sees the bracket), ill-conditioned (its bracket in *_ill_*, placed "
            "by rounding within the samples around it, at most w apart), second solver disagrees");

    for (const RefinedPair& pr : pairs) {
        const Spectrum& r = pr.refined;
        const Spectrum& g = *pr.grid;
        const bool has_grid = !g.intervals.empty();
        const double grid_p = has_grid ? g.intervals.front().from : 0;
        t.row().add(pr.record).add(alpha_label(pr.alpha));
        if (has_grid) t.add(grid_p);
        else t.add("none");
        t.add(static_cast<int>(g.intervals.size()));
        if (r.intervals.empty()) {
            t.add("none up to 30").add("-").add("-").add("-");
        } else {
            const Interval& first = r.intervals.front();
            t.add(r.first_overturning.p);
            if (first.has_lower) t.add(first.lower.p_safe).add(studies::confirmation_name(first.lower.confirmation));
            else t.add("none: overturns at 0.3").add("-");
            add_percent_below(t, r.first_overturning.p, has_grid, grid_p);
        }
        const Interval* robust = robust_interval(r);
        if (!robust) {
            t.add("none up to 30").add("-").add("-").add("-");
        } else {
            t.add(robust->from);
            if (robust->has_lower) t.add(robust->lower.p_safe).add(studies::confirmation_name(robust->lower.confirmation));
            else t.add("none: overturns at 0.3").add("-");
            add_percent_below(t, robust->from, has_grid, grid_p);
        }
        const double cut = listed_up_to(r, g, o.p_max);
        int listed = 0;
        for (std::size_t i = 0; i < r.intervals.size() && r.intervals[i].from <= cut; ++i) {
            const Interval& in = r.intervals[i];
            ++listed;
            iv.row().add(pr.record).add(alpha_label(pr.alpha)).add(static_cast<int>(i + 1)).add(in.from).add(in.to);
            if (in.has_lower) add_bracket(iv, in.lower, true);
            else iv.add("grid start").add("-").add("-").add("-").add("-");
            if (in.has_upper) add_bracket(iv, in.upper, false);
            else iv.add("grid end").add("-").add("-").add("-").add("-");
            for (int e = 0; e < 2; ++e) {
                const Boundary& b = e == 0 ? in.lower : in.upper;
                if ((e == 0 ? in.has_lower : in.has_upper) && !b.detail.empty())
                    iv.note("detail " + pr.record + " alpha " + alpha_label(pr.alpha) + " interval " +
                                std::to_string(i + 1) + (e == 0 ? " from" : " to"),
                            b.detail);
            }
        }
        t.add(static_cast<int>(r.intervals.size())).add(listed);
        const std::vector<studies::Span> spans = spans_of(r);
        if (robust && robust->from > r.first_overturning.p)
            t.add(studies::covered_share(spans, r.first_overturning.p, robust->from));
        else t.add("-");
        if (has_grid && grid_p / kBelowGrid >= o.p_min) t.add(studies::covered_share(spans, grid_p / kBelowGrid, grid_p));
        else t.add("-");
        const studies::Band* band = r.intervals.empty() ? nullptr : band_at(r, r.first_overturning.p);
        if (band) t.add(band->share);
        else t.add("-");
        t.add(std::isinf(r.unguaranteed_from) ? "yes" : "no");
    }
    ctx.write(t, kRefinedFile);
    ctx.write(iv, kRefinedIntervalsFile);
}

}  // namespace rocking::scenes
