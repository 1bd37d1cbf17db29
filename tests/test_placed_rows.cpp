// The results file when the ranks write their own rows (issue 42): the
// checksum that sums one term a row (row_digest.hpp), chunks placed by rank 0
// and written and synced by others in any order, the state counting only the
// chunks synced in order, a resume of what a kill left, and a state written
// by a rocking before the sum (SHA-256 of the bytes) still resumed.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "batch/job_row.hpp"
#include "batch/results_file.hpp"
#include "batch/row_digest.hpp"
#include "batch/sha256.hpp"
#include "test_util.hpp"

using namespace rocking::batch;

namespace {

const std::string kDigest(64, 'a');
const std::string kHeader = "# a test\ni,value\n";
const std::string kPreamble = "# manifest sha256: " + kDigest + "\n" + kHeader;

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Job i's row: every fourth one with a quoted line break, as a record's path may hold.
std::string row(std::size_t i) {
    return std::to_string(i) + (i % 4 == 3 ? ",\"two\nlines\"" : "," + std::to_string(i * i));
}

std::string whole_file(std::size_t n) {
    std::string text = kPreamble;
    for (std::size_t i = 0; i < n; ++i) text += row(i) + "\n";
    return text + "# end: " + std::to_string(n) + " jobs, 0 failed\n";
}

RowChunk chunk_of(std::size_t first, std::size_t count) {
    RowChunk chunk;
    chunk.first = first;
    for (std::size_t i = first; i < first + count; ++i) chunk.add(JobRow{row(i), false});
    return chunk;
}

// The jobs the state on the disk counts (its fifth word).
std::size_t state_jobs(const std::string& out) {
    std::istringstream in(slurp(out + ".partial.state"));
    std::string word;
    for (int k = 0; k < 4; ++k) in >> word;
    std::size_t jobs = 0;
    in >> jobs;
    return jobs;
}

// Another process's writes: its own descriptor on the partial file.
void write_elsewhere(const std::string& path, std::uint64_t offset, const std::string& text) {
    const int fd = ::open(path.c_str(), O_WRONLY);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::pwrite(fd, text.data(), text.size(), static_cast<off_t>(offset)), static_cast<ssize_t>(text.size()));
    ASSERT_EQ(::fdatasync(fd), 0);
    ::close(fd);
}

}  // namespace

TEST(PlacedRows, TheChecksumIsXxh3AndSumsTheSameWhateverTheChunks) {
    // xxHash's own vector: XXH3_64 of no bytes, seed 0.
    EXPECT_EQ(header_digest(""), 0x2D06800538D394C2ull);
    EXPECT_EQ(digest_hex(0x2D06800538D394C2ull), "2d06800538d394c2");
    std::uint64_t one_by_one = 0;
    for (std::size_t i = 0; i < 40; ++i) one_by_one += row_digest(row(i) + "\n", i);
    for (std::size_t size : {1, 3, 7, 40}) {
        std::uint64_t sum = 0;
        for (std::size_t at = 0; at < 40; at += size) sum += chunk_of(at, std::min<std::size_t>(size, 40 - at)).digest;
        EXPECT_EQ(sum, one_by_one) << "chunks of " << size;
    }
    // The seed puts a row at its place: two rows swapped change the sum.
    EXPECT_NE(row_digest(row(1) + "\n", 0) + row_digest(row(0) + "\n", 1),
              row_digest(row(0) + "\n", 0) + row_digest(row(1) + "\n", 1));
    // Read back in pieces of every size, quoted line breaks inside rows: the same sum.
    const std::string text = chunk_of(0, 40).text;
    for (std::size_t piece = 1; piece <= text.size(); piece += piece < 16 ? 1 : 37) {
        RowsDigest read;
        for (std::size_t at = 0; at < text.size(); at += piece) read.feed(text.data() + at, std::min(piece, text.size() - at));
        EXPECT_EQ(read.sum(), one_by_one) << "pieces of " << piece;
        EXPECT_EQ(read.rows(), 40u);
        EXPECT_FALSE(read.row_open());
    }
}

