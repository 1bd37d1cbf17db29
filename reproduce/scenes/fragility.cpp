// Fragility of a few blocks over the shared records and over a fixed synthetic
// set (issue 28, item 5): each record's incremental dynamic analysis (IDA) on
// each block, its first collapse q with the check of that bracket, the
// lognormal fit per block with a seeded bootstrap interval, and eq. 27's share
// of non-conservative cases per to_k over the same points (no IDA is run
// twice), with its bootstrap over records (the same resamples, seed and level
// as the fits').
//
// The shared records' files (fragility_*.csv) are written only when the
// records folder is there; the synthetic set's (fragility_synthetic_*.csv) is
// generated at run time (Mavroeidis & Papageorgiou 2003 pulses and Rezaeian &
// Der Kiureghian 2008 stochastic records, records/synthetic.hpp) and always
// written: it needs no file.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "batch/pool.hpp"
#include "dynamics/ground_input.hpp"
#include "harness/compare.hpp"
#include "harness/table.hpp"
#include "qfactor/closed_forms.hpp"
#include "records/measures.hpp"
#include "records/record.hpp"
#include "records/synthetic.hpp"
#include "fragility_capacities.hpp"
#include "fragility_eq27.hpp"
#include "fragility_scene.hpp"
#include "fragility_synthetic.hpp"
#include "records_analysis.hpp"
#include "scene.hpp"
#include "studies/eq27_at_scale.hpp"
#include "studies/fragility.hpp"
#include "studies/ida.hpp"
#include "studies/scaled_input.hpp"

