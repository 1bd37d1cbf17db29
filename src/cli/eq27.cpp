// rocking eq27: eq. 27 at scale (studies/eq27_at_scale.hpp).  Each record's
// first collapse q on every block of a grid against eq. 27 at x = p to_k:
// the share of non-conservative cases per to_k with its bootstrap interval
// over records (--bootstrap K --seed S) and its Wilson interval (the cases
// taken as independent), the records non-conservative on any block, and the
// map over (alpha, p) as CSV, as text or JSON.  Each (block, record) IDA is
// a job of the batch engine, fragility's (jobs/fragility_plan.hpp), so that
// the study runs on threads or on the ranks of an MPI run alike, and rank 0
// counts the cases from the rows.  With --method refine (issue 39) the shares
// under each capacity: the first overturning and the first robust collapse.
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/engine.hpp"
#include "batch/ranks.hpp"
#include "cli/cluster_front.hpp"
#include "cli/distinct_inputs.hpp"
#include "cli/help.hpp"
#include "cli/imperfection.hpp"
#include "cli/json_text.hpp"
#include "json/eq27_json.hpp"
#include "cli/options.hpp"
#include "cli/plots.hpp"
#include "harness/table.hpp"
#include "jobs/fragility_plan.hpp"
#include "studies/eq27_at_scale.hpp"
#include "studies/record_order.hpp"
#include "studies/search_alpha.hpp"

