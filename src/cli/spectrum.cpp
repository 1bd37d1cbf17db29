// rocking spectrum: the rocking spectrum of a record (studies/spectrum.hpp)
// for one or more alpha, its overturning intervals in p beside Table 1's
// first collapse, as text or JSON, with the grid as CSV and a PNG
// (plot_spectrum.cpp).
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/engine.hpp"
#include "batch/ranks.hpp"
#include "cli/cluster_front.hpp"
#include "cli/distinct_inputs.hpp"
#include "cli/geometry.hpp"
#include "cli/help.hpp"
#include "cli/imperfection.hpp"
#include "cli/json_text.hpp"
#include "cli/options.hpp"
#include "cli/plots.hpp"
#include "cli/set_words.hpp"
#include "harness/table.hpp"
#include "jobs/spectrum_plan.hpp"
#include "json/spectrum_json.hpp"
#include "records/collapse.hpp"
#include "studies/spectrum.hpp"
#include "studies/spectrum_mark.hpp"
#include "studies/search_alpha.hpp"

namespace rocking::cli {

namespace {

using studies::Boundary;
using studies::Interval;
using studies::Spectrum;
using studies::SpectrumOptions;

using Study = jobs::SpectrumStudy;

std::string g7(double v) { return significant(v, 7); }

std::vector<double> alphas_from(const std::string& text) {
    std::vector<double> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        const double alpha = number("--alpha", item);
        if (!studies::in_search_alpha_range(alpha))
            throw UsageError("--alpha: each must be in " + std::string(studies::kSearchAlphaRange) + " (got " + item + ")");
        out.push_back(alpha);
    }
    if (out.empty() || text.back() == ',') throw UsageError("--alpha: a list of numbers, A or A,A,... (got '" + text + "')");
    if (out.size() > 20) throw UsageError("--alpha: at most 20 values");
    refuse_repeated_values("--alpha", out);
    return out;
}

// The grid's options; p is kept to 0.01-1000 rad/s (half-heights from 74 km
// down to 7 micrometres), beyond which a run's free rocking or its steps
// grow without bound and no block is physical.
SpectrumOptions grid_from(const Args& a) {
    SpectrumOptions o;
    if (a.values.count("--p-min")) o.p_min = number("--p-min", a.values.at("--p-min"));
    if (a.values.count("--p-max")) o.p_max = number("--p-max", a.values.at("--p-max"));
    if (!(o.p_min >= 0.01 && o.p_min <= 1000)) throw UsageError("--p-min: must be in [0.01, 1000] rad/s");
    if (!(o.p_max >= 0.01 && o.p_max <= 1000)) throw UsageError("--p-max: must be in [0.01, 1000] rad/s");
    if (!(o.p_max > o.p_min))
        throw UsageError("--p-max: must be above --p-min (" + g7(o.p_min) + " rad/s)");
    if (a.values.count("--points")) o.points = integer("--points", a.values.at("--points"), 2, 100000);
    const MethodChoice m = method_options(a, "p");
    if (m.refine) o.method = SpectrumOptions::Method::refine;
    o.width = m.width;
    o.robust_width = m.robust_width;
    restitution_into(a, o.model);
    friction_into(a, o.model);
    imperfection_into(a, o.model);
    return o;
}

bool refined(const SpectrumOptions& o) { return o.method == SpectrumOptions::Method::refine; }

std::string grid_text(const SpectrumOptions& o) { return json::spectrum_grid_note(o); }


// How a boundary stands, in words: its check, and what the probe or the
// second solver saw where it is not confirmed.
std::string standing(const Boundary& b) {
    const std::string name = studies::confirmation_name(b.confirmation);
    return b.detail.empty() ? name : name + " (" + b.detail + ")";
}

// [p_from, p_to] rad/s with the heights of the blocks of this alpha at its ends
// (H = 2 R cos alpha, R = 3 g/(4 p^2): the larger block at p_from).
std::string interval_text(const Interval& in, double alpha) {
    return "[" + g7(in.from) + ", " + g7(in.to) + "] (H " + significant(studies::height_at_p(alpha, in.from), 4) + " to " +
           significant(studies::height_at_p(alpha, in.to), 4) + " m)  from: " +
           (in.has_lower ? standing(in.lower) : std::string("the grid's start (the set may go on below)")) +
           "; to: " + (in.has_upper ? standing(in.upper) : std::string("the grid's end (the set may go on above)"));
}

std::string table1_text(const records::CollapseResult& c) {
    if (c.below_range()) return "p <= " + g7(c.p) + " rad/s, below the search's lowest p";
    if (!c.found) return "no collapse up to 30 rad/s";
    return "p = " + g7(c.p) + " rad/s (safe at " + g7(c.p_safe) + ")";
}

// Where Table 1's p stands in the spectrum: on an island that only its own
// bracket revealed (no point of either grid on it), and whether the
// spectrum overturns the block at a lower p.
std::string table1_remark(const Study& s) {
    if (!s.table1.found || s.spectrum.intervals.empty()) return "";
    std::string text;
    if (s.spectrum.refined) {
        bool inside = false;
        for (const Interval& in : s.spectrum.intervals) inside = inside || (s.table1.p >= in.from && s.table1.p <= in.to);
        if (!inside) text = "; it lies in no interval of the refined set (its island is narrower than w)";
    }
    for (const Interval& in : s.spectrum.intervals) {
        if (s.spectrum.refined || s.table1.p < in.from || s.table1.p > in.to) continue;
        bool gridded = false;
        for (const studies::SpectrumPoint& pt : s.spectrum.points)
            gridded = gridded || (pt.grid != studies::GridKind::extra && pt.p >= in.from && pt.p <= in.to);
        if (!gridded) text = "; it lies on an island narrower than the grids' step, found through its bracket";
    }
    // Below the bracket, not inside it: there the bisection only refines Table 1's own 1e-4.
    const double lowest = s.spectrum.intervals.front().from;
    if (lowest < (s.table1.below_range() ? s.table1.p : s.table1.p_safe))
        text += "; the spectrum overturns the block from p = " + g7(lowest) + ", below it";
    return text;
}

// The first overturning with its bracket and check, the first robust
// collapse and the overturned share of each band, in words.
std::string refine_lines(const Spectrum& sp) {
    std::string text = "  first overturning: ";
    if (!sp.first_overturning.found) text += "none up to p_max";
    else {
        const Interval& in = sp.intervals.front();
        text += "p = " + g7(sp.first_overturning.p) +
                (in.has_lower ? " in [" + g7(in.lower.p_safe) + ", " + g7(in.lower.p_collapse) + "] (" + standing(in.lower) + ")"
                              : std::string(" (the grid's lowest p)"));
    }
    text += "\n  first robust collapse: " +
            (sp.first_robust_collapse.found ? "p = " + g7(sp.first_robust_collapse.p) : std::string("none up to p_max")) +
            "\n  overturned share: " + bands_summary(sp.bands, "p") + "\n  " + std::to_string(sp.samples) +
            " runs with margins, " + std::to_string(sp.accepted) + " intervals accepted by them, " +
            std::to_string(sp.at_width) + " split to w" +
            (sp.with_margins ? "" : " (no margins for this model: every interval split to w)");
    if (std::isfinite(sp.unguaranteed_from)) text += "; the guarantee does not hold (the record's q is above the turn-back bound)";
    return text + "\n";
}

// The refine method may find hundreds of islands: the text shows the first
// ones, --json and --output every one.
constexpr std::size_t kIntervalsShown = 20;

void print_text(const std::string& path, const records::Record& r, const SpectrumOptions& o,
                const std::vector<Study>& studies, const std::vector<studies::SpectrumMark>& marks) {
    std::printf("%s: rocking spectrum of %s (%zu samples, dt = %g s, PGA %.4f g)\n", r.name.c_str(), path.c_str(),
                r.accel.size(), r.dt, r.pga() / dynamics::kGravity);
    std::printf("  model: %s\n  grid: %s\n  %s\n", o.describe_model().c_str(), grid_text(o).c_str(),
                o.describe_refinement().c_str());
    if (refined(o)) std::printf("  refine: %s\n", o.describe_guarantee().c_str());
    for (const Study& s : studies) {
        const Spectrum& sp = s.spectrum;
        if (!sp.lifts)
            std::printf("alpha = %.7g: the record never lifts the block (PGA %.4f g <= the uplift threshold alpha g): no p overturns it\n",
                        sp.alpha, r.pga() / dynamics::kGravity);
        else if (sp.intervals.empty())
            std::printf("alpha = %.7g: no overturning for p from %g to %g rad/s on the grid\n", sp.alpha, o.p_min, o.p_max);
        else {
            std::printf("alpha = %.7g: overturns for p (rad/s) in (H: the heights of the blocks of this alpha at its ends)\n", sp.alpha);
            for (std::size_t i = 0; i < sp.intervals.size(); ++i) {
                if (sp.refined && i == kIntervalsShown) {
                    std::printf("  ... %zu more intervals (--json or --output lists every one)\n", sp.intervals.size() - i);
                    break;
                }
                std::printf("  %s\n", interval_text(sp.intervals[i], sp.alpha).c_str());
            }
        }
        if (sp.refined) std::printf("%s", refine_lines(sp).c_str());
        std::printf("  Table 1's search (p from 0.3 by x1.01, the first collapse): %s%s\n", table1_text(s.table1).c_str(),
                    table1_remark(s).c_str());
        std::printf("  %ld simulations, %ld by the second solver\n", sp.simulations, sp.check_simulations);
    }
    for (const studies::SpectrumMark& m : marks) {
        const std::vector<std::string> lines = studies::describe_mark_lines(m);
        std::printf("marked: %s\n", lines[0].c_str());
        for (std::size_t k = 1; k < lines.size(); ++k) std::printf("  %s\n", lines[k].c_str());
    }
}

std::string intervals_note(const Spectrum& sp) {
    if (sp.intervals.empty()) return "none";
    std::string text;
    for (const Interval& in : sp.intervals) text += (text.empty() ? "" : "; ") + interval_text(in, sp.alpha);
    return text;
}

void write_csv(const std::string& csv, const std::string& path, const records::Record& r, const SpectrumOptions& o,
               const std::vector<Study>& studies, const std::vector<studies::SpectrumMark>& marks) {
    harness::Table t({"alpha", "p", "grid", "max_theta_over_alpha", "final_rotation", "peak_rotation", "overturning",
                      "t_overturn"});
    t.note("command", "rocking spectrum");
    t.note("model", o.describe_model());
    t.note("input", r.name + " (" + path + ", " + std::to_string(r.accel.size()) + " samples, dt = " + g7(r.dt) +
                        " s, PGA " + g7(r.pga() / dynamics::kGravity) + " g)");
    t.note("grid", grid_text(o));
    t.note("refinement", o.describe_refinement());
    t.note("columns", "p in rad/s; max |theta|/alpha during the input; collapse under each criterion; t_overturn in s, "
                      "'-' where the block does not overturn or is taken to overturn by its energy");
    if (refined(o)) t.note("refine", o.describe_guarantee());
    for (const studies::SpectrumMark& m : marks) t.note("marked", studies::describe_mark(m));
    for (const Study& s : studies) {
        t.note("intervals at alpha " + g7(s.spectrum.alpha), intervals_note(s.spectrum));
        t.note("Table 1's p at alpha " + g7(s.spectrum.alpha), table1_text(s.table1));
        if (!s.spectrum.refined) continue;
        const Spectrum& sp = s.spectrum;
        t.note("first overturning at alpha " + g7(sp.alpha), sp.first_overturning.found ? g7(sp.first_overturning.p) : "none");
        t.note("first robust collapse at alpha " + g7(sp.alpha),
               sp.first_robust_collapse.found ? g7(sp.first_robust_collapse.p) : "none");
        t.note("overturned share at alpha " + g7(sp.alpha), bands_text(sp.bands));
    }
    for (const Study& s : studies)
        for (const studies::SpectrumPoint& pt : s.spectrum.points) {
            t.row().add(s.spectrum.alpha).add(pt.p).add(studies::grid_kind_name(pt.grid)).add(pt.max_theta);
            t.add(pt.final_rotation).add(pt.peak_rotation).add(pt.overturning);
            if (std::isnan(pt.t_overturn)) t.add("-");
            else t.add(pt.t_overturn);
        }
    write_output(t, csv);
}

struct Command {
    std::string path;
    Args args;
    std::vector<double> alphas;
    std::vector<studies::BlockShape> marks;  // --mark: the engineer's blocks, each on its alpha's spectrum
    SpectrumOptions grid;
    batch::EngineOptions engine;
};

Command command_from(int argc, char** argv, bool mpi) {
    Command c;
    std::vector<char*> args = without_engine_switches(argc, argv, c.engine.resume, c.engine.quiet);
    const int count = static_cast<int>(args.size());
    c.path = file_argument(count, args.data(), 2, usage_line("spectrum"));
    c.args = parse(count, args.data(), 3, {"--alpha", "--p-min", "--p-max", "--points", "--unit", "--dt", "--floor", "--restitution", "--friction", "--lean", "--out-of-plumb", "--fc", "--density", "--jobs",
                                           "--output", "--png", "--rows", "--method", "--width", "--robust-width",
                                           "--mark"});
    const Args& a = c.args;
    if (!a.values.count("--alpha") && !a.values.count("--mark"))
        throw UsageError("--alpha is required, or --mark BxH for the alphas of the blocks marked");
    if (a.values.count("--alpha")) c.alphas = alphas_from(a.values.at("--alpha"));
    if (a.values.count("--mark")) {
        c.marks = study_blocks(a, "--mark");
        for (const studies::BlockShape& b : c.marks)
            if (std::find(c.alphas.begin(), c.alphas.end(), b.alpha) == c.alphas.end()) c.alphas.push_back(b.alpha);
        if (c.alphas.size() > 20) throw UsageError("--alpha and --mark: at most 20 alphas in all");
    }
    c.grid = grid_from(a);
    // With --fc the tallest blocks crush: without --p-min the range starts where every alpha's stand.
    if (!a.values.count("--p-min")) {
        c.grid.p_min = std::fmax(c.grid.p_min, dynamics::lowest_standing_p(c.alphas, c.grid.model.imperfection));
        if (!(c.grid.p_max > c.grid.p_min))
            throw UsageError("--fc: the blocks of these alphas stand only above p = " + g7(c.grid.p_min) +
                             " rad/s, at or above --p-max (" + g7(c.grid.p_max) + " rad/s)");
    }
    for (const studies::BlockShape& b : c.marks) {
        const std::string why = studies::why_not_markable(b, c.grid);
        if (!why.empty()) throw UsageError("--mark " + b.built + ": " + why + " (--p-min, --p-max)");
    }
    check_outputs(a, {"--output", "--png", "--rows"}, {c.path});
    require_gnuplot(a);
    refuse_engine_files_over(a, "--rows", {"--output", "--png"}, {c.path});
    if (a.values.count("--rows")) c.engine.output = a.values.at("--rows");
    if (c.engine.resume && c.engine.output.empty())
        throw UsageError("--resume needs --rows FILE: the spectra of an interrupted study are resumed from that file");
    set_threads_and_flush(c.engine, a, mpi);
    c.engine.command = "rocking spectrum";
    c.engine.jobs_from = "study";
    return c;
}

// The '#' lines of the rows file: what the spectra are of.
std::string description(const Command& c) {
    return "# rocking spectrum: the spectra of " + c.path + " at " + std::to_string(c.alphas.size()) +
           " alpha(s)\n# model: " + c.grid.describe_model() + "\n# grid: " + grid_text(c.grid) +
           "\n# refinement: " + c.grid.describe_refinement() + "\n";
}

}  // namespace

