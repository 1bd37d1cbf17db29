// The batch engine's pieces without physics (src/batch/): the results file
// with its resume, and the engine itself on a plan of synthetic jobs whose
// costs vary by 1000x: the same bytes on any number of threads (the inputs:
// test_batch_inputs.cpp).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "batch/cache.hpp"
#include "batch/engine.hpp"
#include "batch/manifest.hpp"
#include "batch/pool.hpp"
#include "batch/progress.hpp"
#include "batch/ranks.hpp"
#include "batch/results_file.hpp"
#include "batch/sha256.hpp"
#include "test_util.hpp"

using namespace rocking::batch;

namespace {

std::string temp_dir() { return rocking::testing::temp_folder("rocking-batch-test"); }

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

bool exists(const std::string& path) {
    struct stat s {};
    return ::stat(path.c_str(), &s) == 0;
}

const std::string kDigest(64, 'a'), kOtherDigest(64, 'b');
const std::string kHeader = "# a test\ni,value\n";

std::string row(std::size_t i) { return std::to_string(i) + "," + std::to_string(i * i); }

// The file a run of n rows never interrupted writes.
std::string whole_file(std::size_t n, std::size_t failed_every = 0) {
    std::string text = "# manifest sha256: " + kDigest + "\n" + kHeader;
    std::size_t failed = 0;
    for (std::size_t i = 0; i < n; ++i) {
        text += row(i) + "\n";
        failed += failed_every && i % failed_every == 0;
    }
    return text + "# end: " + std::to_string(n) + " jobs, " + std::to_string(failed) + " failed\n";
}

}  // namespace

TEST(BatchEngine, AFreshResultsFileAppearsWholeAtTheEnd) {
    const std::string dir = temp_dir(), out = dir + "/r.csv";
    {
        ResultsFile f({out, false, 0.0}, kHeader, kDigest, 5);
        EXPECT_EQ(f.done(), 0u);
        for (std::size_t i = 0; i < 5; ++i) {
            f.append(row(i), i % 2 == 0);
            EXPECT_FALSE(exists(out)) << "the results are at their name before they are complete";
        }
        f.finish();
        EXPECT_EQ(f.failed(), 3u);
    }
    EXPECT_EQ(slurp(out), whole_file(5, 2));
    EXPECT_FALSE(exists(out + ".partial"));
    EXPECT_FALSE(exists(out + ".partial.state"));
}

TEST(BatchEngine, AResumeCutsOffWhatTheStateDoesNotCountAndEndsWithTheSameBytes) {
    for (std::size_t flushed : {0, 1, 4, 7}) {
        const std::string dir = temp_dir(), out = dir + "/r.csv";
        {
            // flush_seconds 1e9: nothing flushed but by hand, as a kill would find it.
            ResultsFile f({out, false, 1e9}, kHeader, kDigest, 7);
            for (std::size_t i = 0; i < flushed; ++i) f.append(row(i), false);
            f.flush();
            for (std::size_t i = flushed; i < 7; ++i) f.append(row(i), false);
        }  // killed: the rows after the flush never reached the file
        // ... or reached it only in part.
        std::ofstream(out + ".partial", std::ios::app) << "9,half a ro";
        ResultsFile f({out, true, 0.0}, kHeader, kDigest, 7);
        ASSERT_EQ(f.done(), flushed);
        EXPECT_FALSE(f.complete());
        for (std::size_t i = flushed; i < 7; ++i) f.append(row(i), false);
        f.finish();
        EXPECT_EQ(slurp(out), whole_file(7)) << flushed << " rows flushed";
    }
}

