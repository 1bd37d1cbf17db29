// Imperfect blocks (issue 41; dynamics/imperfect_block.hpp) against truth
// that does not come from their code: each corner's inertia, rebound and
// arm by quadrature over the block's own mass (a 2-point Gauss product rule,
// exact for the quadratics involved); the static moment of NTC 2018 eq.
// 7.8.2 for the setback; the closed-form response of eq. 3 on the corner
// theta < 0; the mirror image (swap the corners, flip the input); the
// symmetric limit; and overturning in free rocking decided by simulation
// against Model::may_overturn's one-rebound look-ahead.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "dynamics/imperfect_block.hpp"
#include "dynamics/model.hpp"
#include "dynamics/simulate.hpp"
#include "pulse/pulse_train.hpp"
#include "qfactor/imperfect_q.hpp"

using namespace rocking;
using namespace rocking::dynamics;

namespace {

constexpr double g = kGravity;

// The block's mass as points with weights (total 1): the parallelogram of
// half-width b, height 2h whose axis leans by phi (x = u + v tan phi, its
// base on y = 0 from -b to b), turned about the origin by the lean psi
// toward +x.  2 x 2 Gauss points on each of n x n cells.
struct MassPoint {
    double x, y, w;
};
std::vector<MassPoint> mass_points(double b, double h, double phi, double psi, int n = 4) {
    std::vector<MassPoint> pts;
    const double gp[2] = {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
    const double du = 2 * b / n, dv = 2 * h / n, c = std::cos(psi), s = std::sin(psi);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (double gu : gp)
                for (double gv : gp) {
                    const double u = -b + du * (i + 0.5 + 0.5 * gu), v = dv * (j + 0.5 + 0.5 * gv);
                    const double x = u + v * std::tan(phi), y = v;
                    pts.push_back({x * c + y * s, -x * s + y * c, 1.0 / (4.0 * n * n)});
                }
    return pts;
}

// A pivot on the bed at distance d from its centre, turned with the block.
struct Point {
    double x, y;
};
Point bed_point(double d, double psi) { return {d * std::cos(psi), -d * std::sin(psi)}; }

// By quadrature: the centre of gravity; the inertia about a pivot; the
// angular momentum about `to` of the block turning at unit rate about
// `from` (sum of m r_to x v, v = z x r_from).
Point centre(const std::vector<MassPoint>& m) {
    Point c{0, 0};
    for (const auto& q : m) c = {c.x + q.w * q.x, c.y + q.w * q.y};
    return c;
}
double inertia_about(const std::vector<MassPoint>& m, Point o) {
    double i = 0;
    for (const auto& q : m) i += q.w * ((q.x - o.x) * (q.x - o.x) + (q.y - o.y) * (q.y - o.y));
    return i;
}
double momentum_about(const std::vector<MassPoint>& m, Point from, Point to) {
    double hsum = 0;
    for (const auto& q : m) {
        const double rx = q.x - from.x, ry = q.y - from.y;  // v = (-ry, rx)
        const double sx = q.x - to.x, sy = q.y - to.y;
        hsum += q.w * (sx * rx + sy * ry);                   // s x v
    }
    return hsum;
}

struct Case {
    double b, h, phi, psi, setback;
};

}  // namespace

// Every corner's alpha, R, p and rebound from the block's own mass, by
// quadrature: nothing of imperfect_geometry's formulas (k^2, the dot
// product, the rotation) is used.
TEST(ImperfectBlock, CornersAgreeWithTheMassByQuadrature) {
    const double rho = 1800, fc = 1.5e6;
    for (const Case& c : {Case{0.15, 1.5, 0, 0, 0}, Case{0.15, 1.5, 0.02, 0, 0}, Case{0.2, 1.0, 0, 0.03, 0},
                          Case{0.3, 2.0, -0.05, 0.04, 0}, Case{0.25, 1.2, 0.03, -0.02, 1}}) {
        Imperfection imp;
        imp.out_of_plumb = c.phi;
        imp.lean = c.psi;
        if (c.setback) {
            imp.fc = fc;
            imp.density = rho;
        }
        const ImperfectGeometry geo = imperfect_geometry(c.b, c.h, imp);
        // The setback by NTC 2018 eq. 7.8.2: its moment (l^2 t sigma0 / 2)(1
        // - sigma0 / 0.85 fc) per unit thickness t is the weight times the arm.
        const double sigma0 = rho * g * 2 * c.h, l = 2 * c.b;
        const double mu_ntc = l * l * sigma0 / 2 * (1 - sigma0 / (0.85 * fc));
        const double bp = c.setback ? mu_ntc / (sigma0 * l) : c.b;
        if (c.setback) {
            EXPECT_NEAR(geo.setback, c.b - bp, 1e-15);
        }
        const auto m = mass_points(c.b, c.h, c.phi, c.psi);
        const Point cg = centre(m), pp = bed_point(bp, c.psi), pm = bed_point(-bp, c.psi);
        for (int sigma : {1, -1}) {
            const CornerGeometry& k = sigma > 0 ? geo.plus : geo.minus;
            const Point pv = sigma > 0 ? pp : pm, other = sigma > 0 ? pm : pp;
            const double R = std::hypot(cg.x - pv.x, cg.y - pv.y);
            const double alpha = std::atan2(sigma * (pv.x - cg.x), cg.y - pv.y);
            const double I = inertia_about(m, pv);  // per unit mass
            EXPECT_NEAR(k.alpha, alpha, 1e-14) << c.phi << " " << c.psi << " sigma " << sigma;
            EXPECT_NEAR(k.R, R, 1e-14 * R);
            EXPECT_NEAR(k.p, std::sqrt(g * R / I), 1e-13 * k.p);
            // Landing on this corner from the other: angular momentum about
            // it is kept (the impulse acts there).
            EXPECT_NEAR(k.restitution_onto, momentum_about(m, other, pv) / I, 1e-13);
            EXPECT_LT(k.restitution_onto, 1.0);
        }
        if (c.phi == 0 && c.psi == 0 && !c.setback) {  // the perfect block: eqs. 2, 4 and Housner
            const Block perfect = Block::from_half_dimensions(c.b, c.h);
            EXPECT_NEAR(geo.plus.alpha, perfect.alpha, 1e-15);
            EXPECT_NEAR(geo.plus.p, perfect.p, 1e-14);
            EXPECT_NEAR(geo.plus.restitution_onto, housner_restitution(perfect.alpha), 1e-15);
        }
    }
}

// A lean alone turns the block on its bed: alpha -+ psi, and R, p and the
// restitution of the perfect block on both corners.
TEST(ImperfectBlock, ALeanShiftsAlphaAlone) {
    Imperfection imp;
    imp.lean = 0.03;
    const Block base = Block::from_half_dimensions(0.2, 1.6);
    const ImperfectGeometry geo = imperfect_geometry(0.2, 1.6, imp);
    EXPECT_NEAR(geo.plus.alpha, base.alpha - 0.03, 1e-15);
    EXPECT_NEAR(geo.minus.alpha, base.alpha + 0.03, 1e-15);
    for (const CornerGeometry* k : {&geo.plus, &geo.minus}) {
        EXPECT_NEAR(k->p, base.p, 1e-14);
        EXPECT_NEAR(k->restitution_onto, housner_restitution(base.alpha), 1e-15);
    }
}

TEST(ImperfectBlock, RefusesBlocksThatCannotStand) {
    Imperfection lean;
    lean.lean = 0.13;  // beyond alpha = atan(0.2/1.6) = 0.124
    EXPECT_THROW(imperfect_geometry(0.2, 1.6, lean), std::invalid_argument);
    Imperfection weak;
    weak.fc = 2 * 1800 * g * 1.6 / 0.85 * 0.99;  // 0.85 fc just below sigma0
    EXPECT_THROW(imperfect_geometry(0.2, 1.6, weak), std::invalid_argument);
    Imperfection nan_fc;
    nan_fc.fc = NAN;
    EXPECT_THROW(imperfect_geometry(0.2, 1.6, nan_fc), std::invalid_argument);
}

namespace {

// The block 0.2 x 1.6 m (half-dimensions) with a lean and an out-of-plumb
// angle: every corner quantity differs between the two sides.
Model imperfect(Equation eq, double lean, double phi, double restitution = NAN) {
    Imperfection imp;
    imp.lean = lean;
    imp.out_of_plumb = phi;
    return imperfect_model(eq, Block::from_half_dimensions(0.2, 1.6), imp, restitution);
}

// The same block seen in a mirror: its corners swapped.
Model mirrored(const Model& m) {
    Model r = m;
    r.block = {m.minus.alpha, m.minus.p, 0.0};
    r.restitution = m.minus.restitution;
    r.minus = {m.block.alpha, m.block.p, m.restitution};
    return r;
}

SimulationOptions with(SolverKind kind, double rtol = 1e-12) {
    SimulationOptions o;
    o.solver.kind = kind;
    o.solver.rtol = rtol;
    o.solver.atol_alpha = rtol;
    return o;
}

// A record-like input: three decaying sines, 4 s at 100 Hz, peak about a_g
// (1.6 alpha rocks the 0.4 x 3.2 m block with a few impacts, no fall).
SampledInput shaking(double a_g, double sign = 1.0) {
    std::vector<double> s;
    for (int k = 0; k <= 400; ++k) {
        const double t = 0.01 * k;
        s.push_back(sign * a_g * std::exp(-0.4 * t) *
                    (std::sin(8.4 * t) + 0.6 * std::sin(21.2 * t + 0.4) + 0.3 * std::sin(44.0 * t + 1.0)));
    }
    return SampledInput(s, 0.01, "shaking");
}

}  // namespace

// At rest, a/g lifts the block onto corner +1 only beyond that corner's
// alpha (tan alpha on the full equation), onto -1 only beyond -alpha_minus.
TEST(ImperfectBlock, UpliftsOnEachSideAtItsOwnThreshold) {
    for (Equation eq : {Equation::linearised, Equation::full}) {
        const Model m = imperfect(eq, 0.03, 0.0);
        const double up = eq == Equation::linearised ? m.block.alpha : std::tan(m.block.alpha);
        const double down = eq == Equation::linearised ? m.minus.alpha : std::tan(m.minus.alpha);
        ASSERT_LT(up, down);
        const SolverKind kind = eq == Equation::linearised ? SolverKind::exact : SolverKind::dopri5;
        auto run = [&](double a) { return simulate(m, SampledInput({a, a}, 0.5, "constant"), with(kind, 1e-10)); };
        const double between = 0.5 * (up + down);
        EXPECT_TRUE(run(between).uplifted);
        EXPECT_GT(run(between).theta_at_tfin, 0.0);
        EXPECT_FALSE(run(-between).uplifted);  // below the corner -1's threshold
        EXPECT_FALSE(run(up * (1 - 1e-9)).uplifted);
        EXPECT_TRUE(run(-down * (1 + 1e-6)).uplifted);
        EXPECT_LT(run(-down * (1 + 1e-6)).theta_at_tfin, 0.0);
        // A side's threshold holds on a ramp through it as well: the uplift
        // comes where a/g passes -down, not -up.
        const SimulationResult ramp = simulate(m, SampledInput({0.0, -2 * down}, 1.0, "ramp"), with(kind, 1e-10));
        ASSERT_TRUE(ramp.uplifted);
        ASSERT_FALSE(ramp.impact_times.empty() && std::isnan(ramp.t_first_alpha) && ramp.theta_at_tfin == 0.0);
        EXPECT_LT(ramp.theta_at_tfin, 0.0);
    }
}

// On the corner theta < 0 under a constant a = -A (A > alpha_minus), eq. 3
// with that corner's alpha and p gives theta = (A - alpha_minus)(1 - cosh
// p_minus t), and the full equation keeps its first integral
// theta'^2 / 2 + p^2 [cos(u) + a sin(u)], u = -alpha_minus - theta.
TEST(ImperfectBlock, TheCornerBelowRocksByItsOwnAlphaAndP) {
    const Model lin = imperfect(Equation::linearised, 0.02, 0.03);
    ASSERT_NE(lin.minus.p, lin.block.p);
    const double A = 1.5 * lin.minus.alpha, T = 1.2 / lin.minus.p;
    SimulationOptions o = with(SolverKind::exact);
    o.record_dt = T / 40;
    o.free_rocking = false;
    const SimulationResult r = simulate(lin, SampledInput({-A, -A}, T, "step"), o);
    ASSERT_GT(r.samples.size(), 30u);
    for (const Sample& s : r.samples) {
        const double truth = (A - lin.minus.alpha) * (1 - std::cosh(lin.minus.p * s.t));
        EXPECT_NEAR(s.theta, truth, 1e-13 * lin.minus.alpha) << s.t;
    }
    // Further on, theta reaches -alpha_minus where cosh(p_minus t) = 1 +
    // alpha_minus / (A - alpha_minus): the first alpha is its own side's.
    const SimulationResult on = simulate(lin, SampledInput({-A, -A}, 3 * T, "step"), with(SolverKind::exact));
    EXPECT_NEAR(on.t_first_alpha, std::acosh(1 + lin.minus.alpha / (A - lin.minus.alpha)) / lin.minus.p, 1e-12);
    const Model full = imperfect(Equation::full, 0.02, 0.03);
    SimulationOptions f = with(SolverKind::dopri5, 1e-12);
    f.record_dt = T / 40;
    f.free_rocking = false;
    const double a = -1.5 * std::tan(full.minus.alpha), p2 = full.minus.p * full.minus.p;
    const SimulationResult rf = simulate(full, SampledInput({a, a}, T, "step"), f);
    ASSERT_GT(rf.samples.size(), 30u);
    auto first_integral = [&](const Sample& s) {
        const double u = -full.minus.alpha - s.theta;
        return 0.5 * s.omega * s.omega + p2 * (std::cos(u) + a * std::sin(u));
    };
    const double e0 = first_integral(rf.samples.front());
    double moved = 0;
    for (const Sample& s : rf.samples) {
        EXPECT_NEAR(first_integral(s), e0, 1e-10 * p2) << s.t;
        moved = std::max(moved, -s.theta);
    }
    EXPECT_GT(moved, 0.1 * full.minus.alpha);  // it did rock, on its corner -1
}

// Released from theta0 on corner +1 (eq. 3, ground at rest), the block
// lands on corner -1 at theta' = -p_+ sqrt(alpha_+^2 - (alpha_+ - theta0)^2)
// and leaves it at e times that, e the rebound of the block's own mass about
// the corner landed on (by quadrature, as above); it then rises to theta_m =
// -alpha_- + sqrt(alpha_-^2 - (e theta'/p_-)^2), and back.  The other
// corner's e would miss it by 1e-3 alpha.
TEST(ImperfectBlock, TheImpactKeepsTheMomentumAboutTheCornerLandedOn) {
    const double b = 0.2, h = 1.6, phi = 0.03;
    const Model m = imperfect(Equation::linearised, 0.0, phi);
    const auto mass = mass_points(b, h, phi, 0.0);
    const double e_minus = momentum_about(mass, bed_point(b, 0), bed_point(-b, 0)) / inertia_about(mass, bed_point(-b, 0));
    const double e_plus = momentum_about(mass, bed_point(-b, 0), bed_point(b, 0)) / inertia_about(mass, bed_point(b, 0));
    ASSERT_GT(std::fabs(e_plus - e_minus), 1e-3);
    SimulationOptions o = with(SolverKind::exact);
    const double theta0 = 0.5 * m.block.alpha;
    o.initial_theta = theta0;
    o.record_dt = 1e-4;
    o.free_record_time = 3.0;
    const SimulationResult r = simulate(m, SampledInput({0.0, 0.0}, 1e-3, "rest"), o);
    ASSERT_GE(r.impacts, 2);
    const double ap = m.block.alpha, am = m.minus.alpha;
    const double landing = m.block.p * std::sqrt(ap * ap - (ap - theta0) * (ap - theta0));
    const double w = e_minus * landing / m.minus.p, truth = -am + std::sqrt(am * am - w * w);
    double lowest = 0;
    for (const Sample& s : r.samples)
        if (s.t < r.impact_times[1]) lowest = std::min(lowest, s.theta);
    EXPECT_NEAR(lowest, truth, 1e-6 * am);
}

// The block in a mirror under the input flipped: theta(t) flipped, the same
// impacts, the same outcome, on either equation.
TEST(ImperfectBlock, MirrorImage) {
    for (Equation eq : {Equation::linearised, Equation::full}) {
        const Model m = imperfect(eq, 0.015, -0.02);
        const Model w = mirrored(m);
        const SolverKind kind = eq == Equation::linearised ? SolverKind::exact : SolverKind::gsl_rk8pd;
        SimulationOptions o = with(kind, 1e-12);
        o.record_dt = 0.01;
        const double a = 1.6 * std::max(m.block.alpha, m.minus.alpha);
        const SimulationResult r = simulate(m, shaking(a), o), s = simulate(w, shaking(a, -1.0), o);
        ASSERT_GT(r.impacts, 2);
        EXPECT_EQ(r.impacts, s.impacts);
        EXPECT_EQ(r.overturned, s.overturned);
        ASSERT_EQ(r.samples.size(), s.samples.size());
        for (std::size_t k = 0; k < r.samples.size(); ++k)
            EXPECT_NEAR(r.samples[k].theta, -s.samples[k].theta, 1e-9 * m.block.alpha) << r.samples[k].t;
        for (std::size_t k = 0; k < r.impact_times.size(); ++k)
            EXPECT_NEAR(r.impact_times[k], s.impact_times[k], 1e-9);
        EXPECT_NEAR(r.peak_plus_input, s.peak_minus_input, 1e-9 * m.block.alpha);
        EXPECT_NEAR(r.peak_minus_input, s.peak_plus_input, 1e-9 * m.block.alpha);
    }
}

// The imperfect path with two equal corners is the symmetric block; and as
// the lean goes to 0 the response goes to the symmetric one's linearly.
TEST(ImperfectBlock, SymmetricLimit) {
    const Block base = Block::from_half_dimensions(0.2, 1.6);
    Model sym;
    sym.block = base;
    sym.restitution = housner_restitution(base.alpha);
    Model twin = sym;
    twin.minus = {base.alpha, base.p, sym.restitution};
    ASSERT_FALSE(twin.symmetric());
    SimulationOptions o = with(SolverKind::exact);
    o.record_dt = 0.01;
    const SampledInput in = shaking(1.6 * base.alpha);
    const SimulationResult a = simulate(sym, in, o), b = simulate(twin, in, o);
    ASSERT_GT(a.impacts, 2);
    EXPECT_EQ(a.impacts, b.impacts);
    for (std::size_t k = 0; k < a.samples.size(); ++k) EXPECT_NEAR(a.samples[k].theta, b.samples[k].theta, 1e-14);
    auto gap = [&](double lean) {
        const SimulationResult r = simulate(imperfect(Equation::linearised, lean, 0.0), in, o);
        double d = 0;
        for (std::size_t k = 0; k < a.samples.size(); ++k) d = std::max(d, std::fabs(r.samples[k].theta - a.samples[k].theta));
        return d;
    };
    const double d4 = gap(1e-4), d5 = gap(1e-5), d6 = gap(1e-6);
    EXPECT_GT(d4, 0.0);
    EXPECT_NEAR(d5 / d4, 0.1, 0.02);
    EXPECT_NEAR(d6 / d5, 0.1, 0.02);
}

// After the input, free rocking decides: a block on its stocky corner below
// that corner's barrier still overturns when its rebound onto the slender
// corner carries it over the top there.  Simulated far past the look-ahead's
// horizon, the fall or its absence against Model::may_overturn.
TEST(ImperfectBlock, MayOverturnLooksOneReboundAhead) {
    for (double e : {1.0, double(NAN)}) {
        const Model m = imperfect(Equation::full, 0.04, 0.0, e);  // alpha 0.084 on +1, 0.164 on -1
        SimulationOptions o = with(SolverKind::gsl_rk8pd, 1e-12);
        o.free_record_time = 30;
        const SampledInput quiet({0.0, 0.0}, 0.001, "rest");
        int both = 0;
        for (double w = 0.05; w < 0.6; w += 0.01) {
            o.initial_theta = -0.5 * m.minus.alpha;
            o.initial_omega = w * m.minus.p;  // toward the ground, then onto corner +1
            const bool predicted = m.may_overturn(o.initial_theta, o.initial_omega, -1);
            const bool below_own = m.energy(o.initial_theta, o.initial_omega, -1) < m.barrier_on(-1);
            const SimulationResult r = simulate(m, quiet, o);
            EXPECT_EQ(!std::isnan(r.t_overturn), predicted) << "e " << e << " w " << w;
            if (predicted && below_own) ++both;
        }
        EXPECT_GT(both, 0) << "no state below its own barrier that overturns on the other corner (e " << e << ")";
    }
}

TEST(ImperfectBlock, CollapseMeasuresEachSideByItsAlpha) {
    SimulationResult r;
    r.theta_at_tfin = -0.12;
    r.peak_minus_input = 0.12;
    r.max_abs_theta_input = 0.12;
    EXPECT_FALSE(r.collapse(Criterion::final_rotation, 0.1, 0.15));
    EXPECT_FALSE(r.collapse(Criterion::peak_rotation, 0.1, 0.15));
    EXPECT_TRUE(r.collapse(Criterion::final_rotation, 0.1));
    r.theta_at_tfin = 0.11;
    r.peak_plus_input = 0.11;
    EXPECT_TRUE(r.collapse(Criterion::final_rotation, 0.1, 0.15));
    EXPECT_TRUE(r.collapse(Criterion::peak_rotation, 0.1, 0.15));
}

// The uplift of an imperfect block from rest: the first time a/g > up or
// a/g < -down on a record (linear between samples), against a scan written
// here; with up = down, first_above's.  A crossing that first_above has just
// located at one level once rounded below its own piece and was skipped to
// the next sample (2.5 ms late on a real record).
TEST(ImperfectBlock, UpliftTimeOnARecordAgainstAScan) {
    std::vector<double> a;
    unsigned state = 12345;
    for (int k = 0; k <= 3000; ++k) {
        state = state * 1103515245u + 12345u;
        a.push_back(0.3 * std::sin(0.013 * k) * std::sin(0.0021 * k) + 0.02 * ((state >> 16) % 1000 / 500.0 - 1.0));
    }
    const double dt = 0.005;
    const SampledInput in(a, dt, "noise");
    auto scan = [&](double t0, double up, double down) {
        for (std::size_t k = static_cast<std::size_t>(t0 / dt); k + 1 < a.size(); ++k) {
            const double ta = std::max(t0, k * dt), c1 = (a[k + 1] - a[k]) / dt;
            const double at = a[k] + c1 * (ta - k * dt);
            if (at > up || -at > down) return ta;
            if (c1 > 0 && a[k + 1] > up) return k * dt + (up - a[k]) / c1;
            if (c1 < 0 && -a[k + 1] > down) return k * dt + (-down - a[k]) / c1;
        }
        return double(INFINITY);
    };
    int found = 0;
    for (double t0 : {0.0, 1.234, 4.0, 7.77, 11.0})
        for (double up : {0.05, 0.1, 0.2})
            for (double down : {0.05, 0.12, 0.25}) {
                const double t = first_beyond(in, t0, in.t_end(), up, down), truth = scan(t0, up, down);
                if (std::isinf(truth)) {
                    EXPECT_TRUE(std::isinf(t));
                    continue;
                }
                ++found;
                EXPECT_NEAR(t, truth, 1e-12) << t0 << " " << up << " " << down;
                if (up == down) {
                    EXPECT_EQ(t, in.first_above(t0, in.t_end(), up));
                }
                // From the crossing just found at one level, the other is next.
                const double again = first_beyond(in, t, in.t_end(), up, down);
                EXPECT_NEAR(again, t, 1e-12);
            }
    EXPECT_GT(found, 30);
    // A one-sine pulse (a sinusoidal piece): its first a/g > up or < -down,
    // against a scan at 1e-6 s refined by bisection here.
    const OneSinePulse sine(0.3, 5.0, 0.05);
    for (double up : {0.1, 0.25})
        for (double down : {0.15, 0.28}) {
            auto beyond = [&](double s) { return sine.accel(s) > up || -sine.accel(s) > down; };
            double lo = 0, hi = NAN;
            for (double s = 0; s < sine.t_end(); s += 1e-6)
                if (beyond(s)) {
                    hi = s;
                    break;
                }
                else lo = s;
            ASSERT_FALSE(std::isnan(hi));
            for (int it = 0; it < 60; ++it) (beyond(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
            EXPECT_NEAR(first_beyond(sine, 0.0, sine.t_end(), up, down), hi, 1e-12) << up << " " << down;
        }
}

// The closed-form collapse PGA toward each corner (qfactor/imperfect_q.hpp)
// against the event-driven run of the imperfect block: theta(t_fin) passes
// its side's alpha just above it and not just below (eq. 11 on that corner,
// no impact: where the excursion stays positive).  Toward theta < 0 the
// train is the mirror image: the mirrored block under the train as given
// (MirrorImage shows the two are one run).
TEST(ImperfectBlock, ClosedFormCollapseTowardEachCorner) {
    const Model m = imperfect(Equation::linearised, 0.015, 0.025);
    int checked = 0;
    for (int which : {1, 2, 4})
        for (double x : {0.5, 1.0, 2.0, 4.0}) {
            const PulseTrain train = pulse_case(which);
            const double to = x / m.block.p;
            const ImperfectCollapse c =
                imperfect_collapse(train, to, {m.block.alpha, m.block.p}, {m.minus.alpha, m.minus.p});
            EXPECT_NEAR(c.toward_plus.x, x, 1e-15 * x);
            for (int side : {1, -1}) {
                const DirectionalCollapse& d = side > 0 ? c.toward_plus : c.toward_minus;
                if (!d.excursion.stays_positive()) continue;
                const Model run_model = side > 0 ? m : mirrored(m);
                SimulationOptions o = with(SolverKind::exact);
                o.free_rocking = false;
                auto collapses = [&](double factor) {
                    const SimulationResult r = simulate(run_model, PulseInput(train, d.pga_g * factor, to), o);
                    return r.collapse(Criterion::final_rotation, run_model.block.alpha, run_model.minus.alpha);
                };
                EXPECT_TRUE(collapses(1 + 1e-9)) << which << " x " << x << " side " << side;
                EXPECT_FALSE(collapses(1 - 1e-9)) << which << " x " << x << " side " << side;
                ++checked;
            }
            EXPECT_EQ(c.pga_g(), std::min(c.toward_plus.pga_g, c.toward_minus.pga_g));
        }
    EXPECT_GT(checked, 15);
}
