// Fragility of a few blocks over the shared records (issue 28, item 5): each
// record's incremental dynamic analysis (IDA) on each block, its first
// collapse q with the check of that bracket, the lognormal fit per block with
// a seeded bootstrap interval, and eq. 27's share of non-conservative cases
// per to_k over the same points (no IDA is run twice), with its bootstrap
// over records (the same resamples, seed and level as the fits').
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
#include "records/record.hpp"
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

// The same words as the other record scenes, so a reader sees one reason.
const char* kNoRecords = "the records folder is absent (../shared/records or $ROCKING_RECORDS)";
const std::array<const char*, 4> kFiles = {"fragility_points.csv", "fragility_fits.csv", "fragility_eq27.csv",
                                           "fragility_empirical.csv"};

// Two slendernesses by two sizes: a slender and a stockier block, a large
// (p = 1.5 rad/s, about 4.4 m half-diagonal) and a small one (p = 3 rad/s,
// about 1.1 m).  Chosen so that the scene runs in a few seconds on 2 cores.
const std::vector<BlockShape> kBlocks = {{0.1, 1.5}, {0.1, 3.0}, {0.2, 1.5}, {0.2, 3.0}};
constexpr int kResamples = 500;
constexpr std::uint64_t kSeed = 1;
constexpr double kBootstrapLevel = 0.9;
constexpr double kWilsonLevel = 0.95;

std::string label(double v) {
    char b[16];
    std::snprintf(b, sizeof b, "%.2f", v);
    return b;
}

studies::FragilityStudyOptions study_options() {
    studies::FragilityStudyOptions o;
    o.ida.model = table1_search();  // Table 1's model and solver (its scan fields are unused by the IDA)
    o.ida.checks = studies::IdaOptions::Checks::first_collapse;
    o.resamples = kResamples;
    o.seed = kSeed;
    o.level = kBootstrapLevel;
    return o;
}

bool well_conditioned(Confirmation c) { return c == Confirmation::confirmed || c == Confirmation::disagrees; }

// The reference method on a first-collapse bracket: both ends re-simulated
// through records::collapses_at with table1_check() (GSL rk8pd at rtol = atol
// = 1e-13 alpha) on the input scaled to each end's q, not through the IDA's own
// check path; "yes" when it sees the same bracket.
std::string reference_verdict(const dynamics::GroundInput& input, double alpha, double p, const studies::Bracket& b) {
    const records::CollapseOptions check = table1_check();
    auto at = [&](double q) {
        return records::collapses_at(*studies::scaled(input, q * alpha / input.peak()), alpha, p, check);
    };
    return at(b.collapse) && !at(b.safe) ? "yes" : "no";
}

}  // namespace

