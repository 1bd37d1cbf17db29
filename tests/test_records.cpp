// Record readers (real files and broken ones), ground-motion measures on
// signals whose answers are known in closed form, and the collapse search.
#include <gtest/gtest.h>

#include <gsl/gsl_fft_complex.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

#include <sys/stat.h>
#include <unistd.h>

#include "dynamics/ground_input.hpp"
#include "records/collapse.hpp"
#include "records/cwt.hpp"
#include "records/measures.hpp"
#include "records/record.hpp"
#include "test_util.hpp"

using namespace rocking;
using namespace rocking::records;
namespace fs = std::filesystem;

namespace {
const std::string kRecords = std::string(ROCKING_SOURCE_DIR) + "/../shared/records";

std::string write_file(const std::string& name, const std::string& text) {
    return rocking::testing::write_temp("rocking-record-tests", name, text);
}
using rocking::testing::error_of;

std::string esm(const std::string& ndata, const std::string& pga, const std::string& units, const std::string& samples,
                bool with_dt = true) {
    return std::string("EVENT_ID: TEST\nSTATION_CODE: X\n") + (with_dt ? "SAMPLING_INTERVAL_S: 0.010000\n" : "") +
           "NDATA: " + ndata + "\nUNITS: " + units + "\nPGA_CM/S^2: " + pga + "\n" + samples;
}

// A pipe that a thread writes `text` into, `piece` bytes at a time, then keeps
// open and silent for `linger` before closing it; read by name (/dev/fd/N), as
// a shell's <(cat f) or /dev/stdin is.
class Pipe {
  public:
    Pipe(const std::string& text, std::size_t piece, std::chrono::milliseconds linger = {}) {
        std::signal(SIGPIPE, SIG_IGN);  // a reader that gives up makes write() fail, not the test die
        int fds[2];
        if (::pipe(fds) != 0) throw std::runtime_error("pipe() failed");
        read_end_ = fds[0];
        writer_ = std::thread([text, piece, linger, out = fds[1]] {
            for (std::size_t at = 0; at < text.size(); at += piece) {
                if (::write(out, text.data() + at, std::min(piece, text.size() - at)) < 0) break;
                std::this_thread::sleep_for(std::chrono::microseconds(200));
            }
            std::this_thread::sleep_for(linger);
            ::close(out);
        });
    }
    ~Pipe() {
        ::close(read_end_);  // a writer still writing then gets EPIPE instead of blocking the join
        writer_.join();
    }
    std::string path() const { return "/dev/fd/" + std::to_string(read_end_); }

  private:
    int read_end_ = -1;
    std::thread writer_;
};

// An ESM record of n samples that passes every check of the reader.
std::string esm_of(int n) {
    std::string samples;
    double peak = 0;
    for (int k = 0; k < n; ++k) {
        char line[32];
        const double a = 100 * std::sin(0.01 * k) * std::exp(-1e-4 * k);
        std::snprintf(line, sizeof line, "%.6f\n", a);
        samples += line;
        peak = std::max(peak, std::fabs(std::strtod(line, nullptr)));
    }
    char pga[32];
    std::snprintf(pga, sizeof pga, "%.6f", peak);
    return "NETWORK: XX\nSTATION_CODE: PIPE\nSTREAM: HNE\n" + esm(std::to_string(n), pga, "cm/s^2", samples);
}

const std::string kPeer = "PEER NGA STRONG MOTION DATABASE RECORD\nTEST 1999, PIPE, 180\n"
                          "ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    7, DT=   .0050 SEC\n"
                          "  .1E-02  .2E-02 -.3E-02  .4E-02 -.5E-02\n  .6E-02 -.1E-02\n";

void expect_same(const Record& a, const Record& b, const std::string& what) {
    EXPECT_EQ(a.format, b.format) << what;
    EXPECT_EQ(a.dt, b.dt) << what;
    EXPECT_EQ(a.accel, b.accel) << what;
    EXPECT_EQ(a.header, b.header) << what;
}
}  // namespace

TEST(Readers, EveryRealRecordReadsAndChecksItself) {
    if (!fs::is_directory(kRecords)) GTEST_SKIP() << "shared records folder absent: " << kRecords;
    int files = 0;
    for (const char* sub : {"esm", "peer"})
        for (const auto& e : fs::directory_iterator(fs::path(kRecords) / sub)) {
            const Record r = read_any(e.path().string());
            EXPECT_GE(r.accel.size(), 5000u) << e.path();
            EXPECT_GT(r.dt, 0.0);
            ++files;
        }
    EXPECT_EQ(files, 16);
    const Record norcia = read_esm(kRecords + "/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC");
    EXPECT_EQ(norcia.accel.size(), 8000u);
    EXPECT_NEAR(norcia.pga() * 100, 352.571, 5e-4);
    const Record duzce = read_peer(kRecords + "/peer/RSN1158_KOCAELI_DZC180.AT2");
    EXPECT_EQ(duzce.accel.size(), 5437u);
    EXPECT_NEAR(duzce.pga() / 9.81, 0.312, 5e-4);
}

