// rocking fragility: incremental dynamic analysis of records and blocks
// (studies/ida.hpp), each record's first collapse q and all its overturning
// intervals in q, and per block the lognormal fragility fit with its
// bootstrap interval and the empirical curve, as text, CSV or JSON.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/engine.hpp"
#include "batch/pool.hpp"
#include "batch/ranks.hpp"
#include "cli/cluster_front.hpp"
#include "cli/distinct_inputs.hpp"
#include "cli/geometry.hpp"
#include "cli/help.hpp"
#include "cli/nrml_output.hpp"
#include "cli/imperfection.hpp"
#include "cli/json_text.hpp"
#include "cli/options.hpp"
#include "cli/plots.hpp"
#include "cli/set_words.hpp"
#include "harness/table.hpp"
#include "jobs/fragility_plan.hpp"
#include "json/fragility_json.hpp"
#include "studies/ida.hpp"
#include "studies/search_alpha.hpp"

namespace rocking::cli {

namespace {

using studies::BlockFragility;
using studies::Ida;
using studies::IdaInterval;

std::string g7(double v) { return significant(v, 7); }

// The files: every argument before the first option.
std::vector<double> list_in(const Args& a, const std::string& flag, double lo, double hi, const std::string& range) {
    if (!a.values.count(flag)) throw UsageError(flag + " is required");
    const std::vector<double> values = number_list(flag, a.values.at(flag));
    if (values.empty() || values.size() > 50) throw UsageError(flag + ": from 1 to 50 values");
    for (double v : values)
        if (!(v > lo && v < hi)) throw UsageError(flag + ": each must be in " + range + " (got " + g7(v) + ")");
    return values;
}

studies::FragilityStudyOptions options_from(const Args& a) {
    studies::FragilityStudyOptions o;
    if (a.values.count("--q-max")) o.ida.q_max = number("--q-max", a.values.at("--q-max"));
    // Beyond 1e4 the scaled record reaches thousands of g: no physical input.
    if (!(o.ida.q_max > o.ida.q_min && o.ida.q_max <= 1e4)) throw UsageError("--q-max: must be in (1, 10000]");
    if (a.values.count("--points")) o.ida.points = integer("--points", a.values.at("--points"), 2, 10000);
    const MethodChoice m = method_options(a, "q");
    if (m.refine) o.ida.method = studies::IdaOptions::Method::refine;
    o.ida.width = m.width;
    o.ida.robust_width = m.robust_width;
    const Bootstrap b = bootstrap_options(a);
    o.resamples = b.resamples;
    o.seed = b.seed;
    o.threads = jobs_option(a);
    restitution_into(a, o.ida.model);
    friction_into(a, o.ida.model);
    imperfection_into(a, o.ida.model);
    o.ida.input_note = floor_input_note(a);
    // NRML's intensity is the site's PGA, which a hazard model gives for the ground:
    // a fit in a floor's PGA would be read as the ground's.
    if (a.values.count("--nrml") && a.values.count("--floor"))
        throw UsageError("--nrml with --floor: the fit is in the floor's PGA, which OpenQuake would read as the "
                         "ground's; export the ground's fragility, or keep the floor's in --fits");
    return o;
}

// The first few intervals: a record's whole set (a hundred islands on the
// refine method) is in --json and --output, not on the screen.
std::string interval_list(const Ida& ida) {
    if (ida.intervals.empty()) return "none";
    constexpr std::size_t kShown = 4;
    std::string text;
    for (std::size_t k = 0; k < ida.intervals.size() && k < kShown; ++k) {
        const IdaInterval& in = ida.intervals[k];
        text += (text.empty() ? "[" : " [") + g7(in.from) + ", " + g7(in.to) + (in.has_upper ? "]" : "+]");
    }
    if (ida.intervals.size() > kShown)
        text += " and " + std::to_string(ida.intervals.size() - kShown) + " more to q = " + g7(ida.intervals.back().to) +
                (ida.intervals.back().has_upper ? "" : "+") + " (all in --json, --output)";
    return text;
}

// The first collapse's bracket, as its checks left it (ida.hpp, IdaOptions::checks).
std::string point_check_text(const Ida& ida) {
    const studies::Checked& c = ida.intervals.front().lower_check;
    return studies::confirmation_name(c.confirmation) + (c.detail.empty() ? "" : ": " + c.detail);
}

std::string point_text(const Ida& ida) {
    if (!ida.point.collapsed) return "censored at q_max = " + g7(ida.point.q);
    if (!ida.intervals.front().has_lower) return "q = " + g7(ida.point.q) + " (collapse from the grid's lowest q)";
    return "q = " + g7(ida.point.q) + " (" + point_check_text(ida) + ")";
}

bool refined(const studies::FragilityStudyOptions& o) { return o.ida.method == studies::IdaOptions::Method::refine; }


std::string robust_text(const studies::IdaPoint& p) {
    return p.collapsed ? "q = " + g7(p.q) : "censored at q_max = " + g7(p.q);
}

std::string first_overturning_text(const Ida& ida) {
    if (!ida.first_overturning.collapsed) return "censored at q_max = " + g7(ida.first_overturning.q);
    const IdaInterval& in = ida.intervals.front();
    if (!in.has_lower) return "q = " + g7(ida.first_overturning.q) + " (the grid's lowest q)";
    return "q = " + g7(ida.first_overturning.q) + " in [" + g7(in.lower.safe) + ", " + g7(in.lower.collapse) + "] (" +
           point_check_text(ida) + ")";
}

std::string refine_line(const Ida& ida) {
    std::string text = "first overturning " + first_overturning_text(ida) + "; first robust collapse " +
                       robust_text(ida.first_robust_collapse) + "; overturned share: " + bands_summary(ida.bands, "q") + "; " +
                       std::to_string(ida.samples) + " runs with margins" +
                       (ida.with_margins ? "" : " (no margins: every interval split to w)");
    if (std::isfinite(ida.unguaranteed_from)) text += "; unguaranteed from q = " + g7(ida.unguaranteed_from);
    return text;
}

std::string bootstrap_text(const studies::BootstrapInterval& b) {
    return g7(100 * b.level) + " % bootstrap (" + std::to_string(b.resamples) + " resamples, seed " +
           std::to_string(b.seed) + "): median [" + g7(b.median.lo) + ", " + g7(b.median.hi) + "], beta [" +
           g7(b.beta.lo) + ", " + g7(b.beta.hi) + "]";
}

std::string lognormal_text(const studies::LognormalFragility& fit, bool bootstrapped,
                           const studies::BootstrapInterval& interval) {
    std::string text = "lognormal median q = " + g7(fit.median) + ", beta = " + g7(fit.beta) + " (" +
                       std::to_string(fit.collapsed) + " overturned, " + std::to_string(fit.censored) + " censored)";
    return bootstrapped ? text + "; " + bootstrap_text(interval) : text;
}

std::string fit_text(const BlockFragility& f) {
    return f.fitted ? lognormal_text(f.fit, f.bootstrapped, f.interval) : "no fit: " + f.no_fit;
}

// The refine method's fits on the robust collapse and on the stripes (issue 39, item 3).
std::string robust_fit_text(const BlockFragility& f) {
    const studies::CapacityFit& c = f.robust;
    return c.fitted ? lognormal_text(c.fit, c.bootstrapped, c.interval) : "no fit: " + c.no_fit;
}

std::string stripe_fit_text(const BlockFragility& f) {
    const studies::StripeFit& s = f.stripes;
    if (!s.fitted) return "no fit: " + s.no_fit;
    const std::string text = "lognormal median q = " + g7(s.fit.median) + ", beta = " + g7(s.fit.beta) + " (" +
                             std::to_string(s.stripes.size()) + " stripes x " + std::to_string(s.shares.share.size()) +
                             " records)";
    return s.bootstrapped ? text + "; " + bootstrap_text(s.interval) : text;
}

// The stripes in brief: each one's mean overturned share (z_j / n_j, a
// hundred of them) is in --json and --output.
std::string stripes_text(const BlockFragility& f) {
    const std::vector<studies::Stripe>& stripes = f.stripes.stripes;
    const studies::Stripe *first = nullptr, *whole = nullptr;
    for (const studies::Stripe& s : stripes) {
        if (!first && s.overturned > 0) first = &s;
        if (!whole && s.overturned >= s.records) whole = &s;
    }
    std::string text = std::to_string(stripes.size()) + " (mean overturned share ";
    text += first ? "above 0 from q = " + g7(first->q) : std::string("0 at every stripe");
    if (whole) text += ", first 1 at q = " + g7(whole->q);
    return text + "; each stripe's share in --json and --output)";
}

std::string empirical_text(const BlockFragility& f) {
    std::string text;
    for (const studies::EmpiricalPoint& e : f.empirical) text += (text.empty() ? "" : " ") + g7(e.q) + ":" + g7(e.share);
    return text.empty() ? "none" : text;
}

std::string grid_note(const studies::FragilityStudyOptions& o) { return json::fragility_grid_note(o); }

// Each block's fits first, then its records: the answer before the evidence.
void print_text(const std::vector<std::string>& files, const studies::FragilityStudyOptions& o,
                const std::vector<BlockFragility>& study) {
    std::printf("fragility of %zu record(s)\n  model: %s\n  grid: %s\n", files.size(), o.ida.describe_model().c_str(),
                grid_note(o).c_str());
    if (refined(o)) std::printf("  refine: %s\n", o.describe_fits().c_str());
    for (const BlockFragility& f : study) {
        std::printf("alpha = %g, p = %g rad/s%s:\n", f.block.alpha, f.block.p,
                    f.block.built.empty() ? "" : (" (block " + f.block.built + " m)").c_str());
        if (!f.three_ways) {
            std::printf("  fit on the first overturnings the grid saw (islands between its points missed): %s\n",
                        fit_text(f).c_str());
        } else {
            std::printf("  fit on the first overturning (conservative): %s\n", fit_text(f).c_str());
            std::printf("  fit on the first robust collapse: %s\n", robust_fit_text(f).c_str());
            std::printf("  multiple-stripe fit: %s\n", stripe_fit_text(f).c_str());
        }
        std::printf("  empirical (q:share): %s\n", empirical_text(f).c_str());
        if (f.three_ways)
            std::printf("  stripes: %s\n", stripes_text(f).c_str());
        std::printf("  records:\n");
        for (std::size_t k = 0; k < files.size(); ++k) {
            std::printf("  %s: %s; overturns for q in %s\n", files[k].c_str(), point_text(f.idas[k]).c_str(),
                        interval_list(f.idas[k]).c_str());
            if (refined(o)) std::printf("    %s\n", refine_line(f.idas[k]).c_str());
        }
    }
}

void write_csv(const std::string& csv, const std::vector<std::string>& files, const studies::FragilityStudyOptions& o,
               const std::vector<BlockFragility>& study) {
    std::vector<std::string> columns = {"alpha", "p", "file", "q", "collapsed", "intervals"};
    if (refined(o))
        for (const char* c : {"first_overturning", "first_overturning_safe", "first_overturning_collapse",
                              "first_overturning_check", "first_robust_collapse", "first_robust_collapsed", "bands",
                              "samples", "with_margins", "unguaranteed_from"})
            columns.push_back(c);
    harness::Table t(columns);
    t.note("command", "rocking fragility");
    t.note("model", o.ida.describe_model());
    t.note("solver", dynamics::solver_name(o.ida.model.solver.kind));
    std::string inputs;
    for (const std::string& f : files) inputs += (inputs.empty() ? "" : "; ") + f;
    t.note("inputs", inputs);
    t.note("grid", grid_note(o));
    t.note("columns", "q: the first collapse q, or q_max where collapsed is false (censored); intervals: every "
                      "overturning interval in q, '+' where it runs to q_max");
    if (refined(o)) {
        t.note("refine", o.describe_fits());
        t.note("refine columns",
               "first_overturning: the lowest interval's start (= q), its bracket (first_overturning_safe, "
               "first_overturning_collapse; empty at the grid's end or censored) and check; first_robust_collapse: "
               "the start of the first interval wider than the robust width, or q_max where first_robust_collapsed "
               "is false; bands: each step of the main grid that overturns at all, [from, to]:share of it in ln q; "
               "samples: runs with escape margins; unguaranteed_from: empty where the guarantee holds to q_max");
        t.note("refine fits", "fit at: the fit on the first overturning (conservative); first robust collapse fit at, "
                              "stripe fit at: the other two capacities; stripes at: each stripe's q and mean overturned "
                              "share (q:share), where above 0");
    }
    for (const BlockFragility& f : study) {
        const std::string block = "alpha " + g7(f.block.alpha) + ", p " + g7(f.block.p) +
                                  (f.block.built.empty() ? "" : " (block " + f.block.built + " m)");
        t.note("fit at " + block, fit_text(f));
        t.note("empirical at " + block, empirical_text(f));
        if (!f.three_ways) continue;
        t.note("first robust collapse fit at " + block, robust_fit_text(f));
        t.note("stripe fit at " + block, stripe_fit_text(f));
        t.note("stripes at " + block, stripes_text(f));
    }
    for (const BlockFragility& f : study)
        for (std::size_t k = 0; k < files.size(); ++k) {
            const Ida& ida = f.idas[k];
            auto& row = t.row().add(f.block.alpha).add(f.block.p).add(files[k]).add(ida.point.q)
                            .add(ida.point.collapsed).add(interval_list(ida));
            if (!refined(o)) continue;
            const bool bracketed = ida.first_overturning.collapsed && ida.intervals.front().has_lower;
            row.add(ida.first_overturning.q);
            if (bracketed) row.add(ida.intervals.front().lower.safe).add(ida.intervals.front().lower.collapse)
                               .add(point_check_text(ida));
            else row.add(std::string()).add(std::string()).add(std::string());
            row.add(ida.first_robust_collapse.q).add(ida.first_robust_collapse.collapsed).add(bands_text(ida.bands))
                .add(std::to_string(ida.samples)).add(ida.with_margins);
            if (std::isfinite(ida.unguaranteed_from)) row.add(ida.unguaranteed_from);
            else row.add(std::string());
        }
    write_output(t, csv);
}

struct Command {
    std::vector<std::string> files;
    Args args;
    std::vector<studies::BlockShape> blocks;
    studies::FragilityStudyOptions study;
    batch::EngineOptions engine;
};

Command command_from(int argc, char** argv, bool mpi) {
    Command c;
    std::vector<char*> args = without_engine_switches(argc, argv, c.engine.resume, c.engine.quiet);
    const int count = static_cast<int>(args.size());
    int first = 0;
    c.files = file_arguments(count, args.data(), first, usage_line("fragility"));
    c.args = parse(count, args.data(), first, {"--alpha", "--p", "--block", "--q-max", "--points", "--bootstrap", "--seed", "--unit", "--floor", "--restitution", "--friction", "--lean", "--out-of-plumb", "--fc", "--density",
                                               "--dt", "--jobs", "--output", "--rows", "--method", "--width",
                                               "--robust-width", "--png", "--fits", "--nrml"});
    const Args& a = c.args;
    if (a.values.count("--block")) {
        c.blocks = study_blocks(a);
    } else {
        const std::vector<double> alphas = list_in(a, "--alpha", 0, studies::kSearchAlphaMax, studies::kSearchAlphaRange);
        const std::vector<double> ps = list_in(a, "--p", 0.01, 1000, "(0.01, 1000) rad/s");
        refuse_repeated_values("--alpha", alphas);
        refuse_repeated_values("--p", ps);
        for (double alpha : alphas)
            for (double p : ps) c.blocks.push_back({alpha, p, ""});
    }
    c.study = options_from(a);
    if (c.files.size() > 1000) throw UsageError("at most 1000 files");
    check_outputs(a, {"--output", "--rows", "--fits", "--png", "--nrml"}, c.files);
    refuse_engine_files_over(a, "--rows", {"--output", "--fits", "--png", "--nrml"}, c.files);
    require_gnuplot(a);
    if (a.values.count("--rows")) c.engine.output = a.values.at("--rows");
    if (c.engine.resume && c.engine.output.empty())
        throw UsageError("--resume needs --rows FILE: the IDAs of an interrupted study are resumed from that file");
    set_threads_and_flush(c.engine, a, mpi);
    c.engine.command = "rocking fragility";
    c.engine.jobs_from = "study";
    return c;
}

// The '#' lines of the rows file: what the IDAs are of.
std::string description(const Command& c) {
    std::string text = "# rocking fragility: the IDAs of " + std::to_string(c.files.size()) + " record(s) x " +
                       std::to_string(c.blocks.size()) + " block(s)\n# model: " + c.study.ida.describe_model() +
                       "\n# grid: " + grid_note(c.study) + "\n";
    if (refined(c.study)) text += "# refine: " + c.study.describe_fits() + "\n";
    for (std::size_t k = 0; k < c.files.size(); ++k)
        text += "# record " + std::to_string(k) + ": " + c.files[k] + "\n";
    return text;
}

}  // namespace

int cmd_fragility(int argc, char** argv) {
    const bool mpi = batch::launched_by_mpirun();
    Command c;
    parse_on_every_rank([&] { c = command_from(argc, argv, mpi); });
    std::unique_ptr<batch::Ranks> ranks = join_if_launched("fragility");

    // Every rank reads every record (the jobs of a rank take any of them); a
    // failure is held until all have said how they fared.
    std::vector<std::unique_ptr<dynamics::SampledInput>> records;
    jobs::FragilityJobs jobs;
    std::exception_ptr failure;
    try {
        for (const std::string& path : c.files) {
            const records::Record r = load_record(path, c.args);
            records.push_back(std::make_unique<dynamics::SampledInput>(r.in_g(dynamics::kGravity), r.dt, r.name));
            if (!(records.back()->peak() > 0)) throw std::runtime_error(path + ": the record never moves (PGA 0)");
            double p_max = 0;
            for (const studies::BlockShape& b : c.blocks) p_max = std::max(p_max, b.p);
            refuse_unresolvable_run(p_max, records.back()->t_end(), c.args, {"--dt", "--p"}, path);
            jobs.inputs.push_back(records.back().get());
        }
        refuse_repeated_records(c.files, jobs.inputs);
    } catch (const std::exception&) {
        failure = std::current_exception();
    }
    if (const int status = agree_on_setup(ranks.get(), failure, "rocking fragility")) return status;
    jobs.blocks = c.blocks;
    jobs.ida = c.study.ida;
    jobs.description = description(c);
    jobs.names = c.files;
    const batch::BatchPlan plan = jobs::fragility_plan(jobs);

    // Each (block, record) IDA a job of the engine; rank 0 gets their rows in
    // order, from memory or from the rows file, and fits each block.  A failed
    // IDA's error is held until the batch ends: thrown from inside it, it
    // would end rank 0 while the other ranks still run, and leave the rows
    // file unfinished.
    std::vector<std::vector<studies::Ida>> idas(c.blocks.size());
    const std::size_t n = c.files.size();
    std::exception_ptr first_error;
    c.engine.collect = [&](std::size_t j, const std::string& row) {
        if (first_error) return;
        try {
            idas[j / n].push_back(jobs::ida_from_row(row, j, jobs));
        } catch (const std::exception&) {
            first_error = std::current_exception();
        }
    };
    batch::run_batch(plan, c.engine, ranks.get());
    if (ranks && ranks->rank() != 0) return 0;
    if (first_error) std::rethrow_exception(first_error);

    // The fits draw the records in the order of their samples' digests (the
    // plan's, studies/record_order.hpp), not the command line's.
    std::vector<std::string> identities;
    for (const batch::InputDigest& in : plan.inputs) identities.push_back(in.digest);
    std::vector<BlockFragility> study(c.blocks.size());
    batch::run_ordered<BlockFragility>(
        c.blocks.size(), batch::PoolOptions{c.engine.threads},
        [&](std::size_t b) { return studies::block_fragility(c.blocks[b], std::move(idas[b]), identities, c.study); },
        [&](std::size_t b, BlockFragility& f) { study[b] = std::move(f); });
    const Args& a = c.args;
    if (a.values.count("--output")) write_csv(a.values.at("--output"), c.files, c.study, study);
    if (a.values.count("--fits")) write_fragility_fits(a.values.at("--fits"), c.files, c.study, study);
    if (a.values.count("--png")) write_fragility_png(a.values.at("--png"), c.files, c.study, study);
    if (a.values.count("--nrml")) write_nrml(a.values.at("--nrml"), c.files, c.study, study);
    if (a.json) std::cout << json_text(json::fragility_document(c.files, c.study, study)) << "\n";
    else print_text(c.files, c.study, study);
    return 0;
}

}  // namespace rocking::cli
