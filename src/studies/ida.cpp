#include "studies/ida.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "batch/pool.hpp"
#include "dynamics/escape_margin.hpp"
#include "studies/overturning_set.hpp"
#include "studies/record_order.hpp"
#include "studies/scaled_input.hpp"
#include "studies/spectrum.hpp"
#include "studies/search_alpha.hpp"

namespace rocking::studies {

using dynamics::GroundInput;

std::string IdaOptions::describe_grid() const {
    char text[400];
    const double r = log_step(q_min, q_max, points);
    if (method == Method::refine)
        std::snprintf(text, sizeof text,
                      "refined from %d q log-spaced from %g to %g (x%.6g) down to %g in ln q where the flights' escape "
                      "margins do not clear an interval; boundaries bisected to %g relative; islands narrower than "
                      "%g in ln q may be missed",
                      points, q_min, q_max, r, width, rel_tol, width);
    else if (offset_grid)
        std::snprintf(text, sizeof text,
                      "%d q log-spaced from %g to %g (x%.6g), and %d more offset by half a step (x%.6g); "
                      "boundaries bisected to %g relative; islands narrower than half a step may be missed",
                      points, q_min, q_max, r, points - 1, std::sqrt(r), rel_tol);
    else
        std::snprintf(text, sizeof text,
                      "%d q log-spaced from %g to %g (x%.6g), no offset grid; boundaries bisected to %g relative; "
                      "islands narrower than a step may be missed",
                      points, q_min, q_max, r, rel_tol);
    // Where an imperfect block lifts below q_min its grid starts there (q_start).
    if (model.imperfection.any()) {
        char start[40];
        std::snprintf(start, sizeof start, "%g", q_min);
        return std::string(text) + "; an imperfect block's grid from where it lifts, q = min over its corners of "
                                   "alpha_sigma/alpha, when below " + start + " (each block's q_start)";
    }
    return text;
}

namespace {

std::string g7(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.7g", v);
    return text;
}

}  // namespace

std::string IdaOptions::describe_guarantee() const {
    return "w = " + g7(width) + " in ln q: every island and gap wider than w in ln q found, except above q = "
           "(pi/2 - alpha)/alpha where the margin's guarantee does not hold; islands narrower than w may be missed; "
           "first robust collapse: the start of the first interval wider than " + g7(robust_width) + " in ln q";
}

std::string FragilityStudyOptions::describe_fits() const {
    return ida.describe_guarantee() +
           "; three lognormal fits, each named by its capacity: the first overturning (conservative; the "
           "block's fit and empirical curve), the first robust collapse, and the multiple-stripe fit of the "
           "overturned shares (a stripe at the geometric middle of each step of the main grid, its neighbourhood "
           "the step, half-width " + g7(stripe_half_width(ida.q_min, ida.q_max, ida.points)) +
           " in ln q; binomial likelihood on n records x mean share)";
}

std::string IdaOptions::describe_checks() const {
    if (checks == Checks::none) return "brackets not checked";
    char text[300];
    std::snprintf(text, sizeof text,
                  "%s: the input times 1 +- %g at both ends (a flip: ill-conditioned), then %s",
                  checks == Checks::first_collapse ? "the first collapse's bracket checked" : "every bracket checked",
                  probe, model.friction > 0 ? "the sliding-rocking run at rtol 1e-12 (the same engine, tighter)"
                                            : "GSL rk8pd at rtol 1e-13");
    return text;
}

std::string IdaOptions::describe_model() const {
    std::string text = model.describe_model();
    if (!input_note.empty()) text += "; input: " + input_note;
    return text;
}

namespace {

void check_options(const GroundInput& input, double alpha, double p, const IdaOptions& o) {
    if (!in_search_alpha_range(alpha)) throw std::invalid_argument(std::string("ida: alpha must be in ") + kSearchAlphaRange);
    if (!(std::isfinite(p) && p > 0)) throw std::invalid_argument("ida: p must be finite and > 0");
    if (!(input.peak() > 0)) throw std::invalid_argument("ida: the input never moves (peak 0): it cannot be scaled to a q");
    if (o.points < 2) throw std::invalid_argument("ida: the grid needs at least 2 points");
    if (!(o.q_min > 0 && std::isfinite(o.q_max) && o.q_max > o.q_min))
        throw std::invalid_argument("ida: the grid needs 0 < q_min < q_max, finite");
    // Below 1e-15 the bisection would stall on neighbouring doubles.
    if (!(o.rel_tol >= 1e-15 && o.rel_tol <= 0.1)) throw std::invalid_argument("ida: rel_tol must be in [1e-15, 0.1]");
    if (!(o.probe > 0 && o.probe <= 1e-3)) throw std::invalid_argument("ida: the probe must be in (0, 1e-3]");
    if (!(o.width > 0 && o.width <= 0.1)) throw std::invalid_argument("ida: the width must be in (0, 0.1]");
    if (!(o.robust_width > 0)) throw std::invalid_argument("ida: the robust width must be > 0");
}


// Through scaled(), so that a record stays a record and the exact solver
// takes it through the record kernel.
bool collapses_at_q(const GroundInput& input, double alpha, double p, double q, const IdaOptions& o) {
    const double factor = q * alpha / input.peak();
    return records::collapses_at(*scaled(input, factor), alpha, p, o.model);
}

// Scaling the input by 1 +- probe is the same run as q (1 +- probe); the
// second solver runs the model on the input scaled to q.
BracketChecks checks_of(const GroundInput& input, double alpha, double p, const IdaOptions& o) {
    IdaOptions second = o;
    second.model.solver = SpectrumOptions::rk8pd_check();
    second.model.sliding_rtol = records::CollapseOptions::kSlidingCheckRtol;
    return {[&input, alpha, p, o](double q) { return collapses_at_q(input, alpha, p, q * (1 + o.probe), o); },
            [&input, alpha, p, o](double q) { return collapses_at_q(input, alpha, p, q * (1 - o.probe), o); },
            [&input, alpha, p, second](double q) { return collapses_at_q(input, alpha, p, q, second); }};
}

IdaInterval interval_of(const Span& span, const std::vector<Bracket>& brackets) {
    IdaInterval in;
    in.from = span.from;
    in.to = span.to;
    in.has_lower = span.lower >= 0;
    in.has_upper = span.upper >= 0;
    if (in.has_lower) in.lower = brackets[span.lower];
    if (in.has_upper) in.upper = brackets[span.upper];
    return in;
}

// One run at q with each flight's escape margin, as records::collapses_at
// runs it (the same model, options and scaled samples: the observer changes
// no outcome, EscapeMargin.TheObserverChangesNoOutcome).  Without the record
// kernel (another input, solver, equation or criterion) the outcome only.
class MarginSampler {
public:
    MarginSampler(const GroundInput& input, double alpha, double p, const IdaOptions& o)
        : input_(input), alpha_(alpha), p_(p), o_(o), model_(records::model_of(alpha, p, o.model)) {
        sim_.solver = o.model.solver;
        sim_.free_rocking = o.model.criterion == dynamics::Criterion::overturning;
        record_ = dynamic_cast<const dynamics::SampledInput*>(&input);
        // The margins come from the rocking-only record kernel: a block that
        // slides has none, and an imperfect one's are not derived.
        if (record_ && o.model.criterion == dynamics::Criterion::overturning && !(o.model.friction > 0) &&
            !o.model.imperfection.any() &&
            dynamics::record_kernel_applies(model_, *record_, sim_))
            rest_ = std::make_unique<dynamics::RestOfInput>(*record_, p);
    }
    bool with_margins() const { return rest_ != nullptr; }
    MarginSample operator()(double q) const {
        MarginSample s;
        const double factor = q * alpha_ / input_.peak();
        if (!rest_) {
            s.collapse = collapses_at_q(input_, alpha_, p_, q, o_);
            return s;
        }
        dynamics::FlightMargins margins(model_, *rest_, factor);
        const dynamics::SampledInput at_q = record_->scaled_by(factor, "ida");
        s.collapse = dynamics::simulate_with_margins(model_, at_q, sim_, margins).collapse(o_.model.criterion, alpha_);
        s.has_margins = true;
        for (const dynamics::FlightMargin& f : margins.flights()) {
            s.xi.push_back(f.xi);
            s.slope.push_back(f.slope);
        }
        return s;
    }

private:
    const GroundInput& input_;
    double alpha_, p_;
    const IdaOptions& o_;
    dynamics::Model model_;
    dynamics::SimulationOptions sim_;
    const dynamics::SampledInput* record_ = nullptr;
    std::unique_ptr<dynamics::RestOfInput> rest_;
};

// The three numbers of issue 39 from the intervals, both methods alike.
void summarise(Ida& ida, const IdaOptions& o) {
    std::vector<Span> spans;
    for (const IdaInterval& in : ida.intervals) spans.push_back(Span{in.from, in.to, -1, -1});
    const SetSummary s = summarise_set(spans, o.q_min, o.q_max, o.points, o.robust_width);
    ida.point = IdaPoint{s.first_overturning, s.overturns};
    ida.first_overturning = ida.point;
    ida.first_robust_collapse = IdaPoint{s.first_robust_collapse, s.robustly};
    ida.bands = s.bands;
}

void check_brackets(Ida& ida, const GroundInput& input, double alpha, double p, const IdaOptions& o) {
    if (o.checks == IdaOptions::Checks::none || ida.intervals.empty()) return;
    const BracketChecks checks = checks_of(input, alpha, p, o);
    for (IdaInterval& in : ida.intervals) {
        if (in.has_lower) in.lower_check = check_bracket(in.lower, "q", checks, ida.simulations, ida.check_simulations);
        if (o.checks == IdaOptions::Checks::first_collapse) break;
        if (in.has_upper) in.upper_check = check_bracket(in.upper, "q", checks, ida.simulations, ida.check_simulations);
    }
}

// The refine method: studies/overturning_set.hpp over [q_min, q_max] from the
// main grid, its brackets checked as the grid's.
Ida refined_ida(const GroundInput& input, double alpha, double p, const IdaOptions& o) {
    Ida ida;
    ida.alpha = alpha;
    ida.p = p;
    ida.q_input = input.peak() / alpha;
    ida.refined = true;
    const MarginSampler sampler(input, alpha, p, o);
    ida.with_margins = sampler.with_margins();
    RefineOptions ro;
    ro.width = o.width;
    ro.coarse = o.points;
    ro.rel_tol = o.rel_tol;
    ro.guarantee_below = (M_PI / 2 - alpha) / alpha;
    const RefinedSet set = refine_set([&sampler](double q) { return sampler(q); },
                                      [&](double q) { return collapses_at_q(input, alpha, p, q, o); }, o.q_min,
                                      o.q_max, ro);
    for (const GridPoint& at : log_grid(o.q_min, o.q_max, o.points, false, {})) {
        const auto k = std::lower_bound(set.xs.begin(), set.xs.end(), at.x) - set.xs.begin();
        ida.points.push_back({at.x, GridKind::main, set.collapse[k]});
    }
    for (const Span& span : set.spans) ida.intervals.push_back(interval_of(span, set.brackets));
    ida.samples = set.samples;
    ida.simulations = set.samples + set.bisection_runs;
    ida.accepted = set.accepted;
    ida.at_width = set.at_width;
    ida.unguaranteed_from = set.unguaranteed_from;
    check_brackets(ida, input, alpha, p, o);
    summarise(ida, o);
    return ida;
}

}  // namespace

double lowest_lift_q(double alpha, double p, const records::CollapseOptions& model) {
    if (!model.imperfection.any()) return 1.0;
    return std::fmin(1.0, records::model_of(alpha, p, model).alpha_min() / alpha);
}

double IdaOptions::q_start(double alpha, double p) const { return std::fmin(q_min, lowest_lift_q(alpha, p, model)); }

std::string IdaOptions::describe_q() const {
    if (!model.imperfection.any()) return "q = PGA/(alpha g), 1 where the record reaches the linearised uplift threshold";
    return "q = PGA/(alpha g) with the nominal alpha";
}

Ida incremental_dynamic_analysis(const GroundInput& input, double alpha, double p, const IdaOptions& given) {
    check_options(input, alpha, p, given);
    IdaOptions o = given;
    o.q_min = given.q_start(alpha, p);
    if (o.method == IdaOptions::Method::refine) {
        Ida ida = refined_ida(input, alpha, p, o);
        ida.q_start = o.q_min;
        return ida;
    }
    Ida ida;
    ida.q_start = o.q_min;
    ida.alpha = alpha;
    ida.p = p;
    ida.q_input = input.peak() / alpha;
    const auto collapses = [&](double q) { return collapses_at_q(input, alpha, p, q, o); };

    std::vector<double> qs;
    std::vector<bool> outcomes;
    for (const GridPoint& at : log_grid(o.q_min, o.q_max, o.points, o.offset_grid, {})) {
        const bool c = collapses(at.x);
        ida.points.push_back({at.x, at.kind, c});
        qs.push_back(at.x);
        outcomes.push_back(c);
    }
    ida.simulations = static_cast<long>(qs.size());

    std::vector<Bracket> brackets;
    for (std::size_t k = 1; k < qs.size(); ++k)
        if (outcomes[k] != outcomes[k - 1])
            brackets.push_back(bisect_boundary(collapses, qs[k - 1], outcomes[k - 1], qs[k], o.rel_tol, ida.simulations));
    for (const Span& span : spans_of(qs, outcomes, brackets)) ida.intervals.push_back(interval_of(span, brackets));
    check_brackets(ida, input, alpha, p, o);
    summarise(ida, o);
    return ida;
}

namespace {

// Points whose ln L has no maximum (no collapse, or every collapse at one q
// with no censored record above it: the same record twice, say) are an
// answer about the records, not an error.  `points` in the draw order.
void fit_capacity(CapacityFit& c, const std::vector<IdaPoint>& points, const FragilityStudyOptions& o) {
    c.no_fit = why_no_maximum(points);
    if (!c.no_fit.empty()) return;
    c.fit = fit_lognormal(points);
    c.fitted = true;
    if (o.resamples > 0) {
        c.interval = bootstrap(points, o.resamples, o.seed, o.level);
        c.bootstrapped = true;
    }
}

// The shares are kept in the IDAs' order (a front end lists them so); the
// stripes' sums, the fit and the bootstrap take them in the draw order.
void fit_stripe_set(StripeFit& s, const std::vector<Ida>& idas, const std::vector<std::size_t>& order,
                    const FragilityStudyOptions& o) {
    std::vector<std::vector<Span>> sets;
    for (const Ida& ida : idas) {
        std::vector<Span> set;
        for (const IdaInterval& in : ida.intervals) set.push_back(Span{in.from, in.to, -1, -1});
        sets.push_back(std::move(set));
    }
    // The block's own grid (IdaOptions::q_start): every IDA of it started there.
    s.shares = stripe_shares(sets, idas.front().q_start, o.ida.q_max, o.ida.points);
    StripeShares drawn = s.shares;
    drawn.share = in_draw_order(s.shares.share, order);
    s.stripes = stripes_of(drawn);
    s.no_fit = why_no_stripe_maximum(s.stripes);
    if (!s.no_fit.empty()) return;
    s.fit = fit_stripes(s.stripes);
    s.fitted = true;
    if (o.resamples > 0) {
        s.interval = bootstrap_stripes(drawn, o.resamples, o.seed, o.level);
        s.bootstrapped = true;
    }
}

}  // namespace

BlockFragility block_fragility(const BlockShape& block, std::vector<Ida> idas, const std::vector<std::string>& identities,
                               const FragilityStudyOptions& o) {
    BlockFragility f;
    f.block = block;
    for (const Ida& ida : idas) f.points.push_back(ida.point);
    f.idas = std::move(idas);
    f.identities = identities;
    f.draw_order = draw_order(identities);
    const std::vector<IdaPoint> drawn = in_draw_order(f.points, f.draw_order);
    f.empirical = empirical_curve(f.points);
    CapacityFit first;
    fit_capacity(first, drawn, o);
    f.fitted = first.fitted, f.no_fit = first.no_fit, f.fit = first.fit;
    f.bootstrapped = first.bootstrapped, f.interval = first.interval;
    if (o.ida.method == IdaOptions::Method::refine && !f.idas.empty()) {
        f.three_ways = true;
        for (const Ida& ida : f.idas) f.robust.points.push_back(ida.first_robust_collapse);
        fit_capacity(f.robust, in_draw_order(f.robust.points, f.draw_order), o);
        fit_stripe_set(f.stripes, f.idas, f.draw_order, o);
    }
    return f;
}

std::vector<BlockFragility> fragility_study(const std::vector<const GroundInput*>& inputs,
                                            const std::vector<std::string>& identities,
                                            const std::vector<BlockShape>& blocks, const FragilityStudyOptions& o) {
    if (identities.size() != inputs.size())
        throw std::invalid_argument("fragility: " + std::to_string(identities.size()) + " identities for " +
                                    std::to_string(inputs.size()) + " records");
    // Every (block, input) IDA is a job of the batch engine, block by block;
    // then every block's fit.  The pool hands the results back in this order,
    // so the study is the same on any number of threads.
    std::vector<std::vector<Ida>> idas(blocks.size());
    const std::size_t n = inputs.size();
    const batch::PoolOptions pool{o.threads};
    batch::run_ordered<Ida>(
        blocks.size() * n, pool,
        [&](std::size_t job) {
            return incremental_dynamic_analysis(*inputs[job % n], blocks[job / n].alpha, blocks[job / n].p, o.ida);
        },
        [&](std::size_t job, Ida& ida) { idas[job / n].push_back(std::move(ida)); });
    std::vector<BlockFragility> out(blocks.size());
    batch::run_ordered<BlockFragility>(
        blocks.size(), pool,
        [&](std::size_t b) { return block_fragility(blocks[b], std::move(idas[b]), identities, o); },
        [&](std::size_t b, BlockFragility& f) { out[b] = std::move(f); });
    return out;
}

std::vector<BlockFragility> fragility_study(const std::vector<const GroundInput*>& inputs,
                                            const std::vector<BlockShape>& blocks, const FragilityStudyOptions& o) {
    return fragility_study(inputs, input_digests(inputs), blocks, o);
}

}  // namespace rocking::studies