namespace {
// make() throws a ResultsError whose message holds `says`.
void refused(const std::function<void()>& make, const std::string& says) {
    try {
        make();
        ADD_FAILURE() << "not refused: wanted '" << says << "'";
    } catch (const ResultsError& e) {
        EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
}
}  // namespace

TEST(BatchEngine, AResumeIsRefusedForAnotherManifestOrADamagedFile) {
    const std::string dir = temp_dir(), out = dir + "/r.csv";
    {
        ResultsFile f({out, false, 1e9}, kHeader, kDigest, 7);
        for (std::size_t i = 0; i < 3; ++i) f.append(row(i), false);
        f.flush();
    }
    refused([&] { ResultsFile({out, true}, kHeader, kOtherDigest, 7); }, "the manifest has changed since");
    refused([&] { ResultsFile({out, false}, kHeader, kDigest, 7); }, "Add --resume to complete it");
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 2); }, "more than the manifest's 2");
    refused([&] { ResultsFile({"", true}, kHeader, kDigest, 2); }, "--resume needs --output");
    {
        // Two batches on one results file: the second is refused while the first runs.
        ResultsFile first({out, true}, kHeader, kDigest, 7);
        refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7); }, "is being written by another run");
        // Without --resume too: "add --resume" would lead to the lock (issue 38), so the lock is said first.
        try {
            ResultsFile({out, false}, kHeader, kDigest, 7);
            ADD_FAILURE() << "a second run on a locked partial file";
        } catch (const ResultsError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("is being written by another run, which holds its lock: wait for that run to end"),
                      std::string::npos) << what;
            EXPECT_EQ(what.find("Add --resume"), std::string::npos) << what;
        }
    }
    // A byte of a counted row changed: its checksum no longer holds.
    std::string text = slurp(out + ".partial");
    text[text.size() - 3] ^= 1;
    std::ofstream(out + ".partial", std::ios::binary | std::ios::trunc) << text;
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7); }, "do not match the checksum");
    std::ofstream(out + ".partial.state", std::ios::trunc) << "nonsense\n";
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7); }, "not a state file of rocking batch");
}

// Issue 38, item 2: a record edited between a kill and --resume gave a file
// of rows from both versions, exit 0.  The header keeps each record's
// SHA-256; a resume, or a --resume finding the results complete, refuses
// any that differs now, naming it.
TEST(BatchEngine, AResumeIsRefusedWhenARecordTheJobsReadHasChanged) {
    const std::string a(64, '1'), b(64, '2'), c(64, '3');
    const std::vector<InputDigest> inputs = {{"r1.txt", a}, {"dir/r 2.txt", b}};
    const std::string dir = temp_dir(), out = dir + "/r.csv";
    auto begin = [&](const std::vector<InputDigest>& begun_with) {
        std::filesystem::remove(out + ".partial");
        std::filesystem::remove(out + ".partial.state");
        ResultsFile f({out, false, 1e9}, kHeader, kDigest, 7, begun_with);
        for (std::size_t i = 0; i < 3; ++i) f.append(row(i), false);
        f.flush();
    };
    begin(inputs);
    EXPECT_EQ(slurp(out + ".partial").substr(0, 200),
              ("# manifest sha256: " + kDigest + "\n# record sha256: " + a + " r1.txt\n# record sha256: " + b +
               " dir/r 2.txt\n" + kHeader + row(0) + "\n")
                  .substr(0, 200));
    EXPECT_EQ(ResultsFile({out, true}, kHeader, kDigest, 7, inputs).done(), 3u);  // the same records: resumed
    const std::string since = "dir/r 2.txt, a record the manifest names, has changed since " + out + ".partial was begun";
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7, {{"r1.txt", a}, {"dir/r 2.txt", c}}); },
            since + " (its sha256 was " + b + ", it is now " + c + "): the rows written were computed from the other file");
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7, {{"r1.txt", a}, {"dir/r 2.txt", "unreadable"}}); },
            "it is now none (the file could not be read)");
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7, {{"r1.txt", a}, {"dir/r 2.txt", ""}}); },
            "dir/r 2.txt, a record the manifest names, is not a regular file when resumed (a pipe or a device)");
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7, {{"r1.txt", a}}); },
            "more records' digests were kept when " + out + ".partial was begun than the manifest names now");
    // A record read from a pipe when the batch began cannot be proved the same.
    begin({{"/dev/stdin", ""}});
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7, {{"/dev/stdin", a}}); },
            "/dev/stdin, a record the manifest names, was not a regular file when " + out + ".partial was begun");
    // A partial file that kept no digests cannot prove its rows.
    begin({});
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7, inputs); }, "no sha256 of r1.txt was kept");
    // Complete results: --resume finds them only if their records are unchanged too.
    begin(inputs);
    {
        ResultsFile f({out, true}, kHeader, kDigest, 7, inputs);
        for (std::size_t i = 3; i < 7; ++i) f.append(row(i), false);
        f.finish();
    }
    EXPECT_TRUE(ResultsFile({out, true}, kHeader, kDigest, 7, inputs).complete());
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7, {{"r1.txt", c}, {"dir/r 2.txt", b}}); },
            "r1.txt, a record the manifest names, has changed since " + out + " was written (its sha256 was " + a);
}

