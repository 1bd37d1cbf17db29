// rocking fragility's IDAs through the batch engine's rows (src/jobs/fragility_plan):
// an IDA read back from its row is the IDA computed, field by field and bit by
// bit, so that a study fitted from a rows file (resumed, or from other ranks)
// is the study fitted in memory; a failed job's row carries its error to the
// command, and a row of another job or block is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "jobs/fragility_plan.hpp"
#include "studies/ida.hpp"

using namespace rocking;

namespace {

// A decaying 1 Hz sine of 0.35 g: the block rocks, and overturns on several intervals of q.
dynamics::SampledInput decaying_sine() {
    std::vector<double> a;
    for (int k = 0; k <= 800; ++k) a.push_back(0.35 * std::exp(-0.3 * k * 0.01) * std::sin(2 * M_PI * k * 0.01));
    return dynamics::SampledInput(a, 0.01, "decaying sine");
}

void expect_same(const studies::Ida& got, const studies::Ida& want) {
    EXPECT_EQ(got.alpha, want.alpha);
    EXPECT_EQ(got.p, want.p);
    EXPECT_EQ(got.q_input, want.q_input);
    EXPECT_EQ(got.point.q, want.point.q);
    EXPECT_EQ(got.point.collapsed, want.point.collapsed);
    EXPECT_EQ(got.simulations, want.simulations);
    EXPECT_EQ(got.check_simulations, want.check_simulations);
    ASSERT_EQ(got.intervals.size(), want.intervals.size());
    for (std::size_t i = 0; i < want.intervals.size(); ++i) {
        const studies::IdaInterval &g = got.intervals[i], &w = want.intervals[i];
        EXPECT_EQ(g.from, w.from);
        EXPECT_EQ(g.to, w.to);
        EXPECT_EQ(g.has_lower, w.has_lower);
        EXPECT_EQ(g.has_upper, w.has_upper);
        EXPECT_EQ(g.lower.safe, w.lower.safe);
        EXPECT_EQ(g.lower.collapse, w.lower.collapse);
        EXPECT_EQ(g.upper.safe, w.upper.safe);
        EXPECT_EQ(g.upper.collapse, w.upper.collapse);
    }
    if (!want.intervals.empty()) {
        EXPECT_EQ(got.intervals.front().lower_check.confirmation, want.intervals.front().lower_check.confirmation);
        EXPECT_EQ(got.intervals.front().lower_check.detail, want.intervals.front().lower_check.detail);
    }
    // Issue 39's fields, both methods.
    EXPECT_EQ(got.first_overturning.q, want.first_overturning.q);
    EXPECT_EQ(got.first_overturning.collapsed, want.first_overturning.collapsed);
    EXPECT_EQ(got.first_robust_collapse.q, want.first_robust_collapse.q);
    EXPECT_EQ(got.first_robust_collapse.collapsed, want.first_robust_collapse.collapsed);
    ASSERT_EQ(got.bands.size(), want.bands.size());
    for (std::size_t i = 0; i < want.bands.size(); ++i) {
        EXPECT_EQ(got.bands[i].from, want.bands[i].from);
        EXPECT_EQ(got.bands[i].to, want.bands[i].to);
        EXPECT_EQ(got.bands[i].share, want.bands[i].share);
    }
    EXPECT_EQ(got.refined, want.refined);
    EXPECT_EQ(got.samples, want.samples);
    EXPECT_EQ(got.accepted, want.accepted);
    EXPECT_EQ(got.at_width, want.at_width);
    EXPECT_EQ(got.with_margins, want.with_margins);
    EXPECT_EQ(got.unguaranteed_from, want.unguaranteed_from);
}

}  // namespace

TEST(FragilityRows, AnIdaReadBackFromItsRowIsTheIdaComputed) {
    const dynamics::SampledInput sine = decaying_sine();
    jobs::FragilityJobs jobs;
    jobs.inputs = {&sine};
    jobs.blocks = {{0.1, 2.0}, {0.2, 1.0}, {0.05, 5.0}};
    jobs.ida.points = 30;
    const batch::BatchPlan plan = jobs::fragility_plan(jobs);
    ASSERT_EQ(plan.jobs, 3u);
    int several = 0;
    for (std::size_t j = 0; j < plan.jobs; ++j) {
        const batch::JobRow row = plan.run(j);
        EXPECT_FALSE(row.failed) << row.text;
        const studies::Ida want =
            studies::incremental_dynamic_analysis(sine, jobs.blocks[j].alpha, jobs.blocks[j].p, jobs.ida);
        several += want.intervals.size() > 1;
        expect_same(jobs::ida_from_row(row.text, j, jobs), want);
    }
    EXPECT_GT(several, 0) << "no IDA with more than one interval: the round trip of a list is untested";
}

