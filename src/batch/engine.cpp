#include "batch/engine.hpp"

#include <signal.h>
#include <string.h>
#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <algorithm>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "batch/interrupt.hpp"
#include "batch/pool.hpp"
#include "batch/progress.hpp"
#include "batch/results_file.hpp"
#include "batch/sha256.hpp"

namespace rocking::batch {

namespace {

// What an interrupted batch leaves, and how to finish it.
void say_interrupted(const std::string& command, int sig, const ResultsFile& file, const std::string& output,
                     std::size_t jobs) {
    std::fprintf(stderr, "\n%s: interrupted by %s: the rows of %zu of %zu jobs are written%s%s%s\n", command.c_str(),
                 sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : strsignal(sig),
                 file.kept(), jobs, output.empty() ? "" : " to ", output.empty() ? "" : file.partial_path().c_str(),
                 output.empty() ? "" : "; the same command with --resume completes them");
}

// The threads take the jobs in chunks of consecutive ones, so that a job of a
// few microseconds does not cost a hand-over between threads each (with one
// job a hand-over, 2 threads ran 50000 idle jobs at half one thread's speed:
// 40000 context switches).  Guided: a share of what is left, at most
// kMaxChunk, so that the chunks shrink to single jobs at the end and no
// thread is left with a long tail.  The sizes are fixed before the run: the
// rows do not depend on them anyway.
constexpr std::size_t kMaxChunk = 32;

std::vector<std::size_t> chunk_starts(std::size_t first, std::size_t n, std::size_t threads) {
    std::vector<std::size_t> starts;
    for (std::size_t at = first; at < n;) {
        starts.push_back(at);
        at += std::min(kMaxChunk, std::max<std::size_t>(1, (n - at) / (4 * threads)));
    }
    starts.push_back(n);
    return starts;
}

// The finished file's rows to the front end that asked for them.
void collect_rows(const BatchPlan& plan, const EngineOptions& options) {
    if (!options.collect) return;
    // The inputs' digest lines, then the plan's header (results_file.hpp).
    const std::size_t header_lines =
        plan.inputs.size() + static_cast<std::size_t>(std::count(plan.header.begin(), plan.header.end(), '\n'));
    std::size_t rows = 0;
    ResultsFile::read_rows(options.output, header_lines, [&](std::size_t i, const std::string& row) {
        options.collect(i, row);
        rows = i + 1;
    });
    if (rows != plan.jobs)
        throw ResultsError(options.output + ": holds " + std::to_string(rows) + " rows for " + std::to_string(plan.jobs) +
                           " jobs");
}

// Why `count` threads cannot run at once here ("" when they can): each is
// started and held until all are, then let go.  Under mpirun every rank asks
// before the first job, so that threads refused on any rank end the run with
// one message and exit 2, its files removed, as on threads (the ranks'
// protocol, once begun, can only be ended by MPI_Abort, which left the
// results' partial file and its state asking the next run for a --resume).
std::string threads_refused(std::size_t count) {
    std::mutex mutex;
    std::condition_variable released;
    bool go = false;
    std::vector<std::thread> pool;
    std::string why;
    try {
        start_threads(pool, count, [&] {
            std::unique_lock<std::mutex> lock(mutex);
            released.wait(lock, [&] { return go; });
        });
    } catch (const ThreadsUnavailable& e) {
        why = e.what();
    }
    {
        std::lock_guard<std::mutex> lock(mutex);
        go = true;
    }
    released.notify_all();
    for (std::thread& t : pool) t.join();
    return why;
}

// Under mpirun, before the first job: every rank's threads can start, or
// each rank ends with status 2 (OtherRankFailed), the refusal said once (by
// rank 0, or by each other rank refused when rank 0 was not) and rank 0's
// results file removed if it keeps no row.
void agree_threads_start(Ranks& ranks, std::size_t threads, ResultsFile* file, const std::string& command) {
    const std::string why = threads_refused(threads);
    const bool lead_refused = !ranks.broadcast(why).empty();
    if (ranks.agree(why.empty() ? 0 : 2) == 0) return;
    if (!why.empty() && (ranks.rank() == 0 || !lead_refused))
        std::fprintf(stderr, "%s: %s%s\n", command.c_str(),
                     ranks.rank() == 0 ? "" : ("rank " + std::to_string(ranks.rank()) + ": ").c_str(), why.c_str());
    if (file) file->discard_unless_rows_kept();
    ranks.agree(0);  // said and removed before any rank ends: mpirun stops the others at the first exit
    throw OtherRankFailed(2);
}

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

}  // namespace

BatchOutcome run_batch(const BatchPlan& plan, const EngineOptions& options, Ranks* ranks) {
    const bool lead = !ranks || ranks->rank() == 0;
    // Rows for the front end alone: no file, nothing to resume.
    const bool in_memory = options.collect && options.output.empty();
    std::unique_ptr<ResultsFile> file;
    std::exception_ptr failure;
    if (lead && !in_memory) {
        try {
            file = std::make_unique<ResultsFile>(ResultsOptions{options.output, options.resume, options.flush_seconds,
                                                                 ResultsOptions{}.flush_bytes, options.jobs_from},
                                                 plan.header, plan.digest, plan.jobs, plan.inputs);
        } catch (...) {
            failure = std::current_exception();
        }
    }
    if (ranks) {
        // Every rank must run the same jobs: the manifest and records each read are rank 0's.
        Sha256 identity;
        identity.update(plan.digest);
        for (const InputDigest& input : plan.inputs) identity.update("\n" + input.name + " " + input.digest);
        const bool same = ranks->broadcast(identity.hex()) == identity.hex();
        const int status = ranks->agree(failure || !same ? 1 : 0);
        if (status != 0) {
            std::string message;
            if (failure) {
                try {
                    std::rethrow_exception(failure);
                } catch (const std::exception& e) {
                    message = e.what();
                }
            } else if (!same)
                message = "rank " + std::to_string(ranks->rank()) + " read a manifest or records other than rank 0's (the "
                          "manifest's sha256 is " + plan.digest + "): every rank must read the same files";
            if (!message.empty()) std::fprintf(stderr, "%s: %s\n", options.command.c_str(), message.c_str());
            // Said before any rank ends: mpirun stops the job at the first rank that ends with a
            // non-zero status, and a message not yet written would go with it.
            ranks->agree(0);
            throw OtherRankFailed(status);
        }
    } else if (failure)
        std::rethrow_exception(failure);

    const std::size_t first = file ? file->done() : 0;
    // A thread without a job would only take its stack (--jobs 1500 for 5 jobs).
    const std::size_t threads =
        std::min(options.threads < 1 ? std::size_t{1} : static_cast<std::size_t>(options.threads),
                 std::max<std::size_t>(1, plan.jobs - std::min(first, plan.jobs)));
    if (ranks) agree_threads_start(*ranks, threads, file.get(), options.command);
    Progress progress(plan.jobs, first, lead && !options.quiet && stderr_is_terminal());
    // On every rank: the others end by the signal too (on_signal does nothing there).
    const InterruptWatch watch([&](int sig) {
        if (!file) return;
        file->flush();
        if (progress.enabled()) progress.finish(file->kept(), file->failed());
        say_interrupted(options.command, sig, *file, options.output, plan.jobs);
    });
    if (!lead) {
        ranks->run(0, plan.jobs, static_cast<int>(threads), options.window, plan.run, Delivery{}, options.command);
        return {};
    }
    if (file && (file->complete() || first == plan.jobs)) {
        // Nothing to run: a finished file found by --resume, or a partial one
        // whose rows are all there (killed before its end line).
        if (ranks) ranks->run(first, plan.jobs, static_cast<int>(threads), options.window, plan.run, Delivery{}, options.command);
        file->finish();
        collect_rows(plan, options);
        return {file->done(), file->failed(), 0, file->complete()};
    }
    // ROCKING_BATCH_STATS: the writing thread's CPU a row (bench/batch.sh): with
    // the jobs on other threads or ranks, what one row costs the one thread
    // every row passes through, the bound on how many rows a second a batch takes.
    const double cpu_before = thread_cpu_seconds();
    std::size_t done = 0, failed = 0, chunks = 0, placed = 0;  // chunks through this thread, and placed for their ranks
    double busy_cpu = -1;  // measured by the ranks' rank 0 alone
    const DeliverChunk deliver = [&](RowChunk& chunk) {
        done += chunk.count(), failed += chunk.failed, ++chunks;
        if (file) file->append(chunk);
        else chunk.each([&](std::size_t i, std::string_view row) { options.collect(i, std::string(row)); });
        progress.update(first + done, file ? file->failed() : failed);
    };
    if (ranks) {
        // Room for about four of the largest chunks (cluster_mpi.cpp: 4096 cheap jobs) a rank and
        // thread, at most 2^20 rows out of order (about 200 MB of rows of 200 bytes).
        const std::size_t takers = threads + static_cast<std::size_t>(ranks->size());
        const std::size_t window =
            options.window ? options.window : std::max<std::size_t>(64 * takers, std::min<std::size_t>(16384 * takers, 1 << 20));
        // The ranks write their own rows when they can open the file; rank 0 sees each chunk's summary.
        busy_cpu = 0;
        Delivery delivery{deliver, file.get(), [&](const ChunkSummary& chunk) {
                              done += chunk.count, failed += chunk.failed, ++placed;
                              progress.update(first + done, file->failed());
                          },
                          options.flush_seconds, std::getenv("ROCKING_BATCH_STATS") ? &busy_cpu : nullptr};
        ranks->run(first, plan.jobs, static_cast<int>(threads), window, plan.run, delivery, options.command);
    } else {
        const std::vector<std::size_t> starts = chunk_starts(first, plan.jobs, threads);
        // The window in chunks: at most `window` rows held, or the pool's 64 chunks a thread.
        const std::size_t window = options.window ? std::max<std::size_t>(1, options.window / kMaxChunk) : 0;
        try {
            run_ordered<RowChunk>(
                starts.size() - 1, PoolOptions{static_cast<int>(threads), window},
                [&](std::size_t c) {
                    RowChunk chunk;
                    chunk.first = starts[c];
                    chunk.lengths.reserve(starts[c + 1] - starts[c]);
                    for (std::size_t i = starts[c]; i < starts[c + 1]; ++i) chunk.add(plan.run(i));
                    return chunk;
                },
                [&](std::size_t, RowChunk& chunk) { deliver(chunk); });
        } catch (...) {
            // Threads that cannot start, a row that cannot be written: no state of a run that keeps no row.
            if (file) file->discard_unless_rows_kept();
            throw;
        }
    }
    if (file) {
        try {
            file->finish();
        } catch (...) {
            file->discard_unless_rows_kept();
            throw;
        }
        failed = file->failed();
    }
    progress.finish(first + done, failed);
    if (std::getenv("ROCKING_BATCH_STATS"))
        std::fprintf(stderr,
                     "%s: the writing thread: %.6f s of CPU for %zu rows, in %zu chunks written by their ranks and %zu "
                     "through this thread%s\n",
                     options.command.c_str(), thread_cpu_seconds() - cpu_before, plan.jobs - first, placed, chunks,
                     busy_cpu < 0 ? "" : ("; busy " + std::to_string(busy_cpu) + " s").c_str());
    if (file) collect_rows(plan, options);
    return {plan.jobs, failed, plan.jobs - first, false};
}

}  // namespace rocking::batch
