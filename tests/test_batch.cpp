// The batch engine's thread pool (src/batch/pool.hpp): results in the jobs'
// order whatever the scheduling, jobs handed out on demand, at most `window`
// results held, and a failing job reported as a loop in one thread would.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "batch/pool.hpp"

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
    for (const char* bad : {"", "0", "-2", "2.5", "two", "4097", "99999999999999999999", "3 "})
        EXPECT_THROW(parse_threads(bad), std::invalid_argument) << "'" << bad << "'";
    EXPECT_GE(default_threads(), 1);
    EXPECT_LE(default_threads(), static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
}