TEST(FragilityRows, AFailedJobsErrorReachesTheCommandAndAForeignRowIsRefused) {
    const dynamics::SampledInput sine = decaying_sine();
    const dynamics::SampledInput still(std::vector<double>(100, 0.0), 0.01, "still");
    jobs::FragilityJobs jobs;
    jobs.inputs = {&sine, &still};
    jobs.blocks = {{0.1, 2.0}};
    jobs.ida.points = 20;
    const batch::BatchPlan plan = jobs::fragility_plan(jobs);
    const batch::JobRow failed = plan.run(1);
    EXPECT_TRUE(failed.failed);
    try {
        jobs::ida_from_row(failed.text, 1, jobs);
        ADD_FAILURE() << "a failed row was read as an IDA";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("record 2"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("never moves"), std::string::npos) << e.what();
    }
    const batch::JobRow row = plan.run(0);
    EXPECT_THROW(jobs::ida_from_row(row.text, 1, jobs), std::runtime_error);  // job 0's row as job 1's
    jobs::FragilityJobs other = jobs;
    other.blocks = {{0.1, 2.5}};
    EXPECT_THROW(jobs::ida_from_row(row.text, 0, other), std::runtime_error);  // another block's
    EXPECT_THROW(jobs::ida_from_row(row.text.substr(0, row.text.size() / 2), 0, jobs), std::exception);
    // Two different studies have two different identities, and one study always the same.
    EXPECT_NE(jobs::fragility_plan(other).digest, plan.digest);
    EXPECT_EQ(jobs::fragility_plan(jobs).digest, plan.digest);
}

// Each record is one of the plan's inputs, named as the command line gave it
// and with its samples' digest, so that a resume over an edited record
// names it ("the study has changed" did not say which input had).
TEST(FragilityRows, EachRecordIsANamedInputWhoseDigestFollowsItsSamples) {
    const dynamics::SampledInput sine = decaying_sine();
    std::vector<double> g = sine.samples();
    g[100] = std::nextafter(g[100], 1.0);
    const dynamics::SampledInput edited(g, sine.dt(), "sine");
    jobs::FragilityJobs jobs;
    jobs.inputs = {&sine, &sine};
    jobs.names = {"a.txt", "b.txt"};
    jobs.blocks = {{0.1, 2.0}};
    const batch::BatchPlan plan = jobs::fragility_plan(jobs);
    ASSERT_EQ(plan.inputs.size(), 2u);
    EXPECT_EQ(plan.inputs[0].name, "a.txt");
    EXPECT_EQ(plan.inputs[1].name, "b.txt");
    EXPECT_EQ(plan.inputs[1].digest, plan.inputs[0].digest);
    jobs.inputs[1] = &edited;
    const batch::BatchPlan after = jobs::fragility_plan(jobs);
    EXPECT_EQ(after.inputs[0].digest, plan.inputs[0].digest);
    EXPECT_NE(after.inputs[1].digest, plan.inputs[1].digest) << "one sample of b.txt";
    EXPECT_EQ(after.digest, plan.digest) << "the study itself is the same";
    jobs.names.clear();  // eq27's plan names none
    EXPECT_EQ(jobs::fragility_plan(jobs).inputs[1].name, "record 1");
}

// The refine method's IDA (issue 39) read back from its row bit for bit, its
// first overturning, robust collapse, bands and counts included; the method,
// its width and the robust width are part of the study, so that a resume
// across them is refused.
TEST(FragilityRows, ARefinedIdaReadBackFromItsRowIsTheIdaComputed) {
    const dynamics::SampledInput sine = decaying_sine();
    jobs::FragilityJobs jobs;
    jobs.inputs = {&sine};
    jobs.blocks = {{0.1, 2.0}, {0.2, 1.0}, {0.05, 5.0}};
    jobs.ida.points = 20;
    jobs.ida.q_max = 8;
    jobs.ida.method = studies::IdaOptions::Method::refine;
    jobs.ida.width = 1e-3;
    const batch::BatchPlan plan = jobs::fragility_plan(jobs);
    int with_bands = 0, margins = 0;
    for (std::size_t j = 0; j < plan.jobs; ++j) {
        const batch::JobRow row = plan.run(j);
        EXPECT_FALSE(row.failed) << row.text;
        const studies::Ida want =
            studies::incremental_dynamic_analysis(sine, jobs.blocks[j].alpha, jobs.blocks[j].p, jobs.ida);
        EXPECT_TRUE(want.refined);
        with_bands += !want.bands.empty() && !want.intervals.empty();
        margins += want.with_margins && want.samples > 0;
        expect_same(jobs::ida_from_row(row.text, j, jobs), want);
    }
    EXPECT_GT(with_bands, 0);
    EXPECT_GT(margins, 0) << "no run with margins: the record kernel's fields are untested";
    // An infinite unguaranteed_from (q_max below the turn-back bound) and a finite one both read back.
    jobs.blocks = {{0.3, 2.0}};
    jobs.ida.q_max = 20;  // above (pi/2 - 0.3)/0.3 = 4.24
    const studies::Ida want = studies::incremental_dynamic_analysis(sine, 0.3, 2.0, jobs.ida);
    EXPECT_TRUE(std::isfinite(want.unguaranteed_from));
    expect_same(jobs::ida_from_row(jobs::fragility_plan(jobs).run(0).text, 0, jobs), want);
}

TEST(FragilityRows, TheMethodAndItsWidthsArePartOfTheStudy) {
    const dynamics::SampledInput sine = decaying_sine();
    jobs::FragilityJobs jobs;
    jobs.inputs = {&sine};
    jobs.blocks = {{0.1, 2.0}};
    const std::string grid = jobs::fragility_plan(jobs).digest;
    jobs.ida.method = studies::IdaOptions::Method::refine;
    const std::string refine = jobs::fragility_plan(jobs).digest;
    EXPECT_NE(refine, grid);
    jobs.ida.width = 1e-4;
    const std::string wider = jobs::fragility_plan(jobs).digest;
    EXPECT_NE(wider, refine);
    jobs.ida.robust_width = 1e-2;
    EXPECT_NE(jobs::fragility_plan(jobs).digest, wider);
}
