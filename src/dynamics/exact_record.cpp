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

template <class Real>
struct CoshSinh {
    Real c, s;
};

// cosh x and sinh x.  Below 0.1 (every record piece of a block with
// p dt < 0.1, and the parts of pieces cut by events) the Taylor series to
// x^12 / x^11, whose truncation is below 1e-21 relative (below 0.02, to x^6 /
// x^7: below 1e-18): cheaper than exp and free of the cancellation of
// (e^x - e^-x) / 2.
template <class Real>
CoshSinh<Real> cosh_sinh(Real x) {
    if (std::fabs(x) < 0.1) {
        // 1/((2k-1)(2k)) and 1/((2k)(2k+1)) as products: no division on the
        // hot path; their rounding touches terms below x^2/2 only (< 1e-18).
        const Real c2 = Real(1) / 2, c4 = Real(1) / 12, c6 = Real(1) / 30, c8 = Real(1) / 56, c10 = Real(1) / 90,
                   c12 = Real(1) / 132;
        const Real s3 = Real(1) / 6, s5 = Real(1) / 20, s7 = Real(1) / 42, s9 = Real(1) / 72, s11 = Real(1) / 110;
        const Real y = x * x;
        if (sizeof(Real) == sizeof(double) && y < 4e-4)  // |x| < 0.02 (a record piece, p dt ~ 0.01): x^8 terms below 1e-18
            return {1 + y * c2 * (1 + y * c4 * (1 + y * c6)), x * (1 + y * s3 * (1 + y * s5 * (1 + y * s7)))};
        return {1 + y * c2 * (1 + y * c4 * (1 + y * c6 * (1 + y * c8 * (1 + y * c10 * (1 + y * c12))))),
                x * (1 + y * s3 * (1 + y * s5 * (1 + y * s7 * (1 + y * s9 * (1 + y * s11)))))};
    }
    return {std::cosh(x), std::sinh(x)};
}

// The linearised equation on corner sigma, over a piece where the record is
// linear, a(t + u)/g = a0 + c1 u, from the state (theta0, omega0) at t:
//   theta''(u) = p^2 (theta + a0 + c1 u - sigma alpha)   (eq. 3, corrected sign)
//   theta(u)   = C cosh pu + D sinh pu - lin - c1 u,      lin = a0 - sigma alpha,
//   theta'(u)  = p (C sinh pu + D cosh pu) - c1,          C = theta0 + lin,
//   theta''(u) = p^2 (C cosh pu + D sinh pu),              D = (omega0 + c1) / p.
// The same closed form as ExactStepper's (exact_stepper.cpp).
template <class Real>
struct Closed {
    Real p, C, D, lin, c1;

