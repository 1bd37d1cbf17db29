#include "dynamics/exact_record.hpp"

#include "dynamics/run_rules.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace rocking::dynamics {

namespace {

// The even series of the closed form, in y = x^2:
//   ch1(y) = (cosh x - 1) / x^2 = 1/2! + y/4! + y^2/6! + ...
//   sh1(y) = (sinh x - x) / x^3 = 1/3! + y/5! + y^2/7! + ...
// to y^8, whose first term left out is below 1e-21 relative for x <= 0.6
// (every piece of the kernel: p dt <= max_step_p = 0.5 by default) and
// below 1e-17 for x <= 1; beyond, from cosh and sinh (a few bits lost to
// the cancellation of sinh x - x, on pieces no default option produces).
// They carry cosh x - 1 = y ch1 and sinh x - x = x y sh1 without the
// cancellation of the differences.
template <class Real>
void series(Real y, Real& ch1, Real& sh1) {
    if (y > 1) {
        const Real x = std::sqrt(y);
        ch1 = (std::cosh(x) - 1) / y;
        sh1 = (std::sinh(x) - x) / (x * y);
        return;
    }
    // 1/n! as constants: the divisions are done once, at compile time.
    // Shorter sums where the terms left out stay below 2e-20 relative: to
    // y^3 below y = 4e-4 (x < 0.02: a record piece of a block with p dt ~
    // 0.01, every rebound of a cascade), to y^5 below y = 0.01.
    if (y < Real(4e-4)) {
        ch1 = Real(1) / 2 + y * (Real(1) / 24 + y * (Real(1) / 720 + y * (Real(1) / 40320)));
        sh1 = Real(1) / 6 + y * (Real(1) / 120 + y * (Real(1) / 5040 + y * (Real(1) / 362880)));
        return;
    }
    if (y < Real(0.01)) {
        ch1 = Real(1) / 2 +
              y * (Real(1) / 24 + y * (Real(1) / 720 + y * (Real(1) / 40320 + y * (Real(1) / 3628800 +
                                                                                   y * (Real(1) / 479001600)))));
        sh1 = Real(1) / 6 +
              y * (Real(1) / 120 + y * (Real(1) / 5040 + y * (Real(1) / 362880 + y * (Real(1) / 39916800 +
                                                                                      y * (Real(1) / 6227020800.0L)))));
        return;
    }
    ch1 = Real(1) / 2 +
          y * (Real(1) / 24 +
               y * (Real(1) / 720 +
                    y * (Real(1) / 40320 +
                         y * (Real(1) / 3628800 +
                              y * (Real(1) / 479001600 +
                                   y * (Real(1) / 87178291200.0L +
                                        y * (Real(1) / 20922789888000.0L + y * (Real(1) / 6402373705728000.0L))))))));
    sh1 = Real(1) / 6 +
          y * (Real(1) / 120 +
               y * (Real(1) / 5040 +
                    y * (Real(1) / 362880 +
                         y * (Real(1) / 39916800 +
                              y * (Real(1) / 6227020800.0L +
                                   y * (Real(1) / 1307674368000.0L +
                                        y * (Real(1) / 355687428096000.0L + y * (Real(1) / 121645100408832000.0L))))))));
}

// The linearised equation on corner sigma, over a piece where the record is
// linear, a(t + u)/g = a0 + c1 u, from the state (theta0, omega0) at t:
//   theta''(u) = p^2 (theta + a0 + c1 u - sigma alpha)   (eq. 3, corrected sign)
//   theta(u)   = C cosh pu + D sinh pu - lin - c1 u,      lin = a0 - sigma alpha,
//   C = theta0 + lin, D = (omega0 + c1) / p = W / p
// (the same closed form as ExactStepper's, exact_stepper.cpp), written as
// increments on the state, x = pu, y = x^2:
//   theta(u)        = theta0 + omega0 u + C y ch1 + W u y sh1,
//   theta'(u)       = omega0 + p C x (1 + y sh1) + W y ch1,
//   theta''(u)/p^2  = C (1 + y ch1) + W u (1 + y sh1).
// Each term is a correction of the state, so the rounding is relative to
// theta and theta', not to alpha: the general form's C cosh - lin carries an
// error eps alpha, which divided by theta' at an impact is an error in its
// time (eps alpha / theta', 1e-13 s on a rebound of 1e-4 rad/s).
template <class Real>
struct Closed {
    Real p, theta0, omega0, C, W;

