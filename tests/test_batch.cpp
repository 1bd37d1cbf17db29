// The batch engine's thread pool (src/batch/pool.hpp): results in the jobs'
// order whatever the scheduling, jobs handed out on demand, at most `window`
// results held, a failing job reported as a loop in one thread would, no
// more threads than jobs, and threads the system refuses said before any job.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "batch/pool.hpp"
#include "test_util.hpp"

using namespace rocking::batch;

namespace {

// A cost that varies by 1000x between jobs, as a study's do.
std::uint64_t busy(std::size_t i) {
    std::uint64_t h = 1469598103934665603ull ^ i;
    const int rounds = (i % 13 == 0) ? 200000 : 200;
    for (int k = 0; k < rounds; ++k) h = (h ^ (h >> 29)) * 1099511628211ull;
    return h;
}

}  // namespace

// Issue 38: --jobs 1500 for 5 jobs started 1500 threads, each with its
// stack; under a memory limit the batch failed for threads it never needed.
// Under room for about 25 stacks, 1500 threads asked for 1, 3 and 5 jobs run
// them all (run in a child: the limit is the process's).
TEST(Batch, NoMoreThreadsStartThanJobs) {
    const auto child = [&] {
        rocking::testing::limit_address_space();
        for (std::size_t n : {1, 3, 5}) {
            std::vector<std::size_t> delivered;
            try {
                run_ordered<std::size_t>(
                    n, PoolOptions{1500}, [](std::size_t i) { return i * i; },
                    [&](std::size_t i, std::size_t& r) { delivered.push_back(r == i * i ? i : n + 1); });
            } catch (const std::exception&) {
                std::_Exit(1);
            }
            if (delivered.size() != n || (n > 0 && delivered.back() != n - 1)) std::_Exit(2);
        }
        std::_Exit(3);
    };
    EXPECT_EXIT(child(), ::testing::ExitedWithCode(3), "");
}

// Threads the system refuses: ThreadsUnavailable naming --jobs, and no job
// run, so that nothing is half done (run in a child: the limit is the process's).
TEST(Batch, ThreadsThatCannotStartAreSaidBeforeAnyJobRuns) {
    // The child's work, out of the macro (whose arguments cannot hold commas).
    const auto child = [&] {
        rocking::testing::limit_address_space();
        std::atomic<int> ran{0};
        try {
            run_ordered<int>(
                2000, PoolOptions{1500}, [&](std::size_t) { return ++ran; }, [](std::size_t, int&) {});
            std::_Exit(1);
        } catch (const ThreadsUnavailable& e) {
            const std::string what = e.what();
            const bool named = what.find("--jobs: 1500 threads were needed") != std::string::npos &&
                               what.find("no job was run") != std::string::npos;
            std::_Exit(!named ? 2 : ran.load() != 0 ? 4 : 3);
        }
    };
    EXPECT_EXIT(child(), ::testing::ExitedWithCode(3), "");
}

TEST(Batch, ResultsComeInTheJobsOrderAndEqualOneThreads) {
    const std::size_t n = 500;
    std::vector<std::uint64_t> serial;
    run_ordered<std::uint64_t>(n, PoolOptions{1}, busy, [&](std::size_t i, std::uint64_t& r) {
        ASSERT_EQ(i, serial.size());
        serial.push_back(r);
    });
    ASSERT_EQ(serial.size(), n);
    for (int threads : {2, 3, 8})
        for (std::size_t window : {std::size_t{0}, std::size_t{1}, std::size_t{5}}) {
            std::vector<std::uint64_t> got;
            run_ordered<std::uint64_t>(n, PoolOptions{threads, window}, busy, [&](std::size_t i, std::uint64_t& r) {
                ASSERT_EQ(i, got.size()) << threads << " threads, window " << window;
                got.push_back(r);
            });
            EXPECT_EQ(got, serial) << threads << " threads, window " << window;
        }
}

