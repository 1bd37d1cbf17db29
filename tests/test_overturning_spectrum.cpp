// The refine method of the spectrum (issue 39: studies/overturning_set.hpp
// over ln p, SpectrumOptions::method = refine; the slopes dXi_j / d ln p by a
// second run at p (1 + 1e-9), docs/overturning_set.md section 5) against sets
// known without it: the two-pulse island 5.06e-5 wide in ln p of
// tests/narrow_islands_truth.hpp (closed form), which the grid misses; and
// the islands of the Norcia example on p in [1.183, 1.186] of
// expected/overturning_set/spectrum_islands.csv (an independent dense scan).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "narrow_islands_truth.hpp"
#include "records/collapse.hpp"
#include "records/record.hpp"
#include "studies/spectrum.hpp"
#include "overturning_truths.hpp"
#include "test_util.hpp"

using namespace rocking;
using namespace rocking::studies;
using rocking::testing::restitution_zero;
using rocking::testing::scan_islands;
using rocking::testing::ScanIsland;
using rocking::testing::NarrowIslandInP;

namespace {

SpectrumOptions refine(double width) {
    SpectrumOptions o;
    o.method = SpectrumOptions::Method::refine;
    o.width = width;
    return o;
}


bool meets(double a, double b, double c, double d) { return a <= d && c <= b; }


}  // namespace

TEST(OverturningSpectrum, TheGridIsTheDefaultAndReportsItsFirsts) {
    // The default is the grid, unchanged; both methods report the first
    // overturning and the first robust collapse.
    const SpectrumOptions o;
    EXPECT_EQ(o.method, SpectrumOptions::Method::grid);
    EXPECT_EQ(o.width, 1e-5);
    SpectrumOptions m;
    m.model = restitution_zero();
    const Spectrum s = rocking_spectrum(NarrowIslandInP::input(), NarrowIslandInP::alpha, m);
    EXPECT_FALSE(s.refined);
    ASSERT_FALSE(s.intervals.empty());
    EXPECT_TRUE(s.first_overturning.found);
    EXPECT_EQ(s.first_overturning.p, s.intervals.front().from);
    EXPECT_TRUE(s.first_robust_collapse.found);
    EXPECT_GE(s.first_robust_collapse.p, s.first_overturning.p);
    for (const double bad : {0.0, -1e-5, 0.2}) {
        SpectrumOptions b = refine(bad);
        EXPECT_THROW(rocking_spectrum(NarrowIslandInP::input(), NarrowIslandInP::alpha, b), std::invalid_argument) << bad;
    }
    SpectrumOptions b = refine(1e-5);
    b.slope_step = 1e-3;
    EXPECT_THROW(rocking_spectrum(NarrowIslandInP::input(), NarrowIslandInP::alpha, b), std::invalid_argument);
}

