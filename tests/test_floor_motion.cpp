// The floor's motion (records/floor_motion.hpp) against independent truths: the
// oscillator's closed-form response to a step, a ramp and a resonant sine (damped,
// and undamped with its envelope growing linearly in time), Nigam & Jennings'
// printed matrices, a fine RK4 integration of a synthetic and a real record, and
// what linearity demands (G = 0 is the ground; twice the ground, twice the floor).
// The derivations and the tolerances' reasons: docs/floor_motion.md ("Tests").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "records/floor_motion.hpp"
#include "records/synthetic.hpp"
#include "test_util.hpp"

using namespace rocking::records;
using rocking::testing::error_of;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
using Long = long double;

// D(t) = Dp(t) + e^(-a t) (P cos b t + Q sin b t), a = zeta w, b = w_d, with the homogeneous
// part set by D(0) = D'(0) = 0; a particular solution Dp of D'' + 2 zeta w D' + w^2 D = -a_g
// gives the response from rest.  Everything in long double, from the formulas alone.
struct Particular {
    Long D, V, A;  // Dp, Dp', Dp'' at t
};
struct Truth {
    Long D, V, A;  // D, D', D'' at t
};
template <class F>
Truth from_rest(F particular, Long w, Long zeta, Long t) {
    const Long a = zeta * w, b = w * std::sqrt((1 - zeta) * (1 + zeta));
    const Particular p0 = particular(Long(0)), p = particular(t);
    const Long P = -p0.D, Q = (a * P - p0.V) / b;
    // d/dt e^(-a t)(P cos + Q sin) = e^(-a t)((-a P + b Q) cos + (-a Q - b P) sin)
    const Long P1 = -a * P + b * Q, Q1 = -a * Q - b * P, P2 = -a * P1 + b * Q1, Q2 = -a * Q1 - b * P1;
    const Long e = std::exp(-a * t), c = std::cos(b * t), s = std::sin(b * t);
    return {p.D + e * (P * c + Q * s), p.V + e * (P1 * c + Q1 * s), p.A + e * (P2 * c + Q2 * s)};
}

struct Case {
    double T1, zeta, dt, G;
    std::size_t n;
};
// w dt from 6e-4 (the printed B's cancellation would lose 7 digits there) to 2.5 (the
// closed-form branch of the step's weights, |z| >= 1); zeta from 0 to 0.7.
const Case kCases[] = {{0.5, 0.05, 0.01, 1.5, 2000},  {0.3, 0.0, 0.005, 1.2, 3000}, {2.0, 0.2, 0.02, 0.8, 1500},
                       {10.0, 0.05, 0.001, 1.3, 20000}, {0.05, 0.05, 0.02, 1.0, 500}, {0.7, 0.7, 0.01, -0.4, 1000}};

double omega(const Case& c) { return 2 * M_PI / c.T1; }

// The largest |x_k - truth_k| / scale over the samples.
template <class F>
double worst(const std::vector<double>& x, F truth, double scale) {
    double m = 0;
    for (std::size_t k = 0; k < x.size(); ++k) m = std::max(m, double(std::fabs(Long(x[k]) - truth(k))) / scale);
    return m;
}

std::vector<double> synthetic_ground() { return stochastic_record(default_stochastic_parameters(), 7, 0.01, 30).accel; }

// RK4 on (D, D') with m steps per sample interval, a_g linear inside each: the input is
// smooth within a step, so the error falls as h^4.
std::vector<double> rk4_floor(const std::vector<double>& a_g, double dt, const FloorModel& mod, int m) {
    const double w = 2 * M_PI / mod.T1, h = dt / m;
    std::vector<double> out(a_g.size());
    double D = 0, V = 0;
    auto floor_of = [&](double a, double d, double v) { return a + mod.G * (-a - 2 * mod.zeta * w * v - w * w * d); };
    out[0] = floor_of(a_g[0], D, V);
    for (std::size_t k = 0; k + 1 < a_g.size(); ++k) {
        const double a0 = a_g[k], slope = (a_g[k + 1] - a_g[k]) / dt;
        auto f = [&](double s, double d, double v, double& dd, double& dv) {
            dd = v;
            dv = -(a0 + slope * s) - 2 * mod.zeta * w * v - w * w * d;
        };
        for (int i = 0; i < m; ++i) {
            const double s = i * h;
            double k1d, k1v, k2d, k2v, k3d, k3v, k4d, k4v;
            f(s, D, V, k1d, k1v);
            f(s + h / 2, D + h / 2 * k1d, V + h / 2 * k1v, k2d, k2v);
            f(s + h / 2, D + h / 2 * k2d, V + h / 2 * k2v, k3d, k3v);
            f(s + h, D + h * k3d, V + h * k3v, k4d, k4v);
            D += h / 6 * (k1d + 2 * k2d + 2 * k3d + k4d);
            V += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        }
        out[k + 1] = floor_of(a_g[k + 1], D, V);
    }
    return out;
}

