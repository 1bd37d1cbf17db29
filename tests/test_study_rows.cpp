// rocking spectrum's rows on the batch engine (src/jobs/spectrum_plan.hpp):
// a study comes back from its row bit for bit, every field of it, so that
// the command prints the same bytes whether its spectra came from memory, a
// rows file or another rank; a failed job's row names its alpha and error;
// a damaged row is refused, never read as another study; and the digest
// changes with anything that changes the study, so that a resume on another
// one is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "jobs/spectrum_plan.hpp"
#include "studies/spectrum.hpp"

using namespace rocking;
using jobs::SpectrumJobs;
using jobs::SpectrumStudy;
using studies::Boundary;
using studies::Confirmation;
using studies::GridKind;
using studies::Interval;
using studies::SpectrumPoint;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// Bit for bit (-0 is not 0), any NaN being "nan" in a row.
::testing::AssertionResult same(double a, double b) {
    if (std::isnan(a) && std::isnan(b)) return ::testing::AssertionSuccess();
    std::uint64_t x, y;
    std::memcpy(&x, &a, sizeof x);
    std::memcpy(&y, &b, sizeof y);
    if (x == y) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << a << " != " << b;
}

void expect_same(const Boundary& a, const Boundary& b) {
    EXPECT_TRUE(same(a.p_safe, b.p_safe));
    EXPECT_TRUE(same(a.p_collapse, b.p_collapse));
    EXPECT_EQ(a.confirmation, b.confirmation);
    EXPECT_EQ(a.detail, b.detail);
}

void expect_same(const SpectrumStudy& a, const SpectrumStudy& b) {
    const studies::Spectrum &s = a.spectrum, &t = b.spectrum;
    EXPECT_TRUE(same(s.alpha, t.alpha));
    EXPECT_EQ(s.lifts, t.lifts);
    EXPECT_EQ(s.boundaries, t.boundaries);
    EXPECT_EQ(s.simulations, t.simulations);
    EXPECT_EQ(s.check_simulations, t.check_simulations);
    ASSERT_EQ(s.intervals.size(), t.intervals.size());
    for (std::size_t k = 0; k < s.intervals.size(); ++k) {
        SCOPED_TRACE("interval " + std::to_string(k));
        const Interval &i = s.intervals[k], &j = t.intervals[k];
        EXPECT_TRUE(same(i.from, j.from));
        EXPECT_TRUE(same(i.to, j.to));
        EXPECT_EQ(i.has_lower, j.has_lower);
        EXPECT_EQ(i.has_upper, j.has_upper);
        expect_same(i.lower, j.lower);
        expect_same(i.upper, j.upper);
    }
    ASSERT_EQ(s.points.size(), t.points.size());
    for (std::size_t k = 0; k < s.points.size(); ++k) {
        SCOPED_TRACE("point " + std::to_string(k));
        const SpectrumPoint &p = s.points[k], &q = t.points[k];
        EXPECT_TRUE(same(p.p, q.p));
        EXPECT_EQ(p.grid, q.grid);
        EXPECT_TRUE(same(p.max_theta, q.max_theta));
        EXPECT_EQ(p.final_rotation, q.final_rotation);
        EXPECT_EQ(p.peak_rotation, q.peak_rotation);
        EXPECT_EQ(p.overturning, q.overturning);
        EXPECT_EQ(p.collapse, q.collapse);
        EXPECT_TRUE(same(p.t_overturn, q.t_overturn));
    }
    EXPECT_EQ(a.table1.found, b.table1.found);
    EXPECT_TRUE(same(a.table1.p, b.table1.p));
    EXPECT_TRUE(same(a.table1.p_safe, b.table1.p_safe));
    EXPECT_EQ(a.table1.below_range(), b.table1.below_range());
    EXPECT_EQ(a.table1.simulations, b.table1.simulations);
}

// A decaying 1 Hz sine of 0.3 g, 10 s at dt = 0.01 s (tests/spectrum_cli_test.sh's
// record): at alpha 0.1 three intervals, at 0.5 no lift.
dynamics::SampledInput sine() {
    std::vector<double> g;
    for (int k = 0; k < 1000; ++k) g.push_back(0.3 * std::sin(2 * M_PI * k * 0.01) * std::exp(-k * 0.01 / 3));
    return dynamics::SampledInput(g, 0.01, "sine");
}

SpectrumJobs jobs_on(const dynamics::SampledInput& input, std::vector<double> alphas, int points) {
    SpectrumJobs j;
    j.input = &input;
    j.alphas = std::move(alphas);
    j.grid.points = points;
    j.description = "# a test\n";
    return j;
}