namespace rocking::cli {

namespace {

using studies::Eq27Study;
using studies::kHalfPeriods;

using studies::Eq27ByCapacity;
using studies::kEq27FirstOverturningNote;
using studies::kEq27NoBootstrap;
using studies::kEq27RobustCollapseNote;
using studies::kEq27Verdict;
using studies::kEq27WilsonNote;

std::string g4(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}

std::string g7(double v) { return significant(v, 7); }

double bounded(const Args& a, const std::string& flag, double fallback, double lo, double hi, const std::string& range) {
    if (!a.values.count(flag)) return fallback;
    const double v = number(flag, a.values.at(flag));
    if (!(v > lo && v <= hi)) throw UsageError(flag + ": must be in " + range + " (got " + g7(v) + ")");
    return v;
}

// The p of the grid: --p-points log-spaced from --p-min to --p-max, both
// ends included.  One point is one p: --p-min, and --p-max (when given) must
// be that p, so that no range is given and silently cut to its start
// (Eq27Grid::check refuses it, as the Python module's eq27).
void p_grid_from(const Args& a, studies::Eq27Grid& g) {
    g.p_min = bounded(a, "--p-min", g.p_min, 0.01, 1000, "(0.01, 1000] rad/s");
    g.p_max = bounded(a, "--p-max", g.p_max, 0.01, 1000, "(0.01, 1000] rad/s");
    if (a.values.count("--p-points")) g.p_points = integer("--p-points", a.values.at("--p-points"), 1, 1000);
    if (g.p_points == 1 && a.values.count("--p-min") && !a.values.count("--p-max")) g.p_max = g.p_min;
}

studies::Eq27Grid grid_from(const Args& a) {
    studies::Eq27Grid g;
    if (a.values.count("--alpha")) {
        g.alphas = number_list("--alpha", a.values.at("--alpha"));
        if (g.alphas.empty() || g.alphas.size() > 50) throw UsageError("--alpha: from 1 to 50 values");
        for (double v : g.alphas)
            if (!studies::in_search_alpha_range(v))
                throw UsageError("--alpha: each must be in " + std::string(studies::kSearchAlphaRange) + " (got " + g7(v) + ")");
    }
    p_grid_from(a, g);
    try {
        g.check({"--alpha", "--p-min", "--p-max", "--p-points", " "});
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    return g;
}

studies::Eq27Options options_from(const Args& a) {
    studies::Eq27Options o;
    o.grid = grid_from(a);
    // Beyond 1e4 the scaled record reaches thousands of g: no physical input.
    o.ida.q_max = bounded(a, "--q-max", o.ida.q_max, o.ida.q_min, 1e4, "(1, 10000]");
    // As rocking fragility's --method, --width and --robust-width (in ln q).
    const MethodChoice m = method_options(a, "q");
    if (m.refine) o.ida.method = studies::IdaOptions::Method::refine;
    o.ida.width = m.width;
    o.ida.robust_width = m.robust_width;
    restitution_into(a, o.ida.model);
    friction_into(a, o.ida.model);
    imperfection_into(a, o.ida.model);
    o.ida.input_note = floor_input_note(a);
    // As rocking fragility's: no bootstrap unless asked, and then from a stated seed.
    const Bootstrap b = bootstrap_options(a);
    o.bootstrap.resamples = b.resamples;
    if (b.resamples > 0) o.bootstrap.seed = b.seed;
    return o;
}

struct Command {
    std::vector<std::string> files;
    Args args;
    studies::Eq27Options study;
    std::vector<studies::BlockShape> blocks;
    batch::EngineOptions engine;
};

Command command_from(int argc, char** argv, bool mpi) {
    Command c;
    bool resume = false;
    std::vector<char*> args = without_engine_switches(argc, argv, resume, c.engine.quiet);
    if (resume) throw UsageError("--resume: eq27 keeps no rows file to resume from");
    const int count = static_cast<int>(args.size());
    int first = 0;
    c.files = file_arguments(count, args.data(), first, usage_line("eq27"));
    c.args = parse(count, args.data(), first, {"--alpha", "--p-min", "--p-max", "--p-points", "--q-max", "--bootstrap",
                                               "--seed", "--unit", "--dt", "--floor", "--restitution", "--friction", "--lean", "--out-of-plumb", "--fc", "--density", "--jobs", "--output",
                                               "--method", "--width", "--robust-width", "--png"});
    c.study = options_from(c.args);
    // With --fc the tallest blocks crush: without --p-min the grid starts where every alpha's stand.
    if (!c.args.values.count("--p-min")) {
        studies::Eq27Grid& g = c.study.grid;
        g.p_min = std::fmax(g.p_min, dynamics::lowest_standing_p(g.alphas, c.study.ida.model.imperfection));
        if (!(g.p_max > g.p_min))
            throw UsageError("--fc: the blocks of these alphas stand only above p = " + g7(g.p_min) +
                             " rad/s, at or above --p-max (" + g7(g.p_max) + " rad/s)");
    }
    c.blocks = c.study.grid.blocks();
    if (c.files.size() > 1000) throw UsageError("at most 1000 files");
    check_outputs(c.args, {"--output", "--png"}, c.files);
    require_gnuplot(c.args);
    set_threads_and_flush(c.engine, c.args, mpi);
    c.engine.command = "rocking eq27";
    c.engine.jobs_from = "study";
    return c;
}

// Every record, in g, with its half-periods; each record once (distinct_inputs.hpp).
struct Loaded {
    std::vector<std::unique_ptr<dynamics::SampledInput>> inputs;
    std::vector<std::array<double, kHalfPeriods>> to;
};

Loaded load(const std::vector<std::string>& files, const Args& a, double p_max) {
    Loaded l;
    std::vector<const dynamics::SampledInput*> given;
    for (const std::string& path : files) {
        const records::Record r = load_record(path, a);
        l.inputs.push_back(std::make_unique<dynamics::SampledInput>(r.in_g(dynamics::kGravity), r.dt, r.name));
        refuse_unresolvable_run(p_max, l.inputs.back()->t_end(), a, {"--dt", "--p-max"}, path);
        l.to.push_back(half_periods_of(r, path).to);
        if (!(l.inputs.back()->peak() > 0)) throw std::runtime_error(path + ": the record never moves (PGA 0)");
        given.push_back(l.inputs.back().get());
    }
    refuse_repeated_records(files, given);
    return l;
}

// The capacities of every record on every block, [record][block] (its first
// overturning and first robust collapse, from the row of its IDA): each IDA
// a job of the engine (job j: block j / records, record j % records).
// Filled on rank 0, or without ranks; not on the other ranks.  A failed IDA's
// error waits for the batch's end, as fragility's does.
std::vector<std::vector<studies::Eq27Capacities>> capacities(Command& c, const Loaded& l, batch::Ranks* ranks) {
    jobs::FragilityJobs jobs;
    for (const auto& input : l.inputs) jobs.inputs.push_back(input.get());
    jobs.blocks = c.blocks;
    jobs.ida = c.study.ida;
    jobs.description = "# rocking eq27: the IDAs of " + std::to_string(c.files.size()) + " record(s) x " +
                       std::to_string(c.blocks.size()) + " block(s)\n";
    const batch::BatchPlan plan = jobs::fragility_plan(jobs);
    const std::size_t n = c.files.size();
    std::vector<std::vector<studies::Eq27Capacities>> points(n, std::vector<studies::Eq27Capacities>(c.blocks.size()));
    std::exception_ptr first_error;
    c.engine.collect = [&](std::size_t j, const std::string& row) {
        if (first_error) return;
        try {
            points[j % n][j / n] = studies::capacities_of(jobs::ida_from_row(row, j, jobs));
        } catch (const std::exception&) {
            first_error = std::current_exception();
        }
    };
    batch::run_batch(plan, c.engine, ranks);
    if (first_error) std::rethrow_exception(first_error);
    return points;
}

// The definitions with no non-conservative case anywhere on the grid.
std::string conservative_list(const Eq27Study& s) {
    std::string text;
    for (int k = 0; k < kHalfPeriods; ++k)
        if (s.shares[k].non_conservative == 0) text += (text.empty() ? "to_" : ", to_") + std::to_string(k + 1);
    return text.empty() ? "none" : text;
}

int blocks_hit(const Eq27Study& s, int k) { return json::blocks_with_any(s, k); }

bool bootstrapped(const Eq27Study& s) { return s.bootstrap.resamples > 0; }

bool refined(const studies::Eq27Options& o) { return o.ida.method == studies::IdaOptions::Method::refine; }

// A capacity as the output names it (studies/eq27_at_scale.hpp, Eq27Capacities).
struct Capacity {
    const char* key;       // in the JSON
    const char* note;      // what it is, and what its share means
    const char* censored;  // what a censored case lacks up to q_max
};
const Capacity kFirstOverturning{"first_overturning", kEq27FirstOverturningNote, "no overturning"};
const Capacity kRobustCollapse{"first_robust_collapse", kEq27RobustCollapseNote, "no robust collapse"};

std::string bootstrap_label(const Eq27Study& s) {
    return g7(100 * s.bootstrap.level) + " % bootstrap over records (" + std::to_string(s.bootstrap.resamples) +
           " resamples, seed " + std::to_string(s.bootstrap.seed) + ")";
}

std::string wilson_label(const Eq27Study& s) { return g7(100 * s.level) + " % Wilson, cases taken as independent"; }

std::string range_text(double lo, double hi) { return "[" + g4(lo) + ", " + g4(hi) + "]"; }

std::string count_text(const studies::Eq27Share& sh) {
    return std::to_string(sh.non_conservative) + "/" + std::to_string(sh.cases) + " = " + g4(sh.share);
}

std::string records_text(const studies::Eq27Share& sh) {
    return std::to_string(sh.records_with_any) + "/" + std::to_string(sh.records);
}

// One k in a sentence, for the CSV's notes.
std::string share_text(const Eq27Study& s, int k) {
    const studies::Eq27Share& sh = s.shares[k];
    std::string text = count_text(sh) + "; ";
    if (bootstrapped(s)) text += bootstrap_label(s) + " " + range_text(sh.bootstrap.lo, sh.bootstrap.hi) + "; ";
    return text + wilson_label(s) + " " + range_text(sh.wilson.lo, sh.wilson.hi) + "; records non-conservative on " +
           "any block " + records_text(sh);
}

std::string censored_text(const Eq27Study& s, double q_max, const Capacity& c = kFirstOverturning) {
    return std::to_string(s.censored) + " of " + std::to_string(s.cases.size()) + " cases censored (" + c.censored +
           " up to q_max = " + g7(q_max) + "), counted as conservative";
}

// The shares per to_k, with their intervals, and the definitions conservative everywhere.
void print_shares(const Eq27Study& s) {
    std::printf("  to_k   non-conservative = share   %s%g %% Wilson (independent cases)   records with any   blocks "
                "with any\n", bootstrapped(s) ? (g7(100 * s.bootstrap.level) + " % bootstrap   ").c_str() : "",
                100 * s.level);
    for (int k = 0; k < kHalfPeriods; ++k) {
        const studies::Eq27Share& sh = s.shares[k];
        std::printf("  to_%-2d  %s   %s%s   %s   %d/%zu\n", k + 1, count_text(sh).c_str(),
                    bootstrapped(s) ? (range_text(sh.bootstrap.lo, sh.bootstrap.hi) + "   ").c_str() : "",
                    range_text(sh.wilson.lo, sh.wilson.hi).c_str(), records_text(sh).c_str(), blocks_hit(s, k),
                    s.blocks.size());
    }
    std::printf("  conservative on every block and record: %s\n", conservative_list(s).c_str());
}

void print_text(const std::vector<std::string>& files, const studies::Eq27Options& o, const Eq27ByCapacity& by) {
    const Eq27Study& s = by.first_overturning;
    std::printf("eq. 27 at scale: %zu record(s) x %zu block(s)\n  blocks: %s\n  model: %s\n  IDA: %s\n", files.size(),
                s.blocks.size(), o.grid.describe().c_str(), o.ida.describe_model().c_str(), o.ida.describe_grid().c_str());
    if (refined(o)) std::printf("  refine: %s\n", studies::eq27_refine_note(o.ida).c_str());
    std::printf("  %s\n", kEq27Verdict);
    if (!refined(o)) std::printf("  %s\n", censored_text(s, o.ida.q_max).c_str());
    if (bootstrapped(s)) std::printf("  interval: %s\n", bootstrap_label(s).c_str());
    else std::printf("  %s\n", kEq27NoBootstrap);
    std::printf("  Wilson: %s\n", kEq27WilsonNote);
    if (!refined(o)) {
        print_shares(s);
        return;
    }
    for (const auto& [study, c] : {std::pair{&s, &kFirstOverturning}, std::pair{&by.first_robust_collapse, &kRobustCollapse}}) {
        std::printf("capacity: %s\n  %s\n", c->note, censored_text(*study, o.ida.q_max, *c).c_str());
        print_shares(*study);
    }
}

void write_csv(const std::string& csv, const std::vector<std::string>& files, const studies::Eq27Options& o,
               const Eq27ByCapacity& by) {
    const Eq27Study& s = by.first_overturning;
    const Eq27Study& robust = by.first_robust_collapse;
    std::vector<std::string> columns = {"alpha", "p", "records", "censored"};
    for (int k = 1; k <= kHalfPeriods; ++k) columns.push_back("nc_to" + std::to_string(k));
    if (refined(o)) {
        columns.push_back("robust_censored");
        for (int k = 1; k <= kHalfPeriods; ++k) columns.push_back("robust_nc_to" + std::to_string(k));
    }
    harness::Table t(columns);
    t.note("command", "rocking eq27");
    t.note("model", o.ida.describe_model());
    t.note("solver", dynamics::solver_name(o.ida.model.solver.kind));
    std::string inputs;
    for (const std::string& f : files) inputs += (inputs.empty() ? "" : "; ") + f;
    t.note("inputs", inputs);
    t.note("grid", o.grid.describe());
    t.note("ida", o.ida.describe_grid());
    if (refined(o)) {
        t.note("refine", studies::eq27_refine_note(o.ida));
        t.note("capacity", kFirstOverturning.note);
        t.note("robust capacity", kRobustCollapse.note);
    }
    t.note("verdict", kEq27Verdict);
    t.note("censored", censored_text(s, o.ida.q_max));
    if (refined(o)) t.note("robust censored", censored_text(robust, o.ida.q_max, kRobustCollapse));
    t.note("intervals", (bootstrapped(s) ? bootstrap_label(s) : std::string(kEq27NoBootstrap)) + "; " + kEq27WilsonNote);
    for (int k = 0; k < kHalfPeriods; ++k) t.note("share to_" + std::to_string(k + 1), share_text(s, k));
    if (refined(o))
        for (int k = 0; k < kHalfPeriods; ++k) t.note("robust share to_" + std::to_string(k + 1), share_text(robust, k));
    t.note("columns", std::string("per block (alpha, p rad/s): records, those censored, and nc_toK the records "
                                  "non-conservative for to_K") +
                          (refined(o) ? " (under the first overturning); robust_censored and robust_nc_toK the same "
                                        "under the first robust collapse"
                                      : ""));
    for (std::size_t b = 0; b < s.map.size(); ++b) {
        const studies::Eq27Cell& c = s.map[b];
        t.row().add(c.block.alpha).add(c.block.p).add(c.records).add(c.censored);
        for (int k = 0; k < kHalfPeriods; ++k) t.add(c.non_conservative[k]);
        if (!refined(o)) continue;
        t.add(robust.map[b].censored);
        for (int k = 0; k < kHalfPeriods; ++k) t.add(robust.map[b].non_conservative[k]);
    }
    write_output(t, csv);
}

}  // namespace

int cmd_eq27(int argc, char** argv) {
    const bool mpi = batch::launched_by_mpirun();
    Command c;
    parse_on_every_rank([&] { c = command_from(argc, argv, mpi); });
    std::unique_ptr<batch::Ranks> ranks = join_if_launched("eq27");

    // Every rank reads every record (its jobs take any of them); a failure
    // is held until all have said how they fared.
    Loaded l;
    std::exception_ptr failure;
    try {
        l = load(c.files, c.args, c.study.grid.p_max);
    } catch (const std::exception&) {
        failure = std::current_exception();
    }
    if (const int status = agree_on_setup(ranks.get(), failure, "rocking eq27")) return status;
    const auto points = capacities(c, l, ranks.get());
    if (ranks && ranks->rank() != 0) return 0;

    // The bootstrap draws the records in the order of their samples' digests, not the command line's.
    std::vector<std::string> identities;
    for (const auto& input : l.inputs) identities.push_back(studies::sample_digest(*input));
    const Eq27ByCapacity s =
        studies::eq27_by_capacity(points, l.to, identities, c.blocks, c.study.level, c.study.bootstrap);
    const Args& a = c.args;
    if (a.values.count("--output")) write_csv(a.values.at("--output"), c.files, c.study, s);
    if (a.values.count("--png")) write_eq27_png(a.values.at("--png"), c.files, c.study, s, l.to);
    if (a.json) std::cout << json_text(json::eq27_document(c.files, c.study, s)) << "\n";
    else print_text(c.files, c.study, s);
    return 0;
}

}  // namespace rocking::cli