double largest(const std::vector<double>& x) {
    double m = 0;
    for (double v : x) m = std::max(m, std::fabs(v));
    return m;
}

}  // namespace

// Nigam & Jennings' A and B as printed (in the textbook form of their eqs., e.g. as
// response-spectrum codes use them) against the complex-root form of oscillator_step,
// where their cancellation is mild (w dt >= 0.3: the terms exceed the entries by at most
// (w dt)^-3 / 12 zeta ~ 20 here, so both agree to ~1e-14).
TEST(FloorMotion, StepMatricesAreNigamJenningsPrinted) {
    for (double zeta : {0.0, 0.05, 0.2, 0.7})
        for (double wdt : {0.3, 1.0, 2.5}) {
            const double T1 = 0.7, w = 2 * M_PI / T1, dt = wdt / w, wd = w * std::sqrt(1 - zeta * zeta);
            const double E = std::exp(-zeta * w * dt), S = std::sin(wd * dt), C = std::cos(wd * dt);
            const double r = zeta / std::sqrt(1 - zeta * zeta);
            const double A[2][2] = {{E * (r * S + C), E * S / wd}, {-w / std::sqrt(1 - zeta * zeta) * E * S, E * (C - r * S)}};
            const double t1 = (2 * zeta * zeta - 1) / (w * w * dt), t2 = 2 * zeta / (w * w * w * dt);
            const double B[2][2] = {
                {E * ((t1 + zeta / w) * S / wd + (t2 + 1 / (w * w)) * C) - t2, -E * (t1 * S / wd + t2 * C) - 1 / (w * w) + t2},
                {E * ((t1 + zeta / w) * (C - r * S) - (t2 + 1 / (w * w)) * (wd * S + zeta * w * C)) + 1 / (w * w * dt),
                 -E * (t1 * (C - r * S) - t2 * (wd * S + zeta * w * C)) - 1 / (w * w * dt)}};
            const OscillatorStep s = oscillator_step(T1, zeta, dt);
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j) {
                    EXPECT_NEAR(s.A[i][j], A[i][j], 1e-14 * std::max(std::fabs(A[i][0]), std::fabs(A[i][1])))
                        << "A" << i << j << " zeta " << zeta << " w dt " << wdt;
                    EXPECT_NEAR(s.B[i][j], B[i][j], 1e-13 * std::max(std::fabs(B[i][0]), std::fabs(B[i][1])))
                        << "B" << i << j << " zeta " << zeta << " w dt " << wdt;
                }
        }
}

// Where the printed B cancels (w dt = 6.3e-4 and 6.3e-5: terms of size 2 zeta/(w^3 dt) or
// 1/(w^2 dt) for entries of size dt^2/3 and dt/2, a loss of up to 1e9 in double, measured 6.5e-8
// relative at the first), A and B against the printed forms in 50-digit mpmath
// (docs/floor_motion.md, "The recurrence", gives the snippet): a few ulps, not 1e-8.
TEST(FloorMotion, StepMatricesKeepTheirDigitsAtSmallWdt) {
    struct Exact {
        double T1, zeta, dt, A[4], B[4];
    };
    const Exact cases[] = {
        {10.0, 0.05, 1e-3,
         {0.99999980261205258, 0.00099996851893613309, -0.00039477174781771467, 0.99993697273699436},
         {-3.3332546632416453e-7, -1.6666404541588782e-7, -0.00049997900719608074, -0.00049998951174005234}},
        {100.0, 0.0, 1e-3,
         {0.99999999802607912, 0.00099999999934202639, -3.9478417578381678e-6, 0.99999999802607912},
         {-3.3333333320173862e-7, -1.6666666663376799e-7, -0.00049999999950651979, -0.0004999999998355066}}};
    for (const Exact& c : cases) {
        const OscillatorStep s = oscillator_step(c.T1, c.zeta, c.dt);
        for (int i = 0; i < 4; ++i) {
            EXPECT_NEAR(s.A[i / 2][i % 2], c.A[i], 8 * kEps * std::fabs(c.A[i])) << "A" << i / 2 << i % 2 << " T1 " << c.T1;
            EXPECT_NEAR(s.B[i / 2][i % 2], c.B[i], 8 * kEps * std::fabs(c.B[i])) << "B" << i / 2 << i % 2 << " T1 " << c.T1;
        }
    }
}