TEST(Readers, BrokenFilesAreRefusedWithFileLineAndProblem) {
    const std::string ok = "1.0\n-2.0\n0.5\n";
    EXPECT_EQ(error_of([&] { read_esm(write_file("ok.asc", esm("3", "2.000000", "cm/s^2", ok))); }), "");
    struct Case { std::string name, text, want; };
    const std::vector<Case> cases = {
        {"no_dt.asc", esm("3", "2.0", "cm/s^2", ok, false), ": missing header key SAMPLING_INTERVAL_S"},
        {"bad_sample.asc", esm("3", "2.0", "cm/s^2", "1.0\nabc\n0.5\n"), ":8: sample 'abc' is not a number"},
        {"ndata.asc", esm("4", "2.0", "cm/s^2", ok), ":4: NDATA says 4 samples, the file has 3"},
        {"pga.asc", esm("3", "2.5", "cm/s^2", ok), ":6: PGA_CM/S^2 says 2.5"},
        {"unit.asc", esm("3", "2.0", "g", ok), ":5: UNITS is 'g', expected cm/s^2"},
        {"empty.asc", "", ": empty file"},
        {"peer_npts.at2", "H1\nH2\nACCELERATION IN UNITS OF G\nDT= .01 SEC\n0.1 0.2\n", ":4: expected 'NPTS= n, DT= dt SEC'"},
        // "UNITS OF GAL" (cm/s^2) contains "UNITS OF G": it was read as g, 981 times too strong.
        {"peer_gal.at2", "H1\nH2\nACCELERATION IN UNITS OF GAL\nNPTS= 2, DT= .01 SEC\n0.1 0.2\n",
         ":1: neither ESM ASCII (its header lines are 'KEY: value') nor PEER AT2 ('UNITS OF G' on line 3)"},
        {"peer_count.at2", "H1\nH2\nACCELERATION IN UNITS OF G\nNPTS= 3, DT= .01 SEC\n0.1 0.2\n", ":4: NPTS says 3 samples, the file has 2"},
        {"peer_sample.at2", "H1\nH2\nACCELERATION IN UNITS OF G\nNPTS= 2, DT= .01 SEC\n0.1 x\n", ":5: sample 'x' is not a number"},
        {"peer_range.at2", "H1\nH2\nACCELERATION IN UNITS OF G\nNPTS= 2, DT= .01 SEC\n0.1 1e400\n",
         ":5: sample '1e400' is too large for a double (magnitude beyond 1.7976931348623157e+308)"},
        // A double in g, out of range once in m/s^2 (it was read as inf).
        {"peer_overflow.at2", "H1\nH2\nACCELERATION IN UNITS OF G\nNPTS= 2, DT= .01 SEC\n0.1 -1e308\n",
         ":5: sample '-1e308' g is out of range for a double in m/s^2"},
        {"neither.txt", "0 0.1\n0.01 0.2\n0.02 0.3\n0.03 0.1\n", ":1: neither ESM ASCII"},
        {"short.txt", "0.1\n", ":1: neither ESM ASCII"},
    };
    for (const Case& c : cases) {
        const std::string path = write_file(c.name, c.text);
        const std::string message = error_of([&] { read_any(path); });
        EXPECT_NE(message.find(path + c.want), std::string::npos) << c.name << ": " << message;
    }
    // A folder opens as a stream that reads nothing.
    const std::string folder = std::filesystem::path(write_file("in_folder.txt", "")).parent_path().string();
    EXPECT_NE(error_of([&] { read_any(folder); }).find(folder + ": is a folder, not a record file"), std::string::npos);
    const std::string uneven = write_file("uneven.txt", "0 1\n0.01 2\n0.03 1\n");
    EXPECT_NE(error_of([&] { read_plain(uneven, "g", 0); }).find(":3: uneven time step"), std::string::npos);
    const std::string two = write_file("two.txt", "# t a\n0 1\n0.01 2\n0.02 1\n");
    EXPECT_NE(error_of([&] { read_plain(two, "furlongs", 0); }).find("unknown unit 'furlongs'"), std::string::npos);
    const Record r = read_plain(two, "cm/s2", 0);
    EXPECT_EQ(r.accel.size(), 3u);
    EXPECT_NEAR(r.dt, 0.01, 1e-15);
    EXPECT_NEAR(r.accel[1], 0.02, 1e-15);
    const std::string one = write_file("one.txt", "0.1\n0.2,\n");  // a trailing comma (CSV) is a separator
    EXPECT_EQ(error_of([&] { read_plain(one, "g", 0.01); }), "");
    const Record r1 = read_plain(one, "g", 0.01);
    ASSERT_EQ(r1.accel.size(), 2u);
    EXPECT_DOUBLE_EQ(r1.accel[1], 0.2 * 9.81);
    const std::string bad = write_file("bad.txt", "0.1\nzz\n");
    EXPECT_NE(error_of([&] { read_plain(bad, "g", 0.01); }).find(":2: 'zz' is not a number"), std::string::npos);
    const std::string huge = write_file("huge.txt", "0.1\n-1e400\n");
    EXPECT_NE(error_of([&] { read_plain(huge, "g", 0.01); }).find(":2: '-1e400' is too large for a double (magnitude beyond"),
              std::string::npos);
    const std::string overflow = write_file("overflow.txt", "0 0.1\n0.01 1e308\n");
    EXPECT_NE(error_of([&] { read_plain(overflow, "g", 0); }).find(":2: '1e308' g is out of range for a double in m/s^2"),
              std::string::npos);
}