TEST(BatchEngine, ARowWithAQuotedLineBreakIsReadBackWhole) {
    const std::string dir = temp_dir(), out = dir + "/r.csv";
    const std::vector<std::string> rows = {"0,plain", "1," + csv_cell("two\nlines") + ",x", "2," + csv_cell("\"\n\"")};
    {
        ResultsFile f({out, false}, kHeader, kDigest, rows.size());
        for (const std::string& r : rows) f.append(r, false);
        f.finish();
    }
    std::vector<std::string> read;
    ResultsFile::read_rows(out, 2, [&](std::size_t i, const std::string& r) {
        EXPECT_EQ(i, read.size());
        read.push_back(r);
    });
    EXPECT_EQ(read, rows);
}

TEST(BatchEngine, AResumeOfCompleteResultsRunsNothingAndAPartialWithoutStateStartsOver) {
    const std::string dir = temp_dir(), out = dir + "/r.csv";
    {
        ResultsFile f({out, false}, kHeader, kDigest, 4);
        for (std::size_t i = 0; i < 4; ++i) f.append(row(i), i == 1);
        f.finish();
    }
    {
        ResultsFile f({out, true}, kHeader, kDigest, 4);
        EXPECT_TRUE(f.complete());
        EXPECT_EQ(f.done(), 4u);
        EXPECT_EQ(f.failed(), 1u);
        f.finish();
    }
    EXPECT_EQ(slurp(out), whole_file(4, 5));  // row 0 failed there, row 1 here: one failed either way
    try {
        ResultsFile f({out, true}, kHeader, kOtherDigest, 4);
        ADD_FAILURE() << "another manifest's results taken as complete";
    } catch (const ResultsError& e) {
        EXPECT_NE(std::string(e.what()).find("holds no results of this manifest"), std::string::npos) << e.what();
    }
    // Killed before the header's state was written: nothing counted, so it starts over.
    std::ofstream(out + ".partial") << "# manifest sha256: " << kDigest << "\n# a te";
    ResultsFile f({out, true, 0.0}, kHeader, kDigest, 4);
    EXPECT_EQ(f.done(), 0u);
    for (std::size_t i = 0; i < 4; ++i) f.append(row(i), false);
    f.finish();
    EXPECT_EQ(slurp(out), whole_file(4));
}

namespace {

// A plan of n jobs whose costs vary by 1000x; every seventh fails.
BatchPlan synthetic_plan(std::size_t n) {
    BatchPlan plan;
    plan.jobs = n;
    plan.header = kHeader;
    plan.digest = kDigest;
    plan.run = [](std::size_t i) {
        std::uint64_t h = 1469598103934665603ull ^ i;
        const int rounds = (i % 11 == 0) ? 300000 : 300;
        for (int k = 0; k < rounds; ++k) h = (h ^ (h >> 29)) * 1099511628211ull;
        return JobRow{std::to_string(i) + "," + std::to_string(h % 1000), i % 7 == 3};
    };
    return plan;
}

}  // namespace

TEST(BatchEngine, TheResultsAreTheSameBytesOnAnyNumberOfThreads) {
    const std::string dir = temp_dir();
    const BatchPlan plan = synthetic_plan(300);
    std::string first;
    for (int threads : {1, 2, 3, 8})
        for (std::size_t window : {std::size_t{0}, std::size_t{2}}) {
            EngineOptions o;
            o.output = dir + "/r" + std::to_string(threads) + "_" + std::to_string(window) + ".csv";
            o.threads = threads;
            o.window = window;
            o.quiet = true;
            const BatchOutcome outcome = run_batch(plan, o, nullptr);
            EXPECT_EQ(outcome.jobs, 300u);
            EXPECT_EQ(outcome.failed, 43u);  // i % 7 == 3 for i < 300
            EXPECT_EQ(outcome.ran, 300u);
            const std::string text = slurp(o.output);
            if (first.empty()) first = text;
            EXPECT_EQ(text, first) << threads << " threads, window " << window;
        }
    EXPECT_NE(first.find("\n0,"), std::string::npos);
    EXPECT_NE(first.find("# end: 300 jobs, 43 failed\n"), std::string::npos);
}

