// The refine method of the IDA (issue 39: studies/overturning_set.hpp, the
// search of docs/overturning_set.md section 3) against sets known without
// it: a single pulse as a record (one boundary, in closed form); the two-pulse
// island 4.9e-5 wide in ln q of tests/narrow_islands_truth.hpp (its ends in
// closed form), that today's grid misses; and the islands of the issue's
// Norcia example on q in [1.3190, 1.3215] against an independent dense scan
// (expected/overturning_set/ida_islands.csv, a second implementation).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "records/collapse.hpp"
#include "records/record.hpp"
#include "studies/ida.hpp"
#include "studies/overturning_set.hpp"
#include "studies/scaled_input.hpp"
#include "harness/table.hpp"
#include "narrow_islands_truth.hpp"
#include "overturning_truths.hpp"
#include "test_util.hpp"

using namespace rocking;
using namespace rocking::studies;
using rocking::testing::restitution_zero;
using rocking::testing::scan_islands;
using rocking::testing::ScanIsland;

namespace {

const std::string kNorcia = rocking::testing::shared_record("esm/IT.NRC..HGE.D.20161030.064018.C.ACC.ASC");

IdaOptions refine(double width) {
    IdaOptions o;
    o.method = IdaOptions::Method::refine;
    o.width = width;
    return o;
}


// Whether [lo, hi] lies in bracket [a, b] (either order) widened by tol relative.
bool holds(double a, double b, long double lo, long double hi, double tol) {
    return std::min(a, b) * (1 - tol) <= lo && hi <= std::max(a, b) * (1 + tol);
}

}  // namespace

TEST(OverturningSearch, ASinglePulseRecordHasOneBoundaryAtItsClosedForm) {
    // A record of constant samples is exactly a rectangular pulse (0 after its
    // end): q* = 1 / (1 - e^{-p d}) (test_ida.cpp), 1.2524 at p 2, d 0.8.  The
    // refine method, on the margins (the record kernel), must report one
    // interval from q* to q_max, its bracket holding q* to 1e-6, and accept
    // most of the range on the margins rather than split it to w.
    const double alpha = 0.1, p = 2.0, d = 0.8, dt = 0.01;
    const dynamics::SampledInput record(std::vector<double>(81, 0.15), dt, "pulse");
    const long double known = 1 / -std::expm1(-static_cast<long double>(p) * d);
    const Ida ida = incremental_dynamic_analysis(record, alpha, p, refine(1e-5));
    EXPECT_TRUE(ida.with_margins);
    ASSERT_EQ(ida.intervals.size(), 1u);
    const IdaInterval& in = ida.intervals[0];
    ASSERT_TRUE(in.has_lower);
    EXPECT_LE(std::min(in.lower.safe, in.lower.collapse), known * (1 + 1e-12L));
    EXPECT_GE(std::max(in.lower.safe, in.lower.collapse), known * (1 - 1e-12L));
    EXPECT_LE(std::fabs(in.lower.collapse - in.lower.safe), 1e-6 * in.lower.collapse);
    EXPECT_EQ(ida.first_overturning.q, in.lower.collapse);
    EXPECT_EQ(ida.first_robust_collapse.q, in.lower.collapse);
    EXPECT_EQ(ida.point.q, in.lower.collapse);
    EXPECT_EQ(in.lower_check.confirmation, Confirmation::confirmed) << in.lower_check.detail;
    EXPECT_LT(ida.samples, 2000) << "a uniform scan at w would take 3e5";
    EXPECT_GT(ida.accepted, 90);
    // Below q = (pi/2 - alpha)/alpha = 14.7 the guarantee holds.
    EXPECT_NEAR(ida.unguaranteed_from, (M_PI / 2 - alpha) / alpha, 1e-12);
    // Shares: 0 below q*, 1 above, the band holding q* in between.
    for (const IdaBand& b : ida.bands) {
        if (b.to <= known) EXPECT_EQ(b.share, 0.0);
        else if (b.from >= known) EXPECT_NEAR(b.share, 1.0, 1e-12);
        else EXPECT_NEAR(b.share, std::log(b.to / known) / std::log(b.to / b.from), 1e-5);
    }
}