    struct Point {
        Real theta, omega, curvature;  // curvature: theta''/p^2
    };
    Point at(Real u) const {
        const Real x = p * u, y = x * x;
        Real ch1, sh1;
        series(y, ch1, sh1);
        const Real k1 = y * ch1, s0 = 1 + y * sh1;  // cosh x - 1, sinh x / x
        return {theta0 + omega0 * u + C * k1 + W * u * y * sh1, omega0 + p * C * x * s0 + W * k1,
                C * (1 + k1) + W * u * s0};
    }
    // Rounding levels of theta, theta' and theta''/p^2 on [0, u1] (four
    // ulps of the largest term; k1 = cosh pu1 - 1).
    Real theta_noise(Real u1, Real k1) const {
        return 4 * std::numeric_limits<Real>::epsilon() *
               (std::fabs(theta0) + std::fabs(omega0) * u1 + (std::fabs(C) + std::fabs(W) * u1) * k1);
    }
    Real omega_noise(Real u1, Real k1) const {
        return 4 * std::numeric_limits<Real>::epsilon() *
               (std::fabs(omega0) + (p * std::fabs(C) * p * u1 + std::fabs(W)) * (1 + k1));
    }
    Real curvature_noise(Real u1, Real k1) const {
        return 4 * std::numeric_limits<Real>::epsilon() * (std::fabs(C) + std::fabs(W) * u1) * (1 + k1);
    }
};

// The root of f on [lo, hi], given f(lo) and f(hi) of opposite signs, by
// Newton's method from the false-position point, each iterate kept inside the
// shrinking bracket (bisection otherwise); fdf(u) gives {f(u), f'(u)}.
// Newton's steps shrink quadratically until f is down to its rounding level
// f_noise: the iteration stops after the step from there, or at a step below
// 2 ulps of the iterate.
// Conventions as the general path's locate(): f(hi) = 0 gives hi; f(lo) = 0,
// or no sign change (rounding at a root just located), gives lo.  A caller
// that knows a better first point than false position gives it as start.
template <class Real, class FDF>
Real newton_root(FDF fdf, Real lo, Real hi, Real flo, Real fhi, Real f_noise, Real start = NAN) {
    if (fhi == 0.0) return hi;
    if (flo == 0.0 || (flo < 0) == (fhi < 0)) return lo;
    const Real flip = flo < 0 ? 1 : -1;  // orient so that f(a) < 0 < f(b)
    Real a = lo, b = hi;
    Real x = std::isnan(start) ? lo + (hi - lo) * (flo / (flo - fhi)) : start;
    if (!(x >= a && x <= b)) x = 0.5 * (a + b);
    const Real eps = std::numeric_limits<Real>::epsilon();
    for (int i = 0; i < 100; ++i) {
        const auto v = fdf(x);
        const Real f = flip * v.first, df = flip * v.second;
        if (f < 0) a = x;
        else b = x;
        Real next = x - f / df;
        // At the rounding level, one last step (no further evaluation) takes
        // off the part of the error f / f' that f still resolves.
        if (std::fabs(f) <= f_noise) return next >= a && next <= b ? next : x;
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        if (std::fabs(next - x) <= 2 * eps * std::fabs(x) || b - a <= 2 * eps * std::fmax(std::fabs(a), std::fabs(b)))
            return next;
        x = next;
    }
    return x;
}

// The first root s > 0 of fa + fpa s + fpp s^2 / 2 (Taylor's polynomial of
// f at a bracket's start: Newton's first point), NaN when it has none.
template <class Real>
Real quadratic_root(Real fa, Real fpa, Real fpp) {
    const Real disc = fpa * fpa - 2 * fa * fpp;
    if (!(disc >= 0)) return NAN;
    const Real q = fpa + std::copysign(std::sqrt(disc), fpa);  // no cancellation
    const Real s1 = q != 0 ? -2 * fa / q : Real(NAN), s2 = fpp != 0 ? -q / fpp : Real(NAN);
    Real best = NAN;
    for (Real s : {s1, s2})
        if (s > 0 && !(s >= best)) best = s;
    return best;
}

// Where theta' vanishes inside [lo, hi], given theta' = om_lo and om_hi of
// opposite signs at the ends and theta'' of one sign between: Newton on
// theta', to its rounding level om_noise.
template <class Real>
Real extremum_time(const Closed<Real>& f, Real lo, Real hi, Real om_lo, Real om_hi, Real om_noise) {
    return newton_root<Real>(
        [&f](Real u) {
            const typename Closed<Real>::Point q = f.at(u);
            return std::make_pair(q.omega, f.p * f.p * q.curvature);
        },
        lo, hi, om_lo, om_hi, om_noise);
}

// A bounce: the block leaves theta = 0 with theta' = omega (sigma omega > 0)
// on a piece where the record is linear, a0 + c1 u.  With C = lin
// (theta0 = 0), x = p u, y = x^2 and the even series
//   ch1(y) = (cosh x - 1) / x^2 = 1/2 + y/24 + y^2/720 + ...
//   sh1(y) = (sinh x - x) / x^3 = 1/6 + y/120 + y^2/5040 + ...
// the closed form divided by u (its root at u = 0 taken out) is
//   g(u) = theta(u) / u = omega + p lin x ch1 + (omega + c1) y sh1,
//   g'(u) = p^2 lin (1 + y sh1 - ch1) + p x (omega + c1) (ch1 - sh1),
// every term a correction to omega; the state at the landing is Closed's
// with theta0 = 0.
template <class Real>
struct Bounce {
    Real p, omega, lin, c1;