TEST(BatchEngine, TheEngineResumesFromTheRowsWrittenAndGivesTheUninterruptedFile) {
    const std::string dir = temp_dir();
    const BatchPlan plan = synthetic_plan(120);
    EngineOptions o;
    o.quiet = true;
    o.threads = 2;
    o.output = dir + "/whole.csv";
    run_batch(plan, o, nullptr);
    for (std::size_t written : {0, 1, 57, 119, 120}) {
        o.output = dir + "/part" + std::to_string(written) + ".csv";
        {
            ResultsFile f({o.output, false, 1e9}, plan.header, plan.digest, plan.jobs);
            for (std::size_t i = 0; i < written; ++i) {
                JobRow r = plan.run(i);
                f.append(r.text, r.failed);
            }
            f.flush();
        }
        o.resume = true;
        const BatchOutcome outcome = run_batch(plan, o, nullptr);
        EXPECT_EQ(outcome.ran, 120 - written);
        EXPECT_EQ(outcome.jobs, 120u);
        EXPECT_EQ(slurp(o.output), slurp(dir + "/whole.csv")) << written << " rows written before";
        o.resume = false;
    }
}

// A front end that fits the rows (rocking fragility) gets each once, in order:
// in memory on any number of threads, and from the file after a resume, the
// rows written before it included, so that both give the uninterrupted rows.
TEST(BatchEngine, CollectGivesEveryRowOnceInOrderInMemoryOrAfterAResume) {
    const std::string dir = temp_dir();
    const BatchPlan plan = synthetic_plan(120);
    std::vector<std::string> expected;
    for (std::size_t i = 0; i < plan.jobs; ++i) expected.push_back(plan.run(i).text);
    for (int threads : {1, 3}) {
        EngineOptions o;
        o.quiet = true;
        o.threads = threads;
        std::vector<std::string> rows;
        o.collect = [&](std::size_t i, const std::string& row) {
            EXPECT_EQ(i, rows.size());
            rows.push_back(row);
        };
        const BatchOutcome outcome = run_batch(plan, o, nullptr);
        EXPECT_EQ(outcome.failed, 17u);  // i % 7 == 3 for i < 120
        EXPECT_EQ(rows, expected) << threads << " threads, in memory";
    }
    EngineOptions o;
    o.quiet = true;
    o.threads = 2;
    o.output = dir + "/collected.csv";
    {
        ResultsFile f({o.output, false, 1e9}, plan.header, plan.digest, plan.jobs);
        for (std::size_t i = 0; i < 57; ++i) {
            JobRow r = plan.run(i);
            f.append(r.text, r.failed);
        }
        f.flush();
    }
    o.resume = true;
    std::vector<std::string> rows;
    o.collect = [&](std::size_t i, const std::string& row) {
        EXPECT_EQ(i, rows.size());
        rows.push_back(row);
    };
    EXPECT_EQ(run_batch(plan, o, nullptr).ran, 63u);
    EXPECT_EQ(rows, expected) << "resumed after 57 rows";
    rows.clear();
    EXPECT_TRUE(run_batch(plan, o, nullptr).already_complete);
    EXPECT_EQ(rows, expected) << "a resume of the finished file";
}


// Issue 38, item 7: --jobs 1500 for 5 jobs started 1500 threads, and under a
// memory limit failed for threads it never needed.  Here, under room for
// about 25 stacks (in a child: the limit is the process's), it runs.
TEST(BatchEngine, TheEngineStartsNoMoreThreadsThanJobsLeft) {
    const std::string dir = temp_dir();
    const BatchPlan plan = synthetic_plan(5);
    const auto child = [&] {
        rocking::testing::limit_address_space();
        EngineOptions o;
        o.quiet = true;
        o.threads = 1500;
        o.output = dir + "/r.csv";
        try {
            std::_Exit(run_batch(plan, o, nullptr).ran == 5 ? 3 : 2);
        } catch (const std::exception&) {
            std::_Exit(1);
        }
    };
    EXPECT_EXIT(child(), ::testing::ExitedWithCode(3), "");
    EXPECT_NE(slurp(dir + "/r.csv").find("# end: 5 jobs, 1 failed\n"), std::string::npos);
}