// A sample below the smallest normal double (1.9e-308, as numpy or record
// synth may write one) was refused as out of range; it is read as itself in
// every reader, and one beyond the largest double is refused as too large,
// naming the file and line (numerics/number_text.hpp).
TEST(Readers, ASubnormalSampleIsItselfAndAnOverflowingOneTooLarge) {
    const Record esm_r = read_esm(write_file("tiny.asc", esm("3", "2.0", "cm/s^2", "2.0\n1.9e-308\n-1e-320\n")));
    ASSERT_EQ(esm_r.accel.size(), 3u);
    EXPECT_EQ(esm_r.accel[1], 1.9e-308 * 0.01);
    EXPECT_EQ(esm_r.accel[2], -1e-320 * 0.01);
    const Record peer_r =
        read_peer(write_file("tiny.at2", "H1\nH2\nACCELERATION IN UNITS OF G\nNPTS= 3, DT= .01 SEC\n0.1 1.9e-308 1e-400\n"));
    ASSERT_EQ(peer_r.accel.size(), 3u);
    EXPECT_EQ(peer_r.accel[1], 1.9e-308 * 9.81);
    EXPECT_EQ(peer_r.accel[2], 0.0);  // nearer 0 than any double: rounds to it
    const Record one = read_plain(write_file("tiny1.txt", "0.1\n1.9e-308\n 0.2 \n"), "m/s2", 0.01);
    ASSERT_EQ(one.accel.size(), 3u);
    EXPECT_EQ(one.accel[1], 1.9e-308);
    EXPECT_EQ(one.accel[2], 0.2);
    const Record two = read_plain(write_file("tiny2.txt", "0,1e-310\n0.01,1.9e-308\n0.02,0.5\n"), "m/s2", 0);
    EXPECT_EQ(two.accel[0], 1e-310);
    const std::string too_large = "is too large for a double (magnitude beyond 1.7976931348623157e+308)";
    struct Case { std::string name, text, want; };
    for (const Case& c : std::vector<Case>{
             {"big.asc", esm("3", "2.0", "cm/s^2", "2.0\n1e400\n0.5\n"), ":8: sample '1e400' " + too_large},
             {"big.at2", "H1\nH2\nACCELERATION IN UNITS OF G\nNPTS= 2, DT= .01 SEC\n0.1 -1e400\n", ":5: sample '-1e400' " + too_large},
             {"big.txt", "0 0.1\n0.01 0.2\n0.02 1e400\n", ":3: '1e400' " + too_large}}) {
        const std::string path = write_file(c.name, c.text);
        const std::string message = error_of([&] { c.name == "big.txt" ? read_plain(path, "g", 0) : read_any(path); });
        EXPECT_NE(message.find(path + c.want), std::string::npos) << c.name << ": " << message;
    }
    // A header's value is a parameter of the record, held to the options' rule.
    const std::string tiny_dt = write_file("tiny_dt.at2", "H1\nH2\nACCELERATION IN UNITS OF G\nNPTS= 2, DT= 1e-320 SEC\n0.1 0.2\n");
    EXPECT_NE(error_of([&] { read_peer(tiny_dt); }).find(":4: DT '1E-320' must be > 0"), std::string::npos);
}

// A one-column file with decimal commas ("0,0123") was read as two columns,
// time 0 and acceleration 123 (or refused at a later line for a time that
// does not increase).  With no decimal point anywhere in the file, a comma
// between digits is refused, naming decimal commas; one decimal point
// settles that commas separate, and a two-column CSV reads as before.
TEST(Readers, ADecimalCommaIsRefusedNotReadAsTwoColumns) {
    const std::string refusal = "has a comma between digits and no value in the file has a decimal point: "
                                "decimal commas are not read";
    struct Case { std::string name, text; double dt; std::string want; };
    const std::vector<Case> refused = {
        {"comma_two.txt", "0,0123\n0,0456\n-0,0100\n", 0, ":1: '0,0123' " + refusal},
        {"comma_even.txt", "1,5\n2,5\n3,5\n4,25\n", 0, ":1: '1,5' " + refusal},  // was 4 samples, 25 g
        {"comma_one.txt", "0,0123\n0,0456\n-0,0100\n", 0.01, ":1: '0,0123' " + refusal},
        {"comma_comment.txt", "# dt = 0.01 s\n0\n-0,0123\n", 0.01, ":3: '-0,0123' " + refusal},
        {"comma_tab.txt", "0,00\t0,0123\n0,01\t0,0456\n", 0, ":1: '0,00\t0,0123' " + refusal},
    };
    for (const Case& c : refused) {
        const std::string path = write_file(c.name, c.text);
        const std::string message = error_of([&] { read_plain(path, "g", c.dt); });
        EXPECT_NE(message.find(path + c.want), std::string::npos) << c.name << ": " << message;
    }
    const Record csv = read_plain(write_file("point_csv.txt", "0.00,0.0123\n0.01,0.0456\n0.02,-0.01\n"), "g", 0);
    ASSERT_EQ(csv.accel.size(), 3u);
    EXPECT_NEAR(csv.dt, 0.01, 1e-15);
    EXPECT_DOUBLE_EQ(csv.accel[1], 0.0456 * 9.81);
    // printf's %g writes 0 without a point: the other lines settle it.
    EXPECT_EQ(read_plain(write_file("g_csv.txt", "0,0\n0.01,0.0123\n0.02,-0.01\n"), "g", 0).accel.size(), 3u);
    // A comma and a space is a separator, never a decimal comma.
    EXPECT_EQ(read_plain(write_file("spaced_csv.txt", "0, 1\n1, 2\n2, 3\n"), "cm/s2", 0).accel.size(), 3u);
    const std::string esm_comma = write_file("comma.asc", esm("3", "2.0", "cm/s^2", "1.0\n0,5\n2.0\n"));
    EXPECT_NE(error_of([&] { read_esm(esm_comma); }).find(":8: sample '0,5' is not a number (decimal commas are not read)"),
              std::string::npos);
}