    void at(Real u, Real& theta, Real& omega) const {
        const CoshSinh<Real> cs = cosh_sinh(p * u);
        theta = C * cs.c + D * cs.s - lin - c1 * u;
        omega = p * (C * cs.s + D * cs.c) - c1;
    }
    Real theta_at(Real u) const {
        const CoshSinh<Real> cs = cosh_sinh(p * u);
        return C * cs.c + D * cs.s - lin - c1 * u;
    }
    // theta''/p^2 and its derivative/p^2.
    void curvature_at(Real u, Real& e, Real& de) const {
        const CoshSinh<Real> cs = cosh_sinh(p * u);
        e = C * cs.c + D * cs.s;
        de = p * (C * cs.s + D * cs.c);
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
    const CoshSinh<Real> whole{std::cosh(p * dt), std::sinh(p * dt)};
    const Real noise = 1e-12 * alpha;  // the general path's "rose" rule (simulate.cpp)
    const Real rest = options.rest_velocity;

    SimulationResult result;
    result.t_fin = t_fin;
    rules::RunState<Real> run(options, t_fin);
    // The segment's working copy of the state (the quiet loop keeps it in
    // registers); written back to run at each event and at the segment's end.
    Real &t = run.t, &theta = run.theta, &omega = run.omega;
    int& sigma = run.sigma;
    bool done = false;
    std::size_t k = 0;  // the record piece holding t, while t < t_fin
    Real max_theta = 0;  // largest |theta| on [0, t_fin]

    auto note_theta = [&](Real when, Real value) {
        if (when <= t_fin) max_theta = std::max(max_theta, std::fabs(value));
    };

    while (!done && rules::begin_pass(run, result, model, input, options, t_fin, note_theta, [](Real) {})) {
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
                const Real upper = std::isnan(result.t_first_alpha) && sigma * theta < alpha
                                         ? std::min(alpha, Real(options.overturn_angle))
                                         : options.overturn_angle;
                const std::size_t k0 = k;
                Real peak = 0.0;
                if (t == dt * k) {
                    while (k + 1 < a.size()) {  // t_stop = t_fin here
                        const Real c1 = (a[k + 1] - a[k]) * inv_dt, lin = a[k] - sa;
                        const Real C = theta + lin, D = (omega + c1) * inv_p;
                        const Real e1 = C * whole.c + D * whole.s;
                        const Real th1 = e1 - lin - c1 * dt, om1 = p * (C * whole.s + D * whole.c) - c1;
                        const Real s1 = sigma * th1;
                        // omega om1 > 0 and C e1 > 0: one sign at both ends,
                        // of theta' and of theta'' (an underflow to 0 only
                        // sends the piece to the full analysis).
                        if (!(s1 > noise && s1 < upper && omega * om1 > 0.0 && C * e1 > 0.0)) break;
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
            bool whole_piece = false;
            Real u1;
            if (t < t_fin) {
                // k holds t here: the quiet loop above set it (t = k dt) or left both as they were.
                te = dt * (k + 1);
                c1 = (a[k + 1] - a[k]) * inv_dt;
                // The samples sit at k dt exactly; te and t are that grid
                // rounded.  A whole piece is dt long (as in the quiet loop);
                // a part of one is measured from the exact grid, fma rounding
                // (k + 1) dt - t once (te - t would carry te's rounding, which
                // c1 turns into an error ~ c1 ulp(t), far above theta's).
                whole_piece = t == dt * k;
                a0 = whole_piece ? Real(a[k]) : a[k] + c1 * std::fma(-Real(k), dt, t);
                u1 = whole_piece ? dt : std::max(Real(0), std::fma(Real(k + 1), dt, -t));
            } else {
                te = t + h_free >= t_stop ? t_stop : t + h_free;
                a0 = c1 = 0.0;
                u1 = te - t;
            }
            const Real lin = a0 - sigma * alpha;
            const Closed<Real> f{p, theta + lin, (omega + c1) * inv_p, lin, c1};
            const CoshSinh<Real> cs = whole_piece ? whole : cosh_sinh(p * u1);
            const Real th1 = f.C * cs.c + f.D * cs.s - lin - c1 * u1;
            const Real om1 = p * (f.C * cs.s + f.D * cs.c) - c1;
            ++result.steps;
            // Rounding levels of theta, theta' and theta''/p^2 on this piece.
            const Real eps4 = 4 * std::numeric_limits<Real>::epsilon();
            const Real e_noise = eps4 * (std::fabs(f.C) + std::fabs(f.D));
            const Real th_noise = e_noise + eps4 * (std::fabs(lin) + std::fabs(c1) * u1);
            const Real om_noise = p * e_noise + eps4 * std::fabs(c1);

            // Where theta'' changes sign with theta' keeping its sign at both
            // ends, theta' may vanish twice: split where theta'' = 0.
            Real u_split = u1;
            const Real e0 = f.C, e1 = f.C * cs.c + f.D * cs.s;
            if ((e0 < 0) != (e1 < 0) && e0 != 0.0 && e1 != 0.0 && (omega < 0) == (om1 < 0)) {
                const Real ue = newton_root<Real>(
                    [&](Real u) {
                        Real e, de;
                        f.curvature_at(u, e, de);
                        return std::make_pair(e, de);
                    },
                    0.0, u1, e0, e1, e_noise);
                Real th_e, om_e;
                f.at(ue, th_e, om_e);
                if (ue > 0.0 && ue < u1 && (om_e < 0) != (omega < 0)) u_split = ue;
            }

            Real ua = 0.0, tha = theta, oma = omega;
            while (!event) {
                const Real ub = u_split;
                Real thb = th1, omb = om1;
                if (ub < u1) f.at(ub, thb, omb);
                auto sigma_theta = [&](Real level) {
                    return [&f, sigma, level](Real u) {
                        Real th, om;
                        f.at(u, th, om);
                        return std::make_pair(sigma * th - level, sigma * om);
                    };
                };
                // Extremum of theta inside the part (theta' changes sign, once).
                Real u_ext = NAN, th_ext = NAN;
                if ((oma < 0) != (omb < 0) && oma != 0.0 && omb != 0.0) {
                    u_ext = newton_root<Real>(
                        [&](Real u) {
                            Real e, de;
                            f.curvature_at(u, e, de);
                            return std::make_pair(de - c1, p * p * e);
                        },
                        ua, ub, oma, omb, om_noise);
                    th_ext = f.theta_at(u_ext);
                }
                const bool has_ext = !std::isnan(u_ext);
                // Terminal events: impact (sigma theta reaches 0), fall.
                Real u_impact = INFINITY, u_fall = INFINITY;
                // Next to an extremum theta is a parabola, nearly flat when the
                // rebound is small (the end of an impact cascade): Newton starts
                // from the parabola's root, u_ext -+ sqrt(2 |theta_ext / theta''_ext|).
                auto beside_ext = [&](Real side) {
                    Real e, de;
                    f.curvature_at(u_ext, e, de);
                    return u_ext + side * std::sqrt(std::fabs(2 * th_ext / (p * p * e)));
                };
                auto beside_start = [&]() {
                    Real e, de;
                    f.curvature_at(ua, e, de);
                    return ua + quadratic_root(sigma * tha, sigma * oma, sigma * p * p * e);
                };
                if (has_ext && sigma * th_ext < 0.0)
                    u_impact = newton_root<Real>(sigma_theta(0.0), ua, u_ext, sigma * tha, sigma * th_ext, th_noise,
                                           beside_ext(-1.0));
                else if (sigma * thb < 0.0)
                    u_impact = has_ext ? newton_root<Real>(sigma_theta(0.0), u_ext, ub, sigma * th_ext, sigma * thb, th_noise,
                                                     beside_ext(1.0))
                                       : newton_root<Real>(sigma_theta(0.0), ua, ub, sigma * tha, sigma * thb, th_noise,
                                                     beside_start());
                if (sigma * thb >= options.overturn_angle)
                    u_fall = newton_root<Real>(sigma_theta(options.overturn_angle), ua, ub,
                                         sigma * tha - options.overturn_angle, sigma * thb - options.overturn_angle,
                                         th_noise + eps4 * options.overturn_angle);
                const Real u_cut = std::min({u_impact, u_fall, ub});
                // First time |theta| = alpha.
                if (std::isnan(result.t_first_alpha) && sigma * tha < alpha) {
                    const Real th_cut = u_cut == ub ? thb : f.theta_at(u_cut);
                    if (sigma * th_cut >= alpha)
                        result.t_first_alpha =
                            t + newton_root<Real>(sigma_theta(alpha), ua, u_cut, sigma * tha - alpha, sigma * th_cut - alpha,
                                              th_noise + eps4 * alpha);
                    else if (has_ext && u_ext < u_cut && sigma * th_ext >= alpha)
                        result.t_first_alpha =
                            t + newton_root<Real>(sigma_theta(alpha), ua, u_ext, sigma * tha - alpha, sigma * th_ext - alpha,
                                              th_noise + eps4 * alpha);
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
                    Real th_i, om_i;
                    f.at(u_impact, th_i, om_i);
                    const Real t_impact = t + u_impact;
                    note_theta(t_impact, 0.0);
                    const bool micro = rules::record_impact(result, t_impact, options, p);
                    rules::apply_impact(run, result, model, t_impact, om_i, micro, rest);
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