// Threads the system refuses: no job runs, and a results file begun by this
// run goes, so that the next plain run is not asked for --resume; a partial
// file with rows from before stays as it was, to be resumed.
TEST(BatchEngine, ThreadsThatCannotStartLeaveNoResumeStateBehind) {
    const std::string dir = temp_dir();
    const BatchPlan plan = synthetic_plan(2000);
    {
        ResultsFile f({dir + "/resumed.csv", false, 1e9}, plan.header, plan.digest, plan.jobs);
        for (std::size_t i = 0; i < 5; ++i) f.append(plan.run(i).text, plan.run(i).failed);
        f.flush();
    }
    const std::string state_before = slurp(dir + "/resumed.csv.partial.state");
    // The child's work, out of the macro (whose arguments cannot hold commas).
    const auto child = [&] {
        rocking::testing::limit_address_space();
        EngineOptions o;
        o.quiet = true;
        o.threads = 1500;
        int code = 0;
        for (const char* name : {"/fresh.csv", "/resumed.csv"}) {
            o.output = dir + name;
            o.resume = std::string(name) == "/resumed.csv";
            try {
                run_batch(plan, o, nullptr);
                std::_Exit(1);
            } catch (const ThreadsUnavailable& e) {
                code += std::string(e.what()).find("--jobs: 1500 threads were needed") == std::string::npos;
            }
        }
        std::_Exit(code == 0 ? 3 : 2);
    };
    EXPECT_EXIT(child(), ::testing::ExitedWithCode(3), "");
    EXPECT_FALSE(exists(dir + "/fresh.csv.partial"));
    EXPECT_FALSE(exists(dir + "/fresh.csv.partial.state"));
    EXPECT_FALSE(exists(dir + "/fresh.csv"));
    EXPECT_EQ(slurp(dir + "/resumed.csv.partial.state"), state_before);
}

TEST(BatchEngine, TheProgressLineSaysDoneFailedRateAndTimeLeft) {
    EXPECT_EQ(Progress::line(120, 3, 1000, 20, 2.0), "batch: 120/1000 jobs, 3 failed, 50 jobs/s, 18 s left");
    EXPECT_EQ(Progress::line(0, 0, 10, 0, 0.0), "batch: 0/10 jobs, 0 failed, 0 jobs/s, ? left");
    EXPECT_EQ(Progress::line(10, 0, 100000, 0, 1.0), "batch: 10/100000 jobs, 0 failed, 10 jobs/s, 2 h 46 min left");
}

namespace {

// One rank alone, as the engine sees an MPI run of one process: what the
// engine does under mpirun (the threads tried on every rank before the
// first job, the rows placed in the file as the ranks place them, or
// delivered through rank 0 without a file) without MPI; a row that cannot
// be written removes the files that keep none, as MpiRanks does before its
// MPI_Abort.
class OneRank : public Ranks {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    int agree(int status) override { return status; }
    std::string broadcast(const std::string& text) override { return text; }
    void run(std::size_t first, std::size_t n, int, std::size_t, const JobFunction& job, const Delivery& delivery,
             const std::string&) override {
        const bool placed = delivery.file && delivery.file->on_disk();
        try {
            for (std::size_t i = first; i < n; ++i) {
                RowChunk chunk;
                chunk.first = i;
                chunk.add(job(i));
                if (!placed) {
                    delivery.rows(chunk);
                    continue;
                }
                delivery.file->place_own(chunk);
                delivery.placed(chunk.summary());
                if (delivery.flush_seconds == 0) delivery.file->flush();
            }
        } catch (...) {
            if (delivery.file) delivery.file->discard_unless_rows_kept();
            throw;
        }
    }
};

// The engine's run on `output` in a child whose files may grow to `bytes`
// at most (SIGXFSZ ignored: a write past it fails with EFBIG); the child
// exits 3 when the run failed with a ResultsError naming the file, or under
// ranks, before the first job, with OtherRankFailed once rank 0 said why
// (a row that cannot be written there is MpiRanks's to end by MPI_Abort).
void run_on_a_full_disk(const BatchPlan& plan, const std::string& output, rlim_t bytes, bool ranks) {
    const auto child = [&] {
        signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{bytes, bytes};
        setrlimit(RLIMIT_FSIZE, &limit);
        EngineOptions o;
        o.output = output;
        o.quiet = true;
        o.threads = 2;
        o.flush_seconds = 0;  // each row a flush: the disk fills between two
        OneRank one;
        try {
            run_batch(plan, o, ranks ? &one : nullptr);
        } catch (const ResultsError& e) {
            std::_Exit(std::string(e.what()).find(output) != std::string::npos ? 3 : 2);
        } catch (const OtherRankFailed& e) {
            std::_Exit(ranks && e.status == 1 ? 3 : 2);
        }
        std::_Exit(1);
    };
    // No message is matched: with no room at all, the child's stderr (a file) cannot take one.
    EXPECT_EXIT(child(), ::testing::ExitedWithCode(3), "") << bytes << " bytes, ranks " << ranks;
}

}  // namespace