// (a) A step of ground acceleration A from rest: D = -A/w^2 (1 - e^(-zeta w t)(cos w_d t +
// zeta/sqrt(1 - zeta^2) sin w_d t)), and a_f = A + G D''.  The record is exactly piecewise
// linear, so only rounding separates them: the same rounded A and B every step turn the
// phase by a fixed error, which adds up linearly, under eps a step: N eps of the scale
// (6.7e-13 for 3000 steps, 4.4e-12 for 20000; measured at most 0.4 eps a step, undamped).
TEST(FloorMotion, StepFromRestIsTheClosedForm) {
    const double A = 1.7;
    for (const Case& c : kCases) {
        const Long w = omega(c);
        auto step = [&](Long) { return Particular{-A / (w * w), 0, 0}; };
        const std::vector<double> a_g(c.n, A);
        const OscillatorResponse o = oscillator_response(a_g, c.dt, c.T1, c.zeta);
        const FloorResponse f = floor_response(a_g, c.dt, {c.T1, c.G, c.zeta});
        auto at = [&](std::size_t k) { return from_rest(step, w, c.zeta, Long(c.dt) * k); };
        const double tol = c.n * kEps;
        EXPECT_LT(worst(o.D, [&](std::size_t k) { return at(k).D; }, A / (w * w)), tol) << "T1 " << c.T1;
        EXPECT_LT(worst(o.V, [&](std::size_t k) { return at(k).V; }, A / w), tol) << "T1 " << c.T1;
        EXPECT_LT(worst(f.accel, [&](std::size_t k) { return A + c.G * at(k).A; }, A), tol) << "T1 " << c.T1;
    }
}

// (b) A ramp a_g = r t from rest: Dp = -r (t - 2 zeta/w)/w^2 plus the free motion that
// starts it at rest (Chopra's ramp response for zeta = 0: -r/w^2 (t - sin(w t)/w)).
TEST(FloorMotion, RampFromRestIsTheClosedForm) {
    const double r = -0.9;  // m/s^3
    for (const Case& c : kCases) {
        const Long w = omega(c);
        auto ramp = [&](Long t) { return Particular{-r * (t - 2 * c.zeta / w) / (w * w), -r / (w * w), 0}; };
        std::vector<double> a_g(c.n);
        for (std::size_t k = 0; k < c.n; ++k) a_g[k] = r * (c.dt * k);
        const FloorResponse f = floor_response(a_g, c.dt, {c.T1, c.G, c.zeta});
        const double scale = std::fabs(r) * c.dt * (c.n - 1);  // the largest |a_g|
        const double got = worst(
            f.accel, [&](std::size_t k) { return Long(a_g[k]) + c.G * from_rest(ramp, w, c.zeta, Long(c.dt) * k).A; },
            scale);
        EXPECT_LT(got, c.n * kEps) << "T1 " << c.T1;
    }
}