// Every reader works on the text read once: the same record from a file's
// text as from the file, a last line without its newline included.
TEST(Readers, EveryReaderParsesTheTextReadOnce) {
    const std::string esm_text = esm_of(500), plain1 = "# a\n0.1\n-0.2\n0.3", plain2 = "0,0.1\n0.01,-0.2\n0.02,0.3";
    const std::string esm_file = write_file("text.asc", esm_text), peer_file = write_file("text.at2", kPeer);
    const std::string one_file = write_file("text1.txt", plain1), two_file = write_file("text2.txt", plain2);
    EXPECT_EQ(read_text(esm_file), esm_text);
    expect_same(parse_esm(esm_text, "x"), read_esm(esm_file), "esm");
    expect_same(parse_any(esm_text, "x"), read_any(esm_file), "esm by content");
    expect_same(parse_peer(kPeer, "x"), read_peer(peer_file), "peer");
    expect_same(parse_any(kPeer, "x"), read_any(peer_file), "peer by content");
    expect_same(parse_plain(plain1, "x", "g", 0.01), read_plain(one_file, "g", 0.01), "one column");
    expect_same(parse_plain(plain2, "x", "g", 0), read_plain(two_file, "g", 0), "two columns");
    EXPECT_EQ(parse_esm(esm_text, "x").accel.size(), 500u);
    EXPECT_EQ(parse_peer(kPeer, "x").accel.size(), 7u);
    EXPECT_EQ(parse_plain(plain1, "x", "g", 0.01).accel.size(), 3u);
    EXPECT_EQ(parse_plain(plain2, "x", "g", 0).accel.size(), 3u);
    EXPECT_NE(error_of([] { parse_any("", "named"); }).find("named: empty file"), std::string::npos);
}

// A pipe read by name (<(cat f), /dev/stdin) was opened twice: once to sniff
// its format, once to read it, and the second found the data gone ("missing
// header key SAMPLING_INTERVAL_S").  Each reader now reads it once.
TEST(Readers, APipeIsReadOnceAndSniffedFromItsText) {
    const std::string esm_text = esm_of(20000);  // 200 KB: more than a pipe holds, written in pieces
    const Record file = read_any(write_file("pipe.asc", esm_text));
    {
        Pipe pipe(esm_text, 4096);
        expect_same(read_any(pipe.path()), file, "ESM through a pipe");
    }
    {
        Pipe pipe(kPeer, 10);
        expect_same(read_any(pipe.path()), read_any(write_file("pipe.at2", kPeer)), "PEER through a pipe");
    }
    {
        Pipe pipe("0.1\n0.2\n0.3\n", 3);
        EXPECT_EQ(read_plain(pipe.path(), "g", 0.01).accel.size(), 3u);
    }
    const std::string real = kRecords + "/esm-extra/TV.MIR08..HNN.D.20120529.070002.C.ACC.ASC";
    if (!fs::exists(real)) GTEST_SKIP() << "shared records folder absent, the real record not piped: " << real;
    std::ifstream in(real);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Pipe pipe(text, 65536);
    expect_same(read_any(pipe.path()), read_any(real), "the largest real record through a pipe");
}

// /dev/zero, an endless line and an endless header grew memory without
// bound; each now stops at its cap, named in the error with the file and line.
TEST(Readers, CapsOnLineHeaderAndSizeEndReadingWithTheirName) {
    EXPECT_NE(error_of([] { read_any("/dev/zero"); })
                  .find("/dev/zero:1: a line longer than 1 MiB (the cap on a line's length)"),
              std::string::npos);
    // A line's length carried across the reads of 64 KiB: line 2 spans two of them.
    ReadLimits limits;
    limits.max_line = 70000;
    const std::string fits = "a\n" + std::string(70000, 'x') + "\nb\n", over = "a\n" + std::string(70001, 'x') + "\nb\n";
    EXPECT_EQ(read_text(write_file("line_fits.txt", fits), limits), fits);
    const std::string long_line = write_file("line_over.txt", over);
    EXPECT_NE(error_of([&] { read_text(long_line, limits); })
                  .find(long_line + ":2: a line longer than 70000 bytes (the cap on a line's length)"),
              std::string::npos);
    {
        Pipe pipe(over, 1000);
        EXPECT_NE(error_of([&] { read_text(pipe.path(), limits); }).find(":2: a line longer than 70000 bytes"),
                  std::string::npos);
    }
    limits = ReadLimits{};
    limits.max_bytes = 100;
    EXPECT_EQ(read_text(write_file("size_fits.txt", std::string(100, '\n')), limits).size(), 100u);
    const std::string big = write_file("size_over.txt", std::string(101, '\n'));
    EXPECT_NE(error_of([&] { read_text(big, limits); }).find(big + ": larger than 100 bytes (the cap on a record file's size)"),
              std::string::npos);
    {
        Pipe pipe(std::string(5000, '\n'), 7);
        EXPECT_NE(error_of([&] { read_text(pipe.path(), limits); }).find(": larger than 100 bytes"), std::string::npos);
    }
    // The default cap on a file's size, seen from its size before reading a byte (a sparse file).
    const std::string huge = write_file("sparse.asc", "");
    fs::resize_file(huge, (std::uintmax_t{256} << 20) + 1);
    EXPECT_NE(error_of([&] { read_any(huge); }).find(huge + ": larger than 256 MiB (the cap on a record file's size)"),
              std::string::npos);
    fs::remove(huge);
    // 13 bytes a header line: the 80660th takes the header past 1 MiB.
    std::string header;
    for (int k = 1; header.size() <= kMaxHeaderBytes; ++k) {
        char line[32];
        std::snprintf(line, sizeof line, "KEY%06d: v\n", k);
        header += line;
    }
    EXPECT_NE(error_of([&] { parse_esm(header + "0.1\n", "head"); })
                  .find("head:80660: a header longer than 1 MiB (the cap on an ESM header's size)"),
              std::string::npos);
}