void run_fragility(SceneContext& ctx) {
    const auto& rows = shared_records(ctx.reference());
    if (rows.empty()) {
        for (const char* f : kFiles) ctx.skip(f, kNoRecords);
        return;
    }
    std::vector<std::unique_ptr<dynamics::SampledInput>> owned;
    std::vector<const dynamics::GroundInput*> inputs;
    std::vector<std::array<double, studies::kHalfPeriods>> to;
    for (const RecordRow& r : rows) {
        const records::Record rec = records::read_any(records_dir() + "/" + r.file);
        owned.push_back(std::make_unique<dynamics::SampledInput>(rec.in_g(9.81), rec.dt, rec.name));  // as table1
        inputs.push_back(owned.back().get());
        to.push_back(r.h.to);
    }
    const studies::FragilityStudyOptions o = study_options();

    // The study on the batch engine's threads (every (block, record) IDA a
    // job), then the reference method's verdicts, one job a (block, record):
    // the engine returns both in order, so the threads change the time, never a value.
    studies::FragilityStudyOptions threaded = o;
    threaded.threads = batch::default_threads();
    const std::vector<BlockFragility> study = studies::fragility_study(inputs, kBlocks, threaded);
    // reference[b][r]: the reference method's verdict on record r's first-collapse bracket on block b.
    std::vector<std::vector<std::string>> reference(kBlocks.size(), std::vector<std::string>(rows.size()));
    batch::run_ordered<std::string>(
        kBlocks.size() * rows.size(), batch::PoolOptions{threaded.threads},
        [&](std::size_t job) -> std::string {
            if (!ctx.reference()) return harness::kNotChecked;
            const Ida& ida = study[job / rows.size()].idas[job % rows.size()];
            const bool has = !ida.intervals.empty() && ida.intervals.front().has_lower &&
                             ida.intervals.front().lower_check.confirmation == Confirmation::confirmed;
            return has ? reference_verdict(*inputs[job % rows.size()], ida.alpha, ida.p, ida.intervals.front().lower)
                       : "-";
        },
        [&](std::size_t job, std::string& v) { reference[job / rows.size()][job % rows.size()] = v; });

    // Eq. 27 from the same points: points[r][b].
    std::vector<std::vector<studies::IdaPoint>> points(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t b = 0; b < kBlocks.size(); ++b) points[r].push_back(study[b].points[r]);
    const studies::Eq27Study eq27 =
        studies::eq27_from_points(points, to, kBlocks, kWilsonLevel, {kResamples, kSeed, kBootstrapLevel});

    const std::string model = o.ida.describe_model();
    const std::string grid = o.ida.describe_grid() + "; q = PGA/(alpha g), the record scaled (studies::scaled)";
    const std::string checks = o.ida.describe_checks() + ", in every run (the verdict is part of the result)";
    const std::string reference_text =
        ctx.reference() ? "both ends of every confirmed first-collapse bracket re-simulated by "
                          "records::collapses_at with GSL rk8pd at rtol = atol = 1e-13 alpha (table1_check) on the "
                          "record scaled to each end's q; yes when it sees the same bracket"
                        : "reference column 'not checked' (see reproduce --reference fragility)";
    std::string blocks = "blocks (alpha, p rad/s):";
    for (const BlockShape& b : kBlocks) blocks += " (" + label(b.alpha) + ", " + label(b.p) + ")";
    const std::string inputs_text =
        "every record of the records folder (../shared/records or $ROCKING_RECORDS: esm/ and peer/, as table1), "
        "in g with g = 9.81 m/s^2; " + blocks;
    char boot[200];
    std::snprintf(boot, sizeof boot,
                  "%d resamples of the records with replacement, GSL mt19937 seeded %llu (machine-independent), "
                  "percentile interval at %.0f %%",
                  kResamples, static_cast<unsigned long long>(kSeed), 100 * kBootstrapLevel);

    harness::Table pt({"record", "alpha", "p", "q_input", "outcome", "q_collapse", "q_safe", "q_ill_collapse",
                       "q_ill_safe", "q_censored", "intervals", "check", "reference"});
    pt.note("scene", "fragility: each record's first collapse q on each block, from its incremental dynamic analysis");
    pt.note("model", model);
    pt.note("solver", "exact solver (the record kernel); " + grid);
    pt.note("check", checks);
    pt.note("reference", reference_text);
    pt.note("inputs", inputs_text);
    pt.note("columns",
            "q_input: the record's own q, unscaled; outcome: collapsed (first collapse found) or censored (none up to "
            "q_max: q_censored); q_collapse / q_safe: the first collapse's bracket (1e-6 relative) where the check "
            "finds it well conditioned, q_ill_*: where the probe (input x 1 +- 1e-13) flips an outcome, placed by "
            "rounding within its grid gap; a first collapse at the grid's start has q_collapse = q_min and no bracket; "
            "intervals: the number of overturning intervals in q up to q_max; check: the first bracket's verdict "
            "(confirmed, ill-conditioned, second solver disagrees); reference: the reference method's verdict on a "
            "confirmed bracket");
    for (std::size_t b = 0; b < kBlocks.size(); ++b) {
        for (std::size_t r = 0; r < rows.size(); ++r) {
            const Ida& ida = study[b].idas[r];
            pt.row().add(rows[r].file).add(label(ida.alpha)).add(label(ida.p)).add(ida.q_input);
            if (!ida.point.collapsed) {
                pt.add("censored").add("-").add("-").add("-").add("-").add(ida.point.q);
                pt.add(static_cast<int>(ida.intervals.size())).add("-").add(reference[b][r]);
                continue;
            }
            const studies::IdaInterval& first = ida.intervals.front();
            pt.add("collapsed");
            if (!first.has_lower) {
                pt.add(ida.point.q).add("-").add("-").add("-").add("-");
                pt.add(static_cast<int>(ida.intervals.size())).add("grid start").add(reference[b][r]);
                continue;
            }
            if (well_conditioned(first.lower_check.confirmation))
                pt.add(first.lower.collapse).add(first.lower.safe).add("-").add("-");
            else
                pt.add("-").add("-").add(first.lower.collapse).add(first.lower.safe);
            pt.add("-").add(static_cast<int>(ida.intervals.size()));
            pt.add(studies::confirmation_name(first.lower_check.confirmation)).add(reference[b][r]);
            if (!first.lower_check.detail.empty())
                pt.note("detail " + rows[r].file + " alpha " + label(ida.alpha) + " p " + label(ida.p),
                        first.lower_check.detail);
        }
    }

    // A block whose points include an ill-conditioned first collapse (placed by
    // rounding within its grid gap) has its fit in the *_ill columns, held to
    // that gap's effect (TOLERANCES); the others' to the bisection's 1e-6.
    harness::Table ft({"alpha", "p", "records", "collapsed", "censored", "ill_conditioned", "median", "beta",
                       "log_likelihood", "median_lo", "median_hi", "beta_lo", "beta_hi", "median_ill", "beta_ill",
                       "log_likelihood_ill", "median_lo_ill", "median_hi_ill", "beta_lo_ill", "beta_hi_ill",
                       "resamples", "seed", "level"});
    ft.note("scene", "fragility: the lognormal fragility curve of each block over the records, by maximum likelihood");
    ft.note("model", model);
    ft.note("solver",
            "studies::fit_lognormal (Baker 2015, censored records kept: closed form without censoring, GSL "
            "Nelder-Mead otherwise) on fragility_points.csv's points; bootstrap: " + std::string(boot));
    ft.note("inputs", inputs_text);
    ft.note("columns",
            "P(overturn | q) = Phi(ln(q / median) / beta); median_lo..hi, beta_lo..hi: the bootstrap's percentile "
            "interval; '-' where the block has no fit; ill_conditioned: the block's first collapses whose bracket is "
            "ill-conditioned (fragility_points.csv), whose fit is then in the *_ill columns");
    for (const BlockFragility& f : study) {
        int collapsed = 0, ill = 0;
        for (const studies::IdaPoint& p : f.points) collapsed += p.collapsed;
        for (const Ida& ida : f.idas)
            ill += ida.point.collapsed && !ida.intervals.empty() && ida.intervals.front().has_lower &&
                   ida.intervals.front().lower_check.confirmation == Confirmation::ill_conditioned;
        ft.row().add(label(f.block.alpha)).add(label(f.block.p)).add(static_cast<int>(f.points.size()));
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
        if (!f.fitted) ft.note("no fit alpha " + label(f.block.alpha) + " p " + label(f.block.p), f.no_fit);
    }

    harness::Table et({"k", "non_conservative", "cases", "share", "wilson_lo", "wilson_hi", "blocks_with_any",
                       "records_with_any", "records", "boot_lo", "boot_hi", "boot_level", "resamples", "seed"});
    et.note("scene", "fragility: eq. 27's share of non-conservative cases per to_k over these records and blocks");
    et.note("model", "eq. 27 (q2_n6 at x = p to_k) against each record's first collapse q (fragility_points.csv)");
    et.note("solver", "studies::eq27_from_points on the IDA points of this scene (no IDA rerun); bootstrap over "
                      "records: " + std::string(boot) + ", each drawn record bringing its cases on all " +
                      std::to_string(kBlocks.size()) + " blocks, the same draws for every k");
    et.note("inputs", inputs_text + "; to_k: the records' half-periods (table2)");
    char wil[160];
    std::snprintf(wil, sizeof wil,
                  "wilson_lo..hi: Wilson score interval at %.0f %%, the cases taken as independent (they are not: "
                  "the blocks share their records)", 100 * kWilsonLevel);
    et.note("columns",
            "a case (record, block) is non-conservative for k when collapse q < eq. 27's q; a censored record never "
            "is (" + std::to_string(eq27.censored) + " censored cases); " + wil +
                "; blocks_with_any: blocks on which at least one record is non-conservative; records_with_any: "
                "records non-conservative on at least one block, of records; boot_lo..hi: the percentile interval "
                "at boot_level of the share over resamples of the records (the interval to quote)");
    // How near a verdict is to flipping: the smallest |ln(collapse q / eq. 27's q)| over the collapsed cases.
    // The ill-conditioned first collapses, placed within their grid gap, apart.
    double margin = 1e300, margin_ill = 1e300;
    std::string margin_at;
    for (const studies::Eq27Case& c : eq27.cases) {
        if (!c.point.collapsed) continue;
        const Ida& ida = study[c.block].idas[c.record];
        const bool ill = ida.intervals.front().has_lower &&
                         ida.intervals.front().lower_check.confirmation == Confirmation::ill_conditioned;
        for (int k = 0; k < studies::kHalfPeriods; ++k) {
            const double m = std::fabs(std::log(c.point.q / c.q_eq27[k]));
            if (ill) {
                margin_ill = std::min(margin_ill, m);
                continue;
            }
            if (m < margin) {
                margin = m;
                margin_at = rows[c.record].file + " alpha " + label(kBlocks[c.block].alpha) + " p " +
                            label(kBlocks[c.block].p) + " to_" + std::to_string(k + 1);
            }
        }
    }
    char mg[64], mgi[64];
    std::snprintf(mg, sizeof mg, "%.3g", margin);
    std::snprintf(mgi, sizeof mgi, "%.3g", margin_ill);
    et.note("margin", std::string("the smallest |ln(collapse q / eq. 27's q)| over the collapsed cases with a "
                                  "well-conditioned first collapse: ") + mg + " (" + margin_at + "); over those with an "
                                  "ill-conditioned one: " + (margin_ill < 1e300 ? mgi : "none") +
                          "; a verdict flips only if a collapse q moves by that much");
    // The two intervals at one level: Wilson's at the bootstrap's, width against width.
    double ratio_lo = 1e300, ratio_hi = 0;
    std::string zeros;
    for (int k = 0; k < studies::kHalfPeriods; ++k) {
        const studies::Eq27Share& s = eq27.shares[k];
        if (s.non_conservative == 0) {
            zeros += (zeros.empty() ? "to_" : ", to_") + std::to_string(k + 1);
            continue;
        }
        const studies::WilsonInterval w = studies::wilson_interval(s.non_conservative, s.cases, kBootstrapLevel);
        const double r = (s.bootstrap.hi - s.bootstrap.lo) / (w.hi - w.lo);
        ratio_lo = std::min(ratio_lo, r);
        ratio_hi = std::max(ratio_hi, r);
    }
    char lv[400];
    std::snprintf(lv, sizeof lv,
                  "the columns hold a %.0f %% bootstrap beside a %.0f %% Wilson interval; at %.0f %% both, the "
                  "bootstrap's width is %.3g to %.3g times Wilson's over the k with a non-conservative case",
                  100 * kBootstrapLevel, 100 * kWilsonLevel, 100 * kBootstrapLevel, ratio_lo, ratio_hi);
    et.note("levels", lv);
    if (!zeros.empty()) {
        // Clopper-Pearson's upper bound for 0 of n at the two-sided level: 1 - ((1 - level)/2)^(1/n).
        char z[400];
        std::snprintf(z, sizeof z,
                      ": no case and no record non-conservative, so the bootstrap is [0, 0] (no resample can draw a "
                      "record that is not there); over records, 0 of %d bounds the share of records non-conservative "
                      "anywhere, and so the share of cases, by %.3g (Clopper-Pearson at %.0f %%)",
                      eq27.records, 1 - std::pow((1 - kBootstrapLevel) / 2, 1.0 / eq27.records), 100 * kBootstrapLevel);
        et.note("zero", zeros + z);
    }
    for (int k = 0; k < studies::kHalfPeriods; ++k) {
        const studies::Eq27Share& s = eq27.shares[k];
        int with_any = 0;
        for (const studies::Eq27Cell& c : eq27.map) with_any += c.non_conservative[k] > 0;
        et.row().add(k + 1).add(s.non_conservative).add(s.cases).add(s.share).add(s.wilson.lo).add(s.wilson.hi);
        et.add(with_any).add(s.records_with_any).add(s.records).add(s.bootstrap.lo).add(s.bootstrap.hi);
        et.add(eq27.bootstrap.level).add(eq27.bootstrap.resamples).add(std::to_string(eq27.bootstrap.seed));
    }

    harness::Table em({"alpha", "p", "q", "share"});
    em.note("scene", "fragility: the empirical curves, the plot's data (not compared: see expected/fragility/TOLERANCES)");
    em.note("columns", "at each collapse q of the block, the share of all records (censored counted) overturned at or below it");
    for (const BlockFragility& f : study)
        for (const studies::EmpiricalPoint& e : f.empirical)
            em.row().add(label(f.block.alpha)).add(label(f.block.p)).add(e.q).add(e.share);

    ctx.write(pt, "fragility_points.csv");
    ctx.write(ft, "fragility_fits.csv");
    ctx.write(et, "fragility_eq27.csv");
    ctx.write(em, "fragility_empirical.csv");
}

}  // namespace rocking::scenes