// (c) A sine at the building's own frequency, a_g = a0 sin(w t), zeta = 0.05: the steady floor
// motion is a0 sin(w t) - G a0/(2 zeta) cos(w t) (the 1/(2 zeta) amplification of the mode,
// times G, beside the ground's own term), of amplitude a0 sqrt(1 + G^2/(4 zeta^2)).  The
// record samples the sine and is read linear between samples, off the sine by at most
// eps_i = a0 (w dt)^2/8; the oscillator turns an input error bounded by eps_i into an a_1
// error of at most eps_i (w^2 int|h| + 2 zeta w int|h'|) <= eps_i (coth(pi zeta/(2 sqrt(1 -
// zeta^2))) + 2/sqrt(1 - zeta^2)), h the impulse response: the bound each sample is held to.
TEST(FloorMotion, ResonanceReachesOneOverTwoZeta) {
    const double T1 = 1.0, zeta = 0.05, G = 1.4, a0 = 0.8, dt = 1e-4, w = 2 * M_PI / T1;
    const std::size_t n = 600001;  // 60 s: the transient e^(-zeta w t) falls to 6.6e-9
    std::vector<double> a_g(n);
    for (std::size_t k = 0; k < n; ++k) a_g[k] = a0 * std::sin(w * (dt * k));
    const FloorResponse f = floor_response(a_g, dt, {T1, G, zeta});
    auto sine = [&](Long t) {
        return Particular{a0 / (2 * zeta * w * w) * std::cos(w * t), -a0 / (2 * zeta * w) * std::sin(w * t),
                          -a0 / (2 * zeta) * std::cos(w * t)};
    };
    const double eps_i = a0 * (w * dt) * (w * dt) / 8;
    const double bound = std::fabs(G) * eps_i *
                         (1 / std::tanh(M_PI * zeta / (2 * std::sqrt(1 - zeta * zeta))) + 2 / std::sqrt(1 - zeta * zeta));
    double err = 0;
    for (std::size_t k = 0; k < n; k += 7)
        err = std::max(err, double(std::fabs(f.accel[k] - (Long(a_g[k]) + G * from_rest(sine, w, zeta, Long(dt) * k).A))));
    EXPECT_LT(err, bound);
    EXPECT_LT(bound, 2e-5 * a0 * G / (2 * zeta));  // the bound is tight enough to mean something
    // The last period's peak: the steady amplitude, less the sampled crest's miss 1 - cos(w dt/2).
    double peak = 0;
    for (std::size_t k = n - 10000; k < n; ++k) peak = std::max(peak, std::fabs(f.accel[k]));
    const double steady = a0 * std::sqrt(1 + G * G / (4 * zeta * zeta));
    EXPECT_NEAR(peak, steady, bound + steady * (1 - std::cos(w * dt / 2)) + 1e-8 * steady);
}

// (c) Undamped, zeta = 0: a_g = a0 sin(w t) from rest gives D = a0 (w t cos w t - sin w t)/(2 w^2),
// so a_f = a0 (1 - G/2) sin w t - G a0 w t cos(w t)/2: an envelope growing linearly in t.  The
// same interpolation bound, with w^2 int_0^t |h| = w int_0^t |sin w s| ds <= 2 w t/pi + 2:
// eps_i (2 w t/pi + 2), growing with t as the response does.
TEST(FloorMotion, UndampedResonanceGrowsLinearly) {
    const double T1 = 0.8, G = 1.25, a0 = 0.5, dt = 1e-4, w = 2 * M_PI / T1;
    const std::size_t n = 400001;  // 40 s, 50 periods
    std::vector<double> a_g(n);
    for (std::size_t k = 0; k < n; ++k) a_g[k] = a0 * std::sin(w * (dt * k));
    const FloorResponse f = floor_response(a_g, dt, {T1, G, 0.0});
    auto truth = [&](Long t) { return a0 * (1 - G / 2) * std::sin(w * t) - G * a0 * w * t * std::cos(w * t) / 2; };
    const double eps_i = a0 * (w * dt) * (w * dt) / 8;
    for (std::size_t k = 0; k < n; k += 5) {
        const double t = dt * k;
        ASSERT_NEAR(f.accel[k], double(truth(Long(t))), std::fabs(G) * eps_i * (2 * w * t / M_PI + 2)) << "t " << t;
    }
    // The envelope: the peak over the periods ending at 10 s and at 40 s, against
    // sqrt((a0 (1 - G/2))^2 + (G a0 w t/2)^2) at each period's end (the peak lies inside it).
    for (double t_end : {10.0, 40.0}) {
        const std::size_t last = std::size_t(t_end / dt + 0.5), first = last - std::size_t(T1 / dt + 0.5);
        double peak = 0;
        for (std::size_t k = first; k <= last; ++k) peak = std::max(peak, std::fabs(f.accel[k]));
        const double hi = std::hypot(a0 * (1 - G / 2), G * a0 * w * t_end / 2), lo = std::hypot(a0 * (1 - G / 2), G * a0 * w * (t_end - T1) / 2);
        EXPECT_GT(peak, lo * std::cos(w * dt / 2) - 1e-3 * hi) << t_end;
        EXPECT_LT(peak, hi * (1 + 1e-6)) << t_end;
    }
}

