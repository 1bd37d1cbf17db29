// The dynamics engine against independent truth: the superposition engine,
// closed-form free rocking, invariants, convergence, and the extremes.
#include <gtest/gtest.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "dynamics/simulate.hpp"
#include "qfactor/closed_forms.hpp"
#include "qfactor/superposition.hpp"
#include "full_equation_truth.hpp"
#include "test_util.hpp"

using namespace rocking;
using namespace rocking::dynamics;

namespace {

Model linear_model(double alpha = 0.1, double p = 2.0, double e = 1.0) {
    Model m;
    m.block = Block::from_p(p, alpha);
    m.restitution = e;
    return m;
}

SimulationOptions with(SolverKind kind, double rtol = 1e-10) {
    SimulationOptions o;
    o.solver.kind = kind;
    o.solver.rtol = rtol;
    o.solver.atol_alpha = rtol;
    return o;
}

// A solver to run: each kind by its name, and the exact one once more by its
// general path (ExactStepper + the driver: the record kernel switched off).
struct SolverPath {
    SolverKind kind;
    bool kernel;
    std::string name;
    SimulationOptions options(double rtol) const {
        SimulationOptions o = with(kind, rtol);
        o.solver.record_kernel = kernel;
        return o;
    }
};

std::vector<SolverPath> with_general_path(std::initializer_list<SolverKind> kinds) {
    std::vector<SolverPath> paths;
    for (SolverKind k : kinds) {
        paths.push_back({k, true, solver_name(k)});
        if (k == SolverKind::exact) paths.push_back({k, false, solver_name(k) + " (general path)"});
    }
    return paths;
}

const SolverKind kOde[] = {SolverKind::dopri5, SolverKind::rkf78, SolverKind::bulirsch_stoer, SolverKind::gsl_rk8pd};

// Whether two runs agree to tol (in alpha): outcome, peak and theta(t_fin).
bool runs_agree(const SimulationResult& x, const SimulationResult& y, double alpha, double tol) {
    return x.overturned == y.overturned && x.overturned_during_input == y.overturned_during_input &&
           std::fabs(x.theta_at_tfin - y.theta_at_tfin) <= tol * alpha &&
           std::fabs(x.max_abs_theta_input - y.max_abs_theta_input) <= tol * alpha;
}

// Whether a run is well conditioned: its probe (the same input scaled by
// 1 + 1e-13) gives the same answers to 1e-9 alpha and every impact within 1e-9 s.
bool well_conditioned(const SimulationResult& ref, const SimulationResult& probe, double alpha) {
    if (!runs_agree(ref, probe, alpha, 1e-9) || ref.impacts != probe.impacts ||
        ref.impact_times.size() != probe.impact_times.size())
        return false;
    for (std::size_t i = 0; i < ref.impact_times.size(); ++i)
        if (std::fabs(ref.impact_times[i] - probe.impact_times[i]) > 1e-9) return false;
    return true;
}

// The draws of the random solver comparisons below, from the raw
// mt19937_64 stream (the same on every platform).  block(): alpha
// 0.02-0.32, p 0.5-5.5 rad/s, Housner's restitution on even cases and one
// in [0.5, 1] on odd ones.  sine_just_above(): a one-sine pulse with
// a_p / threshold - 1 in (1e-6, 0.05] and w_p / p in [0.1, 20.1], its probe
// (a_p scaled by 1 + 1e-13) and its description.
struct RandomDraws {
    std::mt19937_64 rng;
    explicit RandomDraws(std::uint64_t seed) : rng(seed) {}
    double operator()() { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
    Model block(int it, Equation equation) {
        const double alpha = 0.02 + 0.3 * (*this)(), p = 0.5 + 5 * (*this)();
        Model m = linear_model(alpha, p, it % 2 == 0 ? housner_restitution(alpha) : 0.5 + 0.5 * (*this)());
        m.equation = equation;
        return m;
    }
    struct Sine {
        OneSinePulse input, nudged;
        std::string what;
    };
    Sine sine_just_above(int it, const Model& m) {
        const double threshold = m.uplift_threshold(), p = m.block.p;
        const double ap = threshold * (1 + 1e-6 + 0.05 * (*this)()), wp = p * (0.1 + 20 * (*this)());
        return {OneSinePulse(ap, wp, threshold), OneSinePulse(ap * (1 + 1e-13), wp, threshold),
                "case " + std::to_string(it) + ", alpha " + std::to_string(m.block.alpha) + ", p " +
                    std::to_string(p) + ", a_p/threshold " + std::to_string(ap / threshold) + ", w_p/p " +
                    std::to_string(wp / p)};
    }
};

// A run against the reference, for a failure's message.
std::string against(const SimulationResult& r, const SimulationResult& ref, double alpha) {
    std::ostringstream os;
    os << "peak " << r.max_abs_theta_input / alpha << " alpha against " << ref.max_abs_theta_input / alpha
       << ", theta(t_fin) " << r.theta_at_tfin / alpha << " against " << ref.theta_at_tfin / alpha << ", overturned "
       << r.overturned << " against " << ref.overturned << ", impacts " << r.impacts << " against " << ref.impacts;
    return os.str();
}

// A well-conditioned run of the record kernel against the same input under
// the general exact path (record_kernel off), which must agree to 1e-9 alpha
// and on every impact, and under ODE solvers, each to its tolerance
// (runs_agree).
void expect_agreement(const SimulationResult& ref, const Model& m, const GroundInput& input, const std::string& what,
                      std::initializer_list<std::pair<SimulationOptions, double>> odes) {
    const double alpha = m.block.alpha;
    SimulationOptions general = with(SolverKind::exact);
    general.solver.record_kernel = false;
    const SimulationResult g = simulate(m, input, general);
    EXPECT_TRUE(runs_agree(ref, g, alpha, 1e-9) && g.impacts == ref.impacts)
        << what << ", exact (general path): " << against(g, ref, alpha);
    for (const auto& [o, tol] : odes) {
        const SimulationResult r = simulate(m, input, o);
        EXPECT_TRUE(runs_agree(ref, r, alpha, tol)) << what << ", " << solver_name(o.solver.kind) << ": "
                                                    << against(r, ref, alpha);
    }
}

// The comparison under one-sine pulses just above the uplift threshold: the
// first 1000 draws of seed (RandomDraws: a block of the equation, a pulse and
// its probe), each kept where the reference run is well conditioned, and
// there rkf78, rk8pd and Bulirsch-Stoer, run with compared(k), must agree with
// the reference to tol alpha and on the number of impacts.  Returns how many
// draws were kept.
int sines_just_above_agree(std::uint64_t seed, Equation equation, const SimulationOptions& reference,
                           const std::function<SimulationOptions(SolverKind)>& compared, double tol) {
    RandomDraws draw(seed);
    int well = 0;
    for (int it = 0; it < 1000; ++it) {
        const Model m = draw.block(it, equation);
        const double alpha = m.block.alpha;
        const auto [input, nudged, what] = draw.sine_just_above(it, m);
        const SimulationResult ref = simulate(m, input, reference);
        if (!well_conditioned(ref, simulate(m, nudged, reference), alpha)) continue;
        ++well;
        for (SolverKind k : {SolverKind::rkf78, SolverKind::gsl_rk8pd, SolverKind::bulirsch_stoer}) {
            const SimulationResult r = simulate(m, input, compared(k));
            EXPECT_TRUE(runs_agree(ref, r, alpha, tol) && r.impacts == ref.impacts)
                << what << ", " << solver_name(k) << ": " << against(r, ref, alpha);
        }
    }
    return well;
}

// The first u after lo where f, positive from lo, stops being positive: bracketed
// by steps of 1 % of u (f's arcs here are single excursions, slower than that),
// then bisected, in long double; until when no bracket ends before until.
template <class F>
long double first_fall(F f, long double lo, long double until) {
    long double hi = lo;
    while (f(hi) > 0 && hi < until) lo = hi, hi *= 1.01L;
    if (hi >= until) return until;
    for (int i = 0; i < 200; ++i) {
        const long double mid = (lo + hi) / 2;
        (f(mid) > 0 ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// A deterministic broadband "record": a sum of decaying sines, sampled at dt.
SampledInput synthetic_record(double dt, double seconds, double scale) {
    std::vector<double> a;
    for (double t = 0; t <= seconds; t += dt)
        a.push_back(scale * std::exp(-0.15 * t) *
                    (std::sin(7.1 * t) + 0.6 * std::sin(13.7 * t + 1.0) + 0.4 * std::sin(3.3 * t + 2.0)));
    return SampledInput(a, dt, "synthetic");
}

// (S1) in long double for a pulse input of peak pga (in g) on a block alpha, p.
rocking::testing::S1Sum s1_long_double(const PulseTrain& train, double pga, double to, double alpha, double p,
                                       double t) {
    return rocking::testing::s1_sum(
        train,
        [&](std::size_t k) { return static_cast<long double>(pga * train.pulses()[k].amplitude) / alpha - 1; }, to,
        p, t);
}

}  // namespace

TEST(Dynamics, ExactSolverMatchesTheSuperpositionEngineAtEveryPulseEnd) {
    // Without impacts before t_fin, the linearised response is (S1).
    for (int c = 1; c <= 5; ++c)
        for (double x : {0.1, 0.3, 0.8, 1.5})
            for (double rd : {1.0, 0.95, 0.8}) {
                const PulseTrain train = pulse_case(c);
                const double q = q_case(c, x) * rd, alpha = 0.1, p = 2.0, to = x / p;
                if (q * train.pulses().front().amplitude <= 1.0) continue;
                const Excursion e = excursion(train, x, q);
                if (!e.stays_positive()) continue;
                const PulseInput input(train, q * alpha, to);
                SimulationOptions o = with(SolverKind::exact);
                o.record_dt = to / 8;  // pulse ends fall on the record grid
                o.free_rocking = false;
                const SimulationResult r = simulate(linear_model(alpha, p), input, o);
                ASSERT_EQ(r.impacts, 0);
                for (const Sample& s : r.samples) {
                    const double tau = s.t / to;
                    const double expected = response(train, x, q, tau).phi;
                    EXPECT_NEAR(s.theta / alpha, expected, 1e-12 * std::fmax(1.0, std::fabs(expected)))
                        << "case " << c << " x " << x << " Rd " << rd << " tau " << tau;
                }
                EXPECT_NEAR(r.theta_at_tfin / alpha, rd == 1.0 ? 1.0 : response(train, x, q, train.t_fin()).phi, 1e-12);
            }
}

TEST(Dynamics, ExactSolverIsExactToTheSumsConditionFromXOf1e4To10) {
    // The extremes of x = p to: a short strong pulse (x = 1e-4, q ~ 1e8) and a
    // long weak one (x = 10), every case, at and below the collapse PGA.
    // Against (S1) in long double, the exact solver (theta(t) on a grid of
    // to/8 and theta(t_fin)) is within 4 eps of the sum's condition: 1e-15
    // alpha where it is O(1) (x <= 1), up to 1e-7 alpha at x = 10 for case 4
    // (condition 7e8: the instability's e^{2x}, which no method escapes).
    // Measured: at most 2 eps times the condition (0.9 at t_fin).  (The closed form
    // evaluated as C cosh pu + D sinh pu - lin rounds at eps q alpha instead:
    // 4e-8 alpha at x = 1e-4, 7 orders of magnitude above this bound.)
    const double alpha = 0.1, p = 2.0, eps = std::numeric_limits<double>::epsilon();
    int checked = 0;
    for (int c = 1; c <= 5; ++c)
        for (double x : {1e-4, 1e-3, 1e-2, 0.1, 1.0, 3.0, 10.0})
            for (double rd : {1.0, 0.9}) {
                const PulseTrain train = pulse_case(c);
                const double pga = q_case(c, x) * rd * alpha, to = x / p;
                if (pga * train.pulses().front().amplitude <= alpha) continue;  // (S1) needs rocking from t = 0
                const PulseInput input(train, pga, to);
                SimulationOptions o = with(SolverKind::exact);
                o.record_dt = to / 8;
                o.free_rocking = false;
                const SimulationResult r = simulate(linear_model(alpha, p), input, o);
                if (r.impacts > 0) continue;  // (S1) holds up to the first impact
                const std::string what = "case " + std::to_string(c) + " x " + std::to_string(x) + " Rd " +
                                         std::to_string(rd);
                for (const Sample& smp : r.samples) {
                    const rocking::testing::S1Sum truth = s1_long_double(train, pga, to, alpha, p, smp.t);
                    EXPECT_NEAR(smp.theta / alpha, static_cast<double>(truth.phi),
                                4 * eps * std::fmax(1.0, static_cast<double>(truth.condition)))
                        << what << " t/to " << smp.t / to;
                }
                const rocking::testing::S1Sum fin = s1_long_double(train, pga, to, alpha, p, input.t_end());
                EXPECT_NEAR(r.theta_at_tfin / alpha, static_cast<double>(fin.phi),
                            4 * eps * std::fmax(1.0, static_cast<double>(fin.condition)))
                    << what;
                ++checked;
            }
    EXPECT_GE(checked, 50);
}

TEST(Dynamics, EachOdeSolverConvergesToTheExactOne) {
    // Case 4 below collapse, with an impact during the free rocking.
    const double x = 0.6, alpha = 0.1, p = 2.0;
    const PulseInput input(pulse_case(4), q4(x) * 0.9 * alpha, x / p);
    const SimulationResult exact = simulate(linear_model(alpha, p), input, with(SolverKind::exact));
    for (SolverKind k : kOde) {
        double previous = INFINITY;
        for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
            const SimulationResult r = simulate(linear_model(alpha, p), input, with(k, tol));
            const double error = std::fabs(r.theta_at_tfin - exact.theta_at_tfin) / alpha;
            EXPECT_LT(error, 200 * tol) << solver_name(k) << " tol " << tol;
            EXPECT_LT(error, previous * 1.01 + 1e-13) << solver_name(k) << " tol " << tol;
            previous = error;
        }
    }
}

TEST(Dynamics, EachOdeSolverMeetsItsToleranceOnARecord) {
    // A record's acceleration is piecewise linear, with a kink at every
    // sample; here a zigzag of +-0.05 g on 0.13 g + 0.05 g sin 20t, dt =
    // 0.01 s, 1.5 s: its slope flips between about +10 and -10 g/s at every
    // sample.  The block (alpha 0.1, p 2) rocks on one corner all along, no
    // impact, to theta(t_fin) = 3.2 alpha; the exact solver (closed form on
    // every piece) is the truth.  Local errors within tol grow at most by
    // cosh(p t_fin) = 10 on the way: 10 tol.  Fehlberg 7(8), Bulirsch-Stoer
    // and rk8pd end their steps on the kinks (ode_steppers.cpp), and are
    // within 1e-2 tol (measured).  When they stepped across them, rkf78 was
    // off by up to 2e7 tol, Bulirsch-Stoer 1.5e6 tol, rk8pd 8e2 tol.
    // Dormand-Prince steps across them as ode45 does: it converges, but its
    // error is not proportional to tol (measured 1.6e3 tol at 1e-6, 4.6e3 tol
    // at 1e-8, 4.4e3 tol at 1e-10): 1e4 tol.
    const double dt = 0.01, alpha = 0.1, p = 2.0;
    std::vector<double> a;
    for (int k = 0; k * dt <= 1.5 + 1e-9; ++k)
        a.push_back(0.13 + 0.05 * std::sin(20 * k * dt) + (k % 2 ? 0.05 : -0.05));
    const SampledInput zigzag(a, dt, "zigzag");
    const SimulationResult exact = simulate(linear_model(alpha, p, 0.9), zigzag, with(SolverKind::exact));
    ASSERT_EQ(exact.impacts, 0);
    ASSERT_NEAR(exact.theta_at_tfin / alpha, 3.2, 0.1);
    for (SolverKind k : kOde)
        for (double tol : {1e-6, 1e-8, 1e-10}) {
            const SimulationResult r = simulate(linear_model(alpha, p, 0.9), zigzag, with(k, tol));
            const double bound = (k == SolverKind::dopri5 ? 1e4 : 10) * tol;
            EXPECT_LT(std::fabs(r.theta_at_tfin - exact.theta_at_tfin) / alpha, bound) << solver_name(k) << " tol " << tol;
        }
}

TEST(Dynamics, FullEquationOnARecordFourSolversAgree) {
    // The full equation has no closed form; on a record the independent
    // truth is agreement between methods.  A block (alpha 0.15, p 2.5,
    // restitution 0.9) rocks through 144 impacts under a synthetic record
    // (dt 0.01 s, 20 s).  At rtol 1e-12: Fehlberg 7(8) (Odeint) and rk8pd
    // (GSL), both stepping sample to sample, agree on every impact time within
    // 1e-10 s (measured 2.7e-12 s) and on the peak within 1e-12 alpha
    // (measured 3.6e-14); Bulirsch-Stoer within 1e-8 s and 1e-10 alpha
    // (measured 1.0e-10 s, 1.4e-12); Dormand-Prince, stepping across the
    // samples as ode45, within 1e-4 s and 1e-6 alpha (measured 2.6e-6 s,
    // 3.5e-8).  When Fehlberg stepped across the samples too, it was 7e-4 s
    // from rk8pd.
    const double alpha = 0.15;
    Model m = linear_model(alpha, 2.5, 0.9);
    m.equation = Equation::full;
    const SampledInput rec = synthetic_record(0.01, 20.0, 0.11);
    const SimulationResult f = simulate(m, rec, with(SolverKind::rkf78, 1e-12));
    ASSERT_GT(f.impacts, 100);
    ASSERT_FALSE(f.overturned);
    const struct {
        SolverKind kind;
        double seconds, peak_alpha;
    } others[] = {{SolverKind::gsl_rk8pd, 1e-10, 1e-12},
                  {SolverKind::bulirsch_stoer, 1e-8, 1e-10},
                  {SolverKind::dopri5, 1e-4, 1e-6}};
    for (const auto& o : others) {
        const SimulationResult r = simulate(m, rec, with(o.kind, 1e-12));
        ASSERT_EQ(r.impact_times.size(), f.impact_times.size()) << solver_name(o.kind);
        for (std::size_t i = 0; i < f.impact_times.size(); ++i)
            EXPECT_NEAR(r.impact_times[i], f.impact_times[i], o.seconds) << solver_name(o.kind) << " impact " << i;
        EXPECT_NEAR(r.max_abs_theta_input / alpha, f.max_abs_theta_input / alpha, o.peak_alpha) << solver_name(o.kind);
    }
}

TEST(Dynamics, OdeSolversRefuseAToleranceBelow100Eps) {
    // Below 100 eps rounding decides the steps: Bulirsch-Stoer gave up at
    // 1e-17, Dormand-Prince and Fehlberg ran over a minute at 1e-30.  A clear
    // error instead; the exact solver has no tolerance and takes any.
    const PulseInput input(pulse_case(2), q2(0.5) * 0.9 * 0.1, 0.25);
    for (SolverKind k : kOde) {
        EXPECT_THROW(simulate(linear_model(), input, with(k, 1e-17)), std::invalid_argument) << solver_name(k);
        EXPECT_THROW(simulate(linear_model(), input, with(k, 1.0)), std::invalid_argument) << solver_name(k);
        SimulationOptions nan_atol = with(k, 1e-6);
        nan_atol.solver.atol_alpha = NAN;
        EXPECT_THROW(simulate(linear_model(), input, nan_atol), std::invalid_argument) << solver_name(k);
        EXPECT_NO_THROW(simulate(linear_model(), input, with(k, kSmallestTolerance))) << solver_name(k);
    }
    EXPECT_NO_THROW(simulate(linear_model(), input, with(SolverKind::exact, 0)));
}

TEST(Dynamics, AOneSinePulseSlowerThanAMillionthOfPIsRefused) {
    // simulate() itself refuses it (until 2026-11-21 only the command line
    // did): at w_p = 1e-20 rad/s the fall came at 35.2 s (exact) or 2795 s
    // (rk8pd) where the closed form gives 24.4 s.  At 1e-6 p the run goes
    // on: a_p = 2 alpha, the block falls within seconds.
    const double alpha = 0.1, p = 2.0;
    for (SolverKind k : {SolverKind::exact, SolverKind::gsl_rk8pd}) {
        for (double wp : {1e-20, 0.999e-6 * p}) {
            const OneSinePulse slow(2 * alpha, wp, alpha);
            try {
                simulate(linear_model(alpha, p), slow, with(k));
                ADD_FAILURE() << solver_name(k) << ", w_p " << wp << ": not refused";
            } catch (const std::invalid_argument& e) {
                EXPECT_NE(std::string(e.what()).find("below 1e-6 p = 2e-06 rad/s"), std::string::npos) << e.what();
            }
        }
        const SimulationResult r = simulate(linear_model(alpha, p), OneSinePulse(2 * alpha, 1e-6 * p, alpha), with(k));
        EXPECT_TRUE(r.overturned && r.overturned_during_input) << solver_name(k);
        EXPECT_LT(r.t_overturn, 30.0) << solver_name(k);
    }
}

TEST(Dynamics, AStepBelowTheResolutionOfTimeStopsTheRunWithAClearError) {
    // Steps are at most max_step_p / p long.  Where that is below half an ulp
    // of t, t + h == t: every solver spun in place for ever (p = 1e20 rad/s
    // under a 0.05 s input; a 6-sample input 5e16 s long at p = 2).  The
    // driver now stops such a run and names the cause.  Inside double's
    // reach (p = 1e10: p ulp(t) ~ 1e-8 at the uplift, 0.00667 s) every
    // solver still follows the block, which falls about 1e-9 s later.
    const SampledInput brief({0.0, 0.3, 0.5, 0.1, -0.4, 0.0}, 0.01, "brief");
    const SampledInput endless({0.0, 0.3, 0.5, 0.1, -0.4, 0.0}, 1e16, "endless");
    for (Equation eq : {Equation::linearised, Equation::full})
        for (SolverKind k : {SolverKind::exact, SolverKind::dopri5, SolverKind::rkf78, SolverKind::bulirsch_stoer,
                             SolverKind::gsl_rk8pd}) {
            if (eq == Equation::full && k == SolverKind::exact) continue;
            const std::string what = solver_name(k) + (eq == Equation::full ? ", full" : ", linearised");
            auto model = [&](double p) {
                Model m = linear_model(0.2, p);
                m.equation = eq;
                return m;
            };
            for (const auto& [input, p] : {std::pair<const SampledInput*, double>{&brief, 1e20}, {&endless, 2.0}}) {
                try {
                    simulate(model(p), *input, with(k, 1e-6));
                    ADD_FAILURE() << what << ", p " << p << ": no error";
                } catch (const std::runtime_error& e) {
                    // It names where: the uplift, the input's 0.3 g reached in one dt.
                    const std::string message = e.what();
                    const double t_up = model(p).uplift_threshold() / 0.3 * input->dt();
                    const std::size_t at = message.find("at t = ");
                    ASSERT_NE(at, std::string::npos) << what << ": " << message;
                    EXPECT_NEAR(std::stod(message.substr(at + 7)), t_up, 1e-12 * t_up) << what << ": " << message;
                    EXPECT_NE(message.find("below double's resolution"), std::string::npos) << what << ": " << message;
                }
            }
            const double t_up = model(1e10).uplift_threshold() / 0.3 * brief.dt();
            const SimulationResult r = simulate(model(1e10), brief, with(k, 1e-6));
            EXPECT_TRUE(r.overturned_during_input) << what;
            EXPECT_GT(r.t_overturn, t_up) << what;
            EXPECT_LT(r.t_overturn, t_up + 1e-8) << what;
        }
}

TEST(Dynamics, UnderARampOfAnyAmplitudeTheBlockFallsWhereTheClosedFormSays) {
    // A record of two samples, 0 and A g, 0.01 s apart: the block lifts at
    // t_up = alpha dt / A and, from rest on a ramp of slope c1 = A / dt,
    // theta = c1 (sinh pu - pu) / p (eq. 3, u = t - t_up), which reaches the
    // fall angle within the piece for A >= 1e10.  Truth in long double (the
    // series of sinh x - x for x < 0.01).  Before 2026-11-21: the kernel put
    // the fall at 1e-15 s from A = 1e20 (its rounding level for the whole
    // piece, 20 rad, above the fall angle), every solver at 1e-15 s from
    // about 1e35 g (move_until's absolute floor), the general path 3e8 times
    // late at 1e100 g (TOMS 748 out of iterations), Bulirsch-Stoer 3.6 times
    // late from 1e150 g and for ever at 1e300 g (it is now refused beyond
    // p^2 PGA = 1e90: its dense output is NaN from 1e100 g).
    const double alpha = 0.2, p = 2.0, dt = 0.01;
    for (double A : {1e10, 1e20, 1e30, 1e50, 1e80, 1e100, 1e200, 1e300, 1.7e306}) {
        const SampledInput ramp({0.0, A}, dt, "ramp");
        const SimulationOptions defaults;
        const long double c1 = static_cast<long double>(A) / dt, fall = defaults.overturn_angle;
        auto theta = [&](long double u) {
            const long double x = p * u;
            return c1 / p * (x < 1e-2L ? x * x * x / 6 * (1 + x * x / 20 * (1 + x * x / 42 * (1 + x * x / 72)))
                                       : std::sinh(x) - x);
        };
        long double lo = 0, hi = 1e-300L;
        while (theta(hi) < fall) hi *= 2;
        for (int i = 0; i < 300; ++i) (theta((lo + hi) / 2) < fall ? lo : hi) = (lo + hi) / 2;
        const double truth = static_cast<double>(alpha / c1 + lo);
        ASSERT_LT(truth, dt) << A;
        for (int path = 0; path < 6; ++path) {
            const SolverKind k = path < 2 ? SolverKind::exact : kOde[path - 2];
            SimulationOptions o = with(k, 1e-10);
            o.solver.atol_alpha = 1e-10;
            o.solver.record_kernel = path == 1;
            const std::string what = (path == 1 ? "record kernel" : solver_name(k)) + " at " + std::to_string(A) + " g";
            if (k == SolverKind::bulirsch_stoer && A > 1e80) {
                EXPECT_THROW(simulate(linear_model(alpha, p), ramp, o), std::invalid_argument) << what;
                continue;
            }
            const SimulationResult r = simulate(linear_model(alpha, p), ramp, o);
            EXPECT_TRUE(r.overturned_during_input) << what;
            // Exact: rounding (measured 3e-16).  ODE solvers at rtol 1e-10:
            // measured 1.9e-12 (Dormand-Prince at 1e10 g), 1e-15 elsewhere.
            EXPECT_NEAR(r.t_overturn, truth, (k == SolverKind::exact ? 2e-15 : 1e-10) * truth) << what;
        }
    }
}

TEST(Dynamics, ConvergenceOrderOfTheRungeKuttaMethods) {
    // Fixed steps on one pulse of the linearised equation, where
    // theta/alpha = (q - 1)(cosh pt - 1): the error falls as h^order.
    namespace odeint = boost::numeric::odeint;
    using S = std::array<double, 2>;
    const double p = 2.0, F = 1.5;  // phi'' = p^2 (phi + F)
    auto sys = [&](const S& x, S& d, double) {
        d[0] = x[1];
        d[1] = p * p * (x[0] + F);
    };
    auto error_with = [&](auto stepper, int n) {
        S x{0.0, 0.0};
        odeint::integrate_n_steps(stepper, sys, x, 0.0, 1.0 / n, n);
        return std::fabs(x[0] - F * (std::cosh(p) - 1.0));
    };
    const double dp5 = std::log2(error_with(odeint::runge_kutta_dopri5<S>(), 10) /
                                 error_with(odeint::runge_kutta_dopri5<S>(), 20));
    const double f78 = std::log2(error_with(odeint::runge_kutta_fehlberg78<S>(), 4) /
                                 error_with(odeint::runge_kutta_fehlberg78<S>(), 8));
    EXPECT_NEAR(dp5, 5.0, 0.4);
    EXPECT_NEAR(f78, 8.0, 0.6);  // odeint advances Fehlberg's 8th-order solution
}

TEST(Dynamics, EnergyIsConservedWithRestitutionOne) {
    // Free rocking after a pulse, through several impacts: E = theta'^2/2 - p^2 (theta - sigma alpha)^2 / 2.
    const double alpha = 0.1, p = 2.0, x = 0.5;
    const PulseInput input(pulse_case(2), q2(x) * 0.6 * alpha, x / p);
    for (SolverKind k : {SolverKind::exact, SolverKind::dopri5, SolverKind::gsl_rk8pd}) {
        SimulationOptions o = with(k, 1e-11);
        o.record_dt = 0.01;
        o.free_record_time = 20.0;
        const Model m = linear_model(alpha, p);
        const SimulationResult r = simulate(m, input, o);
        ASSERT_GE(r.impacts, 3) << solver_name(k);
        const double E0 = m.energy(r.theta_at_tfin, r.omega_at_tfin, r.theta_at_tfin >= 0 ? 1 : -1);
        double worst = 0;
        for (const Sample& s : r.samples)
            if (s.t > r.t_fin + 1e-9)
                worst = std::fmax(worst, std::fabs(m.energy(s.theta, s.omega, s.theta >= 0 ? 1 : -1) - E0));
        EXPECT_LT(worst / (p * p * alpha * alpha), k == SolverKind::exact ? 1e-12 : 1e-8) << solver_name(k);
    }
}

TEST(Dynamics, SymmetryUnderASignFlipOfTheInput) {
    const SampledInput up = synthetic_record(0.01, 20.0, 0.35);
    std::vector<double> flipped;
    for (double t = 0; t <= 20.0; t += 0.01) flipped.push_back(-up.accel(t));
    const SampledInput down(flipped, 0.01, "flipped");
    for (Equation eq : {Equation::linearised, Equation::full}) {
        Model m = linear_model(0.15, 2.5, 0.9);
        m.equation = eq;
        const SolverKind k = eq == Equation::linearised ? SolverKind::exact : SolverKind::dopri5;
        const SimulationResult a = simulate(m, up, with(k, 1e-10)), b = simulate(m, down, with(k, 1e-10));
        ASSERT_TRUE(a.uplifted);
        EXPECT_EQ(a.impacts, b.impacts);
        EXPECT_NEAR(a.theta_at_tfin, -b.theta_at_tfin, 1e-9);
        EXPECT_NEAR(a.max_abs_theta_input, b.max_abs_theta_input, 1e-9);
    }
}

TEST(Dynamics, FreeRockingQuarterPeriod) {
    // Released from rest at theta0, the linearised block reaches theta = 0
    // after (1/p) acosh(1/(1 - theta0/alpha)).
    const double alpha = 0.2, p = 1.7;
    const SampledInput none({0.0, 0.0}, 1e-9, "no input");
    for (double ratio : {0.1, 0.5, 0.9, 0.999})
        for (SolverKind k : {SolverKind::exact, SolverKind::dopri5, SolverKind::rkf78}) {
            SimulationOptions o = with(k, 1e-12);
            o.initial_theta = ratio * alpha;
            o.free_record_time = 20.0;
            const SimulationResult r = simulate(linear_model(alpha, p), none, o);
            const double expected = std::acosh(1.0 / (1.0 - ratio)) / p;
            EXPECT_NEAR(r.t_first_impact, expected, k == SolverKind::exact ? 1e-13 : 1e-9)
                << solver_name(k) << " theta0/alpha " << ratio;
            EXPECT_FALSE(r.overturned);
        }
}

TEST(Dynamics, FullEquationFreeRockingImpactsWhereItsFirstIntegralSays) {
    // The full equation against its own first integral (full_equation_truth.hpp,
    // a quadrature in long double), not against another solver: released from
    // rest at theta0, its first six impact times, with restitution 1 and with
    // Housner's, for alpha from 1e-3 to 0.35 and half-heights 0.2 m and 50 m
    // (p 6.1 to 0.37 rad/s).  At rtol = atol = 1e-12 every ODE solver within
    // 1e-9 of each time, relative (measured: at most 3e-10 from 0.999 alpha
    // with Housner's restitution, 2e-11 from 0.1 and 0.9 alpha).  Released
    // from 0.999 alpha without dissipation, every half-cycle passes 1e-3 alpha
    // from the top: on the way there an error grows like the distance's
    // inverse, 1000 times, and the time near the top is as sensitive again to
    // where the block turns, so the times' condition is ~1e5 there and the
    // tolerance 1e-7 (measured 2.2e-8; at rtol 1e-13 still 1e-9, while a
    // solver's error at rtol 1e-10 is 2e-6: the solvers converge to the
    // quadrature until the condition stops them).  Replacing sin u by
    // u - u^3/6 in the equation moves these times by up to 1.5e-2 (alpha =
    // 0.35; measured 2026-11-21), far beyond either tolerance.
    const SampledInput none({0.0, 0.0}, 1e-9, "no input");
    for (double H : {0.2, 50.0})
        for (double alpha : {1e-3, 0.05, 0.35})
            for (bool housner : {false, true})
                for (double ratio : {0.1, 0.9, 0.999}) {
                    Model m;
                    m.block = Block::from_half_height(H, alpha);
                    m.equation = Equation::full;
                    m.restitution = housner ? housner_restitution(alpha) : 1.0;
                    const std::vector<long double> truth = rocking::testing::free_rocking_impact_times(
                        alpha, m.block.p, m.restitution, ratio * alpha, 6);
                    for (SolverKind k : kOde) {
                        SimulationOptions o = with(k, 1e-12);
                        o.initial_theta = ratio * alpha;
                        o.free_record_time = static_cast<double>(truth.back()) * 1.01;
                        const SimulationResult r = simulate(m, none, o);
                        ASSERT_GE(r.impact_times.size(), truth.size()) << solver_name(k);
                        for (std::size_t i = 0; i < truth.size(); ++i)
                            EXPECT_NEAR(r.impact_times[i] / truth[i], 1.0, housner || ratio < 0.99 ? 1e-9 : 1e-7)
                                << solver_name(k) << " H " << H << " alpha " << alpha << " e " << m.restitution
                                << " theta0/alpha " << ratio << " impact " << i;
                        EXPECT_FALSE(r.overturned);
                    }
                }
}

TEST(Dynamics, FullEquationUnderAConstantGroundReachesAlphaAndFallsWhereItsFirstIntegralSays) {
    // A block at rest under a constant ground acceleration A g above g tan
    // alpha (by 1.001, 1.5 and 10 times) uplifts at once; its first integral
    // (full_equation_truth.hpp) gives when theta reaches alpha and when it
    // reaches the fall angle pi/2.  Both signs of A (the mirror image must
    // take the same times), alpha from 1e-3 to 0.35, half-heights 0.2 m and
    // 50 m.  At rtol = atol = 1e-12 every ODE solver within 1e-9, relative.
    // Measured: at most 8e-11 (A = 1.001 g tan alpha, where the block leaves
    // the ground slowly and the start's error weighs), 1e-12 elsewhere.
    for (double H : {0.2, 50.0})
        for (double alpha : {1e-3, 0.05, 0.35})
            for (double lambda : {1.001, 1.5, 10.0})
                for (double sign : {1.0, -1.0}) {
                    Model m;
                    m.block = Block::from_half_height(H, alpha);
                    m.equation = Equation::full;
                    const double A = lambda * std::tan(alpha);
                    const long double to_alpha = rocking::testing::step_time_to(alpha, m.block.p, A, alpha);
                    const long double to_fall = rocking::testing::step_time_to(alpha, m.block.p, A, M_PI / 2);
                    const SampledInput step({sign * A, sign * A}, 2 * static_cast<double>(to_fall) + 1, "step");
                    for (SolverKind k : kOde) {
                        const SimulationResult r = simulate(m, step, with(k, 1e-12));
                        ASSERT_TRUE(r.overturned_during_input) << solver_name(k);
                        EXPECT_NEAR(r.t_first_alpha / to_alpha, 1.0, 1e-9)
                            << solver_name(k) << " H " << H << " alpha " << alpha << " A " << sign * A;
                        EXPECT_NEAR(r.t_overturn / to_fall, 1.0, 1e-9)
                            << solver_name(k) << " H " << H << " alpha " << alpha << " A " << sign * A;
                    }
                }
}

TEST(Dynamics, ABlockPastTheTopWhenTheInputEndsFalls) {
    // With the ground at rest, sigma theta > alpha is the far side of the
    // unstable equilibrium: gravity turns the block outwards, and below the
    // energy barrier it cannot come back over it, so it falls whatever its
    // velocity.  (The energy rule alone, "below the barrier it can never
    // overturn", holds on the near side only; applied here it stopped the
    // run and reported no overturning.)  The linearised fall from d0 =
    // sigma theta0 - alpha, w0 = sigma theta0' is d(t) = A e^(pt) + B e^(-pt),
    // A = (d0 + w0/p)/2, B = (d0 - w0/p)/2, reaching the fall angle when
    // e^(pt) = (D + sqrt(D^2 - 4AB)) / 2A, D = pi/2 - alpha (the later root:
    // a block moving inwards turns first).
    const double alpha = 0.1, p = 2.0;
    const SampledInput none({0.0, 0.0}, 1e-9, "no input");
    struct Start {
        double theta_over_alpha, omega_over_alpha_p;
    };
    // At rest, moving out, and moving in below the barrier (energy
    // (w0^2 - (p d0)^2)/2 < 0), far from the top and near it.
    for (const Start s : {Start{1.5, 0.0}, Start{1.5, 0.2}, Start{1.5, -0.3}, Start{1.05, -0.04}})
        for (double sign : {1.0, -1.0}) {
            const long double d0 = (s.theta_over_alpha - 1) * alpha, w0 = s.omega_over_alpha_p * alpha * p;
            const long double A = (d0 + w0 / p) / 2, B = (d0 - w0 / p) / 2, D = M_PI / 2 - alpha;
            const double expected = static_cast<double>(std::log((D + std::sqrt(D * D - 4 * A * B)) / (2 * A)) / p);
            for (const SolverPath& path :
                 with_general_path({SolverKind::exact, SolverKind::dopri5, SolverKind::rkf78})) {
                SimulationOptions o = path.options(1e-12);
                o.initial_theta = sign * s.theta_over_alpha * alpha;
                o.initial_omega = sign * s.omega_over_alpha_p * alpha * p;
                const SimulationResult r = simulate(linear_model(alpha, p), none, o);
                const std::string what = path.name + " theta0/alpha " + std::to_string(sign * s.theta_over_alpha);
                EXPECT_TRUE(r.overturned) << what;
                EXPECT_FALSE(r.overturned_during_input) << what;
                EXPECT_TRUE(r.collapse(Criterion::overturning, alpha)) << what;
                EXPECT_EQ(r.impacts, 0) << what;
                EXPECT_NEAR(r.t_overturn, expected, path.kind == SolverKind::exact ? 1e-13 : 1e-9) << what;
            }
        }
    // The control, which the energy rule already followed: above the barrier
    // and moving in, the block crosses back over alpha (e^(2pt1) = -B/A) with
    // speed w1 = sqrt(w0^2 - (p d0)^2), reaches the ground after t2 (sinh pt2
    // = alpha p / w1), leaves it with the same speed (restitution 1), reaches
    // -alpha after t2 again (time reversal) with speed w1, and falls after t3
    // (sinh pt3 = D p / w1).
    {
        const long double d0 = 0.05L * alpha, w0 = -0.2L * alpha * p;
        const long double A = (d0 + w0 / p) / 2, B = (d0 - w0 / p) / 2, D = M_PI / 2 - alpha;
        const long double w1 = std::sqrt(w0 * w0 - p * p * d0 * d0);
        const double expected = static_cast<double>(
            (std::log(-B / A) / 2 + 2 * std::asinh(alpha * p / w1) + std::asinh(D * p / w1)) / p);
        for (bool kernel : {true, false}) {
            SimulationOptions o = with(SolverKind::exact);
            o.solver.record_kernel = kernel;
            o.initial_theta = 1.05 * alpha;
            o.initial_omega = -0.2 * alpha * p;
            const SimulationResult back = simulate(linear_model(alpha, p), none, o);
            EXPECT_TRUE(back.overturned) << kernel;
            EXPECT_EQ(back.impacts, 1) << kernel;
            EXPECT_NEAR(back.t_overturn, expected, 1e-13) << kernel;
        }
    }
    // The full equation (no closed form): dopri5 and rkf78 agree on the fall.
    Model full = linear_model(alpha, p);
    full.equation = Equation::full;
    for (const Start s : {Start{1.5, 0.0}, Start{1.5, -0.3}}) {
        SimulationOptions a = with(SolverKind::rkf78, 1e-12), b = with(SolverKind::dopri5, 1e-10);
        a.initial_theta = b.initial_theta = s.theta_over_alpha * alpha;
        a.initial_omega = b.initial_omega = s.omega_over_alpha_p * alpha * p;
        const SimulationResult ra = simulate(full, none, a), rb = simulate(full, none, b);
        EXPECT_TRUE(ra.overturned) << s.omega_over_alpha_p;
        EXPECT_TRUE(rb.overturned) << s.omega_over_alpha_p;
        EXPECT_NEAR(ra.t_overturn, rb.t_overturn, 1e-8) << s.omega_over_alpha_p;
    }
}

TEST(Dynamics, AnExcursionOutAndBackWithinOneStepIsFollowed) {
    // The block leaves the ground at theta' = w0 > 0 on a record piece where
    // the input, a0 + c1 u, rises through alpha: theta'' = p^2 (theta + a0 +
    // c1 u - alpha) turns from negative to positive, so theta rises, falls
    // back to the ground and, on the equation it started on, would turn up
    // again: theta' has the same sign at both ends of the piece.  The general
    // path took one extremum per step at most: it missed the impact (c1 =
    // 0.1: theta ends above 0) or put it at the step's start and rested the
    // block there (c1 = 0.06: theta ends below 0), and the ODE solvers whose
    // steps end on the record's samples did so later in the cascade that
    // follows.  Found by a random comparison of the solvers on synthetic
    // records.  The truth: the impacts of the cascade up to the piece's end,
    // each the first root of the closed form on its corner from the last,
    //   theta(u) = lin (cosh pu - 1) + D sinh pu - c1 u,
    //   lin = a(t_i) - sigma alpha, D = (w + c1) / p,
    // (theta = 0, theta' = w at the impact t_i; restitution 1: w is theta'
    // before it), in long double by bisection.
    const double alpha = 0.1, p = 1.0, dt = 0.4, a0 = 0.09, w0 = 1e-4;
    auto cascade = [&](int sign, long double c1) {
        std::vector<long double> times;
        long double t = 0, w = sign * w0;
        int sigma = sign;
        for (;;) {
            const long double lin = sign * a0 + sign * c1 * t - sigma * alpha, D = (w + sign * c1) / p;
            auto theta = [&](long double u) {
                return lin * (std::cosh(p * u) - 1) + D * std::sinh(p * u) - sign * c1 * u;
            };
            // The first return to 0 (the excursion is one arc: theta''
            // changes sign once at most).
            const long double u = first_fall([&](long double v) { return sigma * theta(v); }, 1e-12L, dt - t);
            if (u >= dt - t) return times;
            w = p * (lin * std::sinh(p * u) + D * std::cosh(p * u)) - sign * c1;
            t += u;
            times.push_back(t);
            sigma = -sigma;
        }
    };
    for (double c1 : {0.1, 0.06})
        for (int sign : {1, -1}) {
            const SampledInput piece({sign * a0, sign * (a0 + c1 * dt)}, dt, "rising through alpha");
            const std::vector<long double> truth = cascade(sign, c1);
            ASSERT_GE(truth.size(), 2u);
            for (const SolverPath& path : with_general_path({SolverKind::exact, SolverKind::dopri5, SolverKind::rkf78,
                                                             SolverKind::bulirsch_stoer, SolverKind::gsl_rk8pd})) {
                SimulationOptions o = path.options(1e-10);
                o.free_rocking = false;
                o.initial_omega = sign * w0;
                const SimulationResult r = simulate(linear_model(alpha, p), piece, o);
                const std::string what = path.name + " c1 " + std::to_string(c1) + " sign " + std::to_string(sign);
                EXPECT_EQ(r.impact_times.size(), truth.size()) << what;
                EXPECT_EQ(r.rests, 0) << what;
                // The exact solvers to rounding: theta's (~1e-19 rad) over theta'
                // at the impacts (down to ~1e-6 rad/s), accumulated along the
                // cascade (measured 7e-14 s at most).  The ODE solvers to their
                // atol, 1e-11 rad, over theta' (measured: dopri5 3.9e-7 s,
                // Bulirsch-Stoer 2.5e-8 s; rkf78 and rk8pd, which step on the
                // record's samples, 7e-14 s).
                const double tol = path.kind == SolverKind::exact ? 5e-13 : 1e-6;
                for (std::size_t i = 0; i < std::min(truth.size(), r.impact_times.size()); ++i)
                    EXPECT_NEAR(r.impact_times[i], static_cast<double>(truth[i]), tol) << what << " impact " << i;
            }
        }
}

TEST(Dynamics, AnUpliftThatFallsBackWithinItsFirstStepIsFollowed) {
    // A block lifted from rest (theta = theta' = 0) by an input that drops
    // back below alpha g within the first step: theta'' turns from positive
    // to negative, theta rises and falls back to the ground inside the step.
    // Both exact paths (the record kernel and the driver over ExactStepper)
    // took a step starting at theta' = 0 for one without an extremum: the
    // fall below the ground looked like an impact at the step's start, and
    // the block was put at rest there, missing the whole motion (0 impacts
    // where there are 84 and 216).  The ODE solvers followed it only because
    // their first step is short.  Found by comparing the solvers on one-sine
    // pulses just above the threshold.  The truth: the closed form from rest
    // in long double, its first root (the first impact) and its extremum
    // before it (the peak) by bisection.
    const double alpha = 0.1;
    auto first_arc = [](auto theta, auto omega, long double until, long double& t_peak) {
        // theta rises first (theta'' > 0 at 0): the peak is where theta' turns
        // negative, the impact where theta turns negative after it.
        t_peak = first_fall(omega, 1e-9L, until);
        return first_fall(theta, t_peak, until);
    };
    struct Case {
        std::string name;
        std::unique_ptr<GroundInput> input;
        double p, impact, peak;
    };
    std::vector<Case> cases;
    {
        // A record whose first piece falls from 1.05 alpha to 0.5 alpha over
        // dt = 0.25 s (p dt = 0.5, one piece, one step):
        //   theta(u) = C (cosh pu - 1) + D sinh pu - c1 u,  C = a0 - alpha,  D = c1 / p.
        const long double p = 2, a0 = 1.05L * alpha, c1 = (0.5L * alpha - a0) / 0.25L, C = a0 - alpha, D = c1 / p;
        long double t_peak;
        const long double t1 = first_arc([&](long double u) { return C * (std::cosh(p * u) - 1) + D * std::sinh(p * u) - c1 * u; },
                                         [&](long double u) { return p * (C * std::sinh(p * u) + D * std::cosh(p * u)) - c1; },
                                         0.25L, t_peak);
        const long double peak = C * (std::cosh(p * t_peak) - 1) + D * std::sinh(p * t_peak) - c1 * t_peak;
        ASSERT_LT(t1, 0.25L);
        cases.push_back({"record piece falling through alpha",
                         std::make_unique<SampledInput>(std::vector<double>{1.05 * alpha, 0.5 * alpha, 0, 0, 0}, 0.25, "r"),
                         2.0, static_cast<double>(t1), static_cast<double>(peak)});
    }
    {
        // The one-sine pulse at a_p = 1.004 alpha: above alpha g for 0.09 s,
        // within the first step (0.5 / w_p = 0.25 s).  From the uplift at t_u
        // (u = t - t_u):
        //   theta = C cosh pu + D sinh pu + alpha + B sin(w t + psi),
        //   B = -p^2 a_p / (p^2 + w^2),  C = -alpha - B sin(w t_u + psi),  D = -B w cos(w t_u + psi) / p,
        // with psi and t_u as the input gives them in double (the uplift
        // waits for a(t) > alpha, up to ~1e-13 s here, which moves the peak
        // by 1e-12 of itself: the input's rounding, not the solver's).
        const double ap = 1.004 * alpha, wd = 2.0;
        auto pulse = std::make_unique<OneSinePulse>(ap, wd, alpha);
        const long double p = 1, w = wd, psi = pulse->psi(),
                          tu = uplift_time(*pulse, 0.0, pulse->t_end(), alpha, [&](double t) { return pulse->accel(t); });
        const long double B = -p * p * ap / (p * p + w * w), C = -alpha - B * std::sin(w * tu + psi),
                          D = -B * w * std::cos(w * tu + psi) / p;
        auto theta = [&](long double t) {
            return C * std::cosh(p * (t - tu)) + D * std::sinh(p * (t - tu)) + alpha + B * std::sin(w * t + psi);
        };
        long double t_peak;
        const long double t1 = first_arc(
            [&](long double u) { return theta(tu + u); },
            [&](long double u) {
                return p * (C * std::sinh(p * u) + D * std::cosh(p * u)) + B * w * std::cos(w * (tu + u) + psi);
            },
            0.25L, t_peak);
        ASSERT_LT(t1, 0.25L);
        cases.push_back({"one-sine pulse at 1.004 alpha", std::move(pulse), 1.0, static_cast<double>(tu + t1),
                         static_cast<double>(theta(tu + t_peak))});
    }
    for (const Case& c : cases)
        for (const SolverPath& path : with_general_path({SolverKind::exact, SolverKind::dopri5, SolverKind::rkf78,
                                                         SolverKind::bulirsch_stoer, SolverKind::gsl_rk8pd})) {
            SimulationOptions o = path.options(1e-12);
            const SimulationResult r = simulate(linear_model(alpha, c.p, 0.9), *c.input, o);
            const std::string what = c.name + ", " + path.name;
            if (r.impacts < 1) {
                ADD_FAILURE() << what << ": no impact, peak " << r.max_abs_theta_input;
                continue;
            }
            // Exact: rounding, at most eps |B| on the sine (its increment
            // sin(w u + ph) - sin ph - w u cos ph cancels terms of B = 0.02 rad):
            // measured 1.3e-18 rad on a peak of 1.8e-6 rad and 1.2e-14 s;
            // on the record 3e-21 rad and 1e-16 s.  ODE at rtol 1e-12: its
            // atol (1e-13 rad) over theta' at the impact (~3e-5 rad/s),
            // measured up to 2e-9 s.
            EXPECT_NEAR(r.t_first_impact, c.impact, path.kind == SolverKind::exact ? 5e-14 : 1e-8) << what;
            EXPECT_NEAR(r.max_abs_theta_input, c.peak, path.kind == SolverKind::exact ? 1e-17 : 1e-13) << what;
        }
}

TEST(Dynamics, ThetaDoubleDotTurningTwiceInsideOneSineStepIsFollowed) {
    // Under a sine, theta'' = p^2 (theta + a - alpha sigma) can change sign
    // twice within one step of the exact solver (w u up to 0.5): here a
    // block chattering at theta ~ 1e-6 alpha under a one-sine pulse just
    // above the threshold, its trough inside a step, turns theta' from
    // negative to positive and back within the step, and theta crosses the
    // ground and comes back.  The driver took theta'' of one sign at both
    // ends for none in between: it missed the impact at 0.0846 s (and the
    // hop of 20 us after it) and went on through the ground, with 124
    // impacts where there are 103.  Found by comparing the solvers on
    // random one-sine pulses just above the threshold.  The truth: the
    // impacts during the pulse, each the first root of the closed form on
    // its corner from the last (in long double),
    //   theta(t) = C cosh pu + D sinh pu + sigma alpha + B sin(w t + psi),  u = t - t_i,
    //   B = -p^2 a_p / (p^2 + w^2),  C = -sigma alpha - B sin(w t_i + psi),
    //   D = (theta'_i - B w cos(w t_i + psi)) / p,
    // theta'_i the rebound (e times theta' before the impact), from the
    // uplift at t_u (psi and t_u as the input gives them in double).
    const double alpha = 0.10373936036768254, p = 5.1272932099689568, e = 0.98391504339584157;
    const OneSinePulse pulse(0.10512835416583353, 37.52302806828132, alpha);
    const long double ap = 0.10512835416583353L, w = 37.52302806828132L, psi = pulse.psi();
    const long double B = -(long double)p * p * ap / ((long double)p * p + w * w);
    std::vector<long double> truth;
    {
        long double ti = uplift_time(pulse, 0.0, pulse.t_end(), alpha, [&](double t) { return pulse.accel(t); });
        long double om = 0;
        int sigma = 1;
        while (ti < pulse.t_end()) {
            const long double C = -sigma * alpha - B * std::sin(w * ti + psi),
                              D = (om - B * w * std::cos(w * ti + psi)) / p;
            auto theta = [&](long double u) {
                return C * std::cosh(p * u) + D * std::sinh(p * u) + sigma * alpha + B * std::sin(w * (ti + u) + psi);
            };
            // The return to the ground, searched from 1e-9 s (1e-5 s after the
            // uplift, where theta grows like u^3 and would be lost in
            // C cosh + sigma alpha's rounding).
            const long double until = pulse.t_end() - ti;
            const long double u =
                first_fall([&](long double v) { return sigma * theta(v); }, truth.empty() ? 1e-5L : 1e-9L, until);
            if (u >= until) break;
            om = e * (p * (C * std::sinh(p * u) + D * std::cosh(p * u)) + B * w * std::cos(w * (ti + u) + psi));
            ti += u;
            truth.push_back(ti);
            sigma = -sigma;
        }
    }
    ASSERT_GE(truth.size(), 90u);
    for (SolverKind k : {SolverKind::exact, SolverKind::dopri5, SolverKind::rkf78, SolverKind::bulirsch_stoer,
                         SolverKind::gsl_rk8pd}) {
        const SimulationResult r = simulate(linear_model(alpha, p, e), pulse, with(k, 1e-12));
        std::vector<double> during;
        for (double t : r.impact_times)
            if (t <= pulse.t_end()) during.push_back(t);
        EXPECT_EQ(during.size(), truth.size()) << solver_name(k);
        // Exact: 5e-12 s.  The double input (sin(w t + psi) rounded, ~1e-17
        // of a) and the solver's rounding drift by ~1e-14 s per impact up
        // to impact 79, where theta grazes the ground at a small theta' and
        // every solver jumps by ~5e-13 s (rk8pd at 1e-13 as well); measured
        // 2.5e-12 s by the pulse's end (rk8pd at 1e-13: 3.5e-12 s).  ODE at
        // rtol 1e-12: its atol (1e-13 rad) over theta' at the impacts
        // (~1e-5 rad/s), 1e-8 s, except Dormand-Prince, which locates
        // events on its fourth-order dense output and drifts to 7.3e-7 s
        // over the 103 impacts (its count is still right).
        const double tol = k == SolverKind::exact ? 5e-12 : k == SolverKind::dopri5 ? 2e-6 : 1e-8;
        for (std::size_t i = 0; i < std::min(during.size(), truth.size()); ++i)
            EXPECT_NEAR(during[i], static_cast<double>(truth[i]), tol) << solver_name(k) << " impact " << i;
    }
}

TEST(Dynamics, OnRandomOneSinePulsesJustAboveTheThresholdTheSolversAgree) {
    // 1000 random blocks (alpha 0.02-0.32, p 0.5-5.5 rad/s, Housner's
    // restitution or one in [0.5, 1]) under one-sine pulses just above the
    // threshold (a_p / alpha - 1 in (1e-6, 0.05], w_p / p in [0.1, 20.1]):
    // brief lifts from rest and chattering at theta ~ 1e-6 alpha, where
    // theta'' changes sign twice within a step.  Where the motion is well
    // conditioned (as in the test below: a_p scaled by 1 + 1e-13 moves the
    // exact solver's answer and impact times by less than 1e-9), the exact
    // solver and three ODE solvers at rtol 1e-12 must agree: peak and
    // theta(t_fin) to 1e-7 alpha (their 1e-12 times the 1e4 the probe
    // allows; measured 3.2e-10), the outcome and the number of impacts.
    // The exact solver's general path missed a lift that falls back within
    // its first step (AnUpliftThatFallsBackWithinItsFirstStepIsFollowed;
    // 30 % of the cases failed) and a passage through the ground inside a
    // step (ThetaDoubleDotTurningTwiceInsideOneSineStepIsFollowed; 5 cases,
    // all but one at w_p / p > 10).  Dormand-Prince is left out: it locates
    // events on its fourth-order dense output (1e-6 s off over a hundred
    // impacts).
    const int well = sines_just_above_agree(
        20261121, Equation::linearised, with(SolverKind::exact), [](SolverKind k) { return with(k, 1e-12); }, 1e-7);
    // Not a vacuous test: most cases are well conditioned (measured 951 of 1000).
    EXPECT_GT(well, 800);
}

TEST(Dynamics, FullEquationOnOneSinePulsesJustAboveTheThresholdHidesNoExcursionInALongStep) {
    // The driver's check for theta'' changing sign twice inside a step under
    // a sine (ThetaDoubleDotTurningTwiceInsideOneSineStepIsFollowed) is proven
    // for eq. 3 only; on the full equation it runs without that proof.  Here
    // it is measured instead: every ODE solver at rtol 1e-12 with its usual
    // steps (max_step_p 0.5) against rkf78 and rk8pd with steps 50 or 500
    // times shorter, where a hidden double turn would need the whole
    // excursion inside 0.01 or 0.001 / p (not impossible, 50 or 500 times less likely).
    // The full equation's threshold is g tan(alpha); one-sine pulses just
    // above it, as in the test above.  Dormand-Prince is left out (its
    // events on its fourth-order dense output).
    auto with_steps = [](SolverKind k, double max_step_p) {
        SimulationOptions o = with(k, 1e-12);
        o.solver.max_step_p = max_step_p;
        return o;
    };
    // 1. Case 912 of the draw below: chattering at theta ~ 1e-5 alpha with
    // 103 impacts, a trough of the sine inside one of rkf78's long steps.
    // With the check switched off for the full equation, rkf78 put the peak
    // at 8.468e-6 alpha where it is 9.2103e-6 (7.4e-7 alpha off, the only
    // failure of the 1000 cases below).  Short-step references: rkf78 and
    // rk8pd at max_step_p 1e-3 agree to 3e-16 alpha on the peak and 4.2e-13 s
    // on the impacts.  Tolerances: 1e-10 alpha (measured 3.4e-12, Bulirsch-
    // Stoer's theta(t_fin)) and 5e-9 s (measured 5.1e-10 s, Bulirsch-Stoer's
    // drift over the 103 impacts).
    {
        const double alpha = 0.050184945984386824, p = 4.4112546067459206, e = 0.99622537722367499;
        Model m = linear_model(alpha, p, e);
        m.equation = Equation::full;
        const OneSinePulse input(0.050717133614236451, 36.013722601245362, std::tan(alpha));
        const SimulationResult ref = simulate(m, input, with_steps(SolverKind::rkf78, 1e-3));
        const SimulationResult ref2 = simulate(m, input, with_steps(SolverKind::gsl_rk8pd, 1e-3));
        ASSERT_EQ(ref.impacts, 103);
        ASSERT_EQ(ref2.impacts, 103);
        EXPECT_NEAR(ref2.max_abs_theta_input, ref.max_abs_theta_input, 1e-13 * alpha);
        for (SolverKind k : {SolverKind::rkf78, SolverKind::gsl_rk8pd, SolverKind::bulirsch_stoer}) {
            const SimulationResult r = simulate(m, input, with_steps(k, 0.5));
            EXPECT_TRUE(runs_agree(ref, r, alpha, 1e-10)) << solver_name(k) << ": " << against(r, ref, alpha);
            ASSERT_EQ(r.impact_times.size(), ref.impact_times.size()) << solver_name(k);
            for (std::size_t i = 0; i < r.impact_times.size(); ++i)
                EXPECT_NEAR(r.impact_times[i], ref.impact_times[i], 5e-9) << solver_name(k) << " impact " << i;
        }
    }
    // 2. 1000 random blocks (alpha 0.02-0.32, p 0.5-5.5 rad/s, Housner's
    // restitution or one in [0.5, 1]) under one-sine pulses with a_p /
    // tan(alpha) - 1 in (1e-6, 0.05] and w_p / p in [0.1, 20.1]; where the
    // short-step rkf78 (max_step_p 0.01) is well conditioned (its answer
    // and impact times move by less than 1e-9 when a_p is scaled by
    // 1 + 1e-13: measured 997 of 1000), the three solvers with their usual
    // steps must agree with it to 1e-7 alpha (as above: 1e-12 times the
    // probe's 1e4; measured 6.1e-10) and on the number of impacts.
    const int well = sines_just_above_agree(20261122, Equation::full, with_steps(SolverKind::rkf78, 0.01),
                                            [&](SolverKind k) { return with_steps(k, 0.5); }, 1e-7);
    EXPECT_GT(well, 900);
}

TEST(Dynamics, OnRandomInputsEverySolverAgreesWhereTheMotionIsWellConditioned) {
    // 400 random blocks (alpha 0.02-0.32, p 0.5-5.5 rad/s, Housner's
    // restitution or one in [0.5, 1]) under random inputs: 70 % synthetic
    // records near the uplift threshold (a chattering block, impact cascades,
    // theta'' changing sign inside pieces), 30 % random pulse trains of 1-6
    // pulses.  Where the motion is well conditioned -- the exact solver's
    // peak, theta(t_fin), outcome and every impact time move by less than
    // 1e-9 (alpha, s) when the input is scaled by 1 + 1e-13 -- the record
    // kernel, the general exact path and three ODE solvers at rtol 1e-12
    // must agree: the exact ones to 1e-9 alpha (rounding 1e-16 times the
    // amplification the probe allows, 1e4; measured 9e-12) and on every
    // impact (expect_agreement; since 2026-11-22), the ODE ones to
    // 1e-7 alpha (their 1e-12 times 1e4; measured: rkf78 1.1e-10, rk8pd
    // 2e-11, Bulirsch-Stoer 4.7e-9).  Dormand-Prince is left out: stepping
    // across the samples it converges slowly on records (docs/solvers.md).  Elsewhere
    // (the probe moves the answer) no solver's answer is the truth: rocking
    // is unstable between impacts.  Comparing the solvers at random this way
    // found two bugs of the general path that hid an excursion inside one
    // step (AnExcursionOutAndBackWithinOneStepIsFollowed); the uniform draws
    // come from the raw mt19937_64 stream, the same on every platform.
    RandomDraws U(20261121);
    int well = 0;
    for (int it = 0; it < 400; ++it) {
        const Model m = U.block(it, Equation::linearised);
        const double alpha = m.block.alpha, p = m.block.p;
        std::unique_ptr<GroundInput> input, nudged;
        std::string what = "case " + std::to_string(it);
        if (U() < 0.7) {
            const int n = 200 + static_cast<int>(1500 * U());
            const double dt = 0.005 + 0.02 * U(), f = 1 + 10 * U();
            std::vector<double> a(n);
            double phase = 0;
            for (int k = 0; k < n; ++k) {
                phase += (U() - 0.5) * 0.6;
                a[k] = (0.8 + 0.6 * U()) * alpha * std::sin(f * k * dt + phase) * std::exp(-k / (0.4 * n));
            }
            std::vector<double> b = a;
            for (double& v : b) v *= 1 + 1e-13;
            input = std::make_unique<SampledInput>(a, dt, "random record");
            nudged = std::make_unique<SampledInput>(b, dt, "random record, nudged");
            what += " (record, dt " + std::to_string(dt) + ")";
        } else {
            std::vector<Pulse> pulses;
            const int n = 1 + static_cast<int>(5 * U());
            for (int k = 0; k < n; ++k) pulses.push_back({k == 0 ? 0.2 + 0.8 * U() : 2 * U() - 1, 0.2 + 2 * U()});
            const double pga = alpha * (1 + 1.2 * U()), to = (0.05 + 3 * U()) / p;
            input = std::make_unique<PulseInput>(PulseTrain(pulses), pga, to);
            nudged = std::make_unique<PulseInput>(PulseTrain(pulses), pga * (1 + 1e-13), to);
            what += " (pulse train)";
        }
        what += ", alpha " + std::to_string(alpha) + ", p " + std::to_string(p);
        const SimulationResult ref = simulate(m, *input, with(SolverKind::exact));
        if (!well_conditioned(ref, simulate(m, *nudged, with(SolverKind::exact)), alpha)) continue;
        ++well;
        expect_agreement(ref, m, *input, what,
                         {{with(SolverKind::rkf78, 1e-12), 1e-7},
                          {with(SolverKind::gsl_rk8pd, 1e-12), 1e-7},
                          {with(SolverKind::bulirsch_stoer, 1e-12), 1e-7}});
    }
    // Not a vacuous test: most cases are well conditioned (measured 323 of 400).
    EXPECT_GT(well, 250);
}

TEST(Dynamics, OnCoarseRecordsTheKernelFollowsTheGeneralPath) {
    // 3000 random blocks under short random records with long pieces (p dt
    // 0.05-0.5, the kernel's longest) and swings of 1-5 alpha: rebounds that
    // outlast their piece, with tops that may be the largest so far, which
    // the kernel takes to the piece's end without locating the top where it
    // can show it below the largest |theta| so far.  Where the run is well
    // conditioned (the probe of the test above), the kernel must agree with
    // the general exact path to 1e-9 alpha (as above) and on every impact,
    // and with rk8pd at rtol 1e-12 to 1e-7 alpha.  Without the bound on the
    // top, 14 of these cases fail (peaks missed, by 8% in case 27); without
    // the concavity at the piece's end, 4.
    RandomDraws U(20261122);
    int well = 0;
    for (int it = 0; it < 3000; ++it) {
        const Model m = U.block(it, Equation::linearised);
        const double alpha = m.block.alpha, p = m.block.p;
        const int n = 10 + static_cast<int>(60 * U());
        const double dt = (0.05 + 0.45 * U()) / p, amplitude = (1 + 4 * U()) * alpha;
        std::vector<double> a(n), b(n);
        for (int k = 0; k < n; ++k) {
            a[k] = amplitude * (2 * U() - 1) * std::exp(-k / (0.5 * n));
            b[k] = a[k] * (1 + 1e-13);
        }
        const SampledInput input(a, dt, "coarse record"), nudged(b, dt, "coarse record, nudged");
        const SimulationResult ref = simulate(m, input, with(SolverKind::exact));
        if (!well_conditioned(ref, simulate(m, nudged, with(SolverKind::exact)), alpha)) continue;
        ++well;
        const std::string what = "case " + std::to_string(it) + ", alpha " + std::to_string(alpha) + ", p " +
                                 std::to_string(p) + ", p dt " + std::to_string(p * dt);
        expect_agreement(ref, m, input, what, {{with(SolverKind::gsl_rk8pd, 1e-12), 1e-7}});
    }
    std::printf("coarse records: %d of 3000 well conditioned\n", well);
    EXPECT_GT(well, 2900);  // measured 2971
}

TEST(Dynamics, StableAtTheExtremes) {
    // x from 1e-4 to 10: ExactSolverIsExactToTheSumsConditionFromXOf1e4To10.
    // Rd -> 1: grazing collapse, just below and just above.
    for (double rd : {1.0 - 1e-9, 1.0 + 1e-9}) {
        const double x = 0.5, alpha = 0.1;
        const PulseInput input(pulse_case(2), q2(x) * rd * alpha, x / 2.0);
        const SimulationResult r = simulate(linear_model(alpha, 2.0), input, with(SolverKind::exact));
        EXPECT_EQ(r.collapse(Criterion::final_rotation, alpha), rd > 1.0) << rd;
    }
    // alpha -> 0 and alpha = 0.35, heights 0.2 m to 50 m, full and linearised:
    // the linearised theta(t_fin) against (S1) in long double to 4 eps of its
    // condition (measured: at most 2.5 eps, 0.3 eps times the condition, which
    // is 2 to 9 here).
    for (double alpha : {1e-4, 0.05, 0.35})
        for (double H : {0.2, 1.0, 50.0}) {
            const Block b = Block::from_half_height(H, alpha);
            const double to = 0.3, x = b.p * to, pga = q2(x) * alpha;
            const PulseInput input(pulse_case(2), pga, to);
            Model lin;
            lin.block = b;
            Model full = lin;
            full.equation = Equation::full;
            SimulationOptions o = with(SolverKind::exact);
            o.free_rocking = false;
            const SimulationResult rl = simulate(lin, input, o);
            const rocking::testing::S1Sum truth = s1_long_double(pulse_case(2), pga, to, alpha, b.p, input.t_end());
            EXPECT_NEAR(rl.theta_at_tfin / alpha, static_cast<double>(truth.phi),
                        4 * std::numeric_limits<double>::epsilon() * static_cast<double>(truth.condition))
                << alpha << " " << H;
            o.solver.kind = SolverKind::dopri5;
            const SimulationResult rf = simulate(full, input, o);
            EXPECT_TRUE(std::isfinite(rf.theta_at_tfin));
            EXPECT_LE(rf.theta_at_tfin, rl.theta_at_tfin * (1 + 1e-9)) << alpha << " " << H;
        }
}

TEST(Dynamics, AMillionSamplesAndAnImpactCascadeEnd) {
    // 10^6 samples: a strong, long record, every solver of the linearised equation.
    const SampledInput big = synthetic_record(0.0005, 500.0, 0.1);
    ASSERT_GE(big.size(), 1000000u);
    const SimulationResult r = simulate(linear_model(0.1, 3.0, 0.9), big, with(SolverKind::exact));
    EXPECT_TRUE(r.uplifted);
    EXPECT_GT(r.impacts, 100);
    EXPECT_FALSE(r.overturned);
    EXPECT_TRUE(std::isfinite(r.theta_at_tfin));
    // GSL's rk8pd at 1e-12 (a second method, its steps ending on the
    // record's samples) agrees on the motion: every impact time within 1e-10 s
    // (measured 4e-12 s) and the peak within 1e-12 rad (measured 8e-15).
    // (When rk8pd stepped across the samples, the first 50 impacts agreed to
    // 1e-6 s only and the cascade's end was decided differently.)
    const SimulationResult r2 = simulate(linear_model(0.1, 3.0, 0.9), big, with(SolverKind::gsl_rk8pd, 1e-12));
    ASSERT_EQ(r2.impact_times.size(), r.impact_times.size());
    for (std::size_t i = 0; i < r.impact_times.size(); ++i) EXPECT_NEAR(r2.impact_times[i], r.impact_times[i], 1e-10) << i;
    EXPECT_NEAR(r2.max_abs_theta_input, r.max_abs_theta_input, 1e-12);
    // A cascade: restitution 0.5 and the ground pushing the block down after a
    // short uplift: impacts shrink geometrically until the block rests.
    std::vector<Pulse> pulses = {{1.0, 1.0}, {-0.05, 40.0}};
    const PulseInput cascade(PulseTrain(pulses), 0.15, 0.2);
    const SimulationResult c = simulate(linear_model(0.1, 3.0, 0.5), cascade, with(SolverKind::exact));
    EXPECT_GE(c.rests, 1);
    EXPECT_LT(c.impacts, 200);
    EXPECT_FALSE(c.overturned);
    const SimulationResult d = simulate(linear_model(0.1, 3.0, 0.5), cascade, with(SolverKind::dopri5, 1e-9));
    EXPECT_GE(d.rests, 1);
}

TEST(Dynamics, RestAndUpliftThresholds) {
    // Below alpha g (linearised) or g tan(alpha) (full) the block never moves.
    const double alpha = 0.2;
    const PulseInput weak(pulse_case(1), alpha * 0.999, 0.3);
    EXPECT_FALSE(simulate(linear_model(alpha), weak, with(SolverKind::exact)).uplifted);
    Model full = linear_model(alpha);
    full.equation = Equation::full;
    const PulseInput between(pulse_case(1), alpha * 1.005, 0.3);  // alpha < 1.005 alpha < tan(alpha)
    EXPECT_TRUE(simulate(linear_model(alpha), between, with(SolverKind::exact)).uplifted);
    EXPECT_FALSE(simulate(full, between, with(SolverKind::dopri5)).uplifted);
    EXPECT_THROW(simulate(full, between, with(SolverKind::exact)), std::invalid_argument);
}

TEST(Dynamics, OneSinePulseStartsRockingAtTimeZero) {
    const double alpha = 0.1, p = 2.0;
    const OneSinePulse pulse(3.0 * alpha, 2.0 * p, alpha);
    EXPECT_NEAR(pulse.accel(0.0), alpha, 1e-15);
    const SimulationResult a = simulate(linear_model(alpha, p), pulse, with(SolverKind::exact));
    const SimulationResult b = simulate(linear_model(alpha, p), pulse, with(SolverKind::rkf78, 1e-12));
    EXPECT_TRUE(a.uplifted);
    EXPECT_NEAR(a.theta_at_tfin, b.theta_at_tfin, 1e-10);
    EXPECT_NEAR(a.max_abs_theta_input, b.max_abs_theta_input, 1e-10);
    EXPECT_EQ(a.overturned, b.overturned);
    EXPECT_THROW(OneSinePulse(0.5 * alpha, 1.0, alpha), std::invalid_argument);
}

namespace {

// x - sin x and sinh x - x without cancellation (series below 0.5).
long double x_minus_sin(long double x) {
    if (std::fabs(x) >= 0.5L) return x - std::sin(x);
    long double term = x * x * x / 6, sum = 0;
    for (int k = 1; k < 12; ++k) sum += term, term *= -x * x / ((2 * k + 2) * (2 * k + 3));
    return sum;
}
long double sinh_minus_x(long double x) {
    if (std::fabs(x) >= 0.5L) return std::sinh(x) - x;
    long double term = x * x * x / 6, sum = 0;
    for (int k = 1; k < 12; ++k) sum += term, term *= x * x / ((2 * k + 2) * (2 * k + 3));
    return sum;
}

// theta(t) of the linearised equation under a_p sin(w t + psi) from rest at
// t = 0 (eq. 3 on the + corner, K = a_p p^2/(p^2 + w^2)):
//   theta = -2 alpha sinh^2(pt/2) + K [sin psi (2 sinh^2(pt/2) + 2 sin^2(wt/2))
//                                      + cos psi ((w/p)(sinh pt - pt) + (wt - sin wt))],
// every bracket a sum of terms of one sign: no cancellation at any a_p.
long double one_sine_theta(long double ap, long double w, long double alpha, long double p, long double t) {
    const long double psi = std::asin(alpha / ap), K = ap * p * p / (p * p + w * w);
    const long double sh = std::sinh(p * t / 2), sn = std::sin(w * t / 2);
    return -2 * alpha * sh * sh +
           K * (std::sin(psi) * (2 * sh * sh + 2 * sn * sn) + std::cos(psi) * ((w / p) * sinh_minus_x(p * t) + x_minus_sin(w * t)));
}

}  // namespace

TEST(Dynamics, AOneSinePulseFallsWhenItsClosedFormSays) {
    // The exact solver's fall time (|theta| = pi/2) against the closed form
    // in long double, up to the strongest pulse taken, 1e9 times the uplift
    // threshold; beyond it the pulse is refused.  Before, 1e20 g fell 6e-6
    // late and from 1e35 g on at the uplift's floor, 1e-15 s.
    struct Block {
        double alpha, wp, p;
    };
    int checked = 0;
    for (const Block& b : {Block{0.1, 10, 2}, Block{0.01, 1, 5}, Block{0.3, 100, 1}, Block{0.05, 0.5, 0.5}})
        for (double ratio : {1e3, 1e6, 1e9}) {
            const double ap = ratio * b.alpha;
            const OneSinePulse pulse(ap, b.wp, b.alpha);
            const SimulationResult r = simulate(linear_model(b.alpha, b.p), pulse, with(SolverKind::exact));
            // The closed form holds during the pulse: a fall after its end is another test's.
            if (one_sine_theta(ap, b.wp, b.alpha, b.p, pulse.t_end()) < M_PI / 2) continue;
            ++checked;
            const long double t = rocking::testing::bisect(
                [&](long double s) { return one_sine_theta(ap, b.wp, b.alpha, b.p, s) - static_cast<long double>(M_PI / 2); },
                0.0L, static_cast<long double>(pulse.t_end()));
            EXPECT_NEAR(r.t_overturn / static_cast<double>(t), 1.0, 1e-11)
                << "alpha " << b.alpha << " w_p " << b.wp << " p " << b.p << " a_p/alpha " << ratio;
        }
    EXPECT_EQ(checked, 11);
    EXPECT_THROW(OneSinePulse(1.01e9 * 0.1, 10, 0.1), std::invalid_argument);
    EXPECT_NO_THROW(OneSinePulse(1e9 * 0.1, 10, 0.1));
}

TEST(Dynamics, WithRestitutionOneAHairlineRockingGoesOnToTheRecordsEnd) {
    // With restitution 1 nothing damps a small rocking: under a constant
    // a0 = 0.5 alpha below the threshold, a block set rocking at theta' =
    // w0 at theta = 0 swings on each corner and comes back at the same speed,
    // for ever.  Each swing ends at the root of its closed form,
    //   u+ = (2/p) atanh(w0 / (p (alpha - a0))),  u- = (2/p) atanh(w0 / (p (alpha + a0))),
    // and theta at most (alpha - a0) (1 - sqrt(1 - r^2)), r = w0 / (p (alpha - a0)),
    // at the middle of a swing on the corner the input pushes away from.  At w0 = 4e-6 rad/s and p = 20 rad/s the swings last 4e-7 s
    // and 1.3e-7 s: 1.1e6 impacts in 0.3 s.  The run used to stop with "impact
    // cascade did not end" at 1e6 impacts, on real records too (e = 1,
    // alpha just below the PGA: 1.06e6 impacts on a Norcia record at p =
    // 0.7 rad/s); the cap is now a guard on run time (1e9), and the first
    // 1e6 impact times are kept.
    const double alpha = 0.1, p = 20.0, a0 = 0.5 * alpha, w0 = 4e-6, T = 0.3;
    const SampledInput input(std::vector<double>(2001, a0), T / 2000, "constant below alpha");
    const long double up = 2 / (long double)p * std::atanh(w0 / (p * (alpha - (long double)a0))),
                      down = 2 / (long double)p * std::atanh(w0 / (p * (alpha + (long double)a0)));
    // Impacts in (0, T]: the swings alternate +, -, +, ... from t = 0.
    long expected = 0;
    for (long double t = 0;; ++expected) {
        t += expected % 2 == 0 ? up : down;
        if (t > T) break;
    }
    const long double r = w0 / (p * (alpha - (long double)a0));
    const double peak = static_cast<double>((alpha - (long double)a0) * r * r / (1 + std::sqrt(1 - r * r)));
    for (bool kernel : {true, false}) {
        SimulationOptions o = with(SolverKind::exact);
        o.solver.record_kernel = kernel;
        o.initial_omega = w0;
        o.free_rocking = false;
        const SimulationResult r = simulate(linear_model(alpha, p, 1.0), input, o);
        const std::string what = kernel ? "record kernel" : "general path";
        // The kernel measures each swing from its record piece's start: its
        // impact times stay within 5e-11 s of the truth over the 1e6 kept
        // and its count is exact to one, its peak to 1e-16 of itself.  The
        // general path measures time from 0, and rounding it (ulp 1.4e-17 s
        // at 0.1 s) moves each impact's rebound by theta'' ulp / theta' ~
        // 1e-10 of itself: a drift that grows like t^3, 6e-7 s (about one
        // cycle) by the 1e6th impact, 4 impacts in the count by 0.3 s, and
        // 2.5e-10 of the peak.
        EXPECT_NEAR(r.impacts, expected, kernel ? 1 : 10) << what;
        EXPECT_GT(expected, 1000000);
        EXPECT_EQ(r.impact_times.size(), o.max_impact_times) << what;
        EXPECT_EQ(r.rests, 0) << what;
        EXPECT_NEAR(r.t_last_impact, T, static_cast<double>(up + down)) << what;
        EXPECT_NEAR(r.max_abs_theta_input, peak, (kernel ? 1e-12 : 1e-8) * peak) << what;
        EXPECT_FALSE(r.overturned) << what;
        // The guard still stops a run past max_impacts, and says which.
        o.max_impacts = 1000;
        try {
            simulate(linear_model(alpha, p, 1.0), input, o);
            ADD_FAILURE() << what << ": no stop at 1000 impacts";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("more than 1000 impacts by t = 0.000267"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("max_impacts"), std::string::npos) << e.what();
        }
    }
}

TEST(Dynamics, JerkIsTheRateOfTheAcceleration) {
    // Model::jerk (theta''' for the driver's check of sinusoidal pieces)
    // against a centred difference of Model::acceleration along theta0 +
    // omega t under a0 + a' t (step 1e-4 s: truncation ~1e-9 of the value).
    for (Equation eq : {Equation::linearised, Equation::full})
        for (int sigma : {1, -1})
            for (double theta : {0.0, 0.05, -0.12}) {
                Model m = linear_model(0.2, 3.0);
                m.equation = eq;
                const double omega = -0.7, a0 = 0.3, rate = 2.5, h = 1e-4;
                const double fd = (m.acceleration(theta + omega * h, sigma, a0 + rate * h) -
                                   m.acceleration(theta - omega * h, sigma, a0 - rate * h)) /
                                  (2 * h);
                const double j = m.jerk(theta, omega, sigma, a0, rate);
                EXPECT_NEAR(j, fd, 1e-7 * std::fabs(j)) << (eq == Equation::full ? "full" : "linearised");
            }
}

TEST(Dynamics, NextSineZeroOfAOneSinePulse) {
    // a = a_p sin(w t + psi) on [0, (2 pi - psi) / w]: its sine crosses 0 at
    // (pi - psi) / w inside, and next at the end; a zero within rounding
    // of t is t's own (no part of zero length).
    const OneSinePulse pulse(0.3, 4.0, 0.1);
    const InputPiece piece = pulse.piece_at(0.0);
    const double z = (M_PI - pulse.psi()) / 4.0;
    EXPECT_NEAR(piece.next_sine_zero(0.0), z, 1e-15);
    EXPECT_NEAR(piece.next_sine_zero(0.5 * z), z, 1e-15);
    EXPECT_EQ(piece.next_sine_zero(z), piece.t1);
    EXPECT_EQ(piece.next_sine_zero(std::nextafter(z, 0.0)), piece.t1);
    EXPECT_EQ(piece.next_sine_zero(z + 0.01), piece.t1);
    EXPECT_NEAR(piece.rate(0.0), 0.3 * 4.0 * std::cos(pulse.psi()), 1e-15);
    const InputPiece linear = PulseInput(pulse_case(1), 0.2, 0.5).piece_at(0.1);
    EXPECT_EQ(linear.next_sine_zero(0.1), linear.t1);
}

TEST(Conservativeness, ClosedFormIsConservativeUnderThePapersCriterionOnItsRange) {
    // The paper's claim (Section 2, Figure 5: x = p to from 0.2 to 0.8) as a
    // tolerance-driven test: for cases 1-5 on a dense grid of x and Rd in
    // [0.5, 0.999] with q_i Rd A_0 > 1, |theta(t_fin)| stays below alpha.  One
    // failing point fails the test.
    const double alpha = 0.1, p = 1.0;
    int points = 0;
    for (int c = 1; c <= 5; ++c)
        for (int ix = 20; ix <= 80; ++ix)
            for (int ir = 0; ir <= 40; ++ir) {
                const double x = ix * 0.01, rd = std::min(0.999, 0.5 + 0.0125 * ir), q = q_case(c, x);
                const PulseTrain train = pulse_case(c);
                if (q * rd * train.pulses().front().amplitude <= 1.0) continue;
                SimulationOptions o = with(SolverKind::exact);
                o.free_rocking = false;
                const SimulationResult r = simulate(linear_model(alpha, p), PulseInput(train, q * rd * alpha, x / p), o);
                ++points;
                EXPECT_LT(std::fabs(r.theta_at_tfin), alpha) << "case " << c << " x " << x << " Rd " << rd;
            }
    EXPECT_GT(points, 10000);
}

TEST(Conservativeness, BeyondThePapersRangeTheBlockCollapsesOnTheOtherSide) {
    // A finding, pinned: above a case-dependent x the reduced input brings the
    // block back to the ground during the input, and the reverse pulse then
    // drives it past -alpha by t_fin.  Smallest failing x on the 0.05 grid:
    const double first_failure[] = {0, 1.55, 2.15, 1.10, 1.05, 1.10};
    const double alpha = 0.1, p = 1.0;
    for (int c = 1; c <= 5; ++c) {
        double smallest = INFINITY;
        for (int ix = 1; ix <= 60; ++ix)
            for (int ir = 0; ir < 40; ++ir) {
                const double x = ix * 0.05, rd = 0.5 + 0.0125 * ir, q = q_case(c, x);
                const PulseTrain train = pulse_case(c);
                if (q * rd * train.pulses().front().amplitude <= 1.0) continue;
                SimulationOptions o = with(SolverKind::exact);
                o.free_rocking = false;
                const SimulationResult r = simulate(linear_model(alpha, p), PulseInput(train, q * rd * alpha, x / p), o);
                if (std::fabs(r.theta_at_tfin) >= alpha) {
                    EXPECT_LT(r.theta_at_tfin, 0.0) << "case " << c << " x " << x << " Rd " << rd;
                    EXPECT_GE(r.impacts, 1) << "case " << c << " x " << x << " Rd " << rd;
                    smallest = std::fmin(smallest, x);
                }
            }
        EXPECT_NEAR(smallest, first_failure[c], 1e-12) << "case " << c;
    }
}

// The solver's own guard behind the commands' refusal of p t above
// kLongestRunTimesP (issue 38): p = 1e20 rad/s, lifted at t = 0.01 alpha / 0.3 g
// = 0.00667 s by a record rising from 0 to 0.3 g in 0.01 s, where a step of
// max_step_p / p is below t's resolution: an error, never an endless loop.
TEST(Dynamics, AStepBelowTheResolutionOfTIsNoProgressNotALoop) {
    const SampledInput ramp({0, 0.3, 0.5}, 0.01, "ramp");
    EXPECT_NE(unresolvable_run(1e20, ramp.t_end()), "");
    EXPECT_EQ(unresolvable_run(1000, 86400), "");  // 1000 rad/s over a day stays within it
    const std::string e = rocking::testing::error_of([&] { simulate(linear_model(0.2, 1e20), ramp, SimulationOptions{}); });
    EXPECT_NE(e.find("no progress at t = 0.00666666666666"), std::string::npos) << e;
}