TEST(OverturningSpectrum, TheNarrowIslandInPIsBracketedWhereTheGridMissesIt) {
    // The island [0.91338608, 0.91343230] (5.06e-5 in ln p, 230 times
    // narrower than the default grid's half step): the grid starts its set
    // at 1.1295; the refine method at w = 1e-5 must bracket both its ends to
    // 1e-6 around the closed form's, report it as the first overturning and
    // the grid's first interval as the first robust collapse.  A pulse train
    // is not a record: no margins, every interval split to w.
    using P = NarrowIslandInP;
    const double lower = static_cast<double>(P::lower), upper = static_cast<double>(P::upper);
    SpectrumOptions g;
    g.model = restitution_zero();
    const Spectrum grid = rocking_spectrum(P::input(), P::alpha, g);
    for (const Interval& in : grid.intervals) EXPECT_FALSE(meets(lower, upper, in.from, in.to)) << "the grid found it";
    ASSERT_TRUE(grid.first_overturning.found);
    ASSERT_GT(grid.first_overturning.p, 1.1);

    SpectrumOptions o = refine(1e-5);
    o.model = restitution_zero();
    o.p_min = 0.85;
    o.p_max = 1.2;
    o.points = 20;
    const Spectrum s = rocking_spectrum(P::input(), P::alpha, o);
    EXPECT_TRUE(s.refined);
    EXPECT_FALSE(s.with_margins);
    ASSERT_GE(s.intervals.size(), 2u);
    const Interval& island = s.intervals[0];
    ASSERT_TRUE(island.has_lower && island.has_upper);
    for (const Boundary* b : {&island.lower, &island.upper}) {
        EXPECT_LE(std::fabs(b->p_collapse - b->p_safe), 1e-6 * b->p_collapse);
        EXPECT_EQ(b->confirmation, Confirmation::confirmed) << b->detail;
    }
    EXPECT_NEAR(island.lower.p_collapse, lower, 1e-6 * lower);
    EXPECT_NEAR(island.upper.p_collapse, upper, 1e-6 * upper);
    EXPECT_LT(island.lower.p_safe, lower);
    EXPECT_GT(island.upper.p_safe, upper);
    EXPECT_TRUE(s.first_overturning.found);
    EXPECT_EQ(s.first_overturning.p, island.lower.p_collapse);
    // Stopped at the first sample that overturns: the same first overturning,
    // the same boundary, for fewer samples, and nothing claimed above it.
    SpectrumOptions first = o;
    first.first_only = true;
    const Spectrum f = rocking_spectrum(P::input(), P::alpha, first);
    ASSERT_TRUE(f.first_overturning.found);
    EXPECT_EQ(f.first_overturning.p, s.first_overturning.p);
    ASSERT_EQ(f.intervals.size(), 1u);
    EXPECT_EQ(f.intervals[0].lower.p_safe, island.lower.p_safe);
    EXPECT_EQ(f.intervals[0].lower.confirmation, Confirmation::confirmed);
    EXPECT_LT(f.samples, s.samples);
    EXPECT_TRUE(f.bands.empty());
    EXPECT_FALSE(f.first_robust_collapse.found);
    EXPECT_LE(f.points.back().p, f.intervals[0].to);
    ASSERT_TRUE(s.first_robust_collapse.found);
    EXPECT_NEAR(s.first_robust_collapse.p, grid.first_robust_collapse.p, 1e-6 * grid.first_robust_collapse.p);
    // Every other interval is the chain's: overturning at its middle.
    for (const Interval& in : s.intervals)
        EXPECT_TRUE(P::overturns(std::sqrt(static_cast<long double>(in.from) * in.to))) << in.from << " " << in.to;
    std::printf("narrow island in p on [%.2f, %.2f], w 1e-5: %zu intervals, %ld samples, %ld runs; island [%.10g, "
                "%.10g] (closed form [%.10g, %.10g])\n",
                o.p_min, o.p_max, s.intervals.size(), s.samples, s.simulations, island.lower.p_collapse,
                island.upper.p_collapse, lower, upper);
}

TEST(OverturningSpectrum, EveryIslandOfNorciaWiderThanWIsFoundAndNoneInvented) {
    // The example (IT.NRC HGE 2016-10-30, unscaled, alpha 0.1,
    // Table 1's model) on p in [1.183, 1.186]: the dense scan's 18 islands
    // (10^5 points, 2.5e-8 apart in ln p, by a second implementation).  The
    // refine method from a coarse grid of 3 points (the margins, not the
    // grid, do the work) at w = 1e-5 and 1e-6: every island of the scan wider than w
    // in ln p must meet one of its intervals, and each of its intervals must
    // meet an island of the scan (or be narrower than two of its steps).
    // Measured: 5 islands wider than 1e-5, 8 wider than 1e-6.
    const std::string path = rocking::testing::shared_record("esm/IT.NRC..HGE.D.20161030.064018.C.ACC.ASC");
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared records folder absent: " << path;
    const records::Record r = records::read_any(path);
    const dynamics::SampledInput input(r.in_g(9.81), r.dt, r.name);
    const std::vector<ScanIsland> truth = scan_islands("spectrum_islands.csv");
    ASSERT_EQ(truth.size(), 18u);
    const double lo = 1.183, hi = 1.186, step = std::log(hi / lo) / (100000 - 1);
    for (const double w : {1e-5, 1e-6}) {
        int wide = 0;
        for (const ScanIsland& t : truth) wide += std::log(t.to / t.from) > w;
        ASSERT_GE(wide, w > 2e-6 ? 4 : 8);
        SpectrumOptions o = refine(w);
        o.p_min = lo;
        o.p_max = hi;
        o.points = 3;
        const Spectrum s = rocking_spectrum(input, 0.1, o);
        EXPECT_TRUE(s.with_margins);
        EXPECT_GT(s.accepted, 0);
        for (const ScanIsland& t : truth) {
            if (!(std::log(t.to / t.from) > w)) continue;
            bool found = false;
            for (const Interval& in : s.intervals) found = found || meets(t.from, t.to, in.from, in.to);
            EXPECT_TRUE(found) << "the island [" << t.from << ", " << t.to << "] (" << std::log(t.to / t.from)
                               << " in ln p) is missed";
        }
        int unchecked = 0;
        for (const Interval& in : s.intervals) {
            bool real = std::log(in.to / in.from) < 2 * step;
            for (const ScanIsland& t : truth) real = real || meets(t.from, t.to, in.from * (1 - 1e-6), in.to * (1 + 1e-6));
            EXPECT_TRUE(real) << "[" << in.from << ", " << in.to << "] is no island of the scan";
            for (const Boundary* b : {&in.lower, &in.upper})
                if ((b == &in.lower ? in.has_lower : in.has_upper) && b->confirmation != Confirmation::confirmed) ++unchecked;
        }
        EXPECT_EQ(unchecked, 0) << "boundaries not confirmed by the probe and the second solver";
        // The first overturning: on the scan's first island wider than w or below it.
        ASSERT_TRUE(s.first_overturning.found);
        double first_wide = hi;
        for (const ScanIsland& t : truth)
            if (std::log(t.to / t.from) > w) {
                first_wide = t.to;
                break;
            }
        EXPECT_GE(s.first_overturning.p, truth.front().from * (1 - 1e-6));
        EXPECT_LE(s.first_overturning.p, first_wide);
        // Each band's overturned share against the scan's: they may differ by
        // the islands narrower than w (missed) and the bisection's 1e-6 at
        // each boundary, no more.
        ASSERT_EQ(s.bands.size(), 2u);
        for (const studies::Band& b : s.bands) {
            double covered = 0, narrow = 0;
            for (const ScanIsland& t : truth) {
                const double a = std::max(b.from, t.from), z = std::min(b.to, t.to);
                if (z > a) covered += std::log(z / a);
                if (z > a && !(std::log(t.to / t.from) > w)) narrow += std::log(z / a);
            }
            const double span = std::log(b.to / b.from);
            EXPECT_NEAR(b.share, covered / span, (narrow + 2e-6 * truth.size() + 2 * step) / span)
                << "band [" << b.from << ", " << b.to << "]";
        }
        std::printf("Norcia p in [%.3f, %.3f], w %g: scan %zu islands (%d wider than w); refine %zu intervals, %ld samples, "
                    "%ld runs, %ld accepted, %ld at w, first overturning %.9g (scan %.9g), first robust %s %.9g\n",
                    lo, hi, w, truth.size(), wide, s.intervals.size(), s.samples, s.simulations, s.accepted, s.at_width,
                    s.first_overturning.p, truth.front().from, s.first_robust_collapse.found ? "" : "(none, p_max)",
                    s.first_robust_collapse.p);
    }
}