TEST(OverturningSearch, TheNarrowIslandInQIsFoundWhereTheGridMissesIt) {
    // tests/narrow_islands_truth.hpp's island in q, [1.26540733, 1.26546961]
    // in closed form (4.9e-5 in ln q, 310 times narrower than the grid's half
    // step): today's grid puts no point on it and no interval over it, its
    // first collapse above it (test_overturning_truth.cpp).  The refine IDA at
    // its default w = 1e-5 must report it as its first interval, each end's
    // bracket holding the closed form's end and at most 1e-6 relative wide,
    // and as the first overturning, the first robust collapse staying where
    // the grid puts it.  A pulse train is not a record: the search has no
    // margins and splits every interval to w (a scan at w).
    using Q = rocking::testing::NarrowIslandInQ;
    const dynamics::PulseInput input = Q::input();
    IdaOptions go;
    go.model = restitution_zero();
    const Ida grid = incremental_dynamic_analysis(input, Q::alpha, Q::p, go);
    for (const IdaInterval& in : grid.intervals)
        EXPECT_FALSE(in.from <= Q::upper && in.to >= Q::lower) << "the grid found the island: [" << in.from << ", " << in.to << "]";
    ASSERT_TRUE(grid.point.collapsed);
    ASSERT_GT(grid.point.q, 1.7) << "the grid's first collapse";
    IdaOptions o;
    o.method = IdaOptions::Method::refine;
    EXPECT_EQ(o.width, 1e-5) << "the default width";
    o.model = restitution_zero();
    o.q_min = 1.2;
    o.q_max = 2.0;
    const Ida ida = incremental_dynamic_analysis(input, Q::alpha, Q::p, o);
    EXPECT_TRUE(ida.refined);
    EXPECT_FALSE(ida.with_margins);
    ASSERT_GE(ida.intervals.size(), 2u) << "the island is missed: first interval from " << ida.point.q;
    const IdaInterval& island = ida.intervals[0];
    ASSERT_TRUE(island.has_lower && island.has_upper);
    // The library's ends lie within 1e-11 of the closed form's (test_overturning_truth.cpp).
    EXPECT_TRUE(holds(island.lower.safe, island.lower.collapse, Q::lower, Q::lower, 1e-10))
        << "lower bracket [" << island.lower.safe << ", " << island.lower.collapse << "], closed form "
        << static_cast<double>(Q::lower);
    EXPECT_TRUE(holds(island.upper.collapse, island.upper.safe, Q::upper, Q::upper, 1e-10))
        << "upper bracket [" << island.upper.collapse << ", " << island.upper.safe << "], closed form "
        << static_cast<double>(Q::upper);
    EXPECT_LE(island.lower.collapse - island.lower.safe, 1e-6 * Q::lower);
    EXPECT_GT(island.lower.collapse, island.lower.safe);
    EXPECT_LE(island.upper.safe - island.upper.collapse, 1e-6 * Q::upper);
    EXPECT_GT(island.upper.safe, island.upper.collapse);
    EXPECT_EQ(island.lower_check.confirmation, Confirmation::confirmed) << island.lower_check.detail;
    EXPECT_EQ(ida.first_overturning.q, island.lower.collapse);
    EXPECT_GT(ida.intervals[1].from, 1.7) << "the next interval is the grid's";
    EXPECT_NEAR(ida.first_robust_collapse.q, grid.point.q, 1e-6 * grid.point.q);
}

namespace {

// A record and block (the Norcia case by default): the library's plain run
// (records::collapses_at, as the IDA scales, no margins), a dense scan every
// `step` in ln q, each change bisected to 1e-9.
struct Norcia {
    dynamics::SampledInput input;
    double alpha = 0.1, p = 2.5;
    explicit Norcia(const records::Record& r) : input(r.in_g(9.81), r.dt, r.name) {}
    Norcia(const records::Record& r, double alpha_, double p_) : input(r.in_g(9.81), r.dt, r.name), alpha(alpha_), p(p_) {}
    bool overturns(double q) const {
        return records::collapses_at(*scaled(input, q * alpha / input.peak()), alpha, p, records::CollapseOptions{});
    }
    // Islands [from, to] of overturning on [lo, hi].
    std::vector<std::pair<double, double>> scan(double lo, double hi, double step) const {
        std::vector<std::pair<double, double>> out;
        const int n = static_cast<int>(std::ceil(std::log(hi / lo) / step));
        double prev_q = lo;
        bool prev = overturns(lo);
        if (prev) out.push_back({lo, hi});
        for (int k = 1; k <= n; ++k) {
            const double q = lo * std::exp(std::log(hi / lo) * k / n);
            const bool now = overturns(q);
            if (now != prev) {
                double a = prev_q, b = q;
                while (b - a > 1e-9 * b) {
                    const double m = 0.5 * (a + b);
                    (overturns(m) == prev ? a : b) = m;
                }
                if (now) out.push_back({b, hi});
                else out.back().second = a;
            }
            prev = now;
            prev_q = q;
        }
        return out;
    }
};

}  // namespace

