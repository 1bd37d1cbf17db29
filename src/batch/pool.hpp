// The batch engine's embedded default: jobs run on a pool of threads on one
// machine, their results handed back in the jobs' order whatever the
// scheduling.  It knows jobs and results, no physics: a study says what job
// i computes and what to do with its result.
//
// Why on demand and in order: the jobs of a study differ in cost by 1000x (a
// block that never lifts costs a scan of the record, one that rocks costs
// thousands of impacts), so a fixed split leaves threads idle; and a result
// file must not depend on which thread finished first.  Memory stays bounded:
// at most `window` results wait for their turn, so a batch of 10^6 jobs never
// holds 10^6 results.
#pragma once

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace rocking::batch {

// The threads a study uses when not told: the cores this process may run on
// (its CPU affinity, so a container's or taskset's limit counts), at least 1.
int default_threads();

// Checks a --jobs value: a whole number in [1, 4096] by numerics::whole_number's rule
// ("8", "8.0", "1e2").  Throws std::invalid_argument "--jobs: must be a whole number
// from 1 to 4096 (got TEXT)" otherwise.
int parse_threads(const std::string& text);

// The threads asked for could not all be started (a limit on processes or
// memory): what() names --jobs, how many started and why, and the remedy.
// No job has run.
struct ThreadsUnavailable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Starts `count` threads running `work` into `pool`, or throws
// ThreadsUnavailable once the system refuses one; the threads already
// started stay in `pool`, for the caller to stop and join.
void start_threads(std::vector<std::thread>& pool, std::size_t count, const std::function<void()>& work);

struct PoolOptions {
    int threads = 1;          // 1: every job in the calling thread, no thread started
    std::size_t window = 0;   // results held at most; 0: 64 per thread
};

// Calls job(i) for i = 0 .. n - 1 on options.threads threads (never more
// than n: a thread without a job would only cost its stack), each idle
// thread taking the next index, and deliver(i, result) in the calling thread
// for i = 0, 1, 2, ... in order.  A job that throws stops the handing out of
// new jobs; the results before it are delivered, the running jobs finish, and
// its exception is rethrown: the same results and the same exception as a
// loop over i in one thread.  No job starts before every thread has: when
// one cannot, ThreadsUnavailable is thrown and no job has run.
template <class Result>
void run_ordered(std::size_t n, const PoolOptions& options, const std::function<Result(std::size_t)>& job,
                 const std::function<void(std::size_t, Result&)>& deliver) {
    const std::size_t threads = std::min<std::size_t>(options.threads < 1 ? 1 : options.threads, n);
    if (threads <= 1) {
        for (std::size_t i = 0; i < n; ++i) {
            Result r = job(i);
            deliver(i, r);
        }
        return;
    }
    const std::size_t window = options.window > 0 ? options.window : 64 * static_cast<std::size_t>(threads);
    struct Slot {
        std::optional<Result> result;
        std::exception_ptr error;
        bool ready = false;
    };
    std::vector<Slot> slots(window);
    std::mutex mutex;
    std::condition_variable job_done, slot_freed;
    std::size_t next = 0, delivered = 0;
    bool stop = false, go = false;

    auto work = [&] {
        for (;;) {
            std::size_t i;
            {
                std::unique_lock<std::mutex> lock(mutex);
                slot_freed.wait(lock, [&] { return stop || (go && (next >= n || next < delivered + window)); });
                if (stop || next >= n) return;
                i = next++;
            }
            Slot done;
            try {
                done.result.emplace(job(i));
            } catch (...) {
                done.error = std::current_exception();
            }
            std::lock_guard<std::mutex> lock(mutex);
            Slot& slot = slots[i % window];
            slot.result = std::move(done.result);
            slot.error = done.error;
            slot.ready = true;
            if (slot.error) stop = true;  // no new jobs; those before it still come in
            job_done.notify_all();
            if (stop) slot_freed.notify_all();
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(threads);
    // Joins the threads however this function is left (deliver may throw too).
    struct Joiner {
        std::vector<std::thread>& pool;
        std::mutex& mutex;
        bool& stop;
        std::condition_variable& freed;
        ~Joiner() {
            {
                std::lock_guard<std::mutex> lock(mutex);
                stop = true;
            }
            freed.notify_all();
            for (std::thread& t : pool)
                if (t.joinable()) t.join();
        }
    } joiner{pool, mutex, stop, slot_freed};
    start_threads(pool, threads, work);
    {
        std::lock_guard<std::mutex> lock(mutex);
        go = true;
    }
    slot_freed.notify_all();

    for (std::size_t i = 0; i < n; ++i) {
        std::optional<Result> result;
        {
            std::unique_lock<std::mutex> lock(mutex);
            Slot& slot = slots[i % window];
            job_done.wait(lock, [&] { return slot.ready; });
            if (slot.error) std::rethrow_exception(slot.error);  // the Joiner stops and joins the rest
            result = std::move(slot.result);
            slot.result.reset();
            slot.ready = false;
            ++delivered;
        }
        slot_freed.notify_all();
        deliver(i, *result);
    }
}

}  // namespace rocking::batch
