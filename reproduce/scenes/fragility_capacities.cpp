// The fragility scene's second half (issue 39, item 4): every record's IDA on
// every block again, by the refine method at a width w (docs/overturning_set.md),
// so that the scene shows both: the grid method's first collapse (fragility.cpp,
// its files unchanged) and, here, each record's first overturning and first
// robust collapse, the three fits of docs/fragility.md ("Three capacities") and
// eq. 27's share under each capacity (docs/eq27_at_scale.md).
#include "fragility_capacities.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "batch/pool.hpp"
#include "harness/compare.hpp"
#include "harness/table.hpp"
#include "studies/eq27_at_scale.hpp"
#include "studies/fragility.hpp"
#include "studies/ida.hpp"

namespace rocking::scenes {

const std::array<const char*, 5> kCapacityFiles = {"fragility_capacities.csv", "fragility_capacity_fits.csv",
                                                   "fragility_stripe_shares.csv", "fragility_stripe_fits.csv",
                                                   "fragility_capacity_eq27.csv"};

namespace {

using namespace fragility_scene;
using studies::BlockFragility;
using studies::Confirmation;
using studies::Ida;
using studies::IdaInterval;

// w in ln q.  At 1e-3 the refine IDAs of the 16 shared records on the four
// blocks cost 22 s of CPU and the 20 synthetic records' 21 s, inside the
// scene's budget of about a minute; 5e-4 costs 41 s for the shared records
// alone (expected/fragility/PROVENANCE.md, "Under each capacity").
constexpr double kWidth = 1e-3;

studies::FragilityStudyOptions refine_options() {
    studies::FragilityStudyOptions o = study_options();
    o.ida.method = studies::IdaOptions::Method::refine;
    o.ida.width = kWidth;  // robust_width: the library's 5e-3
    return o;
}

struct CapacityRun {
    const CapacitySet* in = nullptr;
    std::vector<BlockFragility> study;
    std::vector<std::vector<std::string>> reference;  // reference[b][r], on the first overturning's bracket
};

bool ill(const IdaInterval& in) {
    return in.has_lower && in.lower_check.confirmation == Confirmation::ill_conditioned;
}

bool ill_first_overturning(const Ida& ida) {
    return ida.first_overturning.collapsed && !ida.intervals.empty() && ill(ida.intervals.front());
}

// The interval that starts at the first robust collapse (nullptr when censored).
const IdaInterval* robust_interval(const Ida& ida) {
    if (!ida.first_robust_collapse.collapsed) return nullptr;
    for (const IdaInterval& in : ida.intervals)
        if (in.from == ida.first_robust_collapse.q) return &in;
    throw std::logic_error("fragility: a first robust collapse that starts no interval");
}

// Whether the first robust collapse is the first overturning with an ill-conditioned bracket.
bool ill_robust(const Ida& ida) {
    const IdaInterval* r = robust_interval(ida);
    return r && r == &ida.intervals.front() && ill(*r);
}

CapacityRun run(const CapacitySet& in, bool reference_mode) {
    CapacityRun out;
    out.in = &in;
    studies::FragilityStudyOptions o = refine_options();
    o.threads = batch::default_threads();
    out.study = studies::fragility_study(in.inputs, in.identities, kBlocks, o);
    const std::size_t n = in.inputs.size();
    out.reference.assign(kBlocks.size(), std::vector<std::string>(n));
    batch::run_ordered<std::string>(
        kBlocks.size() * n, batch::PoolOptions{o.threads},
        [&](std::size_t job) -> std::string {
            if (!reference_mode) return harness::kNotChecked;
            const Ida& ida = out.study[job / n].idas[job % n];
            const bool has = ida.first_overturning.collapsed && ida.intervals.front().has_lower &&
                             ida.intervals.front().lower_check.confirmation == Confirmation::confirmed;
            return has ? reference_verdict(*in.inputs[job % n], ida.alpha, ida.p, ida.intervals.front().lower) : "-";
        },
        [&](std::size_t job, std::string& v) { out.reference[job / n][job % n] = v; });
    return out;
}

const std::vector<std::string> kPointColumns = {
    "record", "alpha", "p", "q_input", "outcome", "q_first_overturning", "q_safe", "q_ill_first_overturning",
    "q_ill_safe", "q_censored", "check", "reference", "robust_outcome", "q_robust_collapse", "q_robust_safe",
    "intervals", "below_robust", "below_robust_percent"};
const std::vector<std::string> kFitValues = {
    "ill_conditioned", "median", "beta", "log_likelihood", "median_lo", "median_hi", "beta_lo", "beta_hi",
    "median_ill", "beta_ill", "log_likelihood_ill", "median_lo_ill", "median_hi_ill", "beta_lo_ill", "beta_hi_ill",
    "resamples", "seed", "level", "no_fit"};
std::vector<std::string> fit_columns(std::vector<std::string> lead) {
    lead.insert(lead.end(), kFitValues.begin(), kFitValues.end());
    return lead;
}
const std::vector<std::string> kEq27Columns = {
    "capacity", "k", "non_conservative", "cases", "censored", "share", "wilson_lo", "wilson_hi", "blocks_with_any",
    "records_with_any", "records", "boot_lo", "boot_hi", "boot_level", "resamples", "seed"};

std::vector<std::string> columns(std::vector<std::string> c, bool with_set) {
    if (with_set) c.insert(c.begin(), "set");
    return c;
}

void add_points(harness::Table& t, const CapacityRun& run) {
    const CapacitySet& in = *run.in;
    for (std::size_t b = 0; b < kBlocks.size(); ++b)
        for (std::size_t r = 0; r < in.names.size(); ++r) {
            const Ida& ida = run.study[b].idas[r];
            t.row();
            if (!in.set.empty()) t.add(in.set);
            t.add(in.names[r]).add(label(ida.alpha)).add(label(ida.p)).add(ida.q_input);
            // q_censored: q_max where either capacity is censored (the robust one is whenever the
            // first overturning is).
            const std::string censored_at =
                ida.first_robust_collapse.collapsed ? "-" : harness::format_number(ida.first_robust_collapse.q);
            if (!ida.first_overturning.collapsed) {
                t.add("censored").add("-").add("-").add("-").add("-").add(censored_at).add("-");
            } else {
                const IdaInterval& first = ida.intervals.front();
                const std::string check = studies::confirmation_name(first.lower_check.confirmation);
                t.add("collapsed");
                if (!first.has_lower) t.add(first.from).add("-").add("-").add("-").add(censored_at).add("grid start");
                else if (ill(first))
                    t.add("-").add("-").add(first.lower.collapse).add(first.lower.safe).add(censored_at).add(check);
                else t.add(first.lower.collapse).add(first.lower.safe).add("-").add("-").add(censored_at).add(check);
            }
            t.add(run.reference[b][r]);
            const IdaInterval* robust = robust_interval(ida);
            if (!robust) t.add("censored").add("-").add("-");
            else {
                t.add("collapsed").add(robust->from);
                if (robust->has_lower) t.add(robust->lower.safe);
                else t.add("-");
            }
            int below = 0;
            for (const IdaInterval& i : ida.intervals) below += !robust || i.from < robust->from;
            t.add(static_cast<int>(ida.intervals.size())).add(below);
            if (robust && ida.first_overturning.collapsed)
                t.add(100 * (1 - ida.first_overturning.q / ida.first_robust_collapse.q));
            else t.add("-");
        }
}

// One fit's row: a block whose points include an ill-conditioned boundary has
// its values in the *_ill columns, held to that boundary's effect (TOLERANCES).
struct FitRow {
    std::vector<std::string> counts;  // the cells between the block and ill_conditioned
    int ill = 0;
    bool fitted = false;
    double median = 0, beta = 0, log_likelihood = 0;
    bool bootstrapped = false;
    studies::BootstrapInterval interval;
    std::string no_fit;
};

void add_fit(harness::Table& t, const std::string& set, const studies::BlockShape& block, const FitRow& f) {
    t.row();
    if (!set.empty()) t.add(set);
    t.add(label(block.alpha)).add(label(block.p));
    for (const std::string& c : f.counts) t.add(c);
    t.add(f.ill);
    for (int half = 0; half < 2; ++half) {  // 0: the well-conditioned columns, 1: the *_ill ones
        const bool mine = (half == 1) == (f.ill > 0);
        if (mine && f.fitted) t.add(f.median).add(f.beta).add(f.log_likelihood);
        else t.add("-").add("-").add("-");
        if (mine && f.bootstrapped)
            t.add(f.interval.median.lo).add(f.interval.median.hi).add(f.interval.beta.lo).add(f.interval.beta.hi);
        else t.add("-").add("-").add("-").add("-");
    }
    if (f.bootstrapped) t.add(f.interval.resamples).add(std::to_string(f.interval.seed)).add(f.interval.level);
    else t.add("-").add("-").add("-");
    t.add(f.fitted ? "-" : f.no_fit);
}

FitRow capacity_row(const char* name, const studies::CapacityFit& c, int ill) {
    FitRow f;
    int collapsed = 0;
    for (const studies::IdaPoint& p : c.points) collapsed += p.collapsed;
    const int n = static_cast<int>(c.points.size());
    f.counts = {name, std::to_string(n), std::to_string(collapsed), std::to_string(n - collapsed)};
    f.ill = ill;
    f.fitted = c.fitted;
    f.median = c.fit.median;
    f.beta = c.fit.beta;
    f.log_likelihood = c.fit.log_likelihood;
    f.bootstrapped = c.bootstrapped;
    f.interval = c.interval;
    f.no_fit = c.no_fit;
    return f;
}

// The fits on the points: the first overturning's and the first robust collapse's.
void add_point_fits(harness::Table& t, const CapacityRun& run) {
    for (const BlockFragility& f : run.study) {
        int ill_first = 0, ill_rob = 0;
        for (const Ida& ida : f.idas) ill_first += ill_first_overturning(ida), ill_rob += ill_robust(ida);
        // The first overturning's fit is the block's own (its points are the first overturnings).
        studies::CapacityFit first;
        first.points = f.points;
        first.fitted = f.fitted;
        first.no_fit = f.no_fit;
        first.fit = f.fit;
        first.bootstrapped = f.bootstrapped;
        first.interval = f.interval;
        add_fit(t, run.in->set, f.block, capacity_row("first_overturning", first, ill_first));
        add_fit(t, run.in->set, f.block, capacity_row("first_robust_collapse", f.robust, ill_rob));
    }
}

// The multiple-stripe fits, apart: their shares hold every boundary of every set, so
// their tolerances are not the points' (TOLERANCES).
void add_stripe_fits(harness::Table& t, const CapacityRun& run) {
    for (const BlockFragility& f : run.study) {
        FitRow s;
        s.counts = {std::to_string(f.idas.size()), std::to_string(f.stripes.stripes.size())};
        // An ill-conditioned first overturning is a boundary of its set: it moves one share.
        for (const Ida& ida : f.idas) s.ill += ill_first_overturning(ida);
        s.fitted = f.stripes.fitted;
        s.median = f.stripes.fit.median;
        s.beta = f.stripes.fit.beta;
        s.log_likelihood = f.stripes.fit.log_likelihood;
        s.bootstrapped = f.stripes.bootstrapped;
        s.interval = f.stripes.interval;
        s.no_fit = f.stripes.no_fit;
        add_fit(t, run.in->set, f.block, s);
    }
}

void add_shares(harness::Table& t, const CapacityRun& run) {
    const CapacitySet& in = *run.in;
    for (const BlockFragility& f : run.study)
        for (std::size_t r = 0; r < in.names.size(); ++r) {
            t.row();
            if (!in.set.empty()) t.add(in.set);
            t.add(in.names[r]).add(label(f.block.alpha)).add(label(f.block.p));
            for (double s : f.stripes.shares.share[r]) t.add(s);
        }
}

// Eq. 27 over one population: each record's two capacities on every block.
struct Eq27Input {
    std::string set;
    std::vector<std::vector<studies::Eq27Capacities>> capacities;  // [r][b]
    std::vector<std::vector<bool>> ill_first, ill_rob;             // [r][b]
    std::vector<HalfPeriodArray> to;
    std::vector<std::string> identities;
};

void append(Eq27Input& e, const CapacityRun& run) {
    for (std::size_t r = 0; r < run.in->names.size(); ++r) {
        e.capacities.emplace_back();
        e.ill_first.emplace_back();
        e.ill_rob.emplace_back();
        for (std::size_t b = 0; b < kBlocks.size(); ++b) {
            const Ida& ida = run.study[b].idas[r];
            e.capacities.back().push_back(studies::capacities_of(ida));
            e.ill_first.back().push_back(ill_first_overturning(ida));
            e.ill_rob.back().push_back(ill_robust(ida));
        }
        e.to.push_back(run.in->to[r]);
        e.identities.push_back(run.in->identities[r]);
    }
}

// How near the verdicts are to flipping: the smallest |ln(capacity q / eq. 27's q)|
// over the collapsed cases, well- and ill-conditioned apart.
std::string margin_note(const studies::Eq27Study& s, const std::vector<std::vector<bool>>& ill) {
    double well = 1e300, badly = 1e300;
    for (const studies::Eq27Case& c : s.cases) {
        if (!c.point.collapsed) continue;
        double& m = ill[c.record][c.block] ? badly : well;
        for (int k = 0; k < studies::kHalfPeriods; ++k) m = std::min(m, std::fabs(std::log(c.point.q / c.q_eq27[k])));
    }
    char b[200];
    if (badly < 1e300)
        std::snprintf(b, sizeof b, "%.3g over the well-conditioned cases, %.3g over the ill-conditioned", well, badly);
    else
        std::snprintf(b, sizeof b, "%.3g over the well-conditioned cases, no ill-conditioned case", well);
    return std::string("the smallest |ln(capacity q / eq. 27's q)|: ") + b +
           "; a verdict flips only if a capacity q moves by that much";
}

void add_eq27(harness::Table& t, const Eq27Input& e) {
    const studies::Eq27ByCapacity by = studies::eq27_by_capacity(e.capacities, e.to, e.identities, kBlocks,
                                                                 kWilsonLevel, {kResamples, kSeed, kBootstrapLevel});
    const std::string suffix = e.set.empty() ? "" : " " + e.set;
    t.note("margin first overturning" + suffix, margin_note(by.first_overturning, e.ill_first));
    t.note("margin first robust collapse" + suffix, margin_note(by.first_robust_collapse, e.ill_rob));
    for (const auto& [name, s] : {std::pair<const char*, const studies::Eq27Study*>{"first_overturning",
                                                                                    &by.first_overturning},
                                  {"first_robust_collapse", &by.first_robust_collapse}})
        for (int k = 0; k < studies::kHalfPeriods; ++k) {
            const studies::Eq27Share& sh = s->shares[k];
            int with_any = 0;
            for (const studies::Eq27Cell& c : s->map) with_any += c.non_conservative[k] > 0;
            t.row();
            if (!e.set.empty()) t.add(e.set);
            t.add(name).add(k + 1).add(sh.non_conservative).add(sh.cases).add(s->censored).add(sh.share);
            t.add(sh.wilson.lo).add(sh.wilson.hi).add(with_any).add(sh.records_with_any).add(sh.records);
            t.add(sh.bootstrap.lo).add(sh.bootstrap.hi).add(s->bootstrap.level).add(s->bootstrap.resamples);
            t.add(std::to_string(s->bootstrap.seed));
        }
}

}  // namespace

void write_capacities(SceneContext& ctx, const std::vector<CapacitySet>& sets, const std::string& prefix,
                      const std::string& inputs_text, const std::string& union_name) {
    std::vector<CapacityRun> runs;
    for (const CapacitySet& s : sets) runs.push_back(run(s, ctx.reference()));
    const studies::FragilityStudyOptions o = refine_options();
    const bool with_set = !sets.front().set.empty();
    const std::string model = o.ida.describe_model();
    const std::string solver = "exact solver (the record kernel); refine method (docs/overturning_set.md): " +
                               o.ida.describe_grid() + "; q = PGA/(alpha g), the record scaled (studies::scaled)";
    char bound[400];
    std::snprintf(bound, sizeof bound,
                  "every island and gap wider than w = %g in ln q is found below q = (pi/2 - alpha)/alpha (%.6g at "
                  "alpha 0.1, %.6g at alpha 0.2), where an overturning run must have a flight whose escape margin "
                  "is > 0; above it the search proves less; islands narrower than w may lie below any first "
                  "overturning, which is then an upper bound of the model's",
                  kWidth, (M_PI / 2 - 0.1) / 0.1, (M_PI / 2 - 0.2) / 0.2);
    int above = 0, firsts = 0;
    for (const CapacityRun& r : runs)
        for (const BlockFragility& f : r.study)
            for (const Ida& ida : f.idas)
                if (ida.first_overturning.collapsed) ++firsts, above += ida.first_overturning.q >= ida.unguaranteed_from;
    const std::string guarantee = std::string(bound) + "; " + std::to_string(above) + " of the " +
                                  std::to_string(firsts) + " first overturnings lie above that q";
    const std::string set_note = with_set ? "set: each set a separate population, its own fits and bootstrap; " : "";

    harness::Table pt(columns(kPointColumns, with_set));
    pt.note("scene", "fragility: each record's first overturning and first robust collapse q on each block, from its "
                     "IDA by the refine method (issue 39), beside " + prefix + "_points.csv's grid method");
    pt.note("model", model);
    pt.note("solver", solver);
    pt.note("width", guarantee);
    pt.note("check", o.ida.describe_checks() + " (the first overturning's bracket), in every run");
    pt.note("reference", ctx.reference() ? "both ends of every confirmed first-overturning bracket re-simulated by "
                                           "records::collapses_at with GSL rk8pd at rtol = atol = 1e-13 alpha "
                                           "(table1_check) on the record scaled to each end's q"
                                         : "reference column 'not checked' (see reproduce --reference fragility)");
    pt.note("inputs", inputs_text);
    char robust[120];
    std::snprintf(robust, sizeof robust, "%g", o.ida.robust_width);
    pt.note("columns",
            set_note + "q_input: the record's own q; outcome: collapsed (a first overturning up to q_max) or censored "
            "(q_censored); q_first_overturning / q_safe: the first overturning's bracket (1e-6 relative) where the "
            "check finds it well conditioned, q_ill_*: where the probe (input x 1 +- 1e-13) flips an outcome, placed by "
            "rounding between two samples at most w apart; check: that bracket's verdict; reference: the reference "
            "method's on a confirmed one; robust_outcome, q_robust_collapse: the start of the first interval of "
            "overturning wider than " + std::string(robust) + " in ln q, q_robust_safe the safe end of its bracket; "
            "intervals: the intervals of overturning found up to q_max; below_robust: those starting below the first "
            "robust collapse (all when it is censored); below_robust_percent: 100 (1 - first overturning / first robust "
            "collapse)");
    for (const CapacityRun& r : runs) add_points(pt, r);

    const std::string boot = bootstrap_text();
    const std::string fit_columns_note =
        "P(overturn | q) = Phi(ln(q / median) / beta); median_lo..hi, beta_lo..hi: the bootstrap's percentile "
        "interval; no_fit: why ln L has no maximum ('-' when fitted)";
    harness::Table ft(columns(fit_columns({"alpha", "p", "capacity", "records", "collapsed", "censored"}), with_set));
    ft.note("scene", "fragility: each block's lognormal fragility with the first overturning and with the first robust "
                     "collapse as the record's capacity (docs/fragility.md, 'Three capacities'; the third, the stripes, "
                     "in " + prefix + "_stripe_fits.csv), from " + prefix + "_capacities.csv");
    ft.note("model", model);
    ft.note("solver", solver + "; studies::fit_lognormal on the capacity's points (censored kept); bootstrap: " + boot +
                          ", the same draws for both");
    ft.note("inputs", inputs_text);
    ft.note("columns", set_note + "capacity: first_overturning (conservative) or first_robust_collapse; collapsed, "
                       "censored: the capacity's points; ill_conditioned: those with an ill-conditioned bracket, whose "
                       "block's fit is then in the *_ill columns; " + fit_columns_note);
    for (const CapacityRun& r : runs) add_point_fits(ft, r);

    harness::Table sf(columns(fit_columns({"alpha", "p", "records", "stripes"}), with_set));
    sf.note("scene", "fragility: each block's multiple-stripe fragility fit (docs/fragility.md, 'Three capacities'), "
                     "from " + prefix + "_stripe_shares.csv");
    sf.note("model", model);
    sf.note("solver", solver + "; studies::fit_stripes (Baker's multiple-stripe likelihood, each stripe's count the "
                               "sum of the records' overturned shares of it); bootstrap: " + boot +
                               ", as the point fits' draws");
    sf.note("inputs", inputs_text);
    sf.note("columns", set_note + "records, stripes: the records and stripes fitted; ill_conditioned: the block's "
                       "first overturnings with an ill-conditioned bracket (a boundary of a set, so a share), whose "
                       "fit is then in the *_ill columns; log_likelihood: without the binomial coefficients; " +
                       fit_columns_note);
    for (const CapacityRun& r : runs) add_stripe_fits(sf, r);

    std::vector<std::string> sc = columns({"record", "alpha", "p"}, with_set);
    for (int j = 1; j < o.ida.points; ++j) sc.push_back("stripe_" + std::to_string(j));
    harness::Table st(sc);
    st.note("scene", "fragility: each record's overturned share of each stripe on each block, the stripe fit's data");
    st.note("model", model);
    st.note("solver", solver);
    st.note("inputs", inputs_text);
    char grid[300];
    std::snprintf(grid, sizeof grid,
                  "stripe_j: the share, in ln q, of the main grid's step j, [q_(j-1), q_j], q_k = %g (%g/%g)^(k/%d), "
                  "that the record's set of overturning covers (studies::stripe_shares); the stripe's q is "
                  "sqrt(q_(j-1) q_j)",
                  o.ida.q_min, o.ida.q_max, o.ida.q_min, o.ida.points - 1);
    st.note("columns", set_note + grid);
    for (const CapacityRun& r : runs) add_shares(st, r);

    harness::Table et(columns(kEq27Columns, with_set));
    et.note("scene", "fragility: eq. 27's share of non-conservative cases per to_k under the first overturning and "
                     "under the first robust collapse (docs/eq27_at_scale.md, 'Under each capacity')");
    et.note("model", "eq. 27 (q2_n6 at x = p to_k) against each record's capacity q (" + prefix + "_capacities.csv)");
    et.note("solver", "studies::eq27_by_capacity on the refine IDAs of this scene; " + studies::eq27_refine_note(o.ida) +
                          "; bootstrap over records: " + boot + ", each drawn record bringing its cases on all " +
                          std::to_string(kBlocks.size()) + " blocks");
    et.note("inputs", inputs_text);
    et.note("capacity first_overturning", studies::kEq27FirstOverturningNote);
    et.note("capacity first_robust_collapse", studies::kEq27RobustCollapseNote);
    et.note("columns", (with_set ? "set: a set of records, or their union '" + union_name + "'; " : std::string()) +
                           "a case (record, block) is non-conservative for k when its capacity q < eq. 27's q; a "
                           "censored case never is (censored: the cases without that capacity up to q_max); " +
                           wilson_note() + "; blocks_with_any, records_with_any: blocks and records with a "
                           "non-conservative case, of records; boot_lo..hi: the percentile interval at boot_level of "
                           "the share over resamples of the records (the interval to quote)");
    std::vector<Eq27Input> ins;
    for (const CapacityRun& r : runs) {
        ins.emplace_back();
        ins.back().set = r.in->set;
        append(ins.back(), r);
    }
    if (runs.size() > 1) {
        ins.emplace_back();
        ins.back().set = union_name;
        for (const CapacityRun& r : runs) append(ins.back(), r);
    }
    for (const Eq27Input& e : ins) add_eq27(et, e);

    ctx.write(pt, prefix + "_capacities.csv");
    ctx.write(ft, prefix + "_capacity_fits.csv");
    ctx.write(st, prefix + "_stripe_shares.csv");
    ctx.write(sf, prefix + "_stripe_fits.csv");
    ctx.write(et, prefix + "_capacity_eq27.csv");
}

}  // namespace rocking::scenes