namespace {


}  // namespace

TEST(OverturningSearch, EveryIslandOfTheNorciaDenseScanWiderThanWIsFound) {
    // The example (IT.NRC HGE 2016-10-30, alpha 0.1, p 2.5, Table 1's
    // model) on q in [1.3190, 1.3215], which holds its first overturning
    // (1.3194712) and its first island wider than 1e-5 (1.3200069), against
    // expected/overturning_set/ida_islands.csv: 12 islands of a 10^5-point
    // scan by an independent Python model, every boundary bisected to 1e-10
    // (1 island wider than 1e-5 in ln q, 6 wider than 1e-6).  The refine IDA
    // from a coarse grid of 3 points (so that the margins, not the grid, do
    // the work), at w = 1e-5 and 1e-6: every island of the scan wider than w
    // must lie in one of its intervals whose lower bracket holds the
    // island's start and whose upper bracket holds its end (to 1e-6
    // relative), or the start (end) of an island before (after) it across
    // gaps no wider than w, which the search need not see (at w = 1e-5 it
    // joins [1.3200037, 1.3200059] to the wide island across 7.6e-7); and
    // every interval it reports must be one of the scan's: its brackets
    // holding a start and an end of the scan's islands, to 1e-6.
    if (!std::filesystem::exists(kNorcia)) GTEST_SKIP() << "shared records folder absent: " << kNorcia;
    const std::vector<ScanIsland> scan = scan_islands("ida_islands.csv");
    ASSERT_EQ(scan.size(), 12u);
    const Norcia c(records::read_esm(kNorcia));
    const double lo = 1.3190, hi = 1.3215, tol = 1e-6;
    for (const double w : {1e-5, 1e-6}) {
        int wide = 0;
        for (const ScanIsland& s : scan) wide += std::log(s.to / s.from) > w;
        ASSERT_EQ(wide, w > 2e-6 ? 1 : 6);
        IdaOptions o = refine(w);
        o.q_min = lo;
        o.q_max = hi;
        o.points = 3;
        const Ida ida = incremental_dynamic_analysis(c.input, 0.1, 2.5, o);
        EXPECT_TRUE(ida.with_margins);
        // A gap of the scan no wider than w may be missed: the interval over
        // an island may then start at an island before it (or end at one
        // after it) across such gaps only.
        auto gap = [&](std::size_t k) { return std::log(scan[k].from / scan[k - 1].to); };
        for (std::size_t i = 0; i < scan.size(); ++i) {
            const ScanIsland& s = scan[i];
            if (!(std::log(s.to / s.from) > w)) continue;
            const IdaInterval* found = nullptr;
            for (const IdaInterval& in : ida.intervals)
                if (in.from <= s.to && s.from <= in.to) found = &in;
            if (!found) {
                ADD_FAILURE() << "w " << w << ": the island [" << s.from << ", " << s.to << "] ("
                              << std::log(s.to / s.from) << " in ln q) is missed";
                continue;
            }
            bool start = false, end = false;
            for (std::size_t j = i + 1; j-- > 0;) {
                start = start || (found->has_lower && holds(found->lower.safe, found->lower.collapse, scan[j].from, scan[j].from, tol));
                if (j == 0 || gap(j) > w) break;
            }
            for (std::size_t j = i; j < scan.size(); ++j) {
                end = end || (found->has_upper && holds(found->upper.collapse, found->upper.safe, scan[j].to, scan[j].to, tol));
                if (j + 1 == scan.size() || gap(j + 1) > w) break;
            }
            EXPECT_TRUE(start) << "w " << w << ": the island [" << s.from << ", " << s.to << "]'s start not in the lower bracket ["
                               << found->lower.safe << ", " << found->lower.collapse << "]";
            EXPECT_TRUE(end) << "w " << w << ": the island [" << s.from << ", " << s.to << "]'s end not in the upper bracket ["
                             << found->upper.collapse << ", " << found->upper.safe << "]";
        }
        for (const IdaInterval& in : ida.intervals) {
            bool start = false, end = false;
            for (const ScanIsland& s : scan) {
                start = start || (in.has_lower && holds(in.lower.safe, in.lower.collapse, s.from, s.from, tol));
                end = end || (in.has_upper && holds(in.upper.collapse, in.upper.safe, s.to, s.to, tol));
            }
            EXPECT_TRUE(start && end) << "w " << w << ": [" << in.from << ", " << in.to
                                      << "] is no island of the scan (start " << start << ", end " << end << ")";
        }
        std::printf("Norcia [%.4f, %.4f], w %g: scan %zu islands (%d wider than w); refine %zu intervals, %ld samples, "
                    "%ld runs, %ld accepted, first overturning %.9g (scan %.9g)\n",
                    lo, hi, w, scan.size(), wide, ida.intervals.size(), ida.samples, ida.simulations, ida.accepted,
                    ida.first_overturning.q, scan.front().from);
    }
}