    // The landing: the first root u > 0 of theta, by Newton on g from the
    // parabola's root -2 omega / (p^2 lin); NaN when the iteration does not
    // settle within 8 steps or leaves (0, u_max).
    Real landing(Real u_max) const {
        const Real eps = std::numeric_limits<Real>::epsilon();
        Real u = -2 * omega / (p * p * lin);
        for (int i = 0; i < 8; ++i) {
            if (!(u > 0 && u < u_max)) return NAN;
            const Real x = p * u, y = x * x;
            Real ch1, sh1;
            series(y, ch1, sh1);
            const Real g = omega + p * lin * x * ch1 + (omega + c1) * y * sh1;
            const Real dg = p * p * lin * (1 + y * sh1 - ch1) + p * x * (omega + c1) * (ch1 - sh1);
            const Real next = u - g / dg;
            if (std::fabs(next - u) <= 4 * eps * u) return next > 0 && next < u_max ? next : Real(NAN);
            u = next;
        }
        return NAN;
    }
};

}  // namespace

bool record_kernel_applies(const Model& model, const GroundInput& input, const SimulationOptions& options) {
    if (options.solver.kind != SolverKind::exact || !options.solver.record_kernel) return false;
    if (model.equation != Equation::linearised || options.record_dt > 0.0) return false;
    const auto* sampled = dynamic_cast<const SampledInput*>(&input);
    // Longer pieces are split by ExactStepper (max_step_p); the kernel keeps
    // to pieces it takes whole, as the general path does.
    return sampled != nullptr && model.block.p * sampled->dt() <= options.solver.max_step_p;
}