// (d) A second method: RK4 with m steps per sample on the same piecewise-linear input.  Its
// error falls as m^-4, so RK4 at m = 8 and 16 must close on the exact recurrence by a factor
// near 16, and the exact answer lie within twice Richardson's estimate |RK8 - RK16|/15 of RK16
// (plus RK16's own rounding, 4e4 steps of eps).  On a synthetic record and, where present,
// the Norcia record of ../shared/records.
TEST(FloorMotion, AgreesWithFineRungeKutta) {
    std::vector<std::pair<std::string, Record>> grounds;
    Record syn = stochastic_record(default_stochastic_parameters(), 7, 0.01, 30);
    grounds.emplace_back("RDK2008 seed 7", syn);
    const std::string norcia = rocking::testing::shared_record("esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC");
    if (std::filesystem::exists(norcia)) grounds.emplace_back("Norcia", read_any(norcia));
    else std::printf("note: %s absent: the synthetic record only\n", norcia.c_str());
    for (const auto& [what, g] : grounds)
        for (const FloorModel m : {FloorModel{0.4, 1.3, 0.05}, FloorModel{1.2, 1.5, 0.02}, FloorModel{0.25, 0.9, 0.1}}) {
            const std::vector<double> nj = floor_record(g, m).accel, rk8 = rk4_floor(g.accel, g.dt, m, 8),
                                      rk16 = rk4_floor(g.accel, g.dt, m, 16);
            double e8 = 0, e16 = 0, gap = 0;
            for (std::size_t k = 0; k < nj.size(); ++k) {
                e8 = std::max(e8, std::fabs(rk8[k] - nj[k]));
                e16 = std::max(e16, std::fabs(rk16[k] - nj[k]));
                gap = std::max(gap, std::fabs(rk8[k] - rk16[k]));
            }
            const double scale = largest(nj), rounding = 16.0 * nj.size() * kEps * scale;
            EXPECT_LT(e16, 2 * gap / 15 + rounding) << what << " T1 " << m.T1;
            EXPECT_GT(e8 / e16, 12) << what << " T1 " << m.T1;
            EXPECT_LT(e8 / e16, 20) << what << " T1 " << m.T1;
            EXPECT_LT(e16, 1e-6 * scale) << what << " T1 " << m.T1;  // a close check, not a loose one
        }
}

// (e) G = 0: the ground itself, sample for sample, bit for bit (a record without -0.0).
TEST(FloorMotion, ZeroParticipationIsTheGround) {
    const std::vector<double> g = synthetic_ground();
    for (double T1 : {0.1, 0.5, 3.0}) {
        const FloorResponse f = floor_response(g, 0.01, {T1, 0.0, 0.05});
        ASSERT_EQ(f.accel.size(), g.size());
        EXPECT_EQ(std::memcmp(f.accel.data(), g.data(), g.size() * sizeof(double)), 0) << T1;
        EXPECT_EQ(f.end_amplitude, 0);
    }
}

// (f) Linear in the record: twice the ground gives twice the floor bit for bit (x2 is exact in
// binary and every operation is linear); a sum of two grounds the sum of their floors within
// rounding, N eps of the largest floor acceleration.
TEST(FloorMotion, LinearInTheRecord) {
    const std::vector<double> g = synthetic_ground();
    const Record pulse = pulse_record({0.3, 1.5, 0.4, 2.0, 2.0}, 0.01, 30);
    const FloorModel m{0.6, 1.4, 0.05};
    std::vector<double> twice(g.size()), sum(g.size());
    for (std::size_t k = 0; k < g.size(); ++k) twice[k] = 2 * g[k], sum[k] = g[k] + pulse.accel[k];
    const std::vector<double> f = floor_response(g, 0.01, m).accel, f2 = floor_response(twice, 0.01, m).accel;
    for (std::size_t k = 0; k < g.size(); ++k) ASSERT_EQ(f2[k], 2 * f[k]) << k;
    const std::vector<double> fp = floor_response(pulse.accel, 0.01, m).accel, fs = floor_response(sum, 0.01, m).accel;
    const double tol = g.size() * kEps * largest(fs);
    for (std::size_t k = 0; k < g.size(); ++k) ASSERT_NEAR(fs[k], f[k] + fp[k], tol) << k;
}

