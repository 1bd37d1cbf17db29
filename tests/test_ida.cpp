// The incremental dynamic analysis (studies/ida.hpp) against answers known
// without it: a single rectangular pulse, whose collapse q has a closed form;
// two pulses with restitution 0, whose overturning set in q is two intervals
// by a chain of closed forms (confirmed here by rk8pd too); a short pulse that
// a bound shows cannot overturn the block below q_max (a censored point); and
// the study's fit against fit_lognormal on the known points.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "records/collapse.hpp"
#include "studies/ida.hpp"
#include "studies/record_order.hpp"
#include "studies/scaled_input.hpp"
#include "studies/spectrum.hpp"
#include "two_pulses_truth.hpp"
#include "test_util.hpp"

using namespace rocking;
using namespace rocking::studies;
using dynamics::PulseInput;

namespace {

constexpr long double kHalfPi = 1.5707963267948966192313216916397514L;

// A single rectangular pulse of A g lasting d s overturns the linearised block
// iff p > ln(A / (A - alpha)) / d, whatever the restitution (test_spectrum.cpp
// derives it).  At fixed p, with A = q alpha, that is
//     q > q* = 1 / (1 - e^{-p d}).
long double single_pulse_q(long double p, long double d) { return 1 / -std::expm1(-p * d); }

PulseInput single_pulse(double d) { return PulseInput(PulseTrain({{1.0, 1.0}}), 0.15, d); }

// +A g for d0 then -A g for d1 on a block with restitution 0: two_pulses_truth.hpp
// with B = A0 = A.
struct TwoPulses {
    long double d0 = 0.5L, d1 = 1.4L, alpha = 0.1L, p = 2.0L;
    bool overturns(long double q) const { return q > 1 && rocking::testing::two_pulses_overturn(q * alpha, d0, q * alpha, d1, alpha, p); }
    PulseInput input() const { return PulseInput(PulseTrain({{1.0, 0.5}, {-1.0, 1.4}}), 0.3, 1.0); }
    static IdaOptions options() {
        IdaOptions o;
        o.model.housner_restitution = false;
        o.model.restitution = 0.0;
        return o;
    }
};

// The changes of outcome in q over [lo, hi] by the closed form: a dense scan,
// each change bisected in long double to 1e-15.
std::vector<long double> changes_of(const TwoPulses& t, long double lo, long double hi, int n) {
    std::vector<long double> out;
    long double prev_q = lo;
    bool prev = t.overturns(lo);
    for (int k = 1; k < n; ++k) {
        const long double q = lo * std::pow(hi / lo, static_cast<long double>(k) / (n - 1));
        const bool now = t.overturns(q);
        if (now != prev) {
            long double a = prev_q, b = q;
            while (b - a > 1e-15L * b) ((t.overturns((a + b) / 2) == prev) ? a : b) = (a + b) / 2;
            out.push_back((a + b) / 2);
        }
        prev = now;
        prev_q = q;
    }
    return out;
}

// The bracket holds the known boundary and is no wider than rel_tol.
void expect_bracket(const Bracket& b, long double known, double rel_tol, const char* what) {
    const long double lo = std::min(b.safe, b.collapse), hi = std::max(b.safe, b.collapse);
    EXPECT_LE(lo, known * (1 + 1e-12L)) << what;
    EXPECT_GE(hi, known * (1 - 1e-12L)) << what;
    EXPECT_LE(hi - lo, rel_tol * hi * (1 + 1e-12)) << what;
}

}  // namespace

