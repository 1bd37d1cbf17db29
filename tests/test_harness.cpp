// The reproduce diff: tolerances are read strictly, and a deviation beyond a
// tolerance is caught.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <functional>
#include <filesystem>
#include <fstream>

#include "harness/compare.hpp"
#include "harness/output_paths.hpp"
#include "harness/table.hpp"
#include "scene.hpp"
#include "test_util.hpp"

using namespace rocking::harness;
namespace fs = std::filesystem;

namespace {
std::string write_temp(const std::string& name, const std::string& text) {
    return rocking::testing::write_temp("rocking-harness-test", name, text);
}
using rocking::testing::error_of;
}  // namespace

TEST(Harness, ToleranceFileErrorsNameFileAndLine) {
    const auto p1 = write_temp("t1", "# comment\na.csv x 0 1e-12 reason\na.csv y abc 0 reason\n");
    EXPECT_NE(error_of([&] { ToleranceSpec::read(p1); }).find("t1:3:"), std::string::npos);
    const auto p2 = write_temp("t2", "a.csv x 0 1e-12\n");
    EXPECT_NE(error_of([&] { ToleranceSpec::read(p2); }).find("needs its reason"), std::string::npos);
    const auto p3 = write_temp("t3", "a.csv x 0 1e-12 r\na.csv x 0 1e-12 r\n");
    EXPECT_NE(error_of([&] { ToleranceSpec::read(p3); }).find("second rule"), std::string::npos);
    const auto p4 = write_temp("t4", "a.csv x -1 0 r\n");
    EXPECT_NE(error_of([&] { ToleranceSpec::read(p4); }).find(">= 0"), std::string::npos);
}

TEST(Harness, CsvErrorsNameFileAndLine) {
    const auto p = write_temp("bad.csv", "# note\nx,y\n1,2\n3\n");
    EXPECT_NE(error_of([&] { read_csv(p); }).find("bad.csv:4:"), std::string::npos);
    const auto empty = write_temp("empty.csv", "");
    EXPECT_NE(error_of([&] { read_csv(empty); }).find("empty file"), std::string::npos);
}

TEST(Harness, AReferenceVerdictReadsNotCheckedWithoutTheReferenceRun) {
    // table1_records.csv said bracket_confirmed = yes beside "brackets not
    // re-checked": a plain run must say it did not check, a --reference run
    // must give the expected verdict.
    const auto spec = ToleranceSpec::read(write_temp("spec-ref", "a.csv * exact labels\na.csv ok reference rk8pd's verdict\n"));
    const auto expected = read_csv(write_temp("e-ref.csv", "name,ok\nA,yes\nB,-\n"));
    const auto plain = read_csv(write_temp("plain.csv", "name,ok\nA,not checked\nB,not checked\n"));
    const auto claimed = read_csv(write_temp("claimed.csv", "name,ok\nA,yes\nB,-\n"));
    EXPECT_TRUE(compare(expected, plain, spec, "a.csv", false).match());
    EXPECT_FALSE(compare(expected, claimed, spec, "a.csv", false).match());
    EXPECT_TRUE(compare(expected, claimed, spec, "a.csv", true).match());
    EXPECT_FALSE(compare(expected, plain, spec, "a.csv", true).match());
}

TEST(Harness, CompareCatchesEachKindOfDifference) {
    const auto spec = ToleranceSpec::read(write_temp("spec", "a.csv * 1e-6 0 noise\na.csv label exact text\n"));
    const auto expected = read_csv(write_temp("e.csv", "x,label\n1.0,yes\n2.0,no\n"));
    EXPECT_TRUE(compare(expected, read_csv(write_temp("ok.csv", "x,label\n1.0000005,yes\n2,no\n")), spec, "a.csv").match());
    const auto off = compare(expected, read_csv(write_temp("off.csv", "x,label\n1.000002,yes\n2,no\n")), spec, "a.csv");
    EXPECT_FALSE(off.match());
    EXPECT_EQ(off.failed, 1);
    EXPECT_NEAR(off.worst.ratio, 2.0, 1e-6);
    EXPECT_FALSE(compare(expected, read_csv(write_temp("txt.csv", "x,label\n1,no\n2,no\n")), spec, "a.csv").match());
    EXPECT_FALSE(compare(expected, read_csv(write_temp("nan.csv", "x,label\nnan,yes\n2,no\n")), spec, "a.csv").match());
    EXPECT_FALSE(compare(expected, read_csv(write_temp("rows.csv", "x,label\n1,yes\n")), spec, "a.csv").match());
    EXPECT_FALSE(compare(expected, read_csv(write_temp("cols.csv", "x,other\n1,yes\n2,no\n")), spec, "a.csv").match());
}

TEST(Harness, ExpectedFilesCatchAPerturbationJustBeyondTheirTolerance) {
    // For every scene's expected file: itself matches, and pushing one cell of
    // each column to 1.5 times its allowed deviation makes it fail.  The fresh
    // outputs' match is the reproduce_<scene> tests' (running every scene here
    // again would repeat minutes of searches for nothing this test checks).
    const std::string expected_dir = std::string(ROCKING_SOURCE_DIR) + "/expected";
    int files = 0;
    for (const auto& scene : rocking::scenes::all_scenes()) {
        const auto spec = ToleranceSpec::read(expected_dir + "/" + scene.name + "/TOLERANCES");
        for (const auto& file : spec.files()) {
            ++files;
            const CsvFile expected = read_csv(expected_dir + "/" + scene.name + "/" + file);
            // As a --reference run: the expected files hold the second method's verdicts.
            ASSERT_TRUE(compare(expected, expected, spec, file, true).match()) << scene.name << "/" << file;
            for (std::size_t c = 0; c < expected.columns.size(); ++c) {
                const Tolerance& t = spec.of(file, expected.columns[c]);
                CsvFile broken = expected;
                const std::string cell = expected.rows[0][c];
                char* end = nullptr;
                const double v = std::strtod(cell.c_str(), &end);
                if (t.exact || end != cell.c_str() + cell.size()) {
                    broken.rows[0][c] = cell + "_changed";
                } else {
                    const double allowed = t.abs + t.rel * std::fabs(v);
                    broken.rows[0][c] = format_number(allowed > 0 ? v + 1.5 * allowed : std::nextafter(v, INFINITY));
                }
                EXPECT_FALSE(compare(expected, broken, spec, file, true).match())
                    << scene.name << "/" << file << " column " << expected.columns[c];
            }
        }
    }
    EXPECT_GE(files, 20) << "the TOLERANCES files name fewer expected files than the scenes write";
}

