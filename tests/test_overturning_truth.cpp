// Issue 39's truths known without the method: two islands of overturning about
// 5e-5 wide (tests/narrow_islands_truth.hpp), one in p and one in q, whose
// boundaries follow from closed forms.  Here: the closed forms' boundaries
// (mpmath, tools/narrow_island.py) against a long-double bisection of the
// chain; the library's exact solver checked BY the closed form inside, outside
// and within 1e-9 of each boundary; and today's default grids shown to miss
// both islands, the gap the exact overturning set must close.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "narrow_islands_truth.hpp"
#include "records/collapse.hpp"
#include "records/record.hpp"
#include "studies/ida.hpp"
#include "studies/scaled_input.hpp"
#include "studies/spectrum.hpp"
#include "overturning_truths.hpp"

using namespace rocking;
using namespace rocking::studies;
using rocking::testing::restitution_zero;
using rocking::testing::scan_islands;
using rocking::testing::ScanIsland;
using rocking::testing::NarrowIslandInP;
using rocking::testing::NarrowIslandInQ;

namespace {


// The boundary of a boolean inside [lo, hi] (outcomes differ at the ends),
// bisected in long double until the bracket is 1e-15 relative.
long double bisect(const std::function<bool(long double)>& f, long double lo, long double hi) {
    const bool at_lo = f(lo);
    EXPECT_NE(at_lo, f(hi)) << "no change of outcome in [" << static_cast<double>(lo) << ", " << static_cast<double>(hi) << "]";
    while (hi - lo > 1e-15L * hi) {
        const long double mid = (lo + hi) / 2;
        (f(mid) == at_lo ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// Every change of outcome of a boolean over [lo, hi] on n log-spaced points.
std::vector<long double> changes_of(const std::function<bool(long double)>& f, long double lo, long double hi, int n) {
    std::vector<long double> out;
    long double prev_x = lo;
    bool prev = f(lo);
    for (int k = 1; k < n; ++k) {
        const long double x = lo * std::pow(hi / lo, static_cast<long double>(k) / (n - 1));
        const bool now = f(x);
        if (now != prev) out.push_back(bisect(f, prev_x, x));
        prev = now;
        prev_x = x;
    }
    return out;
}

bool library_in_p(double p) {
    return records::collapses_at(NarrowIslandInP::input(), NarrowIslandInP::alpha, p, restitution_zero());
}

// As the IDA scales its input (studies/ida.cpp): by q alpha / peak, through scaled().
bool library_in_q(double q, const records::CollapseOptions& o = restitution_zero()) {
    const dynamics::PulseInput input = NarrowIslandInQ::input();
    return records::collapses_at(*scaled(input, q * NarrowIslandInQ::alpha / input.peak()), NarrowIslandInQ::alpha,
                                 NarrowIslandInQ::p, o);
}

// Points around an island [lo, hi] and the closed form's outcome at each:
// the middle, 1e-9 relative on either side of each boundary, 1e-6 and 1e-3
// outside it.
struct Probe {
    double x;
    const char* where;
};
std::vector<Probe> probes(long double lo, long double hi) {
    return {{static_cast<double>(std::sqrt(lo * hi)), "middle"},
            {static_cast<double>(lo * (1 - 1e-9L)), "lower boundary - 1e-9"},
            {static_cast<double>(lo * (1 + 1e-9L)), "lower boundary + 1e-9"},
            {static_cast<double>(hi * (1 - 1e-9L)), "upper boundary - 1e-9"},
            {static_cast<double>(hi * (1 + 1e-9L)), "upper boundary + 1e-9"},
            {static_cast<double>(lo * (1 - 1e-6L)), "1e-6 below"},
            {static_cast<double>(hi * (1 + 1e-6L)), "1e-6 above"},
            {static_cast<double>(lo * (1 - 1e-3L)), "1e-3 below"},
            {static_cast<double>(hi * (1 + 1e-3L)), "1e-3 above"}};
}

// Whether a grid's intervals leave [lo, hi] untouched.
template <class Interval>
bool misses(const std::vector<Interval>& intervals, long double lo, long double hi) {
    for (const Interval& in : intervals)
        if (in.from <= hi && in.to >= lo) return false;
    return true;
}

}  // namespace

TEST(OverturningTruth, TheNarrowIslandsBoundariesFromTwoEvaluationsOfTheClosedForms) {
    // mpmath's roots of the margin at 40 digits (the header) against a
    // long-double bisection of the chain's verdict: within 1e-12 relative.
    // The island's width: 100 times narrower than the default grids' half
    // steps at least, and wider than issue 39's w = 1e-5.  And it is alone:
    // the chain's other boundaries on the whole default range are more than
    // a grid step away.  Fails if the header's boundaries or parameters drift.
    using P = NarrowIslandInP;
    using Q = NarrowIslandInQ;
    for (const auto& [name, lower, upper, f] :
         {std::tuple{"p", P::lower, P::upper, std::function<bool(long double)>(P::overturns)},
          std::tuple{"q", Q::lower, Q::upper, std::function<bool(long double)>(Q::overturns)}}) {
        const long double lo = bisect(f, lower * (1 - 1e-7L), lower * (1 + 1e-7L));
        const long double hi = bisect(f, upper * (1 - 1e-7L), upper * (1 + 1e-7L));
        EXPECT_NEAR(static_cast<double>(lo / lower - 1), 0.0, 1e-12) << name << ": lower boundary";
        EXPECT_NEAR(static_cast<double>(hi / upper - 1), 0.0, 1e-12) << name << ": upper boundary";
        EXPECT_TRUE(f(std::sqrt(lower * upper))) << name << ": overturns inside";
        EXPECT_FALSE(f(lower * (1 - 1e-11L))) << name;
        EXPECT_FALSE(f(upper * (1 + 1e-11L))) << name;
        EXPECT_GT(std::log(upper / lower), 1e-5L) << name << ": wider than w = 1e-5";
    }
    const SpectrumOptions so;
    const IdaOptions io;
    const long double p_half_step = std::log(so.p_max / so.p_min) / (so.points - 1) / 2;
    const long double q_half_step = std::log(io.q_max / io.q_min) / (io.points - 1) / 2;
    EXPECT_NEAR(static_cast<double>(std::exp(p_half_step)), 1.0116, 1e-4);
    EXPECT_NEAR(static_cast<double>(std::exp(q_half_step)), 1.01524, 1e-5);
    EXPECT_LE(100 * std::log(P::upper / P::lower), p_half_step) << "the island in p is not 100 times narrower";
    EXPECT_LE(100 * std::log(Q::upper / Q::lower), q_half_step) << "the island in q is not 100 times narrower";

    // Alone: every other change of outcome on the default ranges (scanned
    // 4e5 points, 1.2e-5 and 7.5e-6 apart in log, finer than the islands)
    // lies more than a whole grid step away.
    for (const auto& [name, lower, upper, f, lo, hi, step] :
         {std::tuple{"p", P::lower, P::upper, std::function<bool(long double)>(P::overturns), 0.3L, 30.0L, 2 * p_half_step},
          std::tuple{"q", Q::lower, Q::upper, std::function<bool(long double)>(Q::overturns), 1.0L, 20.0L, 2 * q_half_step}}) {
        const std::vector<long double> all = changes_of(f, lo, hi, 400000);
        int on_island = 0;
        for (const long double x : all) {
            if (std::fabs(x / lower - 1) < 1e-12L || std::fabs(x / upper - 1) < 1e-12L) {
                ++on_island;
            } else {
                EXPECT_GT(std::fabs(std::log(x / lower)), step) << name << ": another boundary at " << static_cast<double>(x);
                EXPECT_GT(std::fabs(std::log(x / upper)), step) << name << ": another boundary at " << static_cast<double>(x);
            }
        }
        EXPECT_EQ(on_island, 2) << name << ": the scan must see both ends of the island";
    }
}

TEST(OverturningTruth, TheExactSolverIsCheckedByTheClosedFormAroundTheIslands) {
    // The library's exact solver (records::collapses_at, restitution 0) at
    // the middle of each island, 1e-9 on either side of each boundary, 1e-6
    // and 1e-3 outside: the closed form's verdict at every point.  At 1e-9
    // from a boundary the closed form's margin is 5e-14 rad (p) and 7e-14
    // rad (q) (tools/narrow_island.py), 5e-13 relative to alpha: two orders
    // above double rounding in a run of a few impacts.  The library's own
    // boundaries, bisected to 1e-15, lie within 1e-11 of the closed form's.
    // Fails with a wrong impact time, restitution or lift-off rule in the
    // exact solver, or with the header's truths moved by more than 1e-9.
    for (const Probe& pr : probes(NarrowIslandInP::lower, NarrowIslandInP::upper)) {
        ASSERT_EQ(NarrowIslandInP::overturns(pr.x), std::string(pr.where) == "middle" ||
                                                        std::string(pr.where) == "lower boundary + 1e-9" ||
                                                        std::string(pr.where) == "upper boundary - 1e-9")
            << "the closed form itself, p " << pr.where;
        EXPECT_EQ(library_in_p(pr.x), NarrowIslandInP::overturns(pr.x)) << "p = " << pr.x << " (" << pr.where << ")";
    }
    for (const Probe& pr : probes(NarrowIslandInQ::lower, NarrowIslandInQ::upper)) {
        EXPECT_EQ(library_in_q(pr.x), NarrowIslandInQ::overturns(pr.x)) << "q = " << pr.x << " (" << pr.where << ")";
    }
    const auto lib_p = [](long double p) { return library_in_p(static_cast<double>(p)); };
    const auto lib_q = [](long double q) { return library_in_q(static_cast<double>(q)); };
    for (const auto& [name, known, f] : {std::tuple{"p lower", NarrowIslandInP::lower, std::function<bool(long double)>(lib_p)},
                                         std::tuple{"p upper", NarrowIslandInP::upper, std::function<bool(long double)>(lib_p)},
                                         std::tuple{"q lower", NarrowIslandInQ::lower, std::function<bool(long double)>(lib_q)},
                                         std::tuple{"q upper", NarrowIslandInQ::upper, std::function<bool(long double)>(lib_q)}}) {
        const long double found = bisect(f, known * (1 - 1e-8L), known * (1 + 1e-8L));
        EXPECT_NEAR(static_cast<double>(found / known - 1), 0.0, 1e-11) << "the library's " << name << " boundary";
    }
    // A second solver sees the islands too (rk8pd at 1e-13: the middle and 1e-6 outside).
    records::CollapseOptions rk = restitution_zero();
    rk.solver = SpectrumOptions::rk8pd_check();
    for (const Probe& pr : probes(NarrowIslandInQ::lower, NarrowIslandInQ::upper)) {
        const std::string w = pr.where;
        if (w == "middle" || w == "1e-6 below" || w == "1e-6 above") {
            EXPECT_EQ(library_in_q(pr.x, rk), w == "middle") << "rk8pd, q = " << pr.x << " (" << w << ")";
        }
    }
}

TEST(OverturningTruth, TodaysDefaultGridsMissBothIslands) {
    // The gap issue 39 is about: the spectrum's and the IDA's default grids
    // (with their offset grids) put no point on the islands, so their
    // intervals leave them out, though every reported boundary is right:
    // the spectrum reports overturning from p = 1.1295 only (the island is
    // at 0.9134), the IDA a first collapse at q = 1.7510 (the block first
    // overturns at 1.2654, 28 % lower).
    // The exact overturning set (method refine) must find both, each end
    // bracketed to 1e-6 around the header's boundaries; that test comes with
    // the search.  Fails (rightly, then: update this test) once the default
    // spectrum or IDA finds the islands.
    SpectrumOptions so;
    so.model = restitution_zero();
    const Spectrum s = rocking_spectrum(NarrowIslandInP::input(), NarrowIslandInP::alpha, so);
    EXPECT_TRUE(misses(s.intervals, NarrowIslandInP::lower, NarrowIslandInP::upper))
        << "today's spectrum found the island in p";
    for (const SpectrumPoint& pt : s.points) {
        EXPECT_FALSE(pt.p >= NarrowIslandInP::lower && pt.p <= NarrowIslandInP::upper) << "a grid point on the island: " << pt.p;
        EXPECT_EQ(pt.collapse, NarrowIslandInP::overturns(pt.p)) << "p = " << pt.p;
    }

    IdaOptions io;
    io.model = restitution_zero();
    const Ida ida = incremental_dynamic_analysis(NarrowIslandInQ::input(), NarrowIslandInQ::alpha, NarrowIslandInQ::p, io);
    EXPECT_TRUE(misses(ida.intervals, NarrowIslandInQ::lower, NarrowIslandInQ::upper)) << "today's IDA found the island in q";
    for (const IdaGridPoint& pt : ida.points) {
        EXPECT_FALSE(pt.q >= NarrowIslandInQ::lower && pt.q <= NarrowIslandInQ::upper) << "a grid point on the island: " << pt.q;
        EXPECT_EQ(pt.collapse, NarrowIslandInQ::overturns(pt.q)) << "q = " << pt.q;
    }
    // Its first collapse lies above the island: the first overturning is missed.
    if (ida.point.collapsed) {
        EXPECT_GT(ida.point.q, NarrowIslandInQ::upper);
    }
}

namespace {


// The scan's islands that no interval of a grid method touches.
template <class Interval>
int missed(const std::vector<ScanIsland>& truth, const std::vector<Interval>& found) {
    int n = 0;
    for (const ScanIsland& t : truth) n += misses(found, t.from, t.to);
    return n;
}

const char* const kNorcia = "/../shared/records/esm/IT.NRC..HGE.D.20161030.064018.C.ACC.ASC";

}  // namespace

TEST(OverturningTruth, TodaysIdaAndSpectrumMissIslandsOfTheDenseScan) {
    // Issue 39's example, IT.NRC HGE 2016-10-30, alpha 0.1 (Table 1's model):
    // the dense scans of expected/overturning_set (10^5 points by a second
    // implementation, each boundary bisected to 1e-10) hold islands on
    // q in [1.3190, 1.3215] (p 2.5) and p in [1.183, 1.186] that today's
    // default IDA and spectrum do not report: their first collapse lies above
    // the scan's first overturning.  Fails (rightly: update it) once the
    // default studies find them.  Skipped without the shared records.
    const std::string path = std::string(ROCKING_SOURCE_DIR) + kNorcia;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared records folder absent: " << path;
    const records::Record r = records::read_any(path);
    const dynamics::SampledInput input(r.in_g(9.81), r.dt, r.name);

    const std::vector<ScanIsland> in_q = scan_islands("ida_islands.csv");
    ASSERT_FALSE(in_q.empty());
    const Ida ida = incremental_dynamic_analysis(input, 0.1, 2.5, IdaOptions{});
    ASSERT_TRUE(ida.point.collapsed);
    EXPECT_GT(ida.point.q, in_q.front().from * (1 + 1e-6)) << "today's IDA finds the first overturning";
    EXPECT_GT(missed(in_q, ida.intervals), 0) << "today's IDA finds every island of the scan in q";

    const std::vector<ScanIsland> in_p = scan_islands("spectrum_islands.csv");
    ASSERT_FALSE(in_p.empty());
    const Spectrum s = rocking_spectrum(input, 0.1, SpectrumOptions{});
    ASSERT_FALSE(s.intervals.empty());
    EXPECT_GT(s.intervals.front().from, in_p.front().from * (1 + 1e-6)) << "today's spectrum finds the first overturning";
    EXPECT_GT(missed(in_p, s.intervals), 0) << "today's spectrum finds every island of the scan in p";
}