TEST(Ida, ASinglePulseFirstOverturnsTheBlockAtItsClosedFormQ) {
    // q* = 1/(1 - e^{-1.6}) = 1.2524 at p = 2, d = 0.8: one interval from q*
    // to q_max, its bracket holding q* within 1e-6, and the IDA's point at
    // the bracket's collapsing end.  Fails with the bisection stopped at
    // 1e-5, the point taken at the safe end, or q scaled without alpha
    // (PGA/g for PGA/(alpha g)).
    const double alpha = 0.1, p = 2.0, d = 0.8;
    const long double known = single_pulse_q(p, d);
    const Ida ida = incremental_dynamic_analysis(single_pulse(d), alpha, p, IdaOptions{});
    ASSERT_EQ(ida.intervals.size(), 1u);
    const IdaInterval& in = ida.intervals[0];
    ASSERT_TRUE(in.has_lower);
    EXPECT_FALSE(in.has_upper);
    EXPECT_EQ(in.to, 20.0);
    expect_bracket(in.lower, known, 1e-6, "single pulse");
    EXPECT_TRUE(ida.point.collapsed);
    EXPECT_EQ(ida.point.q, in.lower.collapse);
    EXPECT_GE(ida.point.q, known * (1 - 1e-15L)) << "the first collapse q must be an overturning run";
    EXPECT_NEAR(ida.q_input, 1.5, 1e-15);
    // The grid: 100 + 99 points, each outcome the closed form's.
    ASSERT_EQ(ida.points.size(), 199u);
    for (const IdaGridPoint& pt : ida.points) EXPECT_EQ(pt.collapse, pt.q > known) << "q = " << pt.q;
}

TEST(Ida, ASinglePulseAtOtherBlocksToo) {
    // The same closed form over a few (p, d): q* from 1.03 to 8.2.
    for (const double p : {0.6, 1.5, 5.0})
        for (const double d : {0.2, 0.7}) {
            const long double known = single_pulse_q(p, d);
            const Ida ida = incremental_dynamic_analysis(single_pulse(d), 0.15, p, IdaOptions{});
            ASSERT_EQ(ida.intervals.size(), 1u) << "p = " << p << ", d = " << d;
            expect_bracket(ida.intervals[0].lower, known, 1e-6, "single pulse");
        }
}

TEST(Ida, EveryOverturningIntervalInQIsReported) {
    // +0.3 g for 0.5 s then -0.3 g for 1.4 s, restitution 0, alpha = 0.1,
    // p = 2: by the closed forms the block overturns for q in [1.0867, 2.8423]
    // and from 3.4892 up: a stronger input throws the block back on its
    // first corner before the second pulse can tip it, then tips it again.
    // Both intervals and all three boundaries must be where the closed forms
    // put them.  Fails when only the first interval is kept, when the point
    // is taken from the last interval, or with the bisection at 1e-5.
    const TwoPulses t;
    const std::vector<long double> known = changes_of(t, 1.0L, 20.0L, 200000);
    ASSERT_EQ(known.size(), 3u);
    ASSERT_NEAR(static_cast<double>(known[0]), 1.0867, 1e-3);
    ASSERT_NEAR(static_cast<double>(known[1]), 2.8423, 1e-3);
    ASSERT_NEAR(static_cast<double>(known[2]), 3.4892, 1e-3);

    const IdaOptions o = TwoPulses::options();
    const Ida ida = incremental_dynamic_analysis(t.input(), static_cast<double>(t.alpha), static_cast<double>(t.p), o);
    ASSERT_EQ(ida.intervals.size(), 2u);
    EXPECT_TRUE(ida.intervals[0].has_lower && ida.intervals[0].has_upper);
    EXPECT_TRUE(ida.intervals[1].has_lower);
    EXPECT_FALSE(ida.intervals[1].has_upper);
    expect_bracket(ida.intervals[0].lower, known[0], o.rel_tol, "first start");
    expect_bracket(ida.intervals[0].upper, known[1], o.rel_tol, "first end");
    expect_bracket(ida.intervals[1].lower, known[2], o.rel_tol, "second start");
    EXPECT_TRUE(ida.point.collapsed);
    EXPECT_EQ(ida.point.q, ida.intervals[0].from);
    for (const IdaGridPoint& pt : ida.points) EXPECT_EQ(pt.collapse, t.overturns(pt.q)) << "q = " << pt.q;
}

