#include "studies/spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "dynamics/escape_margin.hpp"
#include "studies/overturning_set.hpp"
#include "studies/scaled_input.hpp"
#include "studies/search_alpha.hpp"

namespace rocking::studies {

using dynamics::GroundInput;

namespace {

// %g: a tolerance or a restitution as typed (std::to_string printed 1e-7 as 0.000000).
std::string short_number(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

}  // namespace

dynamics::SolverOptions SpectrumOptions::rk8pd_check() {
    dynamics::SolverOptions s;
    s.kind = dynamics::SolverKind::gsl_rk8pd;
    s.rtol = s.atol_alpha = 1e-13;
    return s;
}

double SpectrumOptions::step() const { return log_step(p_min, p_max, points); }

std::string SpectrumOptions::describe_grid() const {
    char text[400];
    const double r = step();
    if (method == Method::refine)
        std::snprintf(text, sizeof text,
                      "refined from %d p log-spaced from %g to %g rad/s (x%.6g) down to %g in ln p where the flights' "
                      "escape margins (slopes by a second run at p (1 + %g)) do not clear an interval; islands "
                      "narrower than %g in ln p may be missed",
                      points, p_min, p_max, r, width, slope_step, width);
    else if (offset_grid)
        std::snprintf(text, sizeof text,
                      "%d p log-spaced from %g to %g rad/s (x%.6g), and %d more offset by half a step (x%.6g); "
                      "islands narrower than half a step (x%.6g) may be missed",
                      points, p_min, p_max, r, points - 1, std::sqrt(r), std::sqrt(r));
    else
        std::snprintf(text, sizeof text,
                      "%d p log-spaced from %g to %g rad/s (x%.6g), no offset grid; islands narrower than a step "
                      "(x%.6g) may be missed",
                      points, p_min, p_max, r, r);
    return text;
}

std::string SpectrumOptions::describe_model() const { return model.describe_model() + ", free rocking after the input followed"; }

std::string SpectrumOptions::describe_guarantee() const {
    return "w = " + short_number(width) + " in ln p: every island and gap wider than w in ln p found, except where "
           "the record's q = PGA/(alpha g) is above (pi/2 - alpha)/alpha (the margin's guarantee does not hold); "
           "islands narrower than w may be missed; first robust collapse: the start of the first interval wider than " +
           short_number(robust_width) + " in ln p";
}

std::string SpectrumOptions::describe_refinement() const {
    std::string text = "boundaries bisected to " + short_number(rel_tol) + " relative";
    if (!confirm) return text + "; not checked";
    const std::string by = model.friction > 0 ? std::string("the sliding-rocking run at rtol 1e-12 (the same engine, tighter)")
                                              : dynamics::solver_name(check_solver.kind) + " (" +
                                                    dynamics::tolerance_text(check_solver) + ")";
    return text + "; each checked by " + by + " unless the input times 1 +- " + short_number(probe) +
           " flips an outcome at either end of its bracket (ill-conditioned: flagged, not checked)";
}


namespace {

void check_options(double alpha, const SpectrumOptions& o) {
    if (!in_search_alpha_range(alpha)) throw std::invalid_argument(std::string("spectrum: alpha must be in ") + kSearchAlphaRange);
    if (o.points < 2) throw std::invalid_argument("spectrum: the grid needs at least 2 points");
    if (!(o.p_min > 0 && std::isfinite(o.p_max) && o.p_max > o.p_min))
        throw std::invalid_argument("spectrum: the grid needs 0 < p_min < p_max, finite");
    // Below 1e-15 the bisection would stall on neighbouring doubles.
    if (!(o.rel_tol >= 1e-15 && o.rel_tol <= 0.1)) throw std::invalid_argument("spectrum: rel_tol must be in [1e-15, 0.1]");
    if (!(o.probe > 0 && o.probe <= 1e-3)) throw std::invalid_argument("spectrum: the probe must be in (0, 1e-3]");
    if (!(o.width > 0 && o.width <= 0.1)) throw std::invalid_argument("spectrum: the width must be in (0, 0.1]");
    if (!(o.slope_step >= 1e-12 && o.slope_step <= 1e-6))
        throw std::invalid_argument("spectrum: the slope step must be in [1e-12, 1e-6]");
    if (!(o.robust_width > 0)) throw std::invalid_argument("spectrum: the robust width must be > 0");
}

SpectrumPoint run_point(const GroundInput& input, double alpha, const GridPoint& at, const SpectrumOptions& o) {
    const dynamics::SimulationResult r = records::simulate_block(input, alpha, at.x, o.model);
    SpectrumPoint pt;
    pt.p = at.x;
    pt.grid = at.kind;
    pt.max_theta = r.max_abs_theta_input / alpha;
    using dynamics::Criterion;
    pt.final_rotation = records::run_collapses(r, Criterion::final_rotation, alpha, at.x, o.model);
    pt.peak_rotation = records::run_collapses(r, Criterion::peak_rotation, alpha, at.x, o.model);
    pt.overturning = records::run_collapses(r, Criterion::overturning, alpha, at.x, o.model);
    pt.t_overturn = r.overturned ? r.t_overturn : NAN;
    pt.collapse = records::run_collapses(r, o.model.criterion, alpha, at.x, o.model);
    return pt;
}

// The grid's runs follow the free rocking for every criterion, collapses_at
// only for overturning: the outcome under the criterion is the same.
Boundary refine(const GroundInput& input, double alpha, double p_a, bool collapse_a, double p_b,
                const SpectrumOptions& o, long& simulations) {
    const Bracket br = bisect_boundary([&](double p) { return records::collapses_at(input, alpha, p, o.model); }, p_a,
                                       collapse_a, p_b, o.rel_tol, simulations);
    Boundary b;
    b.p_safe = br.safe;
    b.p_collapse = br.collapse;
    return b;
}


void confirm(Boundary& b, const GroundInput& input, const GroundInput& up, const GroundInput& down, double alpha,
             const SpectrumOptions& o, Spectrum& s) {
    records::CollapseOptions check = o.model;
    check.solver = o.check_solver;
    check.sliding_rtol = records::CollapseOptions::kSlidingCheckRtol;
    const BracketChecks checks{[&](double p) { return records::collapses_at(up, alpha, p, o.model); },
                               [&](double p) { return records::collapses_at(down, alpha, p, o.model); },
                               [&](double p) { return records::collapses_at(input, alpha, p, check); }};
    const Checked c = check_bracket({b.p_safe, b.p_collapse}, "p", checks, s.simulations, s.check_simulations);
    b.confirmation = c.confirmation;
    b.detail = c.detail;
}

// The intervals of collapse of the spans, each end's boundary attached.
std::vector<Interval> intervals_of(const std::vector<Span>& spans, const std::vector<Boundary>& boundaries) {
    std::vector<Interval> out;
    for (const Span& span : spans) {
        Interval in;
        in.from = span.from;
        in.to = span.to;
        in.has_lower = span.lower >= 0;
        in.has_upper = span.upper >= 0;
        if (in.has_lower) in.lower = boundaries[span.lower];
        if (in.has_upper) in.upper = boundaries[span.upper];
        out.push_back(in);
    }
    return out;
}

// The intervals of collapse from the grid's outcomes and its refined boundaries.
std::vector<Interval> intervals_of(const std::vector<SpectrumPoint>& pts, const std::vector<Boundary>& boundaries) {
    std::vector<double> ps;
    std::vector<bool> collapse;
    for (const SpectrumPoint& pt : pts) {
        ps.push_back(pt.p);
        collapse.push_back(pt.collapse);
    }
    std::vector<Bracket> brackets;
    for (const Boundary& b : boundaries) brackets.push_back({b.p_safe, b.p_collapse});
    return intervals_of(spans_of(ps, collapse, brackets), boundaries);
}

bool record_kernel_runs(const GroundInput& input, double alpha, const SpectrumOptions& o) {
    const auto* record = dynamic_cast<const dynamics::SampledInput*>(&input);
    dynamics::SimulationOptions sim;
    sim.solver = o.model.solver;
    sim.free_rocking = o.model.criterion == dynamics::Criterion::overturning;
    // The margins come from the rocking-only record kernel: a block that
    // slides has none, and an imperfect one's are not derived.
    return record && o.model.criterion == dynamics::Criterion::overturning && !(o.model.friction > 0) &&
           !o.model.imperfection.any() &&
           dynamics::record_kernel_applies(records::model_of(alpha, o.p_min, o.model), *record, sim);
}

// The two runs of a sample in p, at p and at p (1 + slope_step), each with
// its flights' escape margins (no tangent in q: the slopes in ln p are the
// two runs' difference), run as records::collapses_at runs them (the same
// model and options: the observer changes no outcome,
// EscapeMargin.TheObserverChangesNoOutcome).  J is retuned in place from
// sample to sample: one allocation of the record's length per search.
class PMargins {
public:
    PMargins(const dynamics::SampledInput& record, double alpha, const SpectrumOptions& o)
        : record_(record), alpha_(alpha), o_(o), at_p_(record, o.p_min, false), at_p2_(record, o.p_min, false) {
        sim_.solver = o.model.solver;
        sim_.free_rocking = o.model.criterion == dynamics::Criterion::overturning;
    }
    MarginSample operator()(double p) {
        MarginSample s;
        s.collapse = run(at_p_, p, flights_);
        const double p2 = p * (1 + o_.slope_step);
        if (run(at_p2_, p2, flights2_) != s.collapse || flights2_.size() != flights_.size()) return s;
        const double d = std::log(p2 / p);
        s.has_margins = true;
        for (std::size_t j = 0; j < flights_.size(); ++j) {
            s.xi.push_back(flights_[j].xi);
            s.slope.push_back((flights2_[j].xi - flights_[j].xi) / d);
        }
        return s;
    }

private:
    bool run(dynamics::RestOfInput& rest, double p, std::vector<dynamics::FlightMargin>& flights) {
        rest.retune(p);
        const dynamics::Model model = records::model_of(alpha_, p, o_.model);
        dynamics::FlightMargins margins(model, rest, 1.0, false);
        const bool c = dynamics::simulate_with_margins(model, record_, sim_, margins).collapse(o_.model.criterion, alpha_);
        flights = margins.flights();
        return c;
    }