namespace rocking::scenes {

namespace {

using studies::BlockFragility;
using studies::BlockShape;
using studies::Confirmation;
using studies::Ida;
using namespace fragility_scene;

// The same words as the other record scenes, so a reader sees one reason.
const std::array<const char*, 4> kFiles = {"fragility_points.csv", "fragility_fits.csv", "fragility_eq27.csv",
                                           "fragility_empirical.csv"};

bool well_conditioned(Confirmation c) { return c == Confirmation::confirmed || c == Confirmation::disagrees; }

bool ill_first_collapse(const Ida& ida) {
    return ida.point.collapsed && !ida.intervals.empty() && ida.intervals.front().has_lower &&
           ida.intervals.front().lower_check.confirmation == Confirmation::ill_conditioned;
}

// One set of records through the study: the shared records (set "", whose
// files have no set column) or one synthetic set.
struct SetRun {
    std::string set;
    std::vector<std::string> names;  // each record's row label
    std::vector<std::string> identities;  // the draw order's keys (identity_of)
    std::vector<std::unique_ptr<dynamics::SampledInput>> owned;
    std::vector<const dynamics::GroundInput*> inputs;
    std::vector<HalfPeriodArray> to;
    std::vector<double> pulse_half;  // 1/(2 fp) for a pulse, 0 otherwise
    std::vector<BlockFragility> study;
    std::vector<std::vector<std::string>> reference;  // reference[b][r]
};

void add_record(SetRun& s, const records::Record& rec, const std::string& name, const HalfPeriodArray& to,
                double pulse_half, bool generated) {
    s.owned.push_back(std::make_unique<dynamics::SampledInput>(rec.in_g(9.81), rec.dt, rec.name));  // as table1
    s.inputs.push_back(s.owned.back().get());
    s.names.push_back(name);
    s.identities.push_back(identity_of(*s.owned.back(), generated, name));
    s.to.push_back(to);
    s.pulse_half.push_back(pulse_half);
}

// The study on the batch engine's threads (every (block, record) IDA a job),
// then the reference method's verdicts, one job a (block, record): the engine
// returns both in order, so the threads change the time, never a value.
void run_set(SetRun& s, bool reference_mode) {
    studies::FragilityStudyOptions threaded = study_options();
    threaded.threads = batch::default_threads();
    s.study = studies::fragility_study(s.inputs, s.identities, kBlocks, threaded);
    const std::size_t n = s.inputs.size();
    s.reference.assign(kBlocks.size(), std::vector<std::string>(n));
    batch::run_ordered<std::string>(
        kBlocks.size() * n, batch::PoolOptions{threaded.threads},
        [&](std::size_t job) -> std::string {
            if (!reference_mode) return harness::kNotChecked;
            const Ida& ida = s.study[job / n].idas[job % n];
            const bool has = !ida.intervals.empty() && ida.intervals.front().has_lower &&
                             ida.intervals.front().lower_check.confirmation == Confirmation::confirmed;
            return has ? reference_verdict(*s.inputs[job % n], ida.alpha, ida.p, ida.intervals.front().lower) : "-";
        },
        [&](std::size_t job, std::string& v) { s.reference[job / n][job % n] = v; });
}

const char* kPointColumnsNote =
    "q_input: the record's own q, unscaled; outcome: collapsed (first collapse found) or censored (none up to "
    "q_max: q_censored); q_collapse / q_safe: the first collapse's bracket (1e-6 relative) where the check "
    "finds it well conditioned, q_ill_*: where the probe (input x 1 +- 1e-13) flips an outcome, placed by "
    "rounding within its grid gap; a first collapse at the grid's start has q_collapse = q_min and no bracket; "
    "intervals: the number of overturning intervals in q up to q_max; check: the first bracket's verdict "
    "(confirmed, ill-conditioned, second solver disagrees); reference: the reference method's verdict on a "
    "confirmed bracket";

// The point rows of a set: record-major within each block, block by block.
// with_pulse: the synthetic file's two more columns, eq. 27 at the pulse's own half-period.
void add_points(harness::Table& pt, const SetRun& s, bool with_pulse) {
    for (std::size_t b = 0; b < kBlocks.size(); ++b) {
        for (std::size_t r = 0; r < s.names.size(); ++r) {
            const Ida& ida = s.study[b].idas[r];
            pt.row();
            if (!s.set.empty()) pt.add(s.set);
            pt.add(s.names[r]).add(label(ida.alpha)).add(label(ida.p)).add(ida.q_input);
            auto pulse_columns = [&] {  // and the identity, the row's last cell
                if (with_pulse && s.pulse_half[r] <= 0) pt.add("-").add("-");
                if (with_pulse && s.pulse_half[r] > 0) {
                    const double q27 = q2_n6(ida.p * s.pulse_half[r]);
                    pt.add(q27).add(studies::non_conservative(ida.point, q27) ? "yes" : "no");
                }
                pt.add(s.identities[r]);
            };
            if (!ida.point.collapsed) {
                pt.add("censored").add("-").add("-").add("-").add("-").add(ida.point.q);
                pt.add(static_cast<int>(ida.intervals.size())).add("-").add(s.reference[b][r]);
                pulse_columns();
                continue;
            }
            const studies::IdaInterval& first = ida.intervals.front();
            pt.add("collapsed");
            if (!first.has_lower) {
                pt.add(ida.point.q).add("-").add("-").add("-").add("-");
                pt.add(static_cast<int>(ida.intervals.size())).add("grid start").add(s.reference[b][r]);
                pulse_columns();
                continue;
            }
            if (well_conditioned(first.lower_check.confirmation))
                pt.add(first.lower.collapse).add(first.lower.safe).add("-").add("-");
            else
                pt.add("-").add("-").add(first.lower.collapse).add(first.lower.safe);
            pt.add("-").add(static_cast<int>(ida.intervals.size()));
            pt.add(studies::confirmation_name(first.lower_check.confirmation)).add(s.reference[b][r]);
            pulse_columns();
            if (!first.lower_check.detail.empty())
                pt.note("detail " + s.names[r] + " alpha " + label(ida.alpha) + " p " + label(ida.p),
                        first.lower_check.detail);
        }
    }
}

// A block whose points include an ill-conditioned first collapse (placed by
// rounding within its grid gap) has its fit in the *_ill columns, held to
// that gap's effect (TOLERANCES); the others' to the bisection's 1e-6.
void add_fits(harness::Table& ft, const SetRun& s) {
    for (const BlockFragility& f : s.study) {
        int collapsed = 0, ill = 0;
        for (const studies::IdaPoint& p : f.points) collapsed += p.collapsed;
        for (const Ida& ida : f.idas) ill += ill_first_collapse(ida);
        ft.row();
        if (!s.set.empty()) ft.add(s.set);
        ft.add(label(f.block.alpha)).add(label(f.block.p)).add(static_cast<int>(f.points.size()));
        ft.add(collapsed).add(static_cast<int>(f.points.size()) - collapsed).add(ill);
        for (int set = 0; set < 2; ++set) {  // 0: the well-conditioned columns, 1: the *_ill ones
            const bool mine = (set == 1) == (ill > 0);
            if (mine && f.fitted) ft.add(f.fit.median).add(f.fit.beta).add(f.fit.log_likelihood);
            else ft.add("-").add("-").add("-");
            if (mine && f.bootstrapped)
                ft.add(f.interval.median.lo).add(f.interval.median.hi).add(f.interval.beta.lo).add(f.interval.beta.hi);
            else ft.add("-").add("-").add("-").add("-");
        }
        if (f.bootstrapped)
            ft.add(f.interval.resamples).add(std::to_string(f.interval.seed)).add(f.interval.level);
        else ft.add("-").add("-").add("-");
        if (!f.fitted)
            ft.note("no fit " + (s.set.empty() ? "" : s.set + " ") + "alpha " + label(f.block.alpha) + " p " +
                        label(f.block.p),
                    f.no_fit);
    }
}

void append(Eq27Input& in, const SetRun& s) {
    for (std::size_t r = 0; r < s.names.size(); ++r) {
        in.names.push_back(s.names[r]);
        in.identities.push_back(s.identities[r]);
        in.to.push_back(s.to[r]);
        in.points.emplace_back();
        in.ill.emplace_back();
        for (std::size_t b = 0; b < kBlocks.size(); ++b) {
            in.points.back().push_back(s.study[b].points[r]);
            in.ill.back().push_back(ill_first_collapse(s.study[b].idas[r]));
        }
    }
}

const std::vector<std::string> kPointColumns = {"record", "alpha", "p", "q_input", "outcome", "q_collapse",
                                                "q_safe", "q_ill_collapse", "q_ill_safe", "q_censored",
                                                "intervals", "check", "reference", "identity"};
const std::vector<std::string> kFitColumns = {
    "alpha", "p", "records", "collapsed", "censored", "ill_conditioned", "median", "beta", "log_likelihood",
    "median_lo", "median_hi", "beta_lo", "beta_hi", "median_ill", "beta_ill", "log_likelihood_ill",
    "median_lo_ill", "median_hi_ill", "beta_lo_ill", "beta_hi_ill", "resamples", "seed", "level"};
const std::vector<std::string> kEq27Columns = {"k", "non_conservative", "cases", "share", "wilson_lo", "wilson_hi",
                                               "blocks_with_any", "records_with_any", "records", "boot_lo",
                                               "boot_hi", "boot_level", "resamples", "seed"};

std::vector<std::string> with_set(std::vector<std::string> columns) {
    columns.insert(columns.begin(), "set");
    return columns;
}

std::string reference_text(bool reference_mode) {
    return reference_mode ? "both ends of every confirmed first-collapse bracket re-simulated by "
                            "records::collapses_at with GSL rk8pd at rtol = atol = 1e-13 alpha (table1_check) on the "
                            "record scaled to each end's q; yes when it sees the same bracket"
                          : "reference column 'not checked' (see reproduce --reference fragility)";
}

// The same records for the refine method's files (fragility_capacities.cpp).
CapacitySet capacity_set(const SetRun& s) { return {s.set, s.names, s.identities, s.inputs, s.to}; }

// ---- The shared records ----

void run_shared_records(SceneContext& ctx, const std::vector<RecordRow>& rows) {
    SetRun s;
    for (const RecordRow& r : rows) {
        const records::Record rec = records::read_any(records_dir() + "/" + r.file);
        add_record(s, rec, r.file, r.h.to, 0, false);
    }
    run_set(s, ctx.reference());
    const studies::FragilityStudyOptions o = study_options();

    Eq27Input in;
    append(in, s);
    const studies::Eq27Study eq27 = eq27_of(in);

    const std::string model = o.ida.describe_model();
    const std::string grid = o.ida.describe_grid() + "; q = PGA/(alpha g), the record scaled (studies::scaled)";
    const std::string checks = o.ida.describe_checks() + ", in every run (the verdict is part of the result)";
    const std::string inputs_text =
        "every record of the records folder (../shared/records or $ROCKING_RECORDS: esm/ and peer/, as table1), "
        "in g with g = 9.81 m/s^2; " + blocks_text();
    const std::string boot = bootstrap_text();

    harness::Table pt(kPointColumns);
    pt.note("scene", "fragility: each record's first collapse q on each block, from its incremental dynamic analysis");
    pt.note("model", model);
    pt.note("solver", "exact solver (the record kernel); " + grid);
    pt.note("check", checks);
    pt.note("reference", reference_text(ctx.reference()));
    pt.note("inputs", inputs_text);
    pt.note("columns", kPointColumnsNote);
    pt.note("identity", kIdentityNote);
    add_points(pt, s, false);

    harness::Table ft(kFitColumns);
    ft.note("scene", "fragility: the lognormal fragility curve of each block over the records, by maximum likelihood");
    ft.note("model", model);
    ft.note("solver",
            "studies::fit_lognormal (Baker 2015, censored records kept: closed form without censoring, Newton in "
            "Olsen's concave parameters otherwise) on fragility_points.csv's points; bootstrap: " + boot);
    ft.note("inputs", inputs_text);
    ft.note("columns",
            "P(overturn | q) = Phi(ln(q / median) / beta); median_lo..hi, beta_lo..hi: the bootstrap's percentile "
            "interval; '-' where the block has no fit; ill_conditioned: the block's first collapses whose bracket is "
            "ill-conditioned (fragility_points.csv), whose fit is then in the *_ill columns");
    add_fits(ft, s);

    harness::Table et(kEq27Columns);
    et.note("scene", "fragility: eq. 27's share of non-conservative cases per to_k over these records and blocks");
    et.note("model", "eq. 27 (q2_n6 at x = p to_k) against each record's first collapse q (fragility_points.csv)");
    et.note("solver", "studies::eq27_from_points on the IDA points of this scene (no IDA rerun); bootstrap over "
                      "records: " + boot + ", each drawn record bringing its cases on all " +
                      std::to_string(kBlocks.size()) + " blocks, the same draws for every k");
    et.note("inputs", inputs_text + "; to_k: the records' half-periods (table2)");
    et.note("columns",
            "a case (record, block) is non-conservative for k when collapse q < eq. 27's q; a censored record never "
            "is (" + std::to_string(eq27.censored) + " censored cases); " + wilson_note() +
                "; blocks_with_any: blocks on which at least one record is non-conservative; records_with_any: "
                "records non-conservative on at least one block, of records; boot_lo..hi: the percentile interval "
                "at boot_level of the share over resamples of the records (the interval to quote)");
    eq27_notes(et, in, eq27, "");
    eq27_rows(et, eq27, "");

    harness::Table em({"alpha", "p", "q", "share"});
    em.note("scene", "fragility: the empirical curves, the plot's data (not compared: see expected/fragility/TOLERANCES)");
    em.note("columns", "at each collapse q of the block, the share of all records (censored counted) overturned at or below it");
    for (const BlockFragility& f : s.study)
        for (const studies::EmpiricalPoint& e : f.empirical)
            em.row().add(label(f.block.alpha)).add(label(f.block.p)).add(e.q).add(e.share);

    ctx.write(pt, "fragility_points.csv");
    ctx.write(ft, "fragility_fits.csv");
    ctx.write(et, "fragility_eq27.csv");
    ctx.write(em, "fragility_empirical.csv");
    write_capacities(ctx, {capacity_set(s)}, "fragility", inputs_text);
}

void run_synthetic(SceneContext& ctx) {
    // The records and their half-periods, one job a record (the stochastic sum
    // is the costly part); the engine hands them back in order.
    const std::vector<Synthetic> set_list = synthetic_set();
    std::vector<records::HalfPeriods> h(set_list.size());
    batch::run_ordered<records::HalfPeriods>(
        set_list.size(), batch::PoolOptions{batch::default_threads()},
        [&](std::size_t i) { return records::half_periods(set_list[i].record); },
        [&](std::size_t i, records::HalfPeriods& v) { h[i] = v; });

    std::vector<SetRun> sets(2);
    sets[0].set = "pulse";
    sets[1].set = "stochastic";
    for (std::size_t i = 0; i < set_list.size(); ++i) {
        SetRun& s = sets[set_list[i].set == "pulse" ? 0 : 1];
        add_record(s, set_list[i].record, set_list[i].record.name, h[i].to, set_list[i].pulse_half, true);
    }
    for (SetRun& s : sets) run_set(s, ctx.reference());
    const studies::FragilityStudyOptions o = study_options();

    const std::string model = o.ida.describe_model();
    const std::string grid = o.ida.describe_grid() + "; q = PGA/(alpha g), the record scaled (studies::scaled)";
    const std::string checks = o.ida.describe_checks() + ", in every run (the verdict is part of the result)";
    const records::StochasticParameters d = records::default_stochastic_parameters();
    // The set as the constants above define it: fp, T_p and (gamma, nu) listed from them.
    std::string fps, shapes;
    for (double fp : kPulseFp) fps += (fps.empty() ? "" : ", ") + g_text(fp);
    for (const PulseShape& sh : kPulseShapes)
        shapes += (shapes.empty() ? "(" : " and (") + g_text(sh.gamma) + ", " +
                  (sh.nu == M_PI / 2 ? std::string("pi/2") : g_text(sh.nu)) + ")";
    char pulses[800], stochastic[900];
    std::snprintf(pulses, sizeof pulses,
                  "set pulse: %zu Mavroeidis & Papageorgiou (2003) velocity pulses (records::pulse_record, the "
                  "acceleration its exact derivative), A = %g m/s, fp = %s Hz (T_p = %g to %g s), each with "
                  "(gamma, nu) = %s, t0 = %g s + gamma/(2 fp), %g s of rest after the pulse, dt = %g s; the record "
                  "label is the generator's name with every parameter",
                  sets[0].names.size(), kPulseA, fps.c_str(), 1 / kPulseFp.front(), 1 / kPulseFp.back(),
                  shapes.c_str(), kPulseRest, kPulseRest, kPulseDt);
    using D = records::StochasticDefaults;
    std::snprintf(stochastic, sizeof stochastic,
                  "set stochastic: %zu Rezaeian & Der Kiureghian (2008) modulated filtered white noise records "
                  "(records::stochastic_record, GSL mt19937 and gsl_ran_gaussian_ziggurat) for seeds 1 to %d, with "
                  "the documented defaults (records::StochasticDefaults: Ia = %g s g, D5-95 = %g s, t_mid = %g s, "
                  "fmid = %g Hz, f' = %g Hz/s, zeta_f = %g, post-filter corner %g Hz; alpha1 = %.10g, alpha2 = %.10g, "
                  "alpha3 = %.10g 1/s), dt = %g s over %g s",
                  sets[1].names.size(), kStochasticSeeds, D::Ia_s_g, D::D5_95_s, D::tmid_s, D::fmid_hz, D::fprime_hz_s,
                  D::zeta_f, D::fc_hz, d.alpha1, d.alpha2, d.alpha3, kStochasticDt, kStochasticDuration);
    const std::string inputs_text = std::string(pulses) + "; " + stochastic +
                                    "; generated at run time (no file), in g with g = 9.81 m/s^2; " + blocks_text();
    const std::string boot = bootstrap_text();
    const std::string sets_note =
        "each set (pulse, stochastic) is a separate population: its own fits, its own bootstrap over its own records";

    // The records: generator, parameters, half-periods, and which to_k recover a pulse's half-period.
    harness::Table rt({"set", "record", "dt", "duration", "samples", "pga_ms2", "pgv_ms", "to_1", "to_2", "to_3",
                       "to_4", "to_5", "to_6", "to_7", "to_8", "to_9", "to_10", "to_11", "to_pulse", "recovers",
                       "closest", "closest_ratio"});
    rt.note("scene", "fragility: the synthetic records, their half-periods, and for a pulse which to_k recover its own");
    rt.note("inputs", inputs_text);
    rt.note("solver", "records::half_periods (as table2's records: to_1..to_11, Section 4 of the paper)");
    char rec_note[700];
    std::snprintf(rec_note, sizeof rec_note,
                  "record: the generator's name of the record, with its parameters (MP2003 pulse A fp nu gamma t0, "
                  "RDK2008 stochastic seed); dt, duration: s; samples: floor(duration/dt) + 1; pga_ms2, pgv_ms: m/s^2, "
                  "m/s; to_k: s; to_pulse: the pulse's half-period T_p/2 = 1/(2 fp) ('-' for a stochastic record); "
                  "recovers: the k with |to_k/to_pulse - 1| <= %g; closest: the k with to_k/to_pulse nearest 1, "
                  "closest_ratio its to_k/to_pulse (docs/synthetic.md, 'The pulse as a truth for the half-periods', "
                  "has the same ratios over 36 pulses)",
                  kRecoverTol);
    rt.note("columns", rec_note);
    for (std::size_t i = 0; i < set_list.size(); ++i) {
        const records::Record& rec = set_list[i].record;
        rt.row().add(set_list[i].set).add(rec.name).add(rec.dt).add(set_list[i].duration);
        rt.add(static_cast<int>(rec.accel.size())).add(h[i].pga).add(h[i].pgv);
        for (double v : h[i].to) rt.add(v);
        const double half = set_list[i].pulse_half;
        if (half <= 0) {
            rt.add("-").add("-").add("-").add("-");
            continue;
        }
        int closest = 0;
        for (int k = 1; k < studies::kHalfPeriods; ++k)
            if (std::fabs(h[i].to[k] / half - 1) < std::fabs(h[i].to[closest] / half - 1)) closest = k;
        rt.add(half).add(recovering(h[i].to, half)).add(closest + 1).add(h[i].to[closest] / half);
    }

    harness::Table pt2([&] {
        std::vector<std::string> c = with_set(kPointColumns);
        c.insert(c.end() - 1, {"q_eq27_pulse", "non_conservative_pulse"});  // the identity last
        return c;
    }());
    pt2.note("scene", "fragility: each synthetic record's first collapse q on each block, from its incremental "
                      "dynamic analysis");
    pt2.note("model", model);
    pt2.note("solver", "exact solver (the record kernel); " + grid);
    pt2.note("check", checks);
    pt2.note("reference", reference_text(ctx.reference()));
    pt2.note("inputs", inputs_text);
    pt2.note("identity", kIdentityNote);
    pt2.note("columns", std::string("set: pulse or stochastic; ") + kPointColumnsNote +
                            "; q_eq27_pulse: eq. 27's q at x = p to_pulse, the pulse's own half-period 1/(2 fp) "
                            "(fragility_synthetic_records.csv), and non_conservative_pulse whether the first collapse "
                            "q lies below it (a censored point never does); '-' for a stochastic record");
    for (const SetRun& s : sets) add_points(pt2, s, true);

    harness::Table ft(with_set(kFitColumns));
    ft.note("scene", "fragility: the lognormal fragility curve of each block over each synthetic set, by maximum "
                     "likelihood");
    ft.note("model", model);
    ft.note("solver",
            "studies::fit_lognormal (Baker 2015, censored records kept: closed form without censoring, Newton in "
            "Olsen's concave parameters otherwise) on fragility_synthetic_points.csv's points of the set; bootstrap: " + boot);
    ft.note("inputs", inputs_text);
    ft.note("columns",
            "set: " + sets_note + "; P(overturn | q) = Phi(ln(q / median) / beta); median_lo..hi, beta_lo..hi: the "
            "bootstrap's percentile interval; '-' where the block has no fit; ill_conditioned: the block's first "
            "collapses whose bracket is ill-conditioned, whose fit is then in the *_ill columns");
    for (const SetRun& s : sets) add_fits(ft, s);

    // Eq. 27 per set, and over the union (its share depends on the mix, 10 pulses to 10 stochastic records).
    std::vector<Eq27Input> ins(3);
    ins[0].set = "pulse";
    append(ins[0], sets[0]);
    ins[1].set = "stochastic";
    append(ins[1], sets[1]);
    ins[2].set = "synthetic";
    append(ins[2], sets[0]);
    append(ins[2], sets[1]);
    std::vector<studies::Eq27Study> eq27s;
    for (const Eq27Input& in : ins) eq27s.push_back(eq27_of(in));

    harness::Table et(with_set(kEq27Columns));
    et.note("scene", "fragility: eq. 27's share of non-conservative cases per to_k over the synthetic records and "
                     "blocks");
    et.note("model", "eq. 27 (q2_n6 at x = p to_k) against each record's first collapse q "
                     "(fragility_synthetic_points.csv)");
    et.note("solver", "studies::eq27_from_points on the IDA points of this scene (no IDA rerun), per set; bootstrap "
                      "over the set's records: " + boot + ", each drawn record bringing its cases on all " +
                      std::to_string(kBlocks.size()) + " blocks, the same draws for every k");
    et.note("inputs", inputs_text + "; to_k: the records' half-periods (fragility_synthetic_records.csv)");
    std::string censored;
    for (std::size_t i = 0; i < ins.size(); ++i)
        censored += (i ? ", " : "") + ins[i].set + " " + std::to_string(eq27s[i].censored);
    et.note("columns",
            "set: pulse (" + std::to_string(sets[0].names.size()) + " records), stochastic (" +
                std::to_string(sets[1].names.size()) + ") or synthetic (both: its share depends on that mix); a case "
            "(record, block) is non-conservative for k when collapse q < eq. 27's q; a censored record never is "
            "(censored cases: " + censored + "); " + wilson_note() +
                "; blocks_with_any: blocks on which at least one record of the set is non-conservative; "
                "records_with_any: records non-conservative on at least one block, of records; boot_lo..hi: the "
                "percentile interval at boot_level of the share over resamples of the set's records (the interval "
                "to quote)");
    for (std::size_t i = 0; i < ins.size(); ++i) eq27_notes(et, ins[i], eq27s[i], " " + ins[i].set);
    {
        // Eq. 27 at the pulse's own half-period (the to every to_k tries to estimate): the same
        // study with to_k = 1/(2 fp) for every k, so its share, Wilson and bootstrap are one row's.
        Eq27Input truth = ins[0];
        for (std::size_t r = 0; r < truth.to.size(); ++r) truth.to[r].fill(sets[0].pulse_half[r]);
        const studies::Eq27Study t = eq27_of(truth);
        const studies::Eq27Share& s = t.shares[0];
        char note[500];
        std::snprintf(note, sizeof note,
                      "eq. 27 at x = p / (2 fp), the pulse's own half-period (fragility_synthetic_points.csv's "
                      "non_conservative_pulse): %d of %d cases non-conservative, share %.4g, Wilson %.0f %% [%.3g, "
                      "%.3g], bootstrap over the pulses %.0f %% [%.3g, %.3g]; %d of %d pulses non-conservative on at "
                      "least one block",
                      s.non_conservative, s.cases, s.share, 100 * kWilsonLevel, s.wilson.lo, s.wilson.hi,
                      100 * kBootstrapLevel, s.bootstrap.lo, s.bootstrap.hi, s.records_with_any, s.records);
        et.note("pulse half-period", note);
    }
    for (std::size_t i = 0; i < ins.size(); ++i) eq27_rows(et, eq27s[i], ins[i].set);

    harness::Table em({"set", "alpha", "p", "q", "share"});
    em.note("scene", "fragility: the synthetic sets' empirical curves, the plot's data (not compared: see "
                     "expected/fragility/TOLERANCES)");
    em.note("columns", "at each collapse q of the block, the share of the set's records (censored counted) overturned "
                       "at or below it");
    for (const SetRun& s : sets)
        for (const BlockFragility& f : s.study)
            for (const studies::EmpiricalPoint& e : f.empirical)
                em.row().add(s.set).add(label(f.block.alpha)).add(label(f.block.p)).add(e.q).add(e.share);

    ctx.write(rt, "fragility_synthetic_records.csv");
    ctx.write(pt2, "fragility_synthetic_points.csv");
    ctx.write(ft, "fragility_synthetic_fits.csv");
    ctx.write(et, "fragility_synthetic_eq27.csv");
    ctx.write(em, "fragility_synthetic_empirical.csv");
    write_capacities(ctx, {capacity_set(sets[0]), capacity_set(sets[1])}, "fragility_synthetic", inputs_text,
                     "synthetic");
}

}  // namespace

void run_fragility(SceneContext& ctx) {
    const auto& rows = shared_records(ctx.reference());
    if (rows.empty()) {
        for (const char* f : kFiles) ctx.skip(f, kNoRecords);
        for (const char* f : kCapacityFiles) ctx.skip(f, kNoRecords);
    } else
        run_shared_records(ctx, rows);
    run_synthetic(ctx);
}

}  // namespace rocking::scenes