TEST(Ida, TheTwoIntervalsAreSeenByASecondSolver) {
    // The closed forms and the exact solver agree above; rk8pd at 1e-13
    // must see the same outcomes in the middle of each interval and of the
    // gap, so that the non-monotone case is not an artefact of one method.
    const TwoPulses t;
    const PulseInput input = t.input();
    records::CollapseOptions check = TwoPulses::options().model;
    check.solver = SpectrumOptions::rk8pd_check();
    const double alpha = static_cast<double>(t.alpha), p = static_cast<double>(t.p);
    for (const double q : {1.5, 3.15, 6.0, 1.05}) {
        const auto at_q = scaled(input, q * alpha / input.peak());
        EXPECT_EQ(records::collapses_at(*at_q, alpha, p, check), t.overturns(q)) << "q = " << q;
    }
}

TEST(Ida, EachBracketIsCheckedByTheProbeAndASecondSolver) {
    // The spectrum's checks (intervals.hpp) on the IDA's brackets: by default
    // the first collapse's only, the point a fragility fit takes; every one on
    // request.  The two-pulse case is well conditioned: every bracket is
    // confirmed by rk8pd, with 6 runs each (4 probes, 2 second-solver runs).
    // A probe of 1e-3 across a bracket 1e-6 wide flips an end: flagged
    // ill-conditioned, not confirmed (fails if the probe is skipped).
    const TwoPulses t;
    IdaOptions o = TwoPulses::options();
    const double alpha = static_cast<double>(t.alpha), p = static_cast<double>(t.p);
    const Ida first = incremental_dynamic_analysis(t.input(), alpha, p, o);
    ASSERT_EQ(first.intervals.size(), 2u);
    EXPECT_EQ(first.intervals[0].lower_check.confirmation, Confirmation::confirmed) << first.intervals[0].lower_check.detail;
    EXPECT_EQ(first.intervals[0].upper_check.confirmation, Confirmation::not_checked);
    EXPECT_EQ(first.intervals[1].lower_check.confirmation, Confirmation::not_checked);
    EXPECT_EQ(first.check_simulations, 2);

    o.checks = IdaOptions::Checks::every_bracket;
    const Ida every = incremental_dynamic_analysis(t.input(), alpha, p, o);
    for (const Checked& c : {every.intervals[0].lower_check, every.intervals[0].upper_check, every.intervals[1].lower_check})
        EXPECT_EQ(c.confirmation, Confirmation::confirmed) << c.detail;
    EXPECT_EQ(every.check_simulations, 6);

    o.checks = IdaOptions::Checks::none;
    EXPECT_EQ(incremental_dynamic_analysis(t.input(), alpha, p, o).check_simulations, 0);

    o.checks = IdaOptions::Checks::first_collapse;
    o.probe = 1e-3;
    const Ida coarse = incremental_dynamic_analysis(t.input(), alpha, p, o);
    EXPECT_EQ(coarse.intervals[0].lower_check.confirmation, Confirmation::ill_conditioned);
    EXPECT_NE(coarse.intervals[0].lower_check.detail.find("flips the outcome at q = "), std::string::npos)
        << coarse.intervals[0].lower_check.detail;
}

TEST(Ida, AShortPulseThatCannotOverturnTheBlockGivesACensoredPoint) {
    // A sampled triangle of 0.04 s (a record: the record kernel runs it).
    // The linearised equation is monotone in the forcing while the block
    // rocks on one corner, so the triangle does no more than a rectangle of
    // its peak and length, which overturns the block only above
    // q = 1/(1 - e^{-0.04}) = 25.5 at p = 1: no collapse up to q_max = 20,
    // a censored point there.  At p = 20 the same record overturns it (so
    // the test is not vacuous).  Fails with the censored point at q_min, or
    // flagged collapsed.
    const dynamics::SampledInput record({0, 0, 0.05, 0.1, 0.05, 0, 0}, 0.01, "triangle");
    ASSERT_GT(static_cast<double>(single_pulse_q(1.0L, 0.04L)), 20.0);
    const Ida ida = incremental_dynamic_analysis(record, 0.1, 1.0, IdaOptions{});
    EXPECT_TRUE(ida.intervals.empty());
    EXPECT_FALSE(ida.point.collapsed);
    EXPECT_EQ(ida.point.q, 20.0);
    const Ida stiff = incremental_dynamic_analysis(record, 0.1, 20.0, IdaOptions{});
    ASSERT_FALSE(stiff.intervals.empty());
    EXPECT_TRUE(stiff.point.collapsed);
}