// The end amplitude: a record extended by zeros continues in free vibration, whose floor
// acceleration stays within end_amplitude e^(-zeta w tau) and reaches it at its peaks.
TEST(FloorMotion, EndAmplitudeIsTheFreeVibrationLeftOut) {
    // The pulse spans 0.033 to 1.367 s: the record ends in free vibration, which zeros continue.
    const Record pulse = pulse_record({0.3, 1.5, 0.4, 2.0, 0.7}, 0.001, 1.5);
    const FloorModel m{0.45, 1.3, 0.05};
    const double w = 2 * M_PI / m.T1, dt = 0.001;
    const FloorResponse cut = floor_response(pulse.accel, dt, m);
    std::vector<double> longer = pulse.accel;
    longer.resize(pulse.accel.size() + 2000, 0.0);
    const FloorResponse whole = floor_response(longer, dt, m);
    double ratio = 0;
    for (std::size_t k = pulse.accel.size(); k < longer.size(); ++k) {
        const double tau = dt * (k - (pulse.accel.size() - 1));
        const double r = std::fabs(whole.accel[k]) / (cut.end_amplitude * std::exp(-m.zeta * w * tau));
        ASSERT_LE(r, 1 + 1e-12) << k;
        ratio = std::max(ratio, r);
    }
    EXPECT_GT(ratio, std::cos(w * dt / 2) - 1e-12);
}

TEST(FloorMotion, FloorRecordStatesItsModel) {
    const Record g = stochastic_record(default_stochastic_parameters(), 7, 0.01, 30);
    const Record f = floor_record(g, {0.5, 1.5, 0.05});
    EXPECT_EQ(f.dt, g.dt);
    EXPECT_EQ(f.accel.size(), g.accel.size());
    EXPECT_EQ(f.format, "floor motion");
    EXPECT_EQ(f.name, g.name + ", floor T1=0.5 s zeta=0.05 G=1.5");
    EXPECT_EQ(f.header.at("T1_s"), "0.5");
    EXPECT_EQ(f.header.at("G"), "1.5");
    EXPECT_EQ(f.header.at("zeta"), "0.05");
    EXPECT_NE(f.header.at("method").find("Nigam & Jennings (1969)"), std::string::npos);
    EXPECT_EQ(f.header.at("ground_name"), g.name);
    EXPECT_TRUE(warnings_of(f).empty());
    // 9 steps a period: kept, and warned of (the sampled crest up to 1 - cos(pi/9) = 6 % low).
    const Record coarse = floor_record(g, {0.09, 1.5, 0.05});
    ASSERT_EQ(warnings_of(coarse).size(), 1u);
    EXPECT_NE(warnings_of(coarse)[0].find("T1 = 0.09 s has 9 samples per period at dt = 0.01 s, fewer than 10"),
              std::string::npos)
        << warnings_of(coarse)[0];
    EXPECT_NE(warnings_of(coarse)[0].find("6.031 %"), std::string::npos) << warnings_of(coarse)[0];
}

