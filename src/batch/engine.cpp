#include "batch/engine.hpp"

#include <signal.h>
#include <string.h>

#include <cstdio>
#include <exception>
#include <memory>

#include "batch/interrupt.hpp"
#include "batch/pool.hpp"
#include "batch/progress.hpp"
#include "batch/results_file.hpp"

namespace rocking::batch {

namespace {

// What an interrupted batch leaves, and how to finish it.
void say_interrupted(int sig, const ResultsFile& file, const std::string& output, std::size_t jobs) {
    std::fprintf(stderr, "\nrocking batch: interrupted by %s: the rows of %zu of %zu jobs are written%s%s%s\n",
                 sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : strsignal(sig),
                 file.done(), jobs, output.empty() ? "" : " to ", output.empty() ? "" : file.partial_path().c_str(),
                 output.empty() ? "" : "; the same command with --resume completes them");
}

}  // namespace

BatchOutcome run_batch(const BatchPlan& plan, const EngineOptions& options, Ranks* ranks) {
    const bool lead = !ranks || ranks->rank() == 0;
    std::unique_ptr<ResultsFile> file;
    std::exception_ptr failure;
    if (lead) {
        try {
            file = std::make_unique<ResultsFile>(ResultsOptions{options.output, options.resume, options.flush_seconds},
                                                 plan.header, plan.digest, plan.jobs);
        } catch (...) {
            failure = std::current_exception();
        }
    }
    if (ranks) {
        // Every rank must run the same jobs: the manifest each read is rank 0's.
        const bool same = ranks->broadcast(plan.digest) == plan.digest;
        const int status = ranks->agree(failure || !same ? 1 : 0);
        if (!same)
            throw ResultsError("rank " + std::to_string(ranks->rank()) + " read a manifest other than rank 0's (sha256 " +
                               plan.digest + "): every rank must read the same file");
        if (failure) std::rethrow_exception(failure);
        if (status != 0) throw OtherRankFailed(status);
    } else if (failure)
        std::rethrow_exception(failure);

    const std::size_t threads = options.threads < 1 ? 1 : static_cast<std::size_t>(options.threads);
    const std::size_t first = lead ? file->done() : 0;
    Progress progress(plan.jobs, first, lead && !options.quiet && stderr_is_terminal());
    // On every rank: a rank that kept the signals blocked without watching
    // them would outlive mpirun's SIGTERM.
    const InterruptWatch watch([&](int sig) {
        if (!file) return;
        file->flush();
        if (progress.enabled()) progress.finish(file->done(), file->failed());
        say_interrupted(sig, *file, options.output, plan.jobs);
    });
    if (!lead) {
        ranks->run(0, plan.jobs, static_cast<int>(threads), options.window, plan.run, nullptr);
        return {};
    }
    if (file->complete() || first == plan.jobs) {
        // Nothing to run: a finished file found by --resume, or a partial one
        // whose rows are all there (killed before its end line).
        if (ranks) ranks->run(first, plan.jobs, static_cast<int>(threads), options.window, plan.run, nullptr);
        file->finish();
        return {file->done(), file->failed(), 0, file->complete()};
    }
    const DeliverRow deliver = [&](std::size_t, JobRow& row) {
        file->append(row.text, row.failed);
        progress.update(file->done(), file->failed());
    };
    if (ranks) {
        const std::size_t window =
            options.window ? options.window : 64 * (threads + static_cast<std::size_t>(ranks->size()));
        ranks->run(first, plan.jobs, static_cast<int>(threads), window, plan.run, deliver);
    } else {
        run_ordered<JobRow>(
            plan.jobs - first, PoolOptions{static_cast<int>(threads), options.window},
            [&](std::size_t i) { return plan.run(first + i); }, [&](std::size_t i, JobRow& row) { deliver(first + i, row); });
    }
    file->finish();
    progress.finish(file->done(), file->failed());
    return {file->done(), file->failed(), plan.jobs - first, false};
}

}  // namespace rocking::batch