TEST(Ida, TheStudyFitsEachBlocksPointsFromItsRecords) {
    // Single pulses of several lengths: each record's point is its closed
    // form q*, the shortest one censored (q* > 20), in the records' order,
    // and the fit, bootstrap and empirical curve are fit_lognormal's,
    // bootstrap's and empirical_curve's on those points, the first two in
    // the draw order of the inputs' digests.  Fails when the censored record
    // is dropped or counted as a collapse, or the records' order is lost.
    const std::vector<double> lengths = {0.3, 0.05, 0.6, 0.9, 1.2, 2.0};
    std::vector<PulseInput> pulses;
    for (const double d : lengths) pulses.push_back(single_pulse(d));
    std::vector<const dynamics::GroundInput*> inputs;
    for (const PulseInput& in : pulses) inputs.push_back(&in);
    FragilityStudyOptions o;
    o.resamples = 200;
    o.seed = 7;
    const double p = 1.0;
    const std::vector<BlockFragility> study = fragility_study(inputs, {{0.1, p}, {0.2, 0.03}}, o);
    ASSERT_EQ(study.size(), 2u);
    const BlockFragility& f = study[0];
    ASSERT_EQ(f.points.size(), lengths.size());
    for (std::size_t k = 0; k < lengths.size(); ++k) {
        const long double known = single_pulse_q(p, lengths[k]);
        if (known > 20) {
            EXPECT_FALSE(f.points[k].collapsed) << "d = " << lengths[k];
            EXPECT_EQ(f.points[k].q, 20.0);
        } else {
            EXPECT_TRUE(f.points[k].collapsed) << "d = " << lengths[k];
            EXPECT_NEAR(f.points[k].q / known, 1.0, 1.0001e-6) << "d = " << lengths[k];
        }
    }
    ASSERT_TRUE(f.fitted);
    // The fit and bootstrap take the records in the order of their inputs' digests.
    EXPECT_EQ(f.draw_order, draw_order(input_digests(inputs)));
    const std::vector<IdaPoint> drawn = in_draw_order(f.points, f.draw_order);
    const LognormalFragility fit = fit_lognormal(drawn);
    EXPECT_EQ(f.fit.median, fit.median);
    EXPECT_EQ(f.fit.beta, fit.beta);
    EXPECT_EQ(f.fit.censored, 1);
    ASSERT_TRUE(f.bootstrapped);
    EXPECT_EQ(f.interval.median.lo, bootstrap(drawn, 200, 7, 0.9).median.lo);
    EXPECT_EQ(f.empirical.size(), lengths.size() - 1);
    // At p = 0.03 only d = 2 s overturns the block below q = 20 (q* = 17.2;
    // d = 1.2 s needs 28.3): one collapse below six censored points at 20,
    // whose ln L has a maximum (docs/fragility.md): fitted, as fit_lognormal.
    const BlockFragility& stocky = study[1];
    int collapsed = 0;
    for (const IdaPoint& pt : stocky.points) collapsed += pt.collapsed;
    EXPECT_EQ(collapsed, 1);
    ASSERT_TRUE(stocky.fitted);
    EXPECT_EQ(stocky.fit.beta, fit_lognormal(in_draw_order(stocky.points, stocky.draw_order)).beta);
    EXPECT_GT(stocky.fit.median, 20);
    // Without a censored point above it, the one collapse has no fit and says why.
    std::vector<Ida> alone(1, stocky.idas[5]);
    ASSERT_TRUE(alone[0].point.collapsed);
    const BlockFragility single = block_fragility(stocky.block, alone, rocking::testing::listed_order(1), o);
    EXPECT_FALSE(single.fitted);
    EXPECT_NE(single.no_fit.find("no spread to fit"), std::string::npos) << single.no_fit;
}