// A FIFO nobody writes to blocked the reader for ever, and so did a writer
// that stalls; both now end after the read timeout, naming the file.
TEST(Readers, APipeSilentForTheTimeoutIsRefused) {
    ReadLimits limits;
    limits.timeout_s = 0.2;
    const std::string fifo = (fs::path(write_file("fifo.keep", "")).parent_path() / "silent.fifo").string();
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto start = std::chrono::steady_clock::now();
    EXPECT_NE(error_of([&] { read_text(fifo, limits); })
                  .find(fifo + ": no data within 0.2 s (the read timeout): a pipe or FIFO that nobody writes to?"),
              std::string::npos);
    fs::remove(fifo);
    {
        Pipe pipe("EVENT: x\n", 100, std::chrono::milliseconds(800));
        EXPECT_NE(error_of([&] { read_text(pipe.path(), limits); })
                      .find(":2: no more data for 0.2 s after 9 bytes (the read timeout): the writer stalled"),
                  std::string::npos);
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(Measures, CosineHasEveryHalfPeriodAtItsHalfPeriod) {
    const double f = 2.0, dt = 0.001;
    std::vector<double> a;
    for (int k = 0; k <= 20000; ++k) a.push_back(std::cos(2 * M_PI * f * k * dt));
    const HalfPeriods h = half_periods(a, dt);
    const double half = 1 / (2 * f);
    EXPECT_NEAR(h.to[0], half, 1e-9);                       // a full interior half-cycle
    // Areas are exact for the linear interpolation between samples, which
    // differs from the cosine's own integral by (w dt)^2 / 12 relative.
    const double interp = std::pow(2 * M_PI * f * dt, 2) / 12;
    EXPECT_NEAR(h.amax * M_PI * f, 1.0, 2 * interp);        // area of a half-cycle of cos
    EXPECT_NEAR(h.to[2] / half, 1.0, 2 * interp);           // eq. 29 is exact for a sine
    EXPECT_NEAR(h.to[3] * M_PI * f, 1.0, 2 * interp);       // eq. 30: Amax / PGA
    EXPECT_NEAR(h.to[4], half, 1e-4);                       // eq. 31: PGV = 1/(2 pi f)
    EXPECT_NEAR(h.to[5], half, 1e-4);                       // Fourier peaks
    EXPECT_NEAR(h.to[6], half, 1e-4);
    for (int k = 7; k < 11; ++k) EXPECT_NEAR(h.to[k], half, 2e-3) << "to_" << k + 1;  // CWT, 16 voices + parabola
}

TEST(Measures, HalfSinePulseAndRickerWavelet) {
    const double dt = 1e-4;
    {   // one half-sine pulse of duration T: to_1 = to_2 = to_3 = T, Amax = 2T/pi.
        const double T = 0.3;
        std::vector<double> a(1000, 0.0);
        for (double t = 0; t <= T + 1e-12; t += dt) a.push_back(std::sin(M_PI * t / T));
        a.resize(a.size() + 1000, 0.0);
        const auto pulses = pulses_of(a, dt);
        const HalfPeriods h = half_periods(a, dt);
        EXPECT_NEAR(h.amax, 2 * T / M_PI, 1e-7);
        EXPECT_NEAR(h.to[0], T, 2 * dt);
        EXPECT_NEAR(h.to[1], T, 2 * dt);
        EXPECT_NEAR(h.to[2], T, 1e-6);
        EXPECT_NEAR(h.to[3], 2 * T / M_PI, 1e-6);
    }
    {   // Ricker of peak frequency fp: central lobe sqrt(2)/(pi fp), area sqrt(2) e^{-1/2}/(pi fp),
        // Fourier amplitude peak at fp.
        const double fp = 3.0, t0 = 2.0;
        std::vector<double> a;
        for (double t = 0; t <= 2 * t0; t += dt) {
            const double u = M_PI * fp * (t - t0);
            a.push_back((1 - 2 * u * u) * std::exp(-u * u));
        }
        const HalfPeriods h = half_periods(a, dt);
        EXPECT_NEAR(h.to[0], std::sqrt(2.0) / (M_PI * fp), 1e-6);
        EXPECT_NEAR(h.amax / (std::sqrt(2.0) * std::exp(-0.5) / (M_PI * fp)), 1.0, 1e-6);  // O(dt^2) interpolation
        EXPECT_NEAR(h.to[5], 1 / (2 * fp), 1e-3);
    }
}

TEST(Measures, MavroeidisPapageorgiouPulse) {
    // Velocity pulse v(t) = A/2 [1 + cos(2 pi fp (t - t0)/gamma)] cos(2 pi fp (t - t0) + nu) for
    // |t - t0| <= gamma/(2 fp) (Mavroeidis & Papageorgiou 2003), differentiated exactly for a.
    // With gamma = 3 its velocity spectrum peaks at fp within a few per cent, and the
    // velocity-based half-periods (to_7, to_9, to_11) are 1/(2 fp) to that accuracy;
    // PGV = A (at t0 with nu = 0).
    const double fp = 1.0, gamma = 3.0, t0 = 5.0, A = 0.5, dt = 0.002;
    std::vector<double> a;
    for (double t = 0; t <= 10.0; t += dt) {
        const double u = t - t0;
        if (std::fabs(u) > gamma / (2 * fp)) {
            a.push_back(0.0);
            continue;
        }
        const double w = 2 * M_PI * fp, env = 0.5 * A * (1 + std::cos(w * u / gamma));
        const double denv = -0.5 * A * (w / gamma) * std::sin(w * u / gamma);
        a.push_back(denv * std::cos(w * u) - env * w * std::sin(w * u));
    }
    const HalfPeriods h = half_periods(a, dt);
    EXPECT_NEAR(h.pgv, A, 1e-4);
    for (int k : {6, 8, 10}) EXPECT_NEAR(h.to[k] * 2 * fp, 1.0, 0.05) << "to_" << k + 1;
}

namespace {
// The CWT as cwt.hpp defines it, the straightforward way (the code before the
// blocks): the record zero-padded to a power of two n >= 2N, one n-point
// transform per scale with Psi at every positive bin, |W| by hypot.
CwtSummary single_transform_cwt(const std::vector<double>& x, double dt, double f_min, double f_max, int voices) {
    std::size_t n = 1;
    while (n < 2 * x.size()) n <<= 1;
    gsl_fft_complex_wavetable* table = gsl_fft_complex_wavetable_alloc(n);
    gsl_fft_complex_workspace* work = gsl_fft_complex_workspace_alloc(n);
    std::vector<double> X(2 * n, 0.0), W(2 * n);
    for (std::size_t k = 0; k < x.size(); ++k) X[2 * k] = x[k];
    gsl_fft_complex_forward(X.data(), 1, n, table, work);
    const double beta = 27, gamma = 3, wp = std::pow(beta / gamma, 1 / gamma);
    const double a_bg = 2 * std::exp((beta / gamma) * (1 + std::log(gamma / beta)));
    CwtSummary out;
    const int last = static_cast<int>(std::ceil(voices * std::log2(f_max / f_min)));
    for (int j = 0; j <= last; ++j) {
        const double f = f_max * std::pow(2.0, -static_cast<double>(j) / voices), s = wp / (2 * M_PI * f);
        for (std::size_t k = 0; k < n; ++k) {
            const double w = 2 * M_PI * k / (n * dt), sw = s * w;
            const double psi = (k >= 1 && k <= n / 2) ? a_bg * std::exp(beta * std::log(sw) - std::pow(sw, gamma)) : 0.0;
            W[2 * k] = X[2 * k] * psi;
            W[2 * k + 1] = X[2 * k + 1] * psi;
        }
        gsl_fft_complex_inverse(W.data(), 1, n, table, work);
        double mx = 0, sum = 0, energy = 0;
        for (std::size_t k = 0; k < x.size(); ++k) {
            const double m = std::hypot(W[2 * k], W[2 * k + 1]);
            mx = std::max(mx, m), sum += m, energy += m * m * dt;
        }
        out.frequency.push_back(f);
        out.max_amp.push_back(mx);
        out.mean_amp.push_back(sum / x.size());
        out.energy.push_back(energy);
    }
    gsl_fft_complex_workspace_free(work);
    gsl_fft_complex_wavetable_free(table);
    return out;
}

// fourier_peak as measures.hpp defines it, the straightforward way: one transform
// of the record zero-padded to the power of two >= 8 N, the first largest bin,
// a parabola through it and its neighbours.
double padded_fourier_peak(const std::vector<double>& x, double dt) {
    std::size_t n = 1;
    while (n < 8 * x.size()) n <<= 1;
    std::vector<double> X(2 * n, 0.0);
    for (std::size_t k = 0; k < x.size(); ++k) X[2 * k] = x[k];
    gsl_fft_complex_radix2_forward(X.data(), 1, n);
    auto amp = [&](std::size_t k) { return std::hypot(X[2 * k], X[2 * k + 1]); };
    std::size_t best = 1;
    for (std::size_t k = 1; k < n / 2; ++k)
        if (amp(k) > amp(best)) best = k;
    double shift = 0;
    const double ym = amp(best - 1), y0 = amp(best), yp = amp(best + 1), den = ym - 2 * y0 + yp;
    if (best > 1 && den < 0) shift = 0.5 * (ym - yp) / den;
    return (best + shift) / (n * dt);
}

// Noise through a resonator at f0 (damping 5 %) plus Gaussian-windowed pulses:
// a record with a broad spectrum and its energy near f0.  xorshift64, so that the
// record is the same on every platform.
std::vector<double> synthetic_record(std::size_t n, double dt, double f0, std::uint64_t seed) {
    auto uniform = [&seed] {
        seed ^= seed << 13, seed ^= seed >> 7, seed ^= seed << 17;
        return static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
    };
    const double w = 2 * M_PI * f0 * dt, r = std::exp(-0.05 * w);
    std::vector<double> a(n);
    double y1 = 0, y2 = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const double y = 2 * r * std::cos(w) * y1 - r * r * y2 + uniform();
        y2 = y1, y1 = y, a[k] = y;
    }
    for (int p = 0; p < 4; ++p) {
        const double t0 = (0.2 + 0.2 * p) * n * dt, fp = 0.3 + 0.8 * p, height = 20 * (1 + uniform());
        for (std::size_t k = 0; k < n; ++k) {
            const double u = k * dt - t0;
            if (std::fabs(fp * u) < 6) a[k] += height * std::exp(-fp * fp * u * u) * std::cos(2 * M_PI * fp * u);
        }
    }
    return a;
}

// The largest |a - b| over scales, against the largest b: W's rounding is relative
// to the record's largest |X|, so scales far from the peak are held to it too.
double worst_against_peak(const std::vector<double>& a, const std::vector<double>& b) {
    double worst = 0, peak = 0;
    for (std::size_t j = 0; j < a.size(); ++j) worst = std::max(worst, std::fabs(a[j] - b[j])), peak = std::max(peak, b[j]);
    return worst / peak;
}
}  // namespace

TEST(Cwt, BlocksGiveTheSingleTransformsValues) {
    // The blocks cut the wavelet at 40 scales (|psi| <= 3.2e-21 beyond, cwt.cpp) and
    // leave out the bins where Psi < 2e-30: the sums agree with the single
    // transforms to rounding, 6.4e-16 of their peak measured; 1e-13 is the bound
    // (a cut at 30 scales, 1.4e-12, fails it).
    struct Case {
        const char* what;
        std::vector<double> x;
        double dt;
        bool blocks;  // the highest scales by blocks (else every scale by the whole transform)
    };
    std::vector<Case> cases = {{"resonator at 2 Hz, 70,000 samples", synthetic_record(70000, 0.01, 2.0, 7), 0.01, true},
                               {"resonator at 0.4 Hz, 50,000 samples", synthetic_record(50000, 0.005, 0.4, 11), 0.005, true},
                               {"resonator at 9 Hz, 3,001 samples", synthetic_record(3001, 0.002, 9.0, 5), 0.002, false}};
    const std::string norcia = kRecords + "/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC";
    if (fs::exists(norcia)) {
        const Record r = read_esm(norcia);
        cases.push_back({"Norcia 2016-08-24 EW", r.accel, r.dt, true});
    }
    for (const Case& c : cases) {
        const double f_max = std::min(25.0, 0.25 / c.dt);
        const CwtSummary got = morse_cwt(c.x, c.dt, 0.1, f_max, 4), want = single_transform_cwt(c.x, c.dt, 0.1, f_max, 4);
        ASSERT_EQ(got.frequency.size(), want.frequency.size());
        EXPECT_EQ(got.frequency, want.frequency);
        EXPECT_LT(worst_against_peak(got.max_amp, want.max_amp), 1e-13) << c.what;
        EXPECT_LT(worst_against_peak(got.mean_amp, want.mean_amp), 1e-13) << c.what;
        EXPECT_LT(worst_against_peak(got.energy, want.energy), 1e-13) << c.what;
        // Both ways are compared: blocks at the highest frequencies of the long
        // records, the whole record at the lowest of the first and everywhere in the
        // short one.
        std::size_t whole = 1;
        while (whole < 2 * c.x.size()) whole <<= 1;
        const double s_high = std::pow(27.0 / 3.0, 1 / 3.0) / (2 * M_PI * f_max);
        EXPECT_EQ(morse_block_length(morse_half_length(s_high, c.dt), c.x.size()) < whole, c.blocks) << c.what;
    }
    const double s_low = std::pow(27.0 / 3.0, 1 / 3.0) / (2 * M_PI * 0.1);
    EXPECT_EQ(morse_block_length(morse_half_length(s_low, 0.01), 70000), 262144u);
}

TEST(Measures, FourierPeakByEightTransformsIsThePaddedTransformsPeak) {
    // Eight transforms of N points instead of one of 8 N: the same amplitudes to
    // rounding, so the same bin and a parabola within 1e-13 relative (4.4e-16
    // measured).
    for (const auto& [x, dt] : {std::pair{synthetic_record(70000, 0.01, 2.0, 7), 0.01},
                                std::pair{synthetic_record(50000, 0.005, 0.4, 11), 0.005},
                                std::pair{synthetic_record(3001, 0.002, 9.0, 5), 0.002},
                                std::pair{synthetic_record(4, 0.01, 1.0, 3), 0.01}}) {
        EXPECT_NEAR(fourier_peak(x, dt) / padded_fourier_peak(x, dt), 1.0, 1e-13) << x.size() << " samples";
    }
    // Transforms shorter than N fold the record onto them: 256 of 4096 points here.
    const std::vector<double> x = synthetic_record(70000, 0.01, 2.0, 7);
    EXPECT_NEAR(fourier_peak(x, 0.01, 4096) / padded_fourier_peak(x, 0.01), 1.0, 1e-13);
}

TEST(Measures, PeakMotionIsTheOneDefinitionOfTo5) {
    // assess reads PGA, PGV and to_5 from peak_motion alone; half_periods must
    // report the very same numbers.
    for (const auto& [x, dt] : {std::pair{synthetic_record(20000, 0.01, 2.0, 7), 0.01},
                                std::pair{synthetic_record(3001, 0.002, 9.0, 5), 0.002}}) {
        const PeakMotion m = peak_motion(x, dt);
        const HalfPeriods h = half_periods(x, dt);
        EXPECT_EQ(m.pga, h.pga);
        EXPECT_EQ(m.pgv, h.pgv);
        EXPECT_EQ(m.to5, h.to[4]);
        EXPECT_EQ(m.to5, M_PI * m.pgv / m.pga);  // eq. 31
    }
    EXPECT_NE(error_of([] { peak_motion({0, 0, 0, 0}, 0.01); }).find("identically zero"), std::string::npos);
    EXPECT_NE(error_of([] { peak_motion({1, 0, 1}, 0.01); }).find(">= 4 samples"), std::string::npos);
    // No CWT band at so coarse a step: the half-periods are refused, to_5 is not.
    const std::vector<double> coarse = synthetic_record(100, 3.0, 0.05, 3);
    EXPECT_NE(error_of([&] { half_periods(coarse, 3.0); }).find("leaves the CWT no band"), std::string::npos);
    EXPECT_GT(peak_motion(coarse, 3.0).to5, 0);
}

TEST(Measures, ACwtPeakBeyondTheBandIsFlaggedAtItsEdge) {
    // The CWT scans 0.1 Hz to min(25 Hz, 0.25/dt): a 40 Hz cosine is largest on its
    // highest scale, a 0.02 Hz one (the velocity measures) on its lowest; a 2 Hz
    // one peaks inside, with none flagged.
    auto cosine = [](double f, double dt, int n) {
        std::vector<double> a(n);
        for (int k = 0; k < n; ++k) a[k] = std::cos(2 * M_PI * f * k * dt);
        return a;
    };
    const HalfPeriods high = half_periods(cosine(40.0, 0.002, 20000), 0.002);
    EXPECT_EQ(high.cwt_band_hz[1], 25.0);
    EXPECT_NEAR(high.cwt_band_hz[0], 0.1, 0.005);
    for (int k = 0; k < 4; ++k) {
        EXPECT_TRUE(high.cwt_at_band_edge[k]) << "to_" << 8 + k;
        EXPECT_NEAR(high.f_cwt[k], 25.0, 1e-13) << "to_" << 8 + k;  // the edge, not refined
    }
    const HalfPeriods low = half_periods(cosine(0.02, 0.05, 20000), 0.05);
    for (int k : {1, 3}) {  // to_9, to_11: velocity
        EXPECT_TRUE(low.cwt_at_band_edge[k]) << "to_" << 8 + k;
        EXPECT_NEAR(low.f_cwt[k] / low.cwt_band_hz[0], 1.0, 1e-14) << "to_" << 8 + k;
    }
    const HalfPeriods inside = half_periods(cosine(2.0, 0.001, 20001), 0.001);
    for (int k = 0; k < 4; ++k) EXPECT_FALSE(inside.cwt_at_band_edge[k]) << "to_" << 8 + k;
}

TEST(Measures, HalfPeriodsDoNotDependOnTheRecordsScale) {
    // A record near the largest double: its |W|^2 summed as it is overflowed, every
    // scale's energy was inf, and to_10 and to_11 fell on the band's first scale.
    const std::vector<double> x = synthetic_record(20000, 0.01, 2.0, 7);
    const HalfPeriods h = half_periods(x, 0.01);
    for (double scale : {1e300, 1e-300}) {
        std::vector<double> y(x);
        for (double& v : y) v *= scale;
        const HalfPeriods g = half_periods(y, 0.01);
        for (int k = 0; k < 11; ++k) EXPECT_NEAR(g.to[k] / h.to[k], 1.0, 1e-12) << "to_" << k + 1 << " at " << scale;
        for (int k = 0; k < 4; ++k) EXPECT_FALSE(g.cwt_at_band_edge[k]) << "to_" << 8 + k << " at " << scale;
    }
}

TEST(CollapseSearch, ConstantStepHasAClosedFormThreshold) {
    // A step of a/g = A for D seconds, then the ground at rest.  Linearised, no
    // impact before the end: theta/alpha = (q-1)(cosh pt - 1), q = A/alpha, and
    // the block overturns in the free rocking iff (q-1)(e^{pD} - 1) >= 1:
    // p* = ln(q/(q-1)) / D.
    const double alpha = 0.1, A = 0.15, D = 0.4, dt = 1e-4;
    std::vector<double> a;
    for (double t = 0; t <= D + 1e-12; t += dt) a.push_back(A);
    a.push_back(0.0);
    a.push_back(0.0);
    const dynamics::SampledInput input(a, dt, "step");
    CollapseOptions o;
    o.housner_restitution = false;
    o.restitution = 1.0;
    const CollapseResult c = smallest_collapse_p(input, alpha, o);
    const double q = A / alpha, expected = std::log(q / (q - 1)) / D;
    ASSERT_TRUE(c.found);
    EXPECT_NEAR(c.p / expected, 1.0, 2e-3);  // the sampled step ramps down over one dt
    EXPECT_LT(c.p_safe, c.p);
    EXPECT_FALSE(c.below_range());
    // Held for 10 s the same step overturns from p* = ln 3 / 10 = 0.11 rad/s,
    // below the search's lowest p: the search says so (it had reported p_min
    // as the smallest collapsing p, with no safe p below it).
    std::vector<double> longer(static_cast<std::size_t>(10.0 / 1e-3) + 1, A);
    longer.push_back(0.0);
    const CollapseResult l = smallest_collapse_p(dynamics::SampledInput(longer, 1e-3, "long step"), alpha, o);
    ASSERT_TRUE(l.found);
    EXPECT_TRUE(l.below_range());
    EXPECT_EQ(l.p, o.p_min);
    EXPECT_EQ(l.simulations, 1);
}

TEST(CollapseSearch, ItsPIsTheFirstOnItsGridNotABound) {
    // Table 1's search (as the paper's) raises p by 1 % until the block
    // overturns, then bisects.  The set of collapsing p is not an interval:
    // narrower islands of collapse can lie below the p it finds.  Under
    // Norcia's 2016-08-24 02:33 NS record at alpha = 0.1 it finds 5.4806
    // rad/s (expected/table1), yet the block overturns at 4.0018 rad/s, 27 %
    // lower (the first collapse on a grid 10 times finer, bench/:
    // table1_finer_grid.csv): the exact solver's two paths, rk8pd and rkf78
    // agree on the time of the fall to 1e-10 s.
    const std::string path = kRecords + "/esm/IT.NRC..HGN.D.20160824.023329.C.ACC.ASC";
    if (!fs::exists(path)) GTEST_SKIP() << "shared records folder absent: " << path;
    const Record r = read_esm(path);
    const dynamics::SampledInput input(r.in_g(9.81), r.dt, r.name);
    const double alpha = 0.1, p_island = 4.001751175;
    CollapseOptions o;  // Table 1's: linearised, exact solver, Housner restitution, overturning
    const CollapseResult c = smallest_collapse_p(input, alpha, o);
    ASSERT_TRUE(c.found);
    EXPECT_NEAR(c.p, 5.4806, 1e-4);
    double first_fall = NAN;
    for (int path_kind = 0; path_kind < 4; ++path_kind) {
        dynamics::Model m;
        m.block = dynamics::Block::from_p(p_island, alpha);
        m.restitution = dynamics::housner_restitution(alpha);
        dynamics::SimulationOptions s;
        s.solver.kind = path_kind < 2 ? dynamics::SolverKind::exact
                                      : path_kind == 2 ? dynamics::SolverKind::gsl_rk8pd : dynamics::SolverKind::rkf78;
        s.solver.record_kernel = path_kind == 0;
        s.solver.rtol = s.solver.atol_alpha = path_kind == 2 ? 1e-13 : 1e-12;
        const dynamics::SimulationResult run = simulate(m, input, s);
        const std::string what = dynamics::solver_name(s.solver.kind) + (path_kind == 1 ? " (general path)" : "");
        ASSERT_TRUE(run.overturned) << what;
        EXPECT_EQ(run.impacts, 33) << what;
        if (std::isnan(first_fall)) first_fall = run.t_overturn;
        EXPECT_NEAR(run.t_overturn, 25.53772072, 1e-8) << what;
        EXPECT_NEAR(run.t_overturn, first_fall, 1e-9) << what;
    }
    EXPECT_TRUE(collapses_at(input, alpha, p_island, o));
}