// Every field off its default, and what a row's separators could break:
// a detail with '|', ';', '%', a comma, a quote and line ends, an interval
// at the grid's start, NaN, infinity, -0, a subnormal, Table 1 below range.
SpectrumStudy awkward_study() {
    SpectrumStudy s;
    s.spectrum.alpha = 0.15;
    s.spectrum.lifts = true;
    s.spectrum.boundaries = 3;
    s.spectrum.simulations = 12345678901L;
    s.spectrum.check_simulations = 7;
    Interval open_start;
    open_start.from = 0.3;
    open_start.to = 1.0 / 3;
    open_start.has_upper = true;
    open_start.upper = {0.33333333333333337, 1.0 / 3, Confirmation::ill_conditioned,
                        "a|b;c%d %25 e, \"f\"\nsecond line\r end "};
    Interval closed;
    closed.from = 2.5;
    closed.to = 30;
    closed.has_lower = closed.has_upper = true;
    closed.lower = {2.4999999, 2.5, Confirmation::disagrees, "the second solver sees no collapse at p = 2.5"};
    closed.upper = {30.000001, 30, Confirmation::confirmed, ""};
    s.spectrum.intervals = {open_start, closed};
    s.spectrum.points = {{0.3, GridKind::main, 1.5, true, true, true, 0.125, true},
                         {0.31, GridKind::offset, kInf, false, true, false, kNaN, false},
                         {1.0 / 3, GridKind::extra, -0.0, false, false, true, 4.9e-324, true},
                         {30, GridKind::main, 0.0, true, false, false, kNaN, false}};
    s.table1.found = true;
    s.table1.p = 0.3;
    s.table1.p_safe = 0;  // below the search's range
    s.table1.simulations = 1;
    return s;
}

}  // namespace

TEST(StudyRows, AnAwkwardStudyComesBackFromItsRowBitForBit) {
    const dynamics::SampledInput input = sine();
    const SpectrumJobs j = jobs_on(input, {0.2, 0.15}, 5);
    const SpectrumStudy s = awkward_study();
    const std::string row = jobs::study_row(1, s);
    EXPECT_EQ(row.find_first_of("\r\n"), std::string::npos) << row;
    const SpectrumStudy back = jobs::study_from_row(row, 1, j);
    expect_same(s, back);
    EXPECT_TRUE(back.table1.below_range());
    EXPECT_EQ(jobs::study_row(1, back), row);

    SpectrumStudy none;  // no lift: no interval, Table 1 not found
    none.spectrum.alpha = 0.2;
    none.spectrum.points = {{0.3, GridKind::main, 0, false, false, false, kNaN, false}};
    expect_same(none, jobs::study_from_row(jobs::study_row(0, none), 0, j));
}

// The plan's rows give what spectrum_study gives when called directly, on a
// record with a refined and confirmed boundary (NaN fall times off its
// intervals) and at an alpha it never lifts.
TEST(StudyRows, APlansRowsAreTheStudiesTheLibraryGives) {
    const dynamics::SampledInput input = sine();
    const SpectrumJobs j = jobs_on(input, {0.1, 0.5}, 20);
    const batch::BatchPlan plan = jobs::spectrum_plan(j);
    ASSERT_EQ(plan.jobs, 2u);
    for (std::size_t k = 0; k < plan.jobs; ++k) {
        SCOPED_TRACE("alpha " + std::to_string(j.alphas[k]));
        const batch::JobRow row = plan.run(k);
        ASSERT_FALSE(row.failed) << row.text;
        const SpectrumStudy direct = jobs::spectrum_study(input, j.alphas[k], j.grid);
        expect_same(direct, jobs::study_from_row(row.text, k, j));
        bool fall_time_nan = false;
        for (const SpectrumPoint& pt : direct.spectrum.points) fall_time_nan = fall_time_nan || std::isnan(pt.t_overturn);
        EXPECT_TRUE(fall_time_nan);
    }
    const std::vector<Interval> at_01 = jobs::spectrum_study(input, 0.1, j.grid).spectrum.intervals;
    ASSERT_FALSE(at_01.empty());
    EXPECT_TRUE(at_01.front().has_lower && at_01.front().lower.confirmation == Confirmation::confirmed);
    EXPECT_FALSE(jobs::spectrum_study(input, 0.5, j.grid).spectrum.lifts);
}

// A grid that rocking_spectrum refuses makes every job fail: its row holds the
// error on one line, and reading it names the alpha as given.
TEST(StudyRows, AFailedJobsRowNamesItsAlphaAndError) {
    const dynamics::SampledInput input = sine();
    const SpectrumJobs j = jobs_on(input, {0.1}, 1);
    const batch::JobRow row = jobs::spectrum_plan(j).run(0);
    EXPECT_TRUE(row.failed);
    EXPECT_EQ(row.text.find('\n'), std::string::npos);
    try {
        jobs::study_from_row(row.text, 0, j);
        FAIL() << "a failed row read as a study: " << row.text;
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("the spectrum at alpha 0.1: ", 0), 0u) << e.what();
        EXPECT_NE(std::string(e.what()).find("points"), std::string::npos) << e.what();
    }
}

