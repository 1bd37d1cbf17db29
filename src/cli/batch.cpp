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
#include "cli/options.hpp"
#include "jobs/batch_plan.hpp"
#include "jobs/record_store.hpp"

namespace rocking::cli {

namespace {

const char* kUsage = "usage: rocking batch MANIFEST [--jobs N] [--output FILE] [--resume] [--quiet]";

// The exit status of a batch that ran to its end with failed jobs.
constexpr int kSomeJobsFailed = 3;

// Under mpirun, before MPI is started: the rank from the launcher's variables.
bool first_rank() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
        if (const char* v = std::getenv(name)) return std::string(v) == "0";
    return true;
}

struct Options {
    std::string manifest;
    batch::EngineOptions engine;
};

Options options_from(int argc, char** argv, bool mpi) {
    std::vector<char*> args(argv, argv + argc);
    Options o;
    // The flags without a value, before the generic parser.
    for (auto it = args.begin() + (argc > 2 ? 2 : argc); it != args.end();) {
        const std::string flag = *it;
        if (flag == "--resume") o.engine.resume = true, it = args.erase(it);
        else if (flag == "--quiet") o.engine.quiet = true, it = args.erase(it);
        else ++it;
    }
    const int count = static_cast<int>(args.size());
    o.manifest = file_argument(count, args.data(), 2, kUsage);
    const Args a = parse(count, args.data(), 3, {"--jobs", "--output"});
    if (a.json) throw UsageError("--json: the results of a batch are CSV (docs/batch.md)");
    if (a.values.count("--output")) {
        o.engine.output = a.values.at("--output");
        if (o.engine.output.empty()) throw UsageError("--output: an empty file name");
    }
    if (o.engine.resume && o.engine.output.empty())
        throw UsageError("--resume needs --output: rows written to standard output cannot be resumed");
    // How often the rows reach the disk (results_file.hpp): every second,
    // or as the tests ask, to be killed between many flushes.
    if (const char* every = std::getenv("ROCKING_BATCH_FLUSH_SECONDS")) o.engine.flush_seconds = std::atof(every);
    // Under mpirun each rank is one process on one core, as MPI runs are laid out.
    o.engine.threads = a.values.count("--jobs") || !mpi ? jobs_option(a) : 1;
    return o;
}

}  // namespace

int cmd_batch(int argc, char** argv) {
    const bool mpi = batch::launched_by_mpirun();
    if (mpi && !batch::built_with_mpi()) {
        if (!first_rank()) return 2;
        throw UsageError("started by mpirun, but this rocking was built without MPI, and each copy would run the whole "
                         "batch: install libopenmpi-dev and openmpi-bin (make deps) and rebuild, or run it without "
                         "mpirun (--jobs N threads)");
    }
    Options o;
    try {
        o = options_from(argc, argv, mpi);
    } catch (const UsageError&) {
        if (mpi && !first_rank()) return 2;  // every rank has the same error: rank 0 says it
        throw;
    }
    std::unique_ptr<batch::Ranks> ranks = mpi ? batch::join_cluster() : nullptr;

    // Every rank reads the manifest; a failure is held until all have said how they fared.
    std::optional<batch::Manifest> manifest;
    jobs::RecordStore records;
    batch::BatchPlan plan;
    std::exception_ptr failure;
    try {
        manifest.emplace(batch::Manifest::read(o.manifest));
        plan = jobs::make_plan(*manifest, records);
    } catch (const std::exception&) {
        failure = std::current_exception();
    }
    if (ranks) {
        const int status = failure ? 1 : 0;
        const bool first_failed = ranks->broadcast(std::to_string(status)) != "0";
        const int all = ranks->agree(status);
        if (all != 0) {
            // One says why (rank 0, or a rank that failed where rank 0 did not), before any rank
            // ends: mpirun stops the job at the first non-zero exit, and the message with it.
            if (failure && (ranks->rank() == 0 || !first_failed)) {
                try {
                    std::rethrow_exception(failure);
                } catch (const std::exception& e) {
                    std::fprintf(stderr, "rocking batch: %s%s\n",
                                 ranks->rank() == 0 ? "" : ("rank " + std::to_string(ranks->rank()) + ": ").c_str(), e.what());
                }
            }
            ranks->agree(0);
            return all;
        }
    } else if (failure)
        std::rethrow_exception(failure);

    batch::BatchOutcome outcome;
    try {
        outcome = batch::run_batch(plan, o.engine, ranks.get());
    } catch (const batch::OtherRankFailed& e) {
        return e.status;
    }
    if (ranks && ranks->rank() != 0) return 0;
    if (!o.engine.quiet)
        std::fprintf(stderr, "rocking batch: %s%zu jobs, %zu failed%s%s\n",
                     outcome.already_complete ? "already complete: " : "", outcome.jobs, outcome.failed,
                     o.engine.output.empty() ? "" : "; results in ", o.engine.output.c_str());
    return outcome.failed > 0 ? kSomeJobsFailed : 0;
}

}  // namespace rocking::cli
