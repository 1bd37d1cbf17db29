// The batch engine's pieces without physics (src/batch/): SHA-256, the
// manifest's lines and cells, the shared cache, the results file with its
// resume, and the engine itself on a plan of synthetic jobs whose costs
// vary by 1000x: the same bytes on any number of threads.
#include <gtest/gtest.h>

#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "batch/cache.hpp"
#include "batch/engine.hpp"
#include "batch/manifest.hpp"
#include "batch/progress.hpp"
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

TEST(BatchEngine, Sha256MatchesTheStandardsVectors) {
    EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
              "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    // 10^6 'a' fed in uneven pieces: the blocks' boundaries never align with them.
    Sha256 h;
    const std::string piece(997, 'a');
    std::size_t fed = 0;
    for (; fed + piece.size() <= 1000000; fed += piece.size()) h.update(piece);
    h.update(std::string(1000000 - fed, 'a'));
    EXPECT_EQ(h.hex(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
    EXPECT_EQ(h.hex(), h.hex());  // reading the digest leaves the state as it was
}

TEST(BatchEngine, CsvCellsAreReadAsRfc4180WithSpacesAroundDropped) {
    using V = std::vector<std::string>;
    EXPECT_EQ(split_csv_line("a,b,c"), (V{"a", "b", "c"}));
    EXPECT_EQ(split_csv_line(" a , b ,c "), (V{"a", "b", "c"}));
    EXPECT_EQ(split_csv_line("a,,c,"), (V{"a", "", "c", ""}));
    EXPECT_EQ(split_csv_line("\"x, y\",\"say \"\"hi\"\"\" ,z"), (V{"x, y", "say \"hi\"", "z"}));
    EXPECT_EQ(split_csv_line(""), (V{""}));
    EXPECT_THROW(split_csv_line("a,\"b"), std::invalid_argument);
    EXPECT_THROW(split_csv_line("\"b\"c,d"), std::invalid_argument);
    for (const std::string cell : {"plain", "with, comma", "with \"quote\"", " lead", "", "q=2"})
        EXPECT_EQ(split_csv_line(csv_cell(cell) + ",x"), (V{cell, "x"})) << cell;
}

TEST(BatchEngine, TheManifestsJobsAreItsDataLinesWithTheirNumbers) {
    const Manifest m = Manifest::parse("# a comment\n\nkind, record ,alpha\r\nsimulate,a.txt,0.1\n  \n# x\nida,b.txt,0.2",
                                       "dir/sub/m.csv");
    EXPECT_EQ(m.header(), (std::vector<std::string>{"kind", "record", "alpha"}));
    ASSERT_EQ(m.size(), 2u);
    EXPECT_EQ(m.line(0), 4);
    EXPECT_EQ(m.text(0), "simulate,a.txt,0.1");
    EXPECT_EQ(m.line(1), 7);
    EXPECT_EQ(m.text(1), "ida,b.txt,0.2");
    EXPECT_EQ(m.folder(), "dir/sub");
    EXPECT_EQ(Manifest::parse("a\n", "m.csv").folder(), ".");
    EXPECT_EQ(m.digest(), sha256_hex("# a comment\n\nkind, record ,alpha\r\nsimulate,a.txt,0.1\n  \n# x\nida,b.txt,0.2"));
    EXPECT_EQ(Manifest::parse("a,b\n", "m.csv").size(), 0u);
    auto refused = [](const std::string& text, const std::string& says) {
        try {
            Manifest::parse(text, "m.csv");
            ADD_FAILURE() << "accepted: " << text;
        } catch (const ManifestError& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
        }
    };
    refused("", "no header row");
    refused("# only\n\n", "no header row");
    refused("a,b,a\n", "names column 'a' twice");
    refused("a,,b\n", "column 2 has no name");
    refused("a,\"b\n", "m.csv:1: the header row has an unterminated quote");
    EXPECT_THROW(Manifest::read("/no/such/manifest.csv"), ManifestError);
}

TEST(BatchEngine, TheCacheLoadsEachKeyOnceAndSharesItsFailures) {
    SharedCache<std::string> cache(1 << 20, [](const std::string& s) { return s.size(); });
    std::atomic<int> calls{0};
    std::vector<std::thread> threads;
    std::atomic<int> wrong{0}, errors{0};
    for (int t = 0; t < 8; ++t)
        threads.emplace_back([&, t] {
            for (int k = 0; k < 200; ++k) {
                const std::string key = "key" + std::to_string((k + t) % 5);
                try {
                    auto v = cache.get(key, [&] {
                        ++calls;
                        std::this_thread::sleep_for(std::chrono::milliseconds(5));  // others ask meanwhile
                        if (key == "key3") throw std::runtime_error("cannot read " + key);
                        return "value of " + key;
                    });
                    wrong += *v != "value of " + key;
                } catch (const std::runtime_error& e) {
                    wrong += key != "key3" || std::string(e.what()) != "cannot read key3";
                    ++errors;
                }
            }
        });
    for (auto& t : threads) t.join();
    EXPECT_EQ(calls.load(), 5);
    EXPECT_EQ(cache.loads(), 5u);
    EXPECT_EQ(wrong.load(), 0);
    EXPECT_EQ(errors.load(), 8 * 40);
}

TEST(BatchEngine, TheCacheStaysWithinItsBudgetAndReloadsTheSameValue) {
    // Values of 100 bytes, a budget of 350: at most 3 held besides their keys.
    SharedCache<std::string> cache(350, [](const std::string& s) { return s.size(); });
    int calls = 0;
    auto load = [&](int k) {
        return cache.get("k" + std::to_string(k), [&] {
            ++calls;
            return std::string(100, static_cast<char>('a' + k));
        });
    };
    auto held = load(0);  // a job holding a value keeps it alive after it is dropped
    for (int round = 0; round < 3; ++round)
        for (int k = 0; k < 6; ++k) {
            EXPECT_EQ(*load(k), std::string(100, static_cast<char>('a' + k)));
            EXPECT_LE(cache.held_bytes(), 350u);
        }
    EXPECT_GT(calls, 6);  // some were dropped and read again
    EXPECT_EQ(*held, std::string(100, 'a'));
}

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

TEST(BatchEngine, AResumeIsRefusedForAnotherManifestOrADamagedFile) {
    auto refused = [](const std::function<void()>& make, const std::string& says) {
        try {
            make();
            ADD_FAILURE() << "not refused: wanted '" << says << "'";
        } catch (const ResultsError& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
        }
    };
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
        refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7); }, "another run is writing");
    }
    // A byte of a counted row changed: its checksum no longer holds.
    std::string text = slurp(out + ".partial");
    text[text.size() - 3] ^= 1;
    std::ofstream(out + ".partial", std::ios::binary | std::ios::trunc) << text;
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7); }, "do not match the checksum");
    std::ofstream(out + ".partial.state", std::ios::trunc) << "nonsense\n";
    refused([&] { ResultsFile({out, true}, kHeader, kDigest, 7); }, "not a state file of rocking batch");
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

TEST(BatchEngine, TheProgressLineSaysDoneFailedRateAndTimeLeft) {
    EXPECT_EQ(Progress::line(120, 3, 1000, 20, 2.0), "batch: 120/1000 jobs, 3 failed, 50 jobs/s, 18 s left");
    EXPECT_EQ(Progress::line(0, 0, 10, 0, 0.0), "batch: 0/10 jobs, 0 failed, 0 jobs/s, ? left");
    EXPECT_EQ(Progress::line(10, 0, 100000, 0, 1.0), "batch: 10/100000 jobs, 0 failed, 10 jobs/s, 2 h 46 min left");
}