TEST(OverturningSearch, EveryIslandOfNorciaWiderThanWIsFoundWhereTheFlightsAreChaotic) {
    // The same on q in [1.5725, 1.5810], where the prototype's search on
    // tangents alone missed islands (docs/overturning_set.md, section 3:
    // q = 1.5733, 1.5802): a scan every 5e-7 in ln q; w = 1e-5, coarse grid of 3.
    if (!std::filesystem::exists(kNorcia)) GTEST_SKIP() << "shared records folder absent: " << kNorcia;
    const Norcia c(records::read_esm(kNorcia));
    const double lo = 1.5725, hi = 1.5810, w = 1e-5;
    const auto truth = c.scan(lo, hi, 5e-7);
    int wide = 0;
    for (const auto& [a, b] : truth) wide += std::log(b / a) > w;
    ASSERT_GE(wide, 2) << "of " << truth.size() << " islands";
    IdaOptions o = refine(w);
    o.q_min = lo;
    o.q_max = hi;
    o.points = 3;
    const Ida ida = incremental_dynamic_analysis(c.input, 0.1, 2.5, o);
    for (const auto& [a, b] : truth) {
        if (!(std::log(b / a) > w)) continue;
        bool found = false;
        for (const IdaInterval& in : ida.intervals) found = found || (a <= in.to && in.from <= b);
        EXPECT_TRUE(found) << "the island [" << a << ", " << b << "] (" << std::log(b / a) << " in ln q) is missed";
    }
    std::printf("Norcia [%.4f, %.4f], w %g: scan %zu islands (%d wider than w); refine %zu intervals, %ld samples\n", lo,
                hi, w, truth.size(), wide, ida.intervals.size(), ida.samples);
}