int cmd_spectrum(int argc, char** argv) {
    const bool mpi = batch::launched_by_mpirun();
    Command c;
    parse_on_every_rank([&] { c = command_from(argc, argv, mpi); });
    std::unique_ptr<batch::Ranks> ranks = join_if_launched("spectrum");

    // Every rank reads the record (its jobs need it); a failure is held until
    // all have said how they fared.
    std::optional<records::Record> r;
    std::unique_ptr<dynamics::SampledInput> input;
    std::exception_ptr failure;
    try {
        r = load_record(c.path, c.args);
        input = std::make_unique<dynamics::SampledInput>(r->in_g(dynamics::kGravity), r->dt, r->name);
        refuse_unresolvable_run(c.grid.p_max, input->t_end(), c.args, {"--dt", "--p-max"}, c.path);
    } catch (const std::exception&) {
        failure = std::current_exception();
    }
    if (const int status = agree_on_setup(ranks.get(), failure, "rocking spectrum")) return status;
    const jobs::SpectrumJobs jobs{input.get(), c.alphas, c.grid, description(c), c.path};
    const batch::BatchPlan plan = jobs::spectrum_plan(jobs);

    // Each alpha a job of the engine; rank 0 gets the rows in order, from
    // memory or from the rows file, and reads them after the batch: a failed
    // alpha's error thrown from inside it would end rank 0 while the other
    // ranks still run, and leave a rows file unfinished.
    std::vector<std::string> rows(c.alphas.size());
    c.engine.collect = [&](std::size_t k, const std::string& row) { rows[k] = row; };
    batch::run_batch(plan, c.engine, ranks.get());
    if (ranks && ranks->rank() != 0) return 0;

    std::vector<Study> studies;
    for (std::size_t k = 0; k < rows.size(); ++k) studies.push_back(jobs::study_from_row(rows[k], k, jobs));
    std::vector<studies::SpectrumMark> marks;
    for (const studies::BlockShape& b : c.marks)
        for (const Study& st : studies)
            if (st.spectrum.alpha == b.alpha) marks.push_back(studies::mark_block(*input, st.spectrum, b, c.grid));
    const Args& a = c.args;
    if (a.values.count("--output")) write_csv(a.values.at("--output"), c.path, *r, c.grid, studies, marks);
    if (a.values.count("--png")) write_spectrum_png(a.values.at("--png"), *r, c.grid, studies, marks);
    if (a.json) std::cout << json_text(json::spectrum_document(c.path, *r, c.grid, studies, marks)) << "\n";
    else print_text(c.path, *r, c.grid, studies, marks);
    return 0;
}

}  // namespace rocking::cli
