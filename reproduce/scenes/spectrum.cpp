// The rocking spectrum of the Norcia records (issue 28, item 5): the set of p
// at which each record overturns the block, as intervals with checked ends,
// against Table 1's p, the first collapse of its 1 % scan.  Table 1's search
// met islands on these records (docs/spectrum.md): a single p per record hides
// them, the intervals show them.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "batch/pool.hpp"
#include "dynamics/ground_input.hpp"
#include "harness/compare.hpp"
#include "harness/table.hpp"
#include "records/record.hpp"
#include "records_analysis.hpp"
#include "scene.hpp"
#include "spectrum_refined.hpp"
#include "studies/spectrum.hpp"

namespace rocking::scenes {

namespace {

using studies::Boundary;
using studies::Confirmation;
using studies::Interval;
using studies::Spectrum;

// The same words as the other record scenes, so a reader sees one reason.
const char* kNoNorcia = "no Norcia record (esm/IT.NRC..H*) in the records folder";
const std::array<const char*, 5> kFiles = {"spectrum_intervals.csv", "spectrum_summary.csv", "spectrum_grid.csv",
                                           kRefinedFile, kRefinedIntervalsFile};

// The Norcia records: the station where Table 1's search met islands.
bool is_norcia(const RecordRow& r) {
    const std::string name = std::filesystem::path(r.file).filename().string();
    return r.file.rfind("esm/", 0) == 0 && name.rfind("IT.NRC..H", 0) == 0;
}

// One record at one alpha.
struct Task {
    const RecordRow* row = nullptr;
    std::size_t k = 0;  // index into kTableAlphas
    Spectrum spectrum;
    // The reference method's verdict on each interval's ends (reference mode):
    // "yes"/"no" for a confirmed boundary, "-" for any other end.
    std::vector<std::array<std::string, 2>> reference;
    std::string error;
    Spectrum refined;  // the refine method's, on the same p range and main grid (spectrum_refined.hpp)
};

studies::SpectrumOptions spectrum_options(const RecordRow& row, std::size_t k) {
    studies::SpectrumOptions o;  // the default grid: 200 p from 0.3 to 30 rad/s, and the offset grid
    o.model = table1_search();   // Table 1's model and solver, so the two searches see the same block
    // Table 1's bracket joins the grid, as `rocking spectrum` does
    // (src/cli/spectrum.cpp): an island its 1 % scan met and both grids
    // stepped over is then refined as well.
    const records::CollapseResult& c = row.collapse[k];
    if (c.found) o.extra_points.push_back(c.p);
    if (c.found && !c.below_range()) o.extra_points.push_back(c.p_safe);
    return o;
}

// An end's verdict by the reference method: both ends of a confirmed bracket
// re-simulated through records::collapses_at (not the spectrum's own check
// path) with table1_check(), GSL rk8pd at rtol = atol = 1e-13 alpha, as
// table1's --reference does for its brackets.
std::string reference_verdict(const dynamics::GroundInput& input, double alpha, const Boundary& b) {
    if (b.confirmation != Confirmation::confirmed) return "-";
    const records::CollapseOptions check = table1_check();
    const bool at_collapse = records::collapses_at(input, alpha, b.p_collapse, check);
    const bool at_safe = records::collapses_at(input, alpha, b.p_safe, check);
    return at_collapse && !at_safe ? "yes" : "no";
}

void run_task(Task& t, bool reference) {
    const records::Record r = records::read_any(records_dir() + "/" + t.row->file);
    const dynamics::SampledInput input(r.in_g(9.81), r.dt, r.name);  // as table1 (records_analysis.cpp)
    const double alpha = kTableAlphas[t.k];
    t.spectrum = studies::rocking_spectrum(input, alpha, spectrum_options(*t.row, t.k));
    // Every run checks the refined boundaries with rk8pd already: the
    // reference run, which re-simulates the grids' brackets, does not repeat
    // a minute of search to check nothing more.
    if (!reference) t.refined = studies::rocking_spectrum(input, alpha, refined_spectrum_options());
    for (const Interval& in : t.spectrum.intervals) {
        std::array<std::string, 2> v = {harness::kNotChecked, harness::kNotChecked};
        if (reference) {
            v[0] = in.has_lower ? reference_verdict(input, alpha, in.lower) : "-";
            v[1] = in.has_upper ? reference_verdict(input, alpha, in.upper) : "-";
        }
        t.reference.push_back(v);
    }
}

bool well_conditioned(const Boundary& b) {
    return b.confirmation == Confirmation::confirmed || b.confirmation == Confirmation::disagrees;
}

// An end of an interval in the table: its check, and its bracket in the
// columns of its kind.  A well-conditioned bracket is held to the bisection's
// 1e-6; an ill-conditioned one only to its grid gap, where rounding places it
// (TOLERANCES), hence the separate columns.
void add_end(harness::Table& t, bool has, const Boundary& b, const char* grid_end, const std::string& reference) {
    if (!has) {
        t.add(grid_end).add("-").add("-").add("-").add("-").add(reference);
        return;
    }
    t.add(studies::confirmation_name(b.confirmation));
    if (well_conditioned(b)) t.add(b.p_safe).add(b.p_collapse).add("-").add("-");
    else t.add("-").add("-").add(b.p_safe).add(b.p_collapse);
    t.add(reference);
}

// Whether Table 1's p lies on an interval that no point of either grid
// reached: an island found only through Table 1's own bracket.
bool table1_off_grid(const Spectrum& sp, double p) {
    for (const Interval& in : sp.intervals) {
        if (p < in.from || p > in.to) continue;
        for (const studies::SpectrumPoint& pt : sp.points)
            if (pt.grid != studies::GridKind::extra && pt.p >= in.from && pt.p <= in.to) return false;
        return true;
    }
    return false;
}

}  // namespace

void run_spectrum(SceneContext& ctx) {
    const auto& rows = shared_records(ctx.reference());
    if (rows.empty()) {
        for (const char* f : kFiles) ctx.skip(f, kNoRecords);
        return;
    }
    std::vector<Task> tasks;
    for (const RecordRow& r : rows)
        if (is_norcia(r))
            for (std::size_t k = 0; k < kTableAlphas.size(); ++k) tasks.push_back({&r, k, {}, {}, "", {}});
    if (tasks.empty()) {
        for (const char* f : kFiles) ctx.skip(f, kNoNorcia);
        return;
    }
    // Each (record, alpha) a job of the batch engine, taken on demand and
    // delivered in order: the threads change the time, never a value.
    batch::run_ordered<Task>(
        tasks.size(), batch::PoolOptions{batch::default_threads()},
        [&](std::size_t i) {
            Task t = tasks[i];
            try {
                run_task(t, ctx.reference());
            } catch (const std::exception& e) {
                throw std::runtime_error("spectrum: " + t.row->file + ": " + e.what());
            }
            return t;
        },
        [&](std::size_t i, Task& t) { tasks[i] = std::move(t); });

    const studies::SpectrumOptions o = spectrum_options(*tasks.front().row, 0);
    const std::string model = o.describe_model();
    const std::string solver = "grid and bisection: exact solver (the record kernel); " + o.describe_refinement() +
                               "; the probe and rk8pd at every boundary, in every run";
    const std::string reference_solver =
        ctx.reference() ? "reference: both ends of every confirmed bracket re-simulated by records::collapses_at with "
                          "GSL rk8pd at rtol = atol = 1e-13 alpha (table1_check), yes when it sees the same bracket"
                        : "reference columns 'not checked' (see reproduce --reference spectrum)";
    const std::string inputs =
        "the Norcia records esm/IT.NRC..H*.ASC of the records folder (../shared/records or $ROCKING_RECORDS), in g "
        "with g = 9.81 m/s^2; alpha = 0.05 0.10 0.15 0.20 0.25 (Table 1's); Table 1's p and bracket from table1's "
        "search (table1_records.csv: " + table1_search().describe() + ")";
    const std::string grid = o.describe_grid() + "; Table 1's bracket of each record and alpha added as extra points";

    harness::Table iv({"record", "alpha", "interval", "from", "to", "from_check", "from_safe", "from_collapse",
                       "from_ill_safe", "from_ill_collapse", "from_reference", "to_check", "to_collapse", "to_safe",
                       "to_ill_collapse", "to_ill_safe", "to_reference"});
    iv.note("scene", "spectrum: the overturning intervals in p of the Norcia records, each end's bracket and its check");
    iv.note("model", model);
    iv.note("solver", solver);
    iv.note("check", reference_solver);
    iv.note("inputs", inputs);
    iv.note("grid", grid);
    iv.note("columns",
            "p in rad/s; an interval overturns the block from 'from' to 'to'; each end is a boundary (safe at *_safe, "
            "overturning at *_collapse, 1e-6 relative apart) or the grid's own end (the set may go on beyond it); "
            "*_check: confirmed (probe flips nothing, rk8pd sees the bracket), ill-conditioned (the input times "
            "1 +- 1e-13 flips an outcome at an end: its bracket is in *_ill_*, placed by rounding within its grid gap), "
            "second solver disagrees; *_reference: the reference method's verdict on a confirmed bracket");
    harness::Table sm({"record", "alpha", "intervals", "lowest_p", "table1_p", "lowest_over_table1", "boundaries",
                       "ill_conditioned", "confirmed", "disagrees", "table1_on_island_off_grid"});
    sm.note("scene", "spectrum: per Norcia record and alpha, the spectrum's lowest overturning p against Table 1's p");
    sm.note("model", model);
    sm.note("solver", solver);
    sm.note("inputs", inputs);
    sm.note("grid", grid);
    sm.note("columns",
            "lowest_p: the first interval's 'from' (spectrum_intervals.csv); table1_p: table1's first collapse; "
            "boundaries and their checks counted over the intervals' ends; table1_on_island_off_grid: Table 1's p lies "
            "on an interval no point of either grid reached (found only through its bracket)");
    harness::Table gd({"record", "alpha", "p", "grid", "max_theta_over_alpha", "overturning"});
    gd.note("scene", "spectrum: the plot's data (not compared with expected/: see expected/spectrum/TOLERANCES)");
    gd.note("model", model);
    gd.note("solver", "exact solver (the record kernel)");
    gd.note("inputs", inputs);
    gd.note("grid", grid);
    gd.note("columns", "p in rad/s; max |theta|/alpha during the input; overturning at any time (the criterion)");

    for (const Task& t : tasks) {
        const Spectrum& sp = t.spectrum;
        const std::string record = t.row->file;
        const std::string alpha = alpha_label(sp.alpha);
        int ill = 0, confirmed = 0, disagrees = 0, boundaries = 0;
        for (std::size_t i = 0; i < sp.intervals.size(); ++i) {
            const Interval& in = sp.intervals[i];
            iv.row().add(record).add(alpha).add(static_cast<int>(i + 1)).add(in.from).add(in.to);
            add_end(iv, in.has_lower, in.lower, "grid start", t.reference[i][0]);
            // The upper end's columns in its own order: overturning below, safe above.
            if (!in.has_upper) {
                iv.add("grid end").add("-").add("-").add("-").add("-").add(t.reference[i][1]);
            } else {
                const Boundary& b = in.upper;
                iv.add(studies::confirmation_name(b.confirmation));
                if (well_conditioned(b)) iv.add(b.p_collapse).add(b.p_safe).add("-").add("-");
                else iv.add("-").add("-").add(b.p_collapse).add(b.p_safe);
                iv.add(t.reference[i][1]);
            }
            for (int e = 0; e < 2; ++e) {
                const bool has = e == 0 ? in.has_lower : in.has_upper;
                if (!has) continue;
                const Boundary& b = e == 0 ? in.lower : in.upper;
                ++boundaries;
                ill += b.confirmation == Confirmation::ill_conditioned;
                confirmed += b.confirmation == Confirmation::confirmed;
                disagrees += b.confirmation == Confirmation::disagrees;
                if (!b.detail.empty())
                    iv.note("detail " + record + " alpha " + alpha + " interval " + std::to_string(i + 1) +
                                (e == 0 ? " from" : " to"),
                            b.detail);
            }
        }
        const records::CollapseResult& c = t.row->collapse[t.k];
        sm.row().add(record).add(alpha).add(static_cast<int>(sp.intervals.size()));
        if (sp.intervals.empty()) sm.add("none");
        else sm.add(sp.intervals.front().from);
        if (c.found) sm.add(c.p);
        else sm.add("none below 30");
        if (c.found && !sp.intervals.empty()) sm.add(sp.intervals.front().from / c.p);
        else sm.add("-");
        sm.add(boundaries).add(ill).add(confirmed).add(disagrees);
        sm.add(c.found ? table1_off_grid(sp, c.p) : false);
        for (const studies::SpectrumPoint& pt : sp.points)
            gd.row().add(record).add(alpha).add(pt.p).add(studies::grid_kind_name(pt.grid)).add(pt.max_theta).add(pt.collapse);
    }
    ctx.write(iv, "spectrum_intervals.csv");
    ctx.write(sm, "spectrum_summary.csv");
    ctx.write(gd, "spectrum_grid.csv");

    if (ctx.reference()) {
        for (const char* file : {"spectrum_refined.csv", "spectrum_refined_intervals.csv"})
            ctx.skip(file, "the reference run does not repeat the refine search: every run checks its boundaries "
                           "with GSL rk8pd at 1e-13");
        return;
    }
    std::vector<RefinedPair> pairs;
    for (Task& t : tasks) pairs.push_back({t.row->file, t.spectrum.alpha, &t.spectrum, std::move(t.refined)});
    write_spectrum_refined(ctx, pairs, inputs);
}

}  // namespace rocking::scenes