TEST(FloorMotion, RefusesWhatItCannotModel) {
    const std::vector<double> g(100, 0.1);
    auto parameter_of = [&](const FloorModel& m, double dt) {
        try {
            floor_response(g, dt, m);
        } catch (const FloorModelError& e) {
            return e.parameter + ": " + e.what();
        }
        return std::string("accepted");
    };
    EXPECT_EQ(parameter_of({0, 1, 0.05}, 0.01), "T1: T1 must be > 0 and finite, in s (got 0)");
    EXPECT_EQ(parameter_of({NAN, 1, 0.05}, 0.01), "T1: T1 must be > 0 and finite, in s (got nan)");
    EXPECT_EQ(parameter_of({INFINITY, 1, 0.05}, 0.01), "T1: T1 must be > 0 and finite, in s (got inf)");
    EXPECT_EQ(parameter_of({0.5, 1, 1}, 0.01), "zeta: zeta must be in [0, 1): an oscillator below critical damping (got 1)");
    EXPECT_EQ(parameter_of({0.5, 1, -0.01}, 0.01).substr(0, 6), "zeta: ");
    EXPECT_EQ(parameter_of({0.5, NAN, 0.05}, 0.01), "G: G must be finite (got nan)");
    // Beyond any building's first mode: refused, the bounds themselves taken.
    EXPECT_EQ(parameter_of({1e308, 1.3, 0.05}, 0.01), "T1: T1 must be at most 20 s: no building's first period is longer (got 1e+308)");
    EXPECT_EQ(parameter_of({20, 1.3, 0.05}, 0.01), "accepted");
    EXPECT_EQ(parameter_of({0.5, 1e30, 0.05}, 0.01).substr(0, 20), "G: G must be in [-5,");
    EXPECT_EQ(parameter_of({0.5, -5.5, 0.05}, 0.01).substr(0, 20), "G: G must be in [-5,");
    EXPECT_EQ(parameter_of({0.5, 5, 0.05}, 0.01), "accepted");
    // T1 at 2 dt is refused, just above it taken.
    EXPECT_EQ(parameter_of({0.02, 1, 0.05}, 0.01).substr(0, 40), "T1: T1 = 0.02 s is at most 2 dt = 0.02 s");
    EXPECT_EQ(parameter_of({std::nextafter(0.02, 1.0), 1, 0.05}, 0.01), "accepted");
    EXPECT_NE(error_of([&] { floor_response({}, 0.01, {0.5, 1, 0.05}); }).find("no samples"), std::string::npos);
    EXPECT_NE(error_of([&] { floor_response({0.0, NAN}, 0.01, {0.5, 1, 0.05}); }).find("sample 1 is not finite"),
              std::string::npos);
    EXPECT_NE(error_of([&] { floor_response(g, -0.01, {0.5, 1, 0.05}); }).find("dt must be > 0"), std::string::npos);
    // A floor beyond a double's range: resonance times a huge record.
    std::vector<double> huge(2000);
    for (std::size_t k = 0; k < huge.size(); ++k) huge[k] = 1e307 * std::sin(2 * M_PI * 0.01 * k / 0.5);
    EXPECT_NE(error_of([&] { floor_response(huge, 0.01, {0.5, 1.5, 0.01}); }).find("overflows a double"),
              std::string::npos);
}

TEST(FloorMotion, ParsesTheLoaderOption) {
    const FloorModel a = parse_floor_model("0.5,1.5");
    EXPECT_EQ(a.T1, 0.5);
    EXPECT_EQ(a.G, 1.5);
    EXPECT_EQ(a.zeta, 0.05);
    const FloorModel b = parse_floor_model(" 1.2 , 1.3 ,0.02");
    EXPECT_EQ(b.T1, 1.2);
    EXPECT_EQ(b.G, 1.3);
    EXPECT_EQ(b.zeta, 0.02);
    EXPECT_EQ(error_of([] { parse_floor_model("0.5"); }), "floor model '0.5': takes T1,G[,zeta] (s, -, -), got 1 values");
    EXPECT_EQ(error_of([] { parse_floor_model("0.5,1,0.1,2"); }),
              "floor model '0.5,1,0.1,2': takes T1,G[,zeta] (s, -, -), got 4 values");
    EXPECT_EQ(error_of([] { parse_floor_model("a,1"); }).substr(0, 22), "floor model 'a,1': T1:");
    EXPECT_EQ(error_of([] { parse_floor_model("0.5,,0.1"); }).substr(0, 26), "floor model '0.5,,0.1': G:");
    EXPECT_EQ(error_of([] { parse_floor_model("0.5,1,1"); }),
              "floor model '0.5,1,1': zeta must be in [0, 1): an oscillator below critical damping (got 1)");
    EXPECT_EQ(error_of([] { parse_floor_model("-1,1"); }), "floor model '-1,1': T1 must be > 0 and finite, in s (got -1)");
    try {
        parse_floor_model("0.5,inf");
        FAIL() << "inf accepted";
    } catch (const FloorModelError& e) {
        EXPECT_EQ(e.parameter, "G");
    }
}
