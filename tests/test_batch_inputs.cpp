// The batch's inputs (src/batch/): SHA-256 against the standard's vectors,
// the manifest's lines and cells by RFC 4180 (libcsv), the shared records'
// cache, and the paths the ranks of an MPI run cannot share.
#include <gtest/gtest.h>

#include <fcntl.h>
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
#include "batch/manifest.hpp"
#include "batch/ranks.hpp"
#include "batch/sha256.hpp"
#include "test_util.hpp"

using namespace rocking::batch;

namespace {

std::string temp_dir() { return rocking::testing::temp_folder("rocking-batch-test"); }

// The manifest `text` is refused whole, its message holding `says`.
void refused(const std::string& text, const std::string& says) {
    try {
        Manifest::parse(text, "m.csv");
        ADD_FAILURE() << "accepted: " << text;
    } catch (const ManifestError& e) {
        EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
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

// Fed in pieces of every size about the block's 64 bytes, copied and read in
// the middle, the digest is the one Python's hashlib gives the whole (an
// independent implementation; the values computed with it on 2026-11-26).
TEST(BatchEngine, Sha256InPiecesIsTheWholesDigest) {
    std::string text;
    for (int i = 0; i < 4000; ++i) text += static_cast<char>((i * 131 + i / 7) & 0xFF);
    const std::pair<std::size_t, const char*> hashlib[] = {
        {55, "0ba6bc782735d917a64064877efe5dc6a8b0cea5905b9342711bd4698f256d71"},
        {64, "58affdb9b167c9d4a1259e484490f003a9edda5f01120f9dae26a447568d8453"},
        {129, "3799b279c98380a9c6fee5d2defbfe4672d97b8704208418b7fdb25245aef5b5"},
        {4000, "735c128c20a092530e0b8726cf8f5c077b066b91fb3e55c7f25ade56f9b242b4"}};
    for (const auto& [length, digest] : hashlib)
        for (std::size_t piece : {1, 3, 64, 100, 4000}) {
            Sha256 h;
            std::string halfway;
            for (std::size_t at = 0; at < length; at += piece) {
                h.update(text.data() + at, std::min(piece, length - at));
                if (halfway.empty() && at >= length / 2) halfway = h.hex();  // read, then go on
            }
            Sha256 copy = h, assigned;
            assigned = h;
            EXPECT_EQ(h.hex(), digest) << length << " bytes in pieces of " << piece;
            EXPECT_EQ(copy.hex(), digest);
            EXPECT_EQ(assigned.hex(), digest);
        }
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
    EXPECT_THROW(split_csv_line("a\"b,c"), std::invalid_argument);  // RFC 4180: no quote in an unquoted cell
    for (const std::string cell : {"plain", "with, comma", "with \"quote\"", " lead", "", "q=2"})
        EXPECT_EQ(split_csv_line(csv_cell(cell) + ",x"), (V{cell, "x"})) << cell;
}

// Issue 38, RFC 4180: a quoted cell's line break split its row into an error
// row and a phantom job that ran.  Now the break is the cell's, the row is
// known by the line it starts on, and a quote never closed refuses the file.
TEST(BatchEngine, AQuotedLineBreakBelongsToItsCellAndTheRowToTheLineItStartsOn) {
    using V = std::vector<std::string>;
    const Manifest m = Manifest::parse(
        "id,record\n\"two\nlines\",a.txt\nb,\"say \"\"hi\"\"\"\r\n \"x\r\ny\" ,\"c\n\n# not a comment.txt\"\r\nd,e.txt\n",
        "m.csv");
    ASSERT_EQ(m.size(), 4u);
    EXPECT_EQ(m.line(0), 2);
    EXPECT_EQ(split_csv_line(m.text(0)), (V{"two\nlines", "a.txt"}));
    EXPECT_EQ(m.line(1), 4);
    EXPECT_EQ(split_csv_line(m.text(1)), (V{"b", "say \"hi\""}));
    EXPECT_EQ(m.line(2), 5);  // a blank line and a '#' inside a quoted cell are the cell's
    EXPECT_EQ(split_csv_line(m.text(2)), (V{"x\r\ny", "c\n\n# not a comment.txt"}));
    EXPECT_EQ(m.line(3), 9);
    EXPECT_EQ(split_csv_line(m.text(3)), (V{"d", "e.txt"}));
    // Never closed: every row after it would be one cell, so none runs.
    refused("id,record\nok,r.txt\nx,\"r.txt\nnext,r.txt\n",
            "m.csv:3: the row has an unterminated quote: the quoted cell opened on line 3 is never closed");
    refused("id,record\n\"a\nb\",\"c\nd\n", "m.csv:2: the row has an unterminated quote: the quoted cell opened on line 3");
    refused("\"id\n,record\n", "m.csv:1: the header row has an unterminated quote");
    // A closing quote followed by text is the row's error, not the file's (split_csv_line says it).
    EXPECT_EQ(Manifest::parse("id,record\n\"a\"b,r.txt\nc,r.txt\n", "m.csv").size(), 2u);
    for (const std::string cell : {"two\nlines", "cr\rhere", "x\r\ny", "\n"}) {
        EXPECT_EQ(csv_cell(cell).front(), '"') << cell;
        EXPECT_EQ(split_csv_line(csv_cell(cell) + ",x"), (V{cell, "x"})) << cell;
    }
}

TEST(BatchEngine, AByteOrderMarkAtTheHeadIsSkipped) {
    const std::string text = "\xEF\xBB\xBFid,record\nx,r.txt\n";
    const Manifest m = Manifest::parse(text, "m.csv");
    EXPECT_EQ(m.header(), (std::vector<std::string>{"id", "record"}));
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m.line(0), 2);
    EXPECT_EQ(m.digest(), sha256_hex(text));  // the file's bytes, the mark included
    EXPECT_EQ(Manifest::parse("\xEF\xBB\xBF# c\n\xEF\xBB\xBFid\n", "m.csv").header(),
              (std::vector<std::string>{"\xEF\xBB\xBFid"}))
        << "only a mark at the file's head is skipped";
}

// Relative records of a manifest read from a descriptor resolve from the
// current folder (/dev holds no records), and the messages say which folder.
TEST(BatchEngine, TheFolderOfRelativeRecordsIsSaid) {
    const std::string dir = temp_dir();
    std::ofstream(dir + "/m.csv") << "record\n";
    std::filesystem::create_directory(dir + "/links");
    std::filesystem::create_symlink(dir + "/m.csv", dir + "/links/m.csv");
    EXPECT_EQ(Manifest::folder_of(dir + "/m.csv").path, dir);
    EXPECT_EQ(Manifest::folder_of(dir + "/m.csv").said, dir + ", the manifest's folder");
    EXPECT_EQ(Manifest::folder_of(dir + "/links/m.csv").path, dir + "/links");
    EXPECT_EQ(Manifest::folder_of(dir + "/links/m.csv").said,
              dir + "/links, the folder of the link " + dir + "/links/m.csv, not of the file it points to");
    const std::string here = std::filesystem::current_path().string();
    EXPECT_EQ(Manifest::folder_of("/dev/stdin").path, ".");
    EXPECT_EQ(Manifest::folder_of("/dev/stdin").said,
              here + ", the current folder, as the manifest is read from /dev/stdin, not from a file in a folder");
    EXPECT_EQ(Manifest::read(dir + "/links/m.csv").folder_said(), Manifest::folder_of(dir + "/links/m.csv").said);
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

TEST(BatchEngine, CarriageReturnsAloneAreRefusedNamingTheLine) {
    for (const auto& [text, line] : std::vector<std::pair<std::string, std::string>>{
             {"id,record,alpha\rx,r.AT2,0.15\ry,r.AT2,0.2\r", "m.csv:1:"},
             {"id,record,alpha\nx,r.AT2,0.15\ry,r.AT2,0.2\n", "m.csv:2:"},
             {"# a comment\nid,record,alpha\r\nx,r.AT2,0.15\r\n\"y\",r.AT2\r,0.2\n", "m.csv:4:"}}) {
        try {
            Manifest::parse(text, "m.csv");
            ADD_FAILURE() << "read: " << text;
        } catch (const ManifestError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(line + " a carriage return (CR) with no line feed after it", 0), 0u) << what;
        }
    }
    const Manifest m = Manifest::parse("id,record,alpha\r\n\"a\rb\",r.AT2,0.15\r\n", "m.csv");
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(split_csv_line(m.text(0))[0], "a\rb");
}

// A descriptor's path is the process's own: the ranks mpirun starts cannot
// open it, whatever is behind it (bash's <(...) gave "/dev/fd/63:0: cannot
// open the file" on the ranks).
TEST(BatchEngine, DescriptorPathsCannotBeSharedByRanks) {
    const std::string dir = temp_dir();
    const std::string file = dir + "/r.txt";
    std::ofstream(file) << "0.1\n";
    const int fd = ::open(file.c_str(), O_RDONLY);
    ASSERT_GE(fd, 0);
    const std::string n = std::to_string(fd);
    for (const std::string& path : {"/dev/fd/" + n, "/proc/self/fd/" + n, "/proc/thread-self/fd/" + n,
                                    "/proc/" + std::to_string(::getpid()) + "/fd/" + n, std::string("/dev/fd/63"),
                                    std::string("/dev/stdin"), std::string("/proc/1/fd/0")}) {
        EXPECT_TRUE(unshareable_by_ranks(path)) << path;
        EXPECT_NE(unshareable_text(path).find(path + ": a descriptor of the process that names it"), std::string::npos)
            << unshareable_text(path);
    }
    ::close(fd);
    for (const std::string& path : {file, dir, dir + "/none", std::string("/dev/fd/"), std::string("/dev/fdx/3"),
                                    std::string("/proc/self/fdinfo/1"), std::string("/proc/self/fd/x")})
        EXPECT_FALSE(descriptor_path(path)) << path;
    EXPECT_FALSE(unshareable_by_ranks(file));
}