TEST(Ida, TheStudyIsTheSameOnAnyNumberOfThreads) {
    // The batch engine hands the IDAs and fits back in order: every point,
    // interval end, check and fit equal to the one-thread study's, bit for bit.
    const std::vector<double> lengths = {0.3, 0.05, 0.6, 0.9, 1.2, 2.0, 0.45};
    std::vector<PulseInput> pulses;
    for (const double d : lengths) pulses.push_back(single_pulse(d));
    std::vector<const dynamics::GroundInput*> inputs;
    for (const PulseInput& in : pulses) inputs.push_back(&in);
    FragilityStudyOptions o;
    o.resamples = 100;
    o.seed = 11;
    const std::vector<BlockShape> blocks = {{0.1, 1.0}, {0.2, 0.03}, {0.15, 2.5}, {0.05, 4.0}};
    const std::vector<BlockFragility> one = fragility_study(inputs, blocks, o);
    for (int threads : {2, 3, 8}) {
        o.threads = threads;
        const std::vector<BlockFragility> many = fragility_study(inputs, blocks, o);
        ASSERT_EQ(many.size(), one.size());
        for (std::size_t b = 0; b < one.size(); ++b) {
            EXPECT_EQ(many[b].block.p, one[b].block.p);
            ASSERT_EQ(many[b].idas.size(), inputs.size());
            for (std::size_t r = 0; r < inputs.size(); ++r) {
                EXPECT_EQ(many[b].points[r].q, one[b].points[r].q) << threads << " threads, block " << b << ", record " << r;
                EXPECT_EQ(many[b].points[r].collapsed, one[b].points[r].collapsed);
                ASSERT_EQ(many[b].idas[r].intervals.size(), one[b].idas[r].intervals.size());
                for (std::size_t k = 0; k < one[b].idas[r].intervals.size(); ++k) {
                    EXPECT_EQ(many[b].idas[r].intervals[k].from, one[b].idas[r].intervals[k].from);
                    EXPECT_EQ(many[b].idas[r].intervals[k].to, one[b].idas[r].intervals[k].to);
                    EXPECT_EQ(many[b].idas[r].intervals[k].lower_check.confirmation,
                              one[b].idas[r].intervals[k].lower_check.confirmation);
                }
            }
            EXPECT_EQ(many[b].fitted, one[b].fitted);
            EXPECT_EQ(many[b].fit.median, one[b].fit.median);
            EXPECT_EQ(many[b].fit.beta, one[b].fit.beta);
            EXPECT_EQ(many[b].interval.median.lo, one[b].interval.median.lo);
            EXPECT_EQ(many[b].interval.beta.hi, one[b].interval.beta.hi);
        }
    }
}

TEST(Ida, RefusesWhatItCannotScale) {
    const PulseInput pulse = single_pulse(0.5);
    EXPECT_THROW(incremental_dynamic_analysis(pulse, 0.1, 0.0, IdaOptions{}), std::invalid_argument);
    EXPECT_THROW(incremental_dynamic_analysis(pulse, 1.5, 1.0, IdaOptions{}), std::invalid_argument);
    const dynamics::SampledInput silent({0, 0, 0}, 0.01, "silent");
    EXPECT_THROW(incremental_dynamic_analysis(silent, 0.1, 1.0, IdaOptions{}), std::invalid_argument);
    IdaOptions o;
    o.q_max = o.q_min;
    EXPECT_THROW(incremental_dynamic_analysis(pulse, 0.1, 1.0, o), std::invalid_argument);
}