    const dynamics::SampledInput& record_;
    double alpha_;
    const SpectrumOptions& o_;
    dynamics::SimulationOptions sim_;
    dynamics::RestOfInput at_p_, at_p2_;
    std::vector<dynamics::FlightMargin> flights_, flights2_;
};

// The refine method's sampler: margins_in_p where the record kernel runs the
// model, the outcome alone elsewhere.
class PSampler {
public:
    PSampler(const GroundInput& input, double alpha, const SpectrumOptions& o)
        : input_(input), alpha_(alpha), o_(o) {
        if (record_kernel_runs(input, alpha, o))
            margins_ = std::make_unique<PMargins>(dynamic_cast<const dynamics::SampledInput&>(input), alpha, o);
    }
    bool with_margins() const { return margins_ != nullptr; }
    bool collapses(double p) const { return records::collapses_at(input_, alpha_, p, o_.model); }
    MarginSample operator()(double p) const {
        if (margins_) return (*margins_)(p);
        MarginSample s;
        s.collapse = collapses(p);
        return s;
    }

private:
    const GroundInput& input_;
    double alpha_;
    const SpectrumOptions& o_;
    std::unique_ptr<PMargins> margins_;  // its buffers change from sample to sample
};

// The three numbers of issue 39 from the intervals, both methods alike; the
// bands are the main grid's steps.
void summarise(Spectrum& s, const SpectrumOptions& o) {
    std::vector<Span> spans;
    for (const Interval& in : s.intervals) spans.push_back(Span{in.from, in.to, -1, -1});
    const SetSummary sum = summarise_set(spans, o.p_min, o.p_max, o.points, o.robust_width);
    s.first_overturning = SpectrumFirst{sum.first_overturning, sum.overturns};
    s.first_robust_collapse = SpectrumFirst{sum.first_robust_collapse, sum.robustly};
    s.bands = sum.bands;
}

// The refine method: studies/overturning_set.hpp over [p_min, p_max] from
// the main grid, its boundaries checked as the grid's.
void refined_spectrum(Spectrum& s, const GroundInput& input, double alpha, const SpectrumOptions& o) {
    s.refined = true;
    const PSampler sampler(input, alpha, o);
    s.with_margins = sampler.with_margins();
    RefineOptions ro;
    ro.width = o.width;
    ro.coarse = o.points;
    ro.rel_tol = o.rel_tol;
    ro.first_only = o.first_only;
    // The turn-back bound of the IDA, q > (pi/2 - alpha)/alpha, on the input's own q.
    if (input.peak() / alpha > (M_PI / 2 - alpha) / alpha) ro.guarantee_below = 0;
    const RefinedSet set =
        refine_set([&sampler](double p) { return sampler(p); }, [&sampler](double p) { return sampler.collapses(p); },
                   o.p_min, o.p_max, ro);
    const std::vector<GridPoint> coarse = log_grid(o.p_min, o.p_max, o.points, false, {});
    for (const GridPoint& at : coarse)
        if (!set.stopped || at.x <= set.xs.back()) s.points.push_back(run_point(input, alpha, at, o));
    s.samples = set.samples;
    s.simulations = static_cast<long>(s.points.size()) + set.bisection_runs + (s.with_margins ? 2 : 1) * set.samples;
    s.accepted = set.accepted;
    s.at_width = set.at_width;
    s.unguaranteed_from = set.unguaranteed_from;

    std::vector<Boundary> boundaries;
    for (const Bracket& br : set.brackets) {
        Boundary b;
        b.p_safe = br.safe;
        b.p_collapse = br.collapse;
        boundaries.push_back(b);
    }
    s.boundaries = static_cast<int>(boundaries.size());
    if (o.confirm && !boundaries.empty()) {
        const auto up = scaled(input, 1 + o.probe), down = scaled(input, 1 - o.probe);
        for (Boundary& b : boundaries) confirm(b, input, *up, *down, alpha, o, s);
    }
    s.intervals = intervals_of(set.spans, boundaries);
}

}  // namespace

MarginSample margins_in_p(const GroundInput& input, double alpha, double p, const SpectrumOptions& o) {
    if (!record_kernel_runs(input, alpha, o)) throw std::invalid_argument("margins_in_p: the record kernel does not run this model");
    PMargins margins(dynamic_cast<const dynamics::SampledInput&>(input), alpha, o);
    return margins(p);
}

Spectrum rocking_spectrum(const GroundInput& input, double alpha, const SpectrumOptions& o) {
    check_options(alpha, o);
    Spectrum s;
    s.alpha = alpha;
    // An imperfect block lifts lower than the perfect one, and a set-back one
    // the lower the larger it is: the range's weakest block.
    s.lifts = records::input_lifts_any(input, alpha, o.p_min, o.model);
    if (o.method == SpectrumOptions::Method::refine) {
        refined_spectrum(s, input, alpha, o);
        summarise(s, o);
        if (o.first_only) {
            s.bands.clear();
            s.first_robust_collapse = SpectrumFirst{o.p_max, false};
        }
        return s;
    }

    const std::vector<GridPoint> ps = log_grid(o.p_min, o.p_max, o.points, o.offset_grid, o.extra_points);
    for (const GridPoint& at : ps) s.points.push_back(run_point(input, alpha, at, o));
    s.simulations = static_cast<long>(ps.size());

    std::vector<Boundary> boundaries;
    for (std::size_t k = 1; k < s.points.size(); ++k)
        if (s.points[k].collapse != s.points[k - 1].collapse)
            boundaries.push_back(refine(input, alpha, s.points[k - 1].p, s.points[k - 1].collapse, s.points[k].p, o,
                                        s.simulations));
    s.boundaries = static_cast<int>(boundaries.size());
    if (o.confirm && !boundaries.empty()) {
        const auto up = scaled(input, 1 + o.probe), down = scaled(input, 1 - o.probe);
        for (Boundary& b : boundaries) confirm(b, input, *up, *down, alpha, o, s);
    }
    s.intervals = intervals_of(s.points, boundaries);
    summarise(s, o);
    return s;
}

}  // namespace rocking::studies