namespace {

template <class Real>
SimulationResult run_kernel(const Model& model, const SampledInput& input, const SimulationOptions& options) {
    const Real alpha = model.block.alpha, p = model.block.p;
    const std::vector<double>& a = input.samples();
    const Real dt = input.dt(), inv_dt = 1.0 / dt, inv_p = 1.0 / p;
    const Real t_fin = input.t_end();
    const Real h_free = options.solver.max_step_p / p;  // step of the free rocking (ground at rest)
    // A whole piece's constants: cosh p dt - 1, sinh p dt and
    // (sinh p dt - p dt) / p (the increments of the closed form, Closed).
    Real ch1_dt, sh1_dt;
    series(p * dt * p * dt, ch1_dt, sh1_dt);
    const Real k1_dt = p * dt * p * dt * ch1_dt, s_dt = p * dt * (1 + p * dt * p * dt * sh1_dt),
               q_dt = dt * p * dt * p * dt * sh1_dt;
    const Real noise = 1e-12 * alpha;  // the general path's "rose" rule (simulate.cpp)
    const Real rest = options.rest_velocity;

    SimulationResult result;
    result.t_fin = t_fin;
    rules::RunState<Real> run(options, t_fin);
    // The state itself (run's fields), under the names of the equations.
    Real &t = run.t, &theta = run.theta, &omega = run.omega;
    int& sigma = run.sigma;
    bool done = false;
    std::size_t k = 0;  // the record piece holding t, while t < t_fin
    Real max_theta = 0;  // largest |theta| on [0, t_fin]

    auto note_theta = [&](Real when, Real value) {
        if (when <= t_fin) max_theta = std::max(max_theta, std::fabs(value));
    };
    // The rest of record piece j from s (s < t_fin, j holding s): the record
    // a0 + c1 u over 0 <= u <= u1.  The samples sit at j dt exactly; s and
    // the piece's end are that grid rounded.  A whole piece (s = j dt as
    // computed) is dt long, from a[j]; a part of one is measured from the
    // exact grid, fma rounding (j + 1) dt - s once (the rounded end minus s
    // would carry the end's rounding, which c1 turns into an error
    // ~ c1 ulp(s), far above theta's).  rest_of_piece(): piece k from t.
    struct Rest {
        Real a0, c1, u1;
    };
    auto rest_of_piece_at = [&](std::size_t j, Real s) -> Rest {
        const Real c1 = (a[j + 1] - a[j]) * inv_dt;
        if (s == dt * j) return {Real(a[j]), c1, dt};
        return {a[j] + c1 * std::fma(-Real(j), dt, s), c1, std::max(Real(0), std::fma(Real(j + 1), dt, -s))};
    };
    auto rest_of_piece = [&]() { return rest_of_piece_at(k, t); };
    // A block just lifted from rest at t, where uplift_time made the input
    // exceed the threshold as SampledInput::accel evaluates it, from the
    // rounded grid: the exact grid above can put it up to ~ c1 ulp(t) lower,
    // below the threshold, and the block would start pressed into the ground,
    // return to it within rounding and rest to the piece's end, losing the
    // motion there.  t moves on until this interpolation exceeds it too.
    auto lift_on_own_input = [&]() {
        t = move_until(static_cast<double>(t), static_cast<double>(t_fin),
                       [&](double s) { return sigma * rest_of_piece_at(input.piece_index(s), s).a0 > alpha; });
        k = input.piece_index(static_cast<double>(t));
    };

    // The level that sigma theta, rising from s, must stay below for nothing
    // to happen: the first alpha while it is to come, the fall angle.
    auto upper_from = [&](Real s) -> Real {
        return std::isnan(result.t_first_alpha) && s < alpha ? std::min(alpha, Real(options.overturn_angle))
                                                             : Real(options.overturn_angle);
    };
    // An impact at u_impact on the closed form f of the piece from t, and the
    // rebounds after it that land inside the same record piece.
    auto impact_at = [&](const Closed<Real>& f, Real u_impact) {
        const Real om_i = f.at(u_impact).omega;
        const Real t_impact = t + u_impact;
        note_theta(t_impact, 0.0);
        const bool micro = rules::record_impact(result, t_impact, options, p);
        rules::apply_impact(run, result, model, t_impact, om_i, micro, rest);
        // The rebounds that land inside the same record piece (an impact
        // cascade) go by the bounce form, one Newton solve each, while it can
        // be shown that nothing else happens on the way: sigma theta'' < 0 at
        // both ends (theta'' has one sign change at most, so sigma theta is
        // concave: one rise, one fall, no dip), and the rise below the bound
        // of a concave arc, so below the largest |theta| so far and below
        // alpha when alpha has not been reached.  Otherwise the rest of the
        // piece goes back to the piece analysis.
        while (!run.resting && t < t_fin && t < dt * (k + 1)) {
            const Rest piece = rest_of_piece();
            const Real lin_b = piece.a0 - sigma * alpha;
            const Real u_max = std::min(piece.u1, Real(0.1) * inv_p);
            if (!(sigma * lin_b < 0)) break;
            const Real u_land = Bounce<Real>{p, omega, lin_b, piece.c1}.landing(u_max);
            if (std::isnan(u_land)) break;
            const typename Closed<Real>::Point land =
                Closed<Real>{p, 0, omega, lin_b, omega + piece.c1}.at(u_land);
            const Real om_land = land.omega;
            if (!(sigma * land.curvature < 0 && sigma * om_land < 0)) break;
            // On the concave arc theta <= omega u and theta <= |omega_land| (u_land - u).
            const Real w0 = std::fabs(omega), w1 = std::fabs(om_land);
            if (!(w0 * w1 * u_land < max_theta * (w0 + w1))) break;
            ++result.steps;
            const Real t_land = t + u_land;
            const bool micro_b = rules::record_impact(result, t_land, options, p);
            rules::apply_impact(run, result, model, t_land, om_land, micro_b, rest);
        }
    };

    while (!done && rules::begin_pass(run, result, model, input, options, t_fin, note_theta, [](Real) {})) {
        if (theta == 0.0 && omega == 0.0 && t < t_fin) lift_on_own_input();
        const Real t_stop = t < t_fin ? t_fin : run.t_limit;
        bool rose = std::fabs(theta) > noise || std::fabs(omega) > 0.0;
        bool event = false;
        while (!event && t < t_stop) {
            // Quiet whole pieces, a handful of flops each: nothing can happen
            // inside a piece whose ends have sigma theta > noise, theta' of one
            // sign and theta'' of one sign (theta' monotone: no extremum), sigma
            // theta below the fall angle and no first crossing of alpha.
            if (t < t_fin) {
                if (!(dt * k <= t && t < dt * (k + 1))) k = input.piece_index(t);
                const Real sa = sigma * alpha;
                const Real upper = upper_from(sigma * theta);
                const std::size_t k0 = k;
                Real peak = 0.0;
                if (t == dt * k) {
                    while (k + 1 < a.size()) {  // t_stop = t_fin here
                        const Real c1 = (a[k + 1] - a[k]) * inv_dt, lin = a[k] - sa;
                        const Real C = theta + lin, W = omega + c1;
                        const Real th1 = theta + omega * dt + C * k1_dt + W * q_dt;
                        const Real om1 = omega + p * C * s_dt + W * k1_dt;
                        const Real e1 = C * (1 + k1_dt) + W * inv_p * s_dt;  // theta''/p^2 at the end
                        const Real s1 = sigma * th1;
                        // C e1 > 0: theta'' of one sign at both ends, so theta'
                        // is monotone (an underflow to 0 only sends the piece
                        // to the full analysis).
                        if (!(s1 > noise && s1 < upper && C * e1 > 0.0)) break;
                        if (!(omega * om1 > 0.0)) {
                            // theta' changes sign once: one extremum of theta.
                            // Its value is bounded by where the tangents at the
                            // ends meet, v = s0 + w0 (s1 - s0 + w1 dt) / (w0 + w1)
                            // (w0 = sigma theta'(0), w1 = -sigma theta'(dt)): from
                            // above for a maximum of sigma theta (sigma theta''
                            // < 0), from below for a minimum.  The piece stays
                            // quiet when the bound keeps a maximum below the
                            // first alpha and the fall angle, or a minimum above
                            // the ground; a maximum that may be the largest
                            // |theta| so far is located.  The bound's margin,
                            // 1e-9 relative, is far above its rounding.
                            const Real s0 = sigma * theta, w0 = sigma * omega, w1 = -sigma * om1;
                            if (!(s0 > noise && omega * om1 < 0.0)) break;
                            const Real v = s0 + w0 * ((s1 - s0 + w1 * dt) / (w0 + w1));
                            if (sigma * C < 0.0) {
                                if (!(v < upper * Real(1 - 1e-9))) break;
                                if (!(v < std::max(peak, max_theta) * Real(1 - 1e-9))) {
                                    const Closed<Real> f{p, theta, omega, C, W};
                                    const Real u = extremum_time(f, Real(0), dt, omega, om1, f.omega_noise(dt, k1_dt));
                                    peak = std::max(peak, sigma * f.at(u).theta);
                                }
                            } else if (!(v > 2 * noise)) {
                                break;
                            }
                        }
                        ++k;
                        theta = th1;
                        omega = om1;
                        peak = std::max(peak, s1);
                    }
                }
                if (k != k0) {
                    t = dt * k;
                    rose = true;
                    max_theta = std::max(max_theta, peak);
                    result.steps += static_cast<long>(k - k0);
                }
                if (!(t < t_stop)) break;
            }
            // The piece [t, te] and its closed form.
            Real te, a0, c1;
            Real u1;
            if (t < t_fin) {
                // k holds t here: the quiet loop above set it (t = k dt) or left both as they were.
                te = dt * (k + 1);
                const Rest piece = rest_of_piece();
                a0 = piece.a0;
                c1 = piece.c1;
                u1 = piece.u1;
            } else {
                te = t + h_free >= t_stop ? t_stop : t + h_free;
                a0 = c1 = 0.0;
                u1 = te - t;
            }
            const Real lin = a0 - sigma * alpha;
            const Closed<Real> f{p, theta, omega, theta + lin, omega + c1};
            const typename Closed<Real>::Point end = f.at(u1);
            const Real th1 = end.theta, om1 = end.omega;
            ++result.steps;
            // cosh pu1 - 1, bounded above by y/2 + y^2/20 (y = (p u1)^2 <= 1):
            // for rounding levels, which need no more.
            const Real y1 = (p * u1) * (p * u1), k1 = y1 * (Real(0.5) + y1 * Real(0.05));
            // sigma theta - level and its derivative: Newton's function for the
            // times theta reaches a level.
            auto sigma_theta = [&f, sigma](Real level) {
                return [&f, sigma, level](Real u) {
                    const typename Closed<Real>::Point q = f.at(u);
                    return std::make_pair(sigma * q.theta - level, sigma * q.omega);
                };
            };
            // Where theta' and theta'' keep their signs, sigma theta is monotone
            // from s0 >= 0 to s1, and two kinds of piece need none of the
            // analysis below: those that end above noise and below the level
            // that the first alpha or the fall would cross (nothing happens),
            // and those that end below the ground (one impact, nothing before
            // it; rose: the block has left the ground since the pass began,
            // else it rests, which the analysis below decides).
            const Real s0 = sigma * theta, s1 = sigma * th1;
            const bool monotone = f.C * end.curvature > 0.0 && omega * om1 > 0.0 && s0 >= 0.0;
            if (monotone && s1 > noise && s1 < upper_from(s0)) {
                note_theta(te, th1);
                rose = true;
            } else if (monotone && rose && s1 < 0.0) {
                impact_at(f, newton_root<Real>(sigma_theta(0.0), 0.0, u1, s0, s1, f.theta_noise(u1, k1),
                                               quadratic_root(s0, sigma * omega, sigma * p * p * f.C)));
                event = true;
            } else {
                // Rounding levels of theta, theta' and theta''/p^2 on this piece.
                const Real eps4 = 4 * std::numeric_limits<Real>::epsilon();
                const Real e_noise = f.curvature_noise(u1, k1);
                const Real th_noise = f.theta_noise(u1, k1);
                const Real om_noise = f.omega_noise(u1, k1);

                // Where theta'' changes sign with theta' keeping its sign at both
                // ends, theta' may vanish twice: split where theta'' = 0.
                Real u_split = u1;
                const Real e0 = f.C, e1 = end.curvature;
                if ((e0 < 0) != (e1 < 0) && e0 != 0.0 && e1 != 0.0 && (omega < 0) == (om1 < 0)) {
                    const Real ue = newton_root<Real>(
                        [&](Real u) {
                            const typename Closed<Real>::Point q = f.at(u);
                            // (theta + a - sigma alpha)' = theta' + c1
                            return std::make_pair(q.curvature, q.omega + c1);
                        },
                        0.0, u1, e0, e1, e_noise);
                    const Real om_e = f.at(ue).omega;
                    if (ue > 0.0 && ue < u1 && (om_e < 0) != (omega < 0)) u_split = ue;
                }

                Real ua = 0.0, tha = theta, oma = omega;
                while (!event) {
                    const Real ub = u_split;
                    const typename Closed<Real>::Point at_b = ub < u1 ? f.at(ub) : end;
                    const Real thb = at_b.theta, omb = at_b.omega;
                    // Extremum of theta inside the part (theta' changes sign, once).
                    Real u_ext = NAN, th_ext = NAN;
                    if ((oma < 0) != (omb < 0) && oma != 0.0 && omb != 0.0) {
                        u_ext = extremum_time(f, ua, ub, oma, omb, om_noise);
                        th_ext = f.at(u_ext).theta;
                    }
                    const bool has_ext = !std::isnan(u_ext);
                    // Terminal events: impact (sigma theta reaches 0), fall.
                    Real u_impact = INFINITY, u_fall = INFINITY;
                    // Next to an extremum theta is a parabola, nearly flat when the
                    // rebound is small (the end of an impact cascade): Newton starts
                    // from the parabola's root, u_ext -+ sqrt(2 |theta_ext / theta''_ext|).
                    auto beside_ext = [&](Real side) {
                        const Real e = f.at(u_ext).curvature;
                        return u_ext + side * std::sqrt(std::fabs(2 * th_ext / (p * p * e)));
                    };
                    auto beside_start = [&]() {
                        const Real e = f.at(ua).curvature;
                        return ua + quadratic_root(sigma * tha, sigma * oma, sigma * p * p * e);
                    };
                    if (has_ext && sigma * th_ext < 0.0)
                        u_impact = newton_root<Real>(sigma_theta(0.0), ua, u_ext, sigma * tha, sigma * th_ext, th_noise,
                                                     beside_ext(-1.0));
                    else if (sigma * thb < 0.0)
                        u_impact = has_ext ? newton_root<Real>(sigma_theta(0.0), u_ext, ub, sigma * th_ext, sigma * thb,
                                                               th_noise, beside_ext(1.0))
                                           : newton_root<Real>(sigma_theta(0.0), ua, ub, sigma * tha, sigma * thb,
                                                               th_noise, beside_start());
                    if (sigma * thb >= options.overturn_angle)
                        u_fall = newton_root<Real>(
                            sigma_theta(options.overturn_angle), ua, ub, sigma * tha - options.overturn_angle,
                            sigma * thb - options.overturn_angle, th_noise + eps4 * options.overturn_angle);
                    const Real u_cut = std::min({u_impact, u_fall, ub});
                    // First time |theta| = alpha.
                    if (std::isnan(result.t_first_alpha) && sigma * tha < alpha) {
                        const Real th_cut = u_cut == ub ? thb : f.at(u_cut).theta;
                        if (sigma * th_cut >= alpha)
                            result.t_first_alpha =
                                t + newton_root<Real>(sigma_theta(alpha), ua, u_cut, sigma * tha - alpha,
                                                      sigma * th_cut - alpha, th_noise + eps4 * alpha);
                        else if (has_ext && u_ext < u_cut && sigma * th_ext >= alpha)
                            result.t_first_alpha =
                                t + newton_root<Real>(sigma_theta(alpha), ua, u_ext, sigma * tha - alpha,
                                                      sigma * th_ext - alpha, th_noise + eps4 * alpha);
                    }
                    if (has_ext && u_ext <= u_cut) note_theta(t + u_ext, th_ext);
                    if (sigma * thb > noise || (has_ext && u_ext <= u_cut && sigma * th_ext > noise)) rose = true;

                    if (u_fall <= u_cut && u_fall < INFINITY) {
                        result.overturned = true;
                        result.t_overturn = t + u_fall;
                        result.overturned_during_input = result.t_overturn <= t_fin;
                        note_theta(result.t_overturn, sigma * options.overturn_angle);
                        done = event = true;
                    } else if (u_impact <= u_cut && u_impact < INFINITY && !rose) {
                        // Within rounding of the ground: at rest to the piece's end.
                        t = te;
                        theta = omega = 0.0;
                        run.resting = true;
                        event = true;
                    } else if (u_impact <= u_cut && u_impact < INFINITY) {
                        impact_at(f, u_impact);
                        event = true;
                    } else {
                        note_theta(ub >= u1 ? te : t + ub, thb);
                        if (ub >= u1) break;
                        ua = ub;
                        tha = thb;
                        oma = omb;
                        u_split = u1;
                    }
                }
            }
            if (!event) {
                t = te;
                theta = th1;
                omega = om1;
                if (t < t_fin && t >= dt * (k + 1)) ++k;
            }
        }
    }
    rules::decide_by_energy(run, result, model, options, t_fin);
    result.max_abs_theta_input = static_cast<double>(max_theta);
    return result;
}

}  // namespace

SimulationResult simulate_record_kernel(const Model& model, const SampledInput& input, const SimulationOptions& options) {
    return run_kernel<double>(model, input, options);
}

SimulationResult simulate_record_kernel_extended(const Model& model, const SampledInput& input,
                                                const SimulationOptions& options) {
    return run_kernel<long double>(model, input, options);
}

}  // namespace rocking::dynamics
