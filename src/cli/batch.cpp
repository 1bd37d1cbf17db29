// rocking batch: a manifest of jobs (src/jobs/) run by the batch engine
// (src/batch/) on threads, or on the ranks of an MPI run under mpirun, the
// results in the manifest's order (docs/batch.md).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "batch/cluster.hpp"
#include "batch/engine.hpp"
#include "batch/manifest.hpp"
#include "batch/pool.hpp"
#include "batch/results_file.hpp"
#include "batch/shard.hpp"
#include "cli/cluster_front.hpp"
#include "cli/help.hpp"
#include "cli/options.hpp"
#include "jobs/batch_plan.hpp"
#include "jobs/record_store.hpp"

namespace rocking::cli {

namespace {

// The exit status of a batch that ran to its end with failed jobs.
constexpr int kSomeJobsFailed = 3;

struct Options {
    std::string manifest;
    batch::EngineOptions engine;
    std::optional<batch::Shard> shard;
};

Options options_from(int argc, char** argv, bool mpi) {
    Options o;
    std::vector<char*> args = without_engine_switches(argc, argv, o.engine.resume, o.engine.quiet);
    const int count = static_cast<int>(args.size());
    o.manifest = file_argument(count, args.data(), 2, usage_line("batch"));
    const Args a = parse(count, args.data(), 3, {"--jobs", "--output", "--shard"});
    if (a.json) throw UsageError("--json: the results of a batch are CSV (docs/batch.md)");
    if (a.values.count("--shard")) {
        try {
            o.shard = batch::parse_shard(a.values.at("--shard"));
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--shard: ") + e.what());
        }
        if (mpi) throw UsageError("--shard is for clusters without MPI: under mpirun the ranks share the whole batch");
        if (!a.values.count("--output"))
            throw UsageError("--shard needs --output FILE: rocking batch join assembles the shards' files");
    }
    if (a.values.count("--output")) {
        o.engine.output = a.values.at("--output");
        if (o.engine.output.empty()) throw UsageError("--output: an empty file name");
    }
    if (o.engine.resume && o.engine.output.empty())
        throw UsageError("--resume needs --output: rows written to standard output cannot be resumed");
    set_threads_and_flush(o.engine, a, mpi);
    return o;
}

// Before any job (issue 38): jobs::check_output, an output over an input
// being a bad command line.
void check_output(const std::string& output, const batch::Manifest& manifest,
                  const std::vector<jobs::NamedRecord>& records) {
    if (output.empty()) return;
    try {
        jobs::check_output("--output", output, manifest, records);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

}  // namespace

int cmd_batch(int argc, char** argv) {
    if (argc > 2 && std::string(argv[2]) == "join") return cmd_batch_join(argc, argv);
    const bool mpi = batch::launched_by_mpirun();
    Options o;
    parse_on_every_rank([&] { o = options_from(argc, argv, mpi); });
    std::unique_ptr<batch::Ranks> ranks = join_if_launched("batch");

    // Every rank reads the manifest; a failure is held until all have said how they fared.
    std::optional<batch::Manifest> manifest;
    jobs::RecordStore records;
    if (ranks) records.refuse_unshareable();
    batch::BatchPlan plan;
    std::exception_ptr failure;
    try {
        manifest.emplace(batch::Manifest::read(o.manifest));
        const std::vector<jobs::NamedRecord> named = jobs::named_records(*manifest);
        if (!ranks || ranks->rank() == 0) check_output(o.engine.output, *manifest, named);
        plan = jobs::make_plan(*manifest, records, named);
        if (o.shard) plan = batch::shard_plan(plan, *o.shard);
    } catch (const std::exception&) {
        failure = std::current_exception();
    }
    if (const int status = agree_on_setup(ranks.get(), failure, "rocking batch")) return status;

    const batch::BatchOutcome outcome = batch::run_batch(plan, o.engine, ranks.get());
    if (ranks && ranks->rank() != 0) return 0;
    if (!o.engine.quiet)
        std::fprintf(stderr, "rocking batch: %s%zu jobs, %zu failed%s%s\n",
                     outcome.already_complete ? "already complete: " : "", outcome.jobs, outcome.failed,
                     o.engine.output.empty() ? "" : "; results in ", o.engine.output.c_str());
    return outcome.failed > 0 ? kSomeJobsFailed : 0;
}

}  // namespace rocking::cli