TEST(OverturningSearch, EveryGapWiderThanWInsideAnOverturningRangeIsFound) {
    // The tangents' consistency check (accept_interval's last test) end to
    // end: PEER RSN1158 Kocaeli DZC270, alpha 0.2, p 3 (Table 1's model), the
    // IDA's whole range q in [1, 20] from its 100-point grid at w = 1e-3.
    // Between q 1.72 and 1.76 the block overturns except on a gap about
    // 1.5e-3 wide in ln q, near 1.7254, where the margins of the two ends
    // agree in sign and their tangents reach no zero: only the check that
    // each tangent is borne out by the other end refuses the interval.
    // Without it the search reports one interval over the gap (measured
    // 2026-11-26, and the same on 21 other record x block cases of the
    // shared folder).  Truth: a scan by the plain run every 5e-5 in ln q on
    // [1.70, 1.78], each change bisected to 1e-9; every gap and island of it
    // wider than w must be reported as such.  Skipped without the records.
    const std::string kocaeli = rocking::testing::shared_record("peer/RSN1158_KOCAELI_DZC270.AT2");
    if (!std::filesystem::exists(kocaeli)) GTEST_SKIP() << "shared records folder absent: " << kocaeli;
    const Norcia c(records::read_peer(kocaeli), 0.2, 3.0);
    const double lo = 1.70, hi = 1.78, w = 1e-3;
    const auto truth = c.scan(lo, hi, 5e-5);
    int gaps = 0;
    for (std::size_t k = 1; k < truth.size(); ++k) gaps += std::log(truth[k].first / truth[k - 1].second) > w;
    ASSERT_GE(gaps, 1) << "the scan's gaps: the case no longer holds one wider than w";
    IdaOptions o = refine(w);
    o.q_max = 20;
    o.points = 100;
    const Ida ida = incremental_dynamic_analysis(c.input, 0.2, 3.0, o);
    ASSERT_TRUE(ida.with_margins);
    auto meets = [&](double a, double b) {  // some reported interval meets [a, b]
        for (const IdaInterval& in : ida.intervals)
            if (a <= in.to && in.from <= b) return true;
        return false;
    };
    // The reported intervals cover all of [a, b]: no safe q reported inside.
    // (The scan, every 5e-5, does not resolve the set's finer structure: the
    // search may rightly report islands inside a gap of the scan, and gaps
    // inside its islands.)
    auto covers = [&](double a, double b) {
        double reach = a;
        for (const IdaInterval& in : ida.intervals)
            if (in.from <= reach && in.to > reach) reach = in.to;
        return reach >= b;
    };
    for (std::size_t k = 1; k < truth.size(); ++k) {
        const double a = truth[k - 1].second, b = truth[k].first;
        if (!(std::log(b / a) > w)) continue;
        // The gap's inside, clear of its two bisected ends by the brackets' 1e-6.
        EXPECT_FALSE(covers(a * (1 + 2e-6), b * (1 - 2e-6)))
            << "the gap (" << a << ", " << b << ") (" << std::log(b / a) << " in ln q) is reported as overturning";
    }
    for (const auto& [a, b] : truth)
        if (std::log(b / a) > w) {
            EXPECT_TRUE(meets(a, b)) << "the island [" << a << ", " << b << "] is missed";
        }
    std::printf("Kocaeli DZC270 [%.2f, %.2f], w %g: scan %zu islands, %d gaps wider than w; refine %zu intervals on "
                "[1, 20], %ld samples\n", lo, hi, w, truth.size(), gaps, ida.intervals.size(), ida.samples);
}

TEST(OverturningSearch, TheAcceptanceTestRefusesWhatItMustRefuse) {
    // accept_interval on hand-made samples: each condition of section 3.
    RefineOptions o;
    MarginSample a{false, true, {-0.5, -0.2}, {1.0, 2.0}}, b{false, true, {-0.49, -0.18}, {1.0, 2.0}};
    const double d = 0.01;
    EXPECT_TRUE(accept_interval(a, b, d, o));
    MarginSample other = b;
    other.collapse = true;
    EXPECT_FALSE(accept_interval(a, other, d, o)) << "outcomes differ";
    other = b;
    other.xi.push_back(-0.3);
    other.slope.push_back(0.0);
    EXPECT_FALSE(accept_interval(a, other, d, o)) << "another flight";
    other = b;
    other.xi[1] = 0.01;
    EXPECT_FALSE(accept_interval(a, other, d, o)) << "a safe run with Xi > 0";
    EXPECT_FALSE(accept_interval(a, b, 0.1, o)) << "the tangents reach 0 (c d = 0.2 > 0.1 + 0.09)";
    other = b;
    other.slope[0] = -40.0;  // reaches fine (0.1 + 0.012 > 0.02), but b's tangent back to a gives -0.09, not -0.5
    EXPECT_FALSE(accept_interval(a, other, d, o)) << "tangents not borne out";
    other = b;
    other.has_margins = false;
    EXPECT_FALSE(accept_interval(a, other, d, o)) << "no margins";
    // Overturning: only the falling flight's margin counts.
    const MarginSample oa{true, true, {-0.9, 0.3}, {50.0, 1.0}}, ob{true, true, {0.2, 0.31}, {-50.0, 1.0}};
    EXPECT_TRUE(accept_interval(oa, ob, d, o));
    const MarginSample ob_neg{true, true, {-0.9, -0.01}, {50.0, 1.0}};
    EXPECT_FALSE(accept_interval(oa, ob_neg, d, o)) << "the falling flight's Xi must stay > 0";
    // Never lifted at either end: accepted.
    EXPECT_TRUE(accept_interval(MarginSample{false, true, {}, {}}, MarginSample{false, true, {}, {}}, 1.0, o));
}