TEST(StudyRows, ADamagedRowIsRefused) {
    const dynamics::SampledInput input = sine();
    const SpectrumJobs j = jobs_on(input, {0.15, 0.2}, 5);
    const std::string row = jobs::study_row(0, awkward_study());
    ASSERT_NO_THROW(jobs::study_from_row(row, 0, j));
    // The first occurrence of `from` in the row replaced by `to`.
    const auto damaged = [&](const std::string& from, const std::string& to) {
        std::string text = row;
        const std::size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return at == std::string::npos ? text : text.replace(at, from.size(), to);
    };
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"row cut short", row.substr(0, row.find(",\""))},
        {"a cell more", row + ","},
        {"an unterminated quote", row.substr(0, row.find('"') + 5)},
        {"another job's", damaged("0,", "1,")},
        {"another alpha", damaged("0.14999999999999999", "0.20000000000000001")},
        {"a number garbled", damaged(",12345678901,", ",12345678901x,")},
        {"lifts neither yes nor no", damaged(",yes,", ",true,")},
        {"an interval short of a field", damaged("0.29999999999999999|", "")},
        {"an unknown check", damaged("ill-conditioned", "ill conditioned")},
        {"an unknown escape", damaged("%7C", "%7X")},
        {"an escape cut short", damaged("%0A", "%0")},
        {"a point's criterion not 1 or 0", damaged("|1|1|1|", "|1|2|1|")},
        {"an unknown grid", damaged("|offset|", "|shifted|")},
        {"an empty row", ""},
    };
    for (const auto& [what, text] : cases)
        EXPECT_THROW(jobs::study_from_row(text, 0, j), std::runtime_error) << what << ": " << text;
    EXPECT_THROW(jobs::study_from_row(row, 2, j), std::runtime_error) << "a job beyond the plan's";
}

TEST(StudyRows, TheDigestChangesWithTheStudy) {
    dynamics::SampledInput input = sine();
    const std::string digest = jobs::spectrum_plan(jobs_on(input, {0.1, 0.2}, 20)).digest;
    EXPECT_EQ(jobs::spectrum_plan(jobs_on(input, {0.1, 0.2}, 20)).digest, digest);
    EXPECT_NE(jobs::spectrum_plan(jobs_on(input, {0.2, 0.1}, 20)).digest, digest) << "the alphas' order";
    EXPECT_NE(jobs::spectrum_plan(jobs_on(input, {0.1}, 20)).digest, digest) << "an alpha fewer";
    EXPECT_NE(jobs::spectrum_plan(jobs_on(input, {0.1, 0.2}, 21)).digest, digest) << "the grid";
    SpectrumJobs wider = jobs_on(input, {0.1, 0.2}, 20);
    wider.grid.p_max = 30.000000000000004;  // beyond the grid's description's digits
    EXPECT_NE(jobs::spectrum_plan(wider).digest, digest) << "p_max";
    SpectrumJobs described = jobs_on(input, {0.1, 0.2}, 20);
    described.description = "# another record\n";
    EXPECT_NE(jobs::spectrum_plan(described).digest, digest) << "the description";
    std::vector<double> g = input.samples();
    g[500] = std::nextafter(g[500], 1.0);
    const dynamics::SampledInput edited(g, 0.01, "sine");
    // The record is the plan's input, named, its digest in the rows' header: a resume over an
    // edited record names it, where "the study has changed" did not say which input had.
    const batch::BatchPlan plan = jobs::spectrum_plan(jobs_on(input, {0.1, 0.2}, 20));
    SpectrumJobs named = jobs_on(edited, {0.1, 0.2}, 20);
    named.name = "r.txt";
    const batch::BatchPlan edited_plan = jobs::spectrum_plan(named);
    ASSERT_EQ(plan.inputs.size(), 1u);
    ASSERT_EQ(edited_plan.inputs.size(), 1u);
    EXPECT_EQ(edited_plan.inputs[0].name, "r.txt");
    EXPECT_EQ(edited_plan.inputs[0].digest.size(), 64u);
    EXPECT_NE(edited_plan.inputs[0].digest, plan.inputs[0].digest) << "one sample";
    EXPECT_EQ(edited_plan.digest, digest) << "the study itself is the same";
    const dynamics::SampledInput slower(input.samples(), 0.02, "sine");
    EXPECT_NE(jobs::spectrum_plan(jobs_on(slower, {0.1, 0.2}, 20)).inputs[0].digest, plan.inputs[0].digest) << "dt";
}