TEST(Batch, JobsAreHandedOutOnDemand) {
    // Job 0 waits until every other job has started: a fixed split (half the
    // jobs to each thread) would never let the other thread reach them all,
    // and the wait would time out.
    const std::size_t n = 40;
    std::atomic<std::size_t> started{0};
    bool waited_out = false;
    run_ordered<int>(
        n, PoolOptions{2, n},
        [&](std::size_t i) {
            ++started;
            if (i == 0) {
                const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
                while (started.load() < n && std::chrono::steady_clock::now() < until)
                    std::this_thread::sleep_for(std::chrono::milliseconds(1));
                waited_out = started.load() < n;
            }
            return static_cast<int>(i);
        },
        [](std::size_t, int&) {});
    EXPECT_FALSE(waited_out) << "job 0 waited 20 s for the others to start";
}

TEST(Batch, AtMostWindowResultsAreHeld) {
    // Job 0 is slow; the others may run ahead only until `window` results
    // (job 0's slot included) are waiting for their turn.
    const std::size_t n = 200, window = 7;
    std::atomic<std::size_t> highest{0};
    std::atomic<bool> first_done{false};
    std::size_t highest_while_first_ran = 0;
    run_ordered<int>(
        n, PoolOptions{3, window},
        [&](std::size_t i) {
            std::size_t h = highest.load();
            while (i > h && !highest.compare_exchange_weak(h, i)) {}
            if (i == 0) {
                // Until the others have filled the window (20 s at most on a
                // loaded machine), then a while longer to see them stop there.
                const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
                while (highest.load() < window - 1 && std::chrono::steady_clock::now() < until)
                    std::this_thread::sleep_for(std::chrono::milliseconds(1));
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
                highest_while_first_ran = highest.load();
                first_done = true;
            }
            return 0;
        },
        [](std::size_t, int&) {});
    EXPECT_TRUE(first_done);
    EXPECT_EQ(highest_while_first_ran, window - 1);  // jobs 1..6 ran, job 7 waited for job 0's delivery
}

TEST(Batch, AFailingJobStopsTheBatchAsALoopWould) {
    for (int threads : {1, 2, 4}) {
        std::vector<std::size_t> delivered;
        try {
            run_ordered<int>(
                100, PoolOptions{threads, 4},
                [](std::size_t i) {
                    if (i == 37 || i == 61) throw std::runtime_error("job " + std::to_string(i) + " failed");
                    busy(i);
                    return static_cast<int>(i);
                },
                [&](std::size_t i, int& r) {
                    EXPECT_EQ(static_cast<std::size_t>(r), i);
                    delivered.push_back(i);
                });
            ADD_FAILURE() << "no exception with " << threads << " threads";
        } catch (const std::runtime_error& e) {
            EXPECT_STREQ(e.what(), "job 37 failed") << threads << " threads";
        }
        ASSERT_EQ(delivered.size(), 37u) << threads << " threads";
        EXPECT_EQ(delivered.back(), 36u);
    }
}

TEST(Batch, AFailingDeliveryJoinsTheThreadsAndPropagates) {
    EXPECT_THROW(run_ordered<int>(
                     1000, PoolOptions{3, 8}, [](std::size_t i) { return static_cast<int>(busy(i) & 1); },
                     [](std::size_t i, int&) {
                         if (i == 10) throw std::logic_error("the sink failed");
                     }),
                 std::logic_error);
}

TEST(Batch, JobsCountsAreCheckedAndTheDefaultIsTheUsableCores) {
    EXPECT_EQ(parse_threads("1"), 1);
    EXPECT_EQ(parse_threads("12"), 12);
    // The one whole-number rule of every option (numerics/number_text.hpp): blanks
    // at either end alike, and 1e1 or 10.0 are 10.
    for (const char* ten : {"10", " 10", "10 ", "1e1", "10.0"}) EXPECT_EQ(parse_threads(ten), 10) << "'" << ten << "'";
    for (const char* bad : {"", "0", "-2", "2.5", "two", "4097", "99999999999999999999", "3 x"})
        EXPECT_THROW(parse_threads(bad), std::invalid_argument) << "'" << bad << "'";
    EXPECT_GE(default_threads(), 1);
    EXPECT_LE(default_threads(), static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
}