TEST(OverturningSpectrum, TheSlopesInLnPAreTheMarginsDerivatives) {
    // Each sample's dXi_j / d ln p (a second run at p (1 + 1e-9)) against the
    // central difference of the margins themselves at p e^{+-h}, h = 1e-6, on
    // a record of two sines (0.3 g at 0.7 s, 0.2 g at 0.31 s, 6 s, dt 0.01 s),
    // alpha 0.1, where every flight is matched in all three runs.  Dropping
    // the slopes (0) or mis-scaling them fails here; the Norcia tests above do
    // not see it (docs/overturning_set.md, section 5).
    std::vector<double> a(601);
    for (std::size_t k = 0; k < a.size(); ++k) {
        const double t = 0.01 * static_cast<double>(k);
        a[k] = 0.3 * std::sin(2 * M_PI * t / 0.7) + 0.2 * std::sin(2 * M_PI * t / 0.31);
    }
    const dynamics::SampledInput record(a, 0.01, "two sines");
    SpectrumOptions o;
    o.method = SpectrumOptions::Method::refine;
    const double h = 1e-6;
    int compared = 0, steep = 0;
    for (const double p : {1.2, 1.5, 1.8, 2.0, 2.4, 2.7, 3.2, 3.6, 4.3, 5.0, 6.1, 7.5}) {
        const MarginSample s = margins_in_p(record, 0.1, p, o);
        const MarginSample up = margins_in_p(record, 0.1, p * std::exp(h), o);
        const MarginSample down = margins_in_p(record, 0.1, p * std::exp(-h), o);
        if (!s.has_margins || up.xi.size() != s.xi.size() || down.xi.size() != s.xi.size()) continue;
        for (std::size_t j = 0; j < s.xi.size(); ++j) {
            const double central = (up.xi[j] - down.xi[j]) / (2 * h);
            EXPECT_NEAR(s.slope[j], central, 1e-4 * std::fabs(central) + 1e-6) << "p " << p << " flight " << j;
            ++compared;
            steep += std::fabs(central) > 1e-2;
        }
    }
    EXPECT_GE(compared, 20);
    EXPECT_GE(steep, 10) << "too few flights whose margin moves with p to tell a slope from none";
    // Not a record kernel's model: refused, not a silent outcome without margins.
    SpectrumOptions rk = o;
    rk.model.solver = SpectrumOptions::rk8pd_check();
    EXPECT_THROW(margins_in_p(record, 0.1, 2.0, rk), std::invalid_argument);
}
