// The record kernel's closed form on one piece where the record is linear
// (exact_record.cpp): its series, its points, the roots it looks for and the
// bounce form of a rebound.  Templated on the working precision: the kernel
// runs in double, its twin in long double, and the tests check each piece
// against the other precision (tests/test_closed_piece.cpp).
// Divisions by constants other than powers of 2 are written as products by
// their reciprocals, x * Real(1.0L / 3): the compiler must keep x / 3 a
// division (the product rounds differently), ~15 cycles of latency on the
// chain from one impact to the next; the product differs by an ulp, inside
// every rounding level below.  (Norcia's run: 24 -> 22.7 us, bench/.)
#pragma once

#include <cmath>
#include <initializer_list>
#include <limits>
#include <type_traits>

#include "numerics/bisect.hpp"

namespace rocking::dynamics::closed_piece {

// The even series of the closed form, in y = x^2:
//   ch1(y) = (cosh x - 1) / x^2 = 1/2! + y/4! + y^2/6! + ...
//   sh1(y) = (sinh x - x) / x^3 = 1/3! + y/5! + y^2/7! + ...
// to y^8, whose first term left out is below 1e-21 relative for x <= 0.6
// (every piece of the kernel: p dt <= max_step_p = 0.5 by default) and
// below 1e-17 for x <= 1; beyond, from cosh and sinh (a few bits lost to
// the cancellation of sinh x - x, on pieces no default option produces).
// They carry cosh x - 1 = y ch1 and sinh x - x = x y sh1 without the
// cancellation of the differences.  1/n! as constants: the divisions are
// done once, at compile time.  Shorter sums where the terms left out stay
// below 2e-20 relative: to y^3 below y = 4e-4 (x < 0.02: a record piece of
// a block with p dt ~ 0.01, every rebound of a cascade), to y^5 below y =
// 0.01.  The y^3 sum, nearly every call, is inline; the others are not
// (inlined whole, series cost its callers' registers: 0.5 us of Norcia's
// 22 us, bench/).
template <class Real>
__attribute__((noinline)) void series_long(Real y, Real& ch1, Real& sh1) {
    if (y > 1) {
        const Real x = std::sqrt(y);
        ch1 = (std::cosh(x) - 1) / y;
        sh1 = (std::sinh(x) - x) / (x * y);
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

template <class Real>
inline void series(Real y, Real& ch1, Real& sh1) {
    if (y < Real(4e-4)) {
        // Estrin's scheme (y^2 beside the first pair): two operations
        // shorter than Horner's on the chain every root solve sits on.
        const Real y2 = y * y;
        ch1 = (Real(1) / 2 + y * (Real(1) / 24)) + y2 * (Real(1) / 720 + y * (Real(1) / 40320));
        sh1 = (Real(1) / 6 + y * (Real(1) / 120)) + y2 * (Real(1) / 5040 + y * (Real(1) / 362880));
        return;
    }
    series_long(y, ch1, sh1);
}

// The first root s > 0 of fa + fpa s + fpp s^2 / 2 (Taylor's polynomial of
// f at a bracket's start: the root finders' first point), NaN when it has
// none, and the parabola's slope there, fpa + fpp s: with c = sgn(fpa)
// sqrt(disc), the roots are s1 = -2 fa / (fpa + c) (no cancellation) and
// s2 = -(fpa + c) / fpp, where the slope is c and -c.
template <class Real>
struct ParabolaRoot {
    Real s, slope;
};
template <class Real>
ParabolaRoot<Real> parabola_root(Real fa, Real fpa, Real fpp) {
    const Real disc = fpa * fpa - 2 * fa * fpp;
    if (!(disc >= 0)) return {NAN, NAN};
    const Real c = std::copysign(std::sqrt(disc), fpa), q = fpa + c;
    const Real s1 = q != 0 ? -2 * fa / q : Real(NAN), s2 = fpp != 0 ? -q / fpp : Real(NAN);
    ParabolaRoot<Real> best{NAN, NAN};
    if (s1 > 0) best = {s1, c};
    if (s2 > 0 && !(s2 >= best.s)) best = {s2, -c};
    return best;
}
template <class Real>
Real quadratic_root(Real fa, Real fpa, Real fpp) {
    return parabola_root(fa, fpa, fpp).s;
}

// The first root d > 0 of Taylor's polynomial f0 + f1 d + f2 d^2/2 + f3 d^3/6
// + f4 d^4/24: the root d0 of its parabola (parabola_root), corrected by one
// Newton step on the whole polynomial, where the parabola's terms vanish,
//   T(d0) = d0^3 (f3 / 6 + d0 f4 / 24),  T'(d0) = S + E,
//   S = f1 + f2 d0 (the parabola's slope), E = d0^2 (f3 / 2 + d0 f4 / 6).
// On a record piece (p d <= 0.5, where f3 d^3 / (f1 d) ~ (p d)^2) the start
// is then within ~(p d)^4 / 100 relative of the root instead of ~(p d)^2 / 6:
// close enough for solve() to settle at its first point.  The step T / (S +
// E) is taken as (T / S) (1 - E / S) where E / S <= 1e-2 (~(p d)^2 / 2; the
// term left out, (E / S)^2 of the step, is below the start's own error):
// 1 / S is known with the parabola's root, so no division follows T.  A
// correction above d0 / 4 (T' near 0: a grazing parabola) is not trusted
// and d0 is kept.  This start sits on the chain from one impact to the next
// (every cycle in it costs 75 on Norcia's record).
template <class Real>
Real taylor_root(Real f0, Real f1, Real f2, Real f3, Real f4) {
    const ParabolaRoot<Real> r = parabola_root(f0, f1, f2);
    const Real d0 = r.s, inv_s = 1 / r.slope;
    const Real T = d0 * d0 * d0 * (f3 * Real(1.0L / 6) + d0 * f4 * Real(1.0L / 24));
    const Real E = (d0 * d0) * (f3 / 2 + d0 * (f4 * Real(1.0L / 6)));
    const Real e = E * inv_s;
    const Real step = std::fabs(e) <= Real(1e-2) ? (T * inv_s) * (1 - e) : T / (r.slope + E);
    return std::fabs(step) <= Real(0.25) * d0 ? d0 - step : d0;
}

// What a root is sought of on a piece's closed form: sigma theta - level (an
// impact, the first alpha, the fall), theta' (an extremum), theta''/p^2 (where
// theta'' changes sign).
enum class Seek { level, extremum, inflection };

// The linearised equation on corner sigma, over a piece where the record is
// linear, a(t + u)/g = a0 + c1 u, from the state (theta0, omega0) at t:
//   theta''(u) = p^2 (theta + a0 + c1 u - sigma alpha)   (eq. 3, corrected sign)
//   theta(u)   = C cosh pu + D sinh pu - lin - c1 u,      lin = a0 - sigma alpha,
//   C = theta0 + lin, D = (omega0 + c1) / p = W / p
// (the same closed form as ExactStepper's, exact_stepper.cpp, which
// evaluates it through from_series below), written as increments on the
// state, x = pu, y = x^2:
//   theta(u)        = theta0 + omega0 u + C y ch1 + W u y sh1,
//   theta'(u)       = omega0 + p C x (1 + y sh1) + W y ch1,
//   theta''(u)/p^2  = C (1 + y ch1) + W u (1 + y sh1).
// Each term is a correction of the state, so the rounding is relative to
// theta and theta', not to alpha: the general form's C cosh - lin carries an
// error eps alpha, which divided by theta' at an impact is an error in its
// time (eps alpha / theta', 1e-13 s on a rebound of 1e-4 rad/s).
// Eq. 3 differentiated gives each higher derivative from the point itself,
//   theta''' = p^2 (theta' + c1),  theta'''' = p^2 theta''  (c1 = W - omega0),
// which the root finder (solve) uses for a third-order step, for its error bound
// and for the point at the root.
template <class Real>
struct Closed {
    Real p, theta0, omega0, C, W;

    struct Point {
        Real theta, omega, curvature;  // curvature: theta''/p^2
    };
    Real c1() const { return W - omega0; }  // the record's slope
    Point at(Real u) const {
        const Real y = (p * u) * (p * u);
        Real ch1, sh1;
        series(y, ch1, sh1);
        return from_series(u, y, ch1, sh1);
    }
    // The point at u from the series already evaluated there (y = (p u)^2).
    Point from_series(Real u, Real y, Real ch1, Real sh1) const {
        const Real x = p * u, k1 = y * ch1, s0 = 1 + y * sh1;  // cosh x - 1, sinh x / x
        return {theta0 + omega0 * u + C * k1 + W * u * y * sh1, omega0 + p * C * x * s0 + W * k1,
                C * (1 + k1) + W * u * s0};
    }
    // cosh pu - 1 bounded above by y/2 + y^2/20 (y = (p u)^2 <= 1): the k1
    // of the rounding levels below, which need no more.
    Real k1_bound(Real u) const {
        const Real y = (p * u) * (p * u);
        return y * (Real(0.5) + y * Real(0.05));
    }
    // The point at u + d from the point q at u, by Taylor's polynomials in d
    // with the derivatives above (theta to d^4, theta' to d^3, theta''/p^2 to
    // d^2).  For |p d| <= 1e-6 the terms left out are below 1e-25 of the
    // state's scale (|C|, |W| / p), under its rounding; beyond, the closed
    // form itself.  (theta's terms in d^3 and d^4 are below double's
    // rounding there, not below long double's: the kernel's twin needs them.)
    Point near(const Point& q, Real u, Real d) const {
        if (!(std::fabs(p * d) <= Real(1e-6))) return at(u + d);
        const Real p2 = p * p, r = q.omega + c1();
        const Real d2 = p2 * q.curvature, d3 = p2 * r, d4 = p2 * d2;
        const Real d_3 = d * Real(1.0L / 3);
        // theta' by Estrin's scheme: after an impact's root it is the chain's
        // next link (theta' there is the rebound's speed).
        const Real dd_2 = d * d / 2;
        return {q.theta + d * (q.omega + d / 2 * (d2 + d_3 * (d3 + d / 4 * d4))),
                (q.omega + d * d2) + dd_2 * (d3 + d_3 * d4), q.curvature + d * (r + d / 2 * d2)};
    }
    // Where theta's Taylor polynomial at the point q (at u) reaches the
    // ground: the first point of an impact's root finder, NaN when its
    // parabola does not (taylor_root).  sigma theta's polynomial has the same
    // roots, which taylor_root gives to the same bits (each of its operations
    // flips its result's sign when all its inputs flip): sigma stays off the
    // chain to the impact.
    Real ground_root(Real u, const Point& q) const {
        const Real p2 = p * p, k2 = p2 * q.curvature, k3 = p2 * (q.omega + c1());
        const Real d = taylor_root(q.theta, q.omega, k2, k3, p2 * k2);
        return u == 0 ? d : u + d;  // from a piece's start, no add on the chain
    }
    // Where theta''s Taylor polynomial at q (at u) vanishes: the first point
    // of an extremum's root finder (theta'''' = p^2 theta'', theta''''' = p^2 theta''').
    Real slope_root(Real u, const Point& q) const {
        const Real p2 = p * p, k2 = p2 * q.curvature, k3 = p2 * (q.omega + c1());
        return u + taylor_root(q.omega, k2, k3, p2 * k2, p2 * k3);
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

    // What solve() seeks the root of, at the point q.
    static Real sought(Seek seek, Real sigma, Real level, const Point& q) {
        switch (seek) {
            case Seek::level: return sigma * q.theta - level;
            case Seek::extremum: return q.omega;
            default: return q.curvature;
        }
    }
    // The rounding level of what solve() seeks, at u (the levels above on
    // [0, u], plus four ulps of the level sought).
    Real noise_at(Seek seek, Real u, Real level) const {
        const Real k1 = k1_bound(u);
        switch (seek) {
            case Seek::level: return theta_noise(u, k1) + 4 * std::numeric_limits<Real>::epsilon() * std::fabs(level);
            case Seek::extremum: return omega_noise(u, k1);
            default: return curvature_noise(u, k1);
        }
    }

    // A root and the point there.
    struct Found {
        Real u;
        Point q;
    };
    // The root of what is sought (sigma theta - level for Seek::level) on
    // [lo, hi], given its values flo and fhi at the ends of opposite signs:
    // Chebyshev's method from the false-position point (or from start, a
    // better one a caller knows), each iterate kept inside the shrinking
    // bracket (bisection otherwise).  With f and its derivatives f1, f2, f3
    // at the iterate, the step s = (f / f1) (1 + f f2 / (2 f1^2)) leaves an
    // error e' = (f2^2 / (2 f1^2) - f3 / (6 f1)) e^3 + O(e^4), e ~ s: the
    // iteration stops when that bound (doubled for the derivatives' change
    // over e, e taken as 1.25 |s|) is below eps/64 of the root, with no
    // evaluation there (the margin keeps the errors of the test it replaced,
    // one more evaluation to see the step vanish); or when f is down to its
    // rounding level f_noise (after the step from there); or at a step below
    // 2 ulps.  The point at the root is near() the last one evaluated.
    // Conventions as the general path's locate(): fhi = 0 gives hi; flo = 0,
    // or no sign change (rounding at a root just located), gives lo.
    Found solve(Seek seek, Real sigma, Real level, Real lo, Real hi, Real flo, Real fhi, Real f_noise,
                Real start = NAN) const {
        if (fhi == 0.0) return {hi, at(hi)};
        if (flo == 0.0 || (flo < 0) == (fhi < 0)) return {lo, at(lo)};
        const Real flip = flo < 0 ? 1 : -1;  // orient so that f(a) < 0 < f(b)
        const Real eps = std::numeric_limits<Real>::epsilon(), p2 = p * p, c1 = this->c1();
        Real a = lo, b = hi;
        Real x = std::isnan(start) ? lo + (hi - lo) * (flo / (flo - fhi)) : start;
        if (!(x >= a && x <= b)) x = 0.5 * (a + b);
        for (int i = 0; i < 100; ++i) {
            const Point q = at(x);
            // What is sought, g, and its derivatives g1..g3 with its sign
            // taken out (f = sgn g; sigma for a level): Newton's quotient
            // and the ratios below are the same to the bit (sigma^2 = 1)
            // without sigma's products on the chain to the root.
            Real g, g1, g2, g3, sgn = 1;
            switch (seek) {
                case Seek::level:
                    sgn = sigma, g = q.theta - sigma * level;
                    g1 = q.omega, g2 = p2 * q.curvature, g3 = p2 * (q.omega + c1);
                    break;
                case Seek::extremum:
                    g = q.omega, g1 = p2 * q.curvature, g2 = p2 * (q.omega + c1), g3 = p2 * p2 * q.curvature;
                    break;
                default:
                    g = q.curvature, g1 = q.omega + c1, g2 = p2 * q.curvature, g3 = p2 * (q.omega + c1);
            }
            const Real f = sgn * g;
            if (flip * f < 0) a = x;
            else b = x;
            // Chebyshev's step: Newton's, corrected to third order by g2
            // (one division; Halley's form would take two).
            const Real inv1 = 1 / g1, newton = g * inv1, r2 = g2 * inv1, r3 = g3 * inv1;
            {
                // Newton's own step leaves an error (r2 / 2) e^2: where that
                // bound (doubled, e taken as 1.25 |newton|, as below) is
                // already under eps/64 of the root, as from a Taylor start
                // (taylor_root: within ~(p d)^4 / 100), Newton's point is the
                // root, two products and an add sooner than Chebyshev's.
                const Real xn = x - newton, eN = Real(1.25) * std::fabs(newton);
                if (std::fabs(r2) * eN <= Real(0.01) && std::fabs(r2) * eN * eN <= eps / 64 * std::fabs(xn) &&
                    xn > a && xn < b && !(std::fabs(f) <= f_noise))
                    return {xn, near(q, x, -newton)};
            }
            const Real h = newton * r2 / 2;
            const Real step = std::fabs(h) < Real(0.5) ? newton * (1 + h) : newton;
            Real next = x - step;
            // The caller's rounding level holds for the whole bracket; where
            // the state grows by orders of magnitude across it (an input of
            // 1e20 g: theta 1e16 rad at the piece's end, a rounding level of
            // 20 rad against the fall angle sought, 1.57), the level at x is
            // the one that says f is 0 within rounding.
            if (std::fabs(f) <= f_noise && std::fabs(f) <= noise_at(seek, x, level)) {
                if (!(next >= a && next <= b)) next = x;
                return {next, near(q, x, next - x)};
            }
            if (!(next > a && next < b)) {
                x = 0.5 * (a + b);
                continue;
            }
            const Real e = Real(1.25) * std::fabs(step);
            const Real K = 2 * (r2 * r2 / 2 + std::fabs(r3) * Real(1.0L / 6));
            if ((K * e * e <= Real(0.01) && K * e * e * e <= eps / 64 * std::fabs(next)) ||
                std::fabs(next - x) <= 2 * eps * std::fabs(x) ||
                b - a <= 2 * eps * std::fmax(std::fabs(a), std::fabs(b)))
                return {next, near(q, x, next - x)};
            x = next;
        }
        // Not settled in 100 steps: a bracket spanning decades (an input of
        // 1e100 g, whose fall comes 1e-34 s into a 0.01 s piece), where each
        // step from the far side shrinks it by a constant factor only, and
        // the cap returned a point 1e6 times the root.  Bisection
        // (bisect_decades: geometric across decades) to 2 ulps.
        numerics::bisect_decades(a, b, [&](Real u) { return flip * sought(seek, sigma, level, at(u)) < 0; },
                                 [&](Real lo, Real hi) { return hi - lo <= 2 * eps * std::fmax(std::fabs(lo), std::fabs(hi)); });
        x = a + (b - a) / 2;
        return {x, at(x)};
    }
    Found level(Real sigma, Real value, Real lo, Real hi, Real flo, Real fhi, Real f_noise,
                Real start = NAN) const {
        return solve(Seek::level, sigma, value, lo, hi, flo, fhi, f_noise, start);
    }
    // Where theta' vanishes inside [lo, hi], given the point at_lo at lo and
    // theta' = om_hi at hi, of the opposite sign, and theta'' of one sign between.
    Found extremum(const Point& at_lo, Real lo, Real hi, Real om_hi, Real om_noise) const {
        return solve(Seek::extremum, 1, 0, lo, hi, at_lo.omega, om_hi, om_noise, slope_root(lo, at_lo));
    }
    // Where theta'' vanishes inside [lo, hi], given theta''/p^2 = e_lo and
    // e_hi of opposite signs at the ends.
    Found inflection(Real lo, Real hi, Real e_lo, Real e_hi, Real e_noise) const {
        return solve(Seek::inflection, 1, 0, lo, hi, e_lo, e_hi, e_noise);
    }
};

// The landing of a short bounce without iteration: g = 0 of the bounce
// below solved as a power series in its small parameters (Bounce::landing),
//   u = u0 (1 + e),  theta'(u) = omega (v - 1),
// e and v the series of tools/landing_series.py, which derives them on exact
// fractions and checks these lines (ctest landing_series).  For |beta| <=
// 1e-3 and delta <= 1e-5 (kShortBeta, kShortDelta) the terms kept leave out
// below 6e-20 relative, under eps/32 of double (Newton's own criterion), and
// Estrin's scheme in beta keeps the chain short: a cascade's rebounds follow
// one another through it.
inline constexpr double kShortBeta = 1e-3, kShortDelta = 1e-5;

template <class Real>
struct ShortBounce {
    Real e, v;
};

template <class Real>
ShortBounce<Real> short_bounce(Real b, Real d) {
    const Real e0 = d * (Real(-1) + d * (Real(13.0L / 5) + d * (Real(-311.0L / 35) + d * (Real(6063.0L / 175)))));
    const Real e1 = Real(-1) + d * (Real(22.0L / 5) + d * (Real(-741.0L / 35) + d * (Real(18628.0L / 175))));
    const Real e2 = Real(2) + d * (Real(-87.0L / 5) + d * (Real(21912.0L / 175) + d * (Real(-29346.0L / 35))));
    const Real e3 = Real(-5) + d * (Real(336.0L / 5) + d * (Real(-22782.0L / 35)));
    const Real e4 = Real(14) + d * (Real(-258) + d * (Real(110583.0L / 35)));
    const Real e5 = Real(-42) + d * (Real(990));
    const Real e6 = Real(132);
    const Real e7 = Real(-429);
    const Real v0 = d * (Real(-2) + d * (Real(22.0L / 5) + d * (Real(-494.0L / 35) + d * (Real(9314.0L / 175)))));
    const Real v1 = Real(-1) + d * (Real(31.0L / 5) + d * (Real(-1059.0L / 35) + d * (Real(26569.0L / 175))));
    const Real v2 = Real(2) + d * (Real(-108.0L / 5) + d * (Real(28596.0L / 175) + d * (Real(-27912.0L / 25))));
    const Real v3 = Real(-5) + d * (Real(392.0L / 5) + d * (Real(-140586.0L / 175)));
    const Real v4 = Real(14) + d * (Real(-1452.0L / 5) + d * (Real(131472.0L / 35)));
    const Real v5 = Real(-42) + d * (Real(1089));
    const Real v6 = Real(132);
    const Real v7 = Real(-429);
    const Real b2 = b * b, b4 = b2 * b2;
    return {(e0 + b * e1) + b2 * (e2 + b * e3) + b4 * ((e4 + b * e5) + b2 * (e6 + b * e7)),
            (v0 + b * v1) + b2 * (v2 + b * v3) + b4 * ((v4 + b * v5) + b2 * (v6 + b * v7))};
}

// A bounce: the block leaves theta = 0 with theta' = omega (sigma omega > 0)
// on a piece where the record is linear, a0 + c1 u.  With C = lin
// (theta0 = 0), W = omega + c1, x = p u, y = x^2 and the even series
//   ch1(y) = (cosh x - 1) / x^2 = 1/2 + y/24 + y^2/720 + ...
//   sh1(y) = (sinh x - x) / x^3 = 1/6 + y/120 + y^2/5040 + ...
// the closed form divided by u (its root at u = 0 taken out) is
//   g(u) = theta(u) / u = omega + p lin x ch1 + W y sh1,
//   g'(u) = p^2 lin (1 + y sh1 - ch1) + p x W (ch1 - sh1),
// every term a correction to omega, and from the series in x of
// (cosh x - 1)/x and (sinh x - x)/x,
//   |g''(u)| <= p^2 (p |lin| x / 4 + |W| / 3) (1 + x^2 / 3).
template <class Real>
struct Bounce {
    Real p, omega, lin, c1;

    Closed<Real> closed() const { return {p, 0, omega, lin, omega + c1}; }
    // The landing: the first root u > 0 of theta and the state there, by
    // Newton on g from the root of g's series to u^4,
    //   g ~ omega + A u (1 + beta u/u0 + delta (u/u0)^2 + gamma (u/u0)^3),
    //   A = p^2 lin / 2, u0 = -omega / A, beta = W u0 / (3 lin),
    //   delta = y0 / 12, gamma = beta y0 / 20 (y0 = (p u0)^2),
    // to second order in the small beta, delta: u0 (1 + e),
    //   e = -(beta + delta + gamma) + (2 beta + 3 delta)(beta + delta),
    // an error of third order (one step on a cascade's short bounces; the
    // root of the quadratic when beta or delta is not small).
    // Newton's step s from u leaves an error g'' e^2 / (2 g'),
    // e ~ s: the iteration stops when that bound (g'' bounded as above, e
    // taken as 1.25 |s|) is below eps/32 of the root, or at a step below
    // 4 ulps.  The state at the landing is near() the last point evaluated
    // (the closed form's, from the series already there).  Where beta and
    // delta are small enough (most of a cascade's rebounds), short_bounce()
    // gives the root and theta' there to the same criterion with no step
    // (theta''/p^2 = lin + c1 u at theta = 0).
    // u = NaN when the iteration does not settle within 8 steps or leaves (0, u_max).
    typename Closed<Real>::Found landing(Real u_max) const {
        const Real eps = std::numeric_limits<Real>::epsilon(), p2 = p * p, W = omega + c1;
        const typename Closed<Real>::Found none{NAN, {NAN, NAN, NAN}};
        // Grouped for the chain from one rebound to the next (lin, then 1/lin,
        // then these): u0 one product after 1/lin, beta and delta two, with
        // delta = p^2 u0^2 / 12 written as u0 (-omega / (6 lin)) (Norcia:
        // 16.8 -> 16.4 us; written as above, 1/lin took three products
        // more to reach the series).
        const Real inv_lin = 1 / lin, u0 = (omega * (-2 / p2)) * inv_lin;
        const Real beta = u0 * ((W * Real(1.0L / 3)) * inv_lin), delta = u0 * ((omega * Real(-1.0L / 6)) * inv_lin);
        // In double only: the series are cut for double's rounding; long
        // double (the kernel's check on its own rounding) iterates.
        if constexpr (std::is_same_v<Real, double>) {
            if (std::fabs(beta) <= Real(kShortBeta) && delta <= Real(kShortDelta)) {
                const ShortBounce<Real> s = short_bounce(beta, delta);
                const Real u = u0 + u0 * s.e;
                if (!(u > 0 && u < u_max)) return none;
                return {u, {Real(0), omega * s.v - omega, lin + c1 * u}};
            }
        }
        Real u = u0 * (1 - (beta + delta + Real(0.6) * beta * delta) + (2 * beta + 3 * delta) * (beta + delta));
        if (!(std::fabs(beta) + delta < Real(0.1))) u = quadratic_root(omega, p2 * lin / 2, p2 * W / 3);
        for (int i = 0; i < 8; ++i) {
            if (!(u > 0 && u < u_max)) return none;
            const Real x = p * u, y = x * x;
            Real ch1, sh1;
            series(y, ch1, sh1);
            const Real g = omega + p * lin * x * ch1 + W * y * sh1;
            const Real dg = p2 * lin * (1 + y * sh1 - ch1) + p * x * W * (ch1 - sh1);
            const Real next = u - g / dg;
            // max(u, next) as a comparison (as std::fmax when next is NaN; u > 0
            // here): std::fmax is a library call, on the chain from one rebound to the next.
            const Real e = Real(1.25) * std::fabs(next - u), x_hi = p * ((u < next ? next : u) + e);
            const Real M = p2 * (p * std::fabs(lin) * x_hi / 4 + std::fabs(W) * Real(1.0L / 3)) *
                           (1 + x_hi * x_hi * Real(1.0L / 3));
            if ((M * e <= Real(0.2) * std::fabs(dg) && M * e * e <= eps / 32 * std::fabs(dg) * next) ||
                std::fabs(next - u) <= 4 * eps * u) {
                if (!(next > 0 && next < u_max)) return none;
                const Closed<Real> f = closed();
                return {next, f.near(f.from_series(u, y, ch1, sh1), u, next - u)};
            }
            u = next;
        }
        return none;
    }
};

}  // namespace rocking::dynamics::closed_piece