TEST(PlacedRows, TheStateCountsTheChunksSyncedInOrderAndAResumeEndsWithTheSameBytes) {
    const std::string dir = rocking::testing::temp_folder("rocking-placed-test"), out = dir + "/r.csv";
    {
        // flush_seconds 1e9: the state moves only when flushed by hand, as rank 0's rounds do.
        ResultsFile f({out, false, 1e9}, kHeader, kDigest, 20);
        // Chunks of rank 1 (0-4, 9-13), of rank 0 itself (5-8), of rank 2 (14-19).
        const RowChunk a = chunk_of(0, 5), own = chunk_of(5, 4), b = chunk_of(9, 5), c = chunk_of(14, 6);
        const std::uint64_t at_a = f.place(a.summary()).offset;
        f.place_own(own);
        const std::uint64_t at_b = f.place(b.summary()).offset, at_c = f.place(c.summary()).offset;
        EXPECT_EQ(at_a, kPreamble.size());
        EXPECT_EQ(at_b, at_a + a.text.size() + own.text.size());
        EXPECT_EQ(at_c, at_b + b.text.size());
        EXPECT_EQ(f.done(), 20u);
        // Written out of order; the last chunk synced first: nothing counts before chunk 0 is synced.
        write_elsewhere(f.partial_path(), at_c, c.text);
        f.synced(3);
        write_elsewhere(f.partial_path(), at_b, b.text);
        f.flush();
        EXPECT_EQ(f.kept(), 0u);
        EXPECT_EQ(state_jobs(out), 0u);
        write_elsewhere(f.partial_path(), at_a, a.text);
        f.synced(0);
        f.flush();  // chunk 0, its own chunk 1; chunk 2 written but not synced: not counted
        EXPECT_EQ(f.kept(), 9u);
        EXPECT_EQ(state_jobs(out), 9u);
    }  // killed: chunks 2 and 3 are on the disk, but the state does not count them
    ResultsFile f({out, true, 0.0}, kHeader, kDigest, 20);
    ASSERT_EQ(f.done(), 9u);
    for (std::size_t i = 9; i < 20; ++i) f.append(row(i), false);
    f.finish();
    EXPECT_EQ(slurp(out), whole_file(20));
}

TEST(PlacedRows, ARunEndsOnlyWhenEveryChunkPlacedIsSynced) {
    const std::string dir = rocking::testing::temp_folder("rocking-placed-test"), out = dir + "/r.csv";
    ResultsFile f({out, false, 1e9}, kHeader, kDigest, 6);
    const RowChunk a = chunk_of(0, 3), b = chunk_of(3, 3);
    f.place_own(a);
    write_elsewhere(f.partial_path(), f.place(b.summary()).offset, b.text);
    EXPECT_THROW(f.finish(), ResultsError);  // chunk 1 was never said synced
    f.synced(1);
    f.finish();
    EXPECT_EQ(slurp(out), whole_file(6));
}

TEST(PlacedRows, ARowMovedOrChangedIsRefusedAndAnOldStateStillResumes) {
    const std::string dir = rocking::testing::temp_folder("rocking-placed-test"), out = dir + "/r.csv";
    {
        ResultsFile f({out, false, 1e9}, kHeader, kDigest, 12);
        for (std::size_t i = 0; i < 8; ++i) f.append(row(i), false);
        f.flush();
    }
    const std::string kept = slurp(out + ".partial"), state = slurp(out + ".partial.state");
    EXPECT_EQ(state, "rocking batch state: jobs 8 failed 0 bytes " + std::to_string(kept.size()) + " header " +
                         std::to_string(kPreamble.size()) + " xxh3 " +
                         digest_hex(header_digest(kPreamble) + chunk_of(0, 8).digest) + "\n");
    // Rows 0 and 1 swapped, bytes and lengths the same ("0,0\n1,1\n"): the seeds tell.
    std::string swapped = kept;
    swapped.replace(kPreamble.size(), 8, "1,1\n0,0\n");
    std::ofstream(out + ".partial", std::ios::binary | std::ios::trunc) << swapped;
    EXPECT_THROW(ResultsFile({out, true}, kHeader, kDigest, 12), ResultsError);
    // A state of a rocking before the sum: the SHA-256 of the bytes, no header length.
    std::ofstream(out + ".partial", std::ios::binary | std::ios::trunc) << kept;
    std::ofstream(out + ".partial.state", std::ios::trunc)
        << "rocking batch state: jobs 8 failed 0 bytes " << kept.size() << " sha256 " << sha256_hex(kept) << "\n";
    {
        ResultsFile f({out, true, 0.0}, kHeader, kDigest, 12);
        ASSERT_EQ(f.done(), 8u);
        f.append(row(8), false);
        f.flush();  // its state is now the sum's, and a resume of that goes on
    }
    ResultsFile f({out, true, 0.0}, kHeader, kDigest, 12);
    ASSERT_EQ(f.done(), 9u);
    for (std::size_t i = 9; i < 12; ++i) f.append(row(i), false);
    f.finish();
    EXPECT_EQ(slurp(out), whole_file(12));
    // And an old state whose bytes changed is refused.
    std::ofstream(out + ".x.partial", std::ios::binary) << swapped;
    std::ofstream(out + ".x.partial.state")
        << "rocking batch state: jobs 8 failed 0 bytes " << kept.size() << " sha256 " << sha256_hex(kept) << "\n";
    EXPECT_THROW(ResultsFile({out + ".x", true}, kHeader, kDigest, 12), ResultsError);
}