// Issue 38's probe of the merged build: a full disk left an empty
// OUT.partial (or one with a state counting no row, or a stray
// OUT.partial.state.tmp), and the next plain run was asked for a --resume.
TEST(BatchEngine, AFullDiskLeavesNothingUnlessRowsAreKeptAndThoseResume) {
    const std::string dir = temp_dir();
    const BatchPlan plan = synthetic_plan(200);
    EngineOptions clean;
    clean.output = dir + "/clean.csv";
    clean.quiet = true;
    run_batch(plan, clean, nullptr);
    for (bool ranks : {false, true}) {
        const std::string out = dir + (ranks ? "/ranks.csv" : "/threads.csv");
        // No room for the header (its digest's line and kHeader, 101 bytes), then room for it
        // (and for the state, 70 bytes) but none for the first row after it (4 bytes).
        const rlim_t header = std::string("# manifest sha256: \n").size() + kDigest.size() + kHeader.size();
        for (rlim_t bytes : {rlim_t{0}, header + 2}) {
            run_on_a_full_disk(plan, out, bytes, ranks);
            for (const EngineFile& f : engine_files(out))
                EXPECT_FALSE(exists(f.path)) << f.path << " left, " << bytes << " bytes, ranks " << ranks;
        }
        // Room for some rows: they stay, counted, and a resume completes the clean bytes.
        run_on_a_full_disk(plan, out, 1000, ranks);
        EXPECT_FALSE(exists(out + ".partial.state.tmp"));
        const std::string state = slurp(out + ".partial.state");
        EXPECT_EQ(state.find("jobs 0 "), std::string::npos) << state;
        EXPECT_NE(state.find("jobs "), std::string::npos) << state;
        EngineOptions o = clean;
        o.output = out;
        o.resume = true;
        OneRank one;
        const BatchOutcome resumed = run_batch(plan, o, ranks ? &one : nullptr);
        EXPECT_GT(resumed.ran, 0u);
        EXPECT_LT(resumed.ran, 200u);
        EXPECT_EQ(slurp(out), slurp(clean.output)) << "ranks " << ranks;
    }
}

// Under mpirun threads that could not start ended the run by MPI_ABORT
// mid-protocol, leaving OUT.partial and its state ("jobs 0"), and the
// message said "rocking batch:" for every command.  Now every rank tries
// its threads first: status 2 on every rank, said once under the command's
// name, the files gone.
TEST(BatchEngine, UnderRanksThreadsThatCannotStartEndEveryRankWithStatus2AndNoFiles) {
    const std::string dir = temp_dir();
    const BatchPlan plan = synthetic_plan(2000);
    const auto child = [&] {
        rocking::testing::limit_address_space();
        EngineOptions o;
        o.quiet = true;
        o.threads = 1500;
        o.output = dir + "/ranks.csv";
        o.command = "rocking fragility";
        OneRank one;
        try {
            run_batch(plan, o, &one);
        } catch (const OtherRankFailed& e) {
            std::_Exit(e.status == 2 ? 3 : 2);
        } catch (...) {
            std::_Exit(4);
        }
        std::_Exit(1);
    };
    EXPECT_EXIT(child(), ::testing::ExitedWithCode(3), "^rocking fragility: --jobs: 1500 threads were needed");
    for (const EngineFile& f : engine_files(dir + "/ranks.csv")) EXPECT_FALSE(exists(f.path)) << f.path;
}

TEST(BatchEngine, TheEnginesFilesAreTheResultsPartialStateAndItsTemporary) {
    const std::vector<EngineFile> files = engine_files("d/r.csv");
    ASSERT_EQ(files.size(), 4u);
    EXPECT_EQ(files[0].path, "d/r.csv");
    EXPECT_EQ(files[1].path, "d/r.csv.partial");
    EXPECT_EQ(files[2].path, "d/r.csv.partial.state");
    EXPECT_EQ(files[3].path, "d/r.csv.partial.state.tmp");
}

// Lines ended by CR alone (classic Mac OS) were read as one header row:
// "the header names column 'r.AT2' twice".  Refused naming the line; a CR
// in quotes is the cell's, and CRLF still ends a row.