// Issue 38: an output that is an input is refused by inode, whatever its
// spelling or a link to it; two outputs that are one file are refused before
// either exists; a folder that cannot take the file is found before any work,
// and the probe leaves nothing behind.
TEST(OutputPaths, AnOutputThatIsAnInputIsRefusedWhateverItsSpelling) {
    const std::string dir = rocking::testing::temp_folder("rocking-output-paths");
    const std::string record = dir + "/r.txt";
    std::ofstream(record) << "0.1\n";
    fs::create_symlink(record, dir + "/link.txt");
    fs::create_hard_link(record, dir + "/hard.txt");
    for (const std::string& spelling : {record, dir + "/./r.txt", dir + "/link.txt", dir + "/hard.txt"}) {
        const std::string e = error_of([&] { check_outputs({{"--output", spelling}}, {{"FILE", record}}); });
        EXPECT_NE(e.find("--output '" + spelling + "' is the input FILE '" + record + "'"), std::string::npos) << e;
    }
    EXPECT_EQ(error_of([&] { check_outputs({{"--output", dir + "/new.csv"}}, {{"FILE", record}}); }), "");
    EXPECT_FALSE(same_file("/dev/null", "/dev/null"));  // devices are written in place, not replaced
    const std::string two = error_of(
        [&] { check_outputs({{"--output", dir + "/x.csv"}, {"--png", dir + "/../" + fs::path(dir).filename().string() + "/x.csv"}}, {}); });
    EXPECT_NE(two.find("are one file"), std::string::npos) << two;
}

// An empty name is a bad argument (std::invalid_argument, exit 2 on the command line) in
// every check, before the outputs are compared: AtomicFile("") probed a temporary file in
// the working folder and passed, and the run failed at its end moving it onto "".
TEST(OutputPaths, AnEmptyNameIsABadArgumentInEveryCheck) {
    const std::string dir = rocking::testing::temp_folder("rocking-output-paths");
    const std::string here = fs::current_path().string();
    fs::current_path(dir);
    for (const auto& check : std::vector<std::function<void()>>{
             [] { check_writable({"--png", ""}); },
             [] { check_outputs({{"--output", "x.csv"}, {"--png", ""}}, {}); },
             [] { check_outputs({{"--png", ""}, {"--rows", ""}}, {}); }}) {
        try {
            check();
            ADD_FAILURE() << "an empty name was taken";
        } catch (const std::invalid_argument& e) {
            EXPECT_EQ(std::string(e.what()), "--png: an empty file name");
        } catch (const std::exception& e) {
            ADD_FAILURE() << "not a bad argument: " << e.what();
        }
    }
    fs::current_path(here);
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(OutputPaths, AnUnwritableOutputIsFoundBeforeTheWorkAndTheProbeLeavesNothing) {
    const std::string dir = rocking::testing::temp_folder("rocking-output-paths");
    EXPECT_NE(error_of([&] { check_outputs({{"--output", dir + "/no/such/folder/x.csv"}}, {}); })
                  .find("--output: " + dir + "/no/such/folder/x.csv: cannot create a file in"),
              std::string::npos);
    EXPECT_NE(error_of([&] { check_outputs({{"--rows", dir}}, {}); }).find("is a folder"), std::string::npos);
    EXPECT_EQ(error_of([&] { check_outputs({{"--output", dir + "/x.csv"}, {"--png", "/dev/null"}}, {}); }), "");
    EXPECT_TRUE(fs::is_empty(dir));
}

// format_number is printf's %.17g, which every expected file and results row
// was written with: the same bytes for random bit patterns (every exponent,
// subnormals), rounded values, halfway cases and the extremes.
TEST(Harness, FormatNumberIsPrintfs17g) {
    std::mt19937_64 bits(42);
    auto printf17 = [](double v) {
        char text[40];
        std::snprintf(text, sizeof text, "%.17g", v);
        return std::string(text);
    };
    std::vector<double> values = {0.0, -0.0, 1.0, 0.1, 1e16, 1e17, 9.999999999999999e16, 5e-324, 2.2250738585072014e-308,
                                  1.7976931348623157e308, 0.5, 2.5, 1e-5, 123456.5};
    for (int k = 0; k < 1000000; ++k) {
        const std::uint64_t b = bits();
        double v;
        std::memcpy(&v, &b, sizeof v);
        if (std::isfinite(v)) values.push_back(v);
        values.push_back(std::round(static_cast<double>(b >> 20) / 1e3) / (k % 2 ? 1e3 : 7.0));
    }
    std::size_t differ = 0;
    for (double v : values)
        if (format_number(v) != printf17(v) && ++differ < 5) ADD_FAILURE() << printf17(v) << " written " << format_number(v);
    EXPECT_EQ(differ, 0u);
    EXPECT_EQ(format_number(NAN), "nan");
    EXPECT_EQ(format_number(-INFINITY), "-inf");
}
