// The record kernel's closed form on one piece (closed_piece.hpp), each part
// in double against the same closed form in long double: the point moved by
// Taylor's polynomial (near) against the closed form at the new time, the
// root finder (solve: impacts, levels, extrema, inflections) against
// bisection to the last bit of long double, and the bounce form's landing
// against the long-double root of theta.  The tolerances are the double
// evaluation's own rounding levels (Closed's *_noise: four ulps of the
// largest term), so a shortcut that costs accuracy above rounding fails.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "dynamics/closed_piece.hpp"
#include "test_util.hpp"

using namespace rocking::dynamics::closed_piece;
using rocking::testing::bisect;

namespace {

using Ld = long double;
constexpr double kEps = std::numeric_limits<double>::epsilon();

// A piece drawn over the ranges the kernel meets: p from 0.5 to 20 rad/s,
// |theta0| and |lin| up to 0.3 rad, |omega0| up to 1 rad/s, the record's
// slope |c1| up to 50 g/s.
struct Piece {
    double p, theta0, omega0, lin, c1;
    Closed<double> in_double() const { return {p, theta0, omega0, theta0 + lin, omega0 + c1}; }
    // The same piece with C and W formed in long double.
    Closed<Ld> in_long_double() const {
        return {Ld(p), Ld(theta0), Ld(omega0), Ld(theta0) + Ld(lin), Ld(omega0) + Ld(c1)};
    }
};

Piece draw(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double p = 0.5 * std::pow(40.0, 0.5 * (unit(rng) + 1.0));
    return {p, 0.3 * unit(rng), unit(rng), 0.3 * unit(rng), 50.0 * unit(rng)};
}

}  // namespace

TEST(ClosedPiece, NearIsTheClosedFormWithinRounding) {
    // near(q, u, d): the point at u + d from the point q at u by Taylor's
    // polynomials, for |p d| up to 1e-6, where a term left out of theta' (its
    // d^2 term is W (p d)^2 / 2, 5e-13 |W| at the bound) would show 500 times
    // above the tolerance; beyond 1e-6 it is the closed form itself.
    std::mt19937_64 rng(20261121);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0;
    for (int n = 0; n < 4000; ++n) {
        const Piece piece = draw(rng);
        const Closed<double> f = piece.in_double();
        const Closed<Ld> g = piece.in_long_double();
        const double u = 0.5 / piece.p * unit(rng);
        for (double pd : {1e-9, -1e-8, 1e-7, -1e-6, 1e-6, 3e-6}) {
            const double d = pd / piece.p;
            const auto q = f.near(f.at(u), u, d);
            const auto r = g.at(Ld(u) + Ld(d));
            const double u1 = u + std::fabs(d), k1 = f.k1_bound(u1);
            const double e_theta = std::fabs(q.theta - double(r.theta)) / f.theta_noise(u1, k1);
            const double e_omega = std::fabs(q.omega - double(r.omega)) / f.omega_noise(u1, k1);
            const double e_curv = std::fabs(q.curvature - double(r.curvature)) / f.curvature_noise(u1, k1);
            EXPECT_LT(e_theta, 2.0) << "n " << n << ", p d " << pd;
            EXPECT_LT(e_omega, 2.0) << "n " << n << ", p d " << pd;
            EXPECT_LT(e_curv, 2.0) << "n " << n << ", p d " << pd;
            worst = std::max({worst, e_theta, e_omega, e_curv});
        }
    }
    std::printf("near(): largest error %.2f of the rounding level\n", worst);
}

TEST(ClosedPiece, RootsToTheRoundingOfTheirFunction) {
    // solve() for each kind of root (sigma theta at a level: an impact, the
    // first alpha, the fall; theta' = 0: an extremum; theta'' = 0), on the
    // first sign change of a 64-point scan of a random piece, against
    // bisection of the long-double closed form on the same bracket.  The
    // double function is known to its rounding level N (f_noise), so its root
    // to N / |f'| and a few ulps; the point returned at the root to its own
    // rounding plus its slope times that.  The stopping rule that saves the
    // last evaluation (an error bound below eps/64 of the root) must lose
    // nothing measurable against this.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int found[3] = {0, 0, 0};
    double worst_u = 0, worst_om = 0;
    for (int n = 0; n < 3000; ++n) {
        const Piece piece = draw(rng);
        const Closed<double> f = piece.in_double();
        const Closed<Ld> g = piece.in_long_double();
        const double u1 = 0.5 / piece.p, k1 = f.k1_bound(u1);
        const double sigma = unit(rng) < 0.5 ? 1.0 : -1.0;
        const double p2 = piece.p * piece.p, c1 = piece.c1;
        // The level: theta's value at a random time (a crossing there).
        const double level = sigma * double(g.at(Ld(u1 * unit(rng))).theta);
        for (Seek seek : {Seek::level, Seek::extremum, Seek::inflection}) {
            auto value = [&](const auto& q) {
                return seek == Seek::level ? sigma * q.theta - level : seek == Seek::extremum ? q.omega : q.curvature;
            };
            auto slope = [&](const auto& q) {
                return seek == Seek::level       ? sigma * q.omega
                       : seek == Seek::extremum ? p2 * q.curvature
                                                : q.omega + c1;
            };
            const double noise = seek == Seek::level      ? f.theta_noise(u1, k1) + 4 * kEps * std::fabs(level)
                                 : seek == Seek::extremum ? f.omega_noise(u1, k1)
                                                          : f.curvature_noise(u1, k1);
            double lo = 0, f_lo = value(f.at(0.0)), hi = 0, f_hi = 0;
            bool bracket = false;
            for (int i = 1; i <= 64 && !bracket; ++i) {
                hi = u1 * i / 64;
                f_hi = value(f.at(hi));
                if ((f_lo < 0) != (f_hi < 0) && f_lo != 0 && f_hi != 0) bracket = true;
                else lo = hi, f_lo = f_hi;
            }
            if (!bracket) continue;
            // The bracket's ends must straddle the long-double root too.
            const Ld g_lo = value(g.at(Ld(lo))), g_hi = value(g.at(Ld(hi)));
            if ((g_lo < 0) == (g_hi < 0)) continue;
            ++found[static_cast<int>(seek)];
            const auto root = f.solve(seek, sigma, seek == Seek::level ? level : 0.0, lo, hi, f_lo, f_hi, noise);
            const Ld ref = bisect([&](Ld u) { return value(g.at(u)); }, Ld(lo), Ld(hi));
            const auto at_ref = g.at(ref);
            const double s = std::fabs(double(slope(at_ref)));
            const double tol_u = 4 * kEps * std::fabs(double(ref)) + 2 * noise / s;
            const double e_u = std::fabs(root.u - double(ref)) / tol_u;
            EXPECT_LT(e_u, 1.0) << "n " << n << ", kind " << static_cast<int>(seek);
            // theta' at the root: its rounding level (doubled: the double
            // piece rounds its C and W once each, the long-double one forms
            // them exactly) plus theta'' times the root's error (which makes
            // most of it: measured up to 0.95 of the tolerance with a factor
            // 1.01 on that term, hence 1.1).
            const double du = std::fabs(root.u - double(ref));
            const double e_om = std::fabs(root.q.omega - double(at_ref.omega)) /
                                (4 * f.omega_noise(u1, k1) + p2 * std::fabs(double(at_ref.curvature)) * du * 1.1);
            EXPECT_LT(e_om, 1.0) << "n " << n << ", kind " << static_cast<int>(seek);
            worst_u = std::max(worst_u, e_u);
            worst_om = std::max(worst_om, e_om);
        }
    }
    std::printf("solve(): %d levels, %d extrema, %d inflections; largest errors %.2f (root), %.2f (theta') of "
                "the tolerances\n",
                found[0], found[1], found[2], worst_u, worst_om);
    EXPECT_GT(found[0], 1000);
    EXPECT_GT(found[1], 300);
    EXPECT_GT(found[2], 100);
}

TEST(ClosedPiece, TaylorStartsAreAFourthOrderStepCloserThanTheParabola) {
    // The root finder's first point for an impact (ground_root) and for an
    // extremum (slope_root): the root d0 of Taylor's parabola from the
    // piece's start, corrected by one Newton step on Taylor's polynomial to
    // fourth order (taylor_root).  Against the long-double root d* of the
    // closed form, the parabola is off by e0 ~ (p d)^2 / 6 relative (its
    // cubic term); the corrected start must be off by at most
    //   e0 (p d)^2 / 10   (the quintic term left out, (p d)^2 / 20 of the cubic)
    //   + 8 e0^2 / d*     (Newton's own quadratic error)
    //   + 8 eps d*,
    // wherever the parabola is within 5% of the root (beyond, a grazing
    // parabola, the correction may be refused and solve() brackets on).
    // Measured against mutations: theta'''' taken from W instead of C puts
    // the start up to 1300 times the bound away, T(d0) without its quartic
    // term 84,000 times; T'(d0) cut to the parabola's slope (taylor_root's
    // factor 1 - E/S dropped) stays within the bound (0.56 of it: the order
    // of the quintic term) but gains 3.0 digits on average where the start
    // gains 3.5, so the average is held to 3.3.  No start can make a root
    // wrong, only slower: solve() keeps its bracket.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int checked[2] = {0, 0};
    double worst = 0, gain_sum = 0;
    for (int n = 0; n < 100000; ++n) {
        const Piece piece = draw(rng);
        const Closed<double> f = piece.in_double();
        const Closed<Ld> g = piece.in_long_double();
        const double p = piece.p, p2 = p * p, u1 = std::pow(10.0, -3.0 + 1.35 * (unit(rng) + 1.0)) / p;
        const Closed<double>::Point at0{piece.theta0, piece.omega0, f.C};
        const auto end = f.at(u1);
        const double sigma = piece.theta0 > 0 ? 1.0 : -1.0;
        for (int kind = 0; kind < 2; ++kind) {
            // kind 0: sigma theta from above the ground to below it, theta' of
            // one sign (the kernel's monotone impact); kind 1: theta' changing
            // sign with theta'' of one sign (one extremum).
            double start, d0;
            Ld root;
            if (kind == 0) {
                if (!(sigma * end.theta < 0 && (piece.omega0 < 0) == (end.omega < 0))) continue;
                start = f.ground_root(0.0, at0);
                d0 = quadratic_root(sigma * piece.theta0, sigma * piece.omega0, sigma * p2 * f.C);
                root = bisect([&](Ld u) { return Ld(sigma) * g.at(u).theta; }, Ld(0), Ld(u1));
            } else {
                if (!((piece.omega0 < 0) != (end.omega < 0) && (f.C < 0) == (end.curvature < 0))) continue;
                start = f.slope_root(0.0, at0);
                d0 = quadratic_root(piece.omega0, p2 * f.C, p2 * f.W);
                root = bisect([&](Ld u) { return g.at(u).omega; }, Ld(0), Ld(u1));
            }
            const double r = double(root), e0 = std::fabs(d0 - r), e1 = std::fabs(start - r);
            if (!(e0 < 0.05 * r)) continue;
            ++checked[kind];
            const double bound = e0 * (p * r) * (p * r) / 10 + 8 * e0 * e0 / r + 8 * kEps * r;
            EXPECT_LE(e1, bound) << "n " << n << ", kind " << kind << ", p d " << p * r << ", parabola off by "
                                 << e0 / r << " relative";
            worst = std::max(worst, e1 / bound);
            gain_sum += std::log10(std::max(e0, kEps * r) / std::max(e1, kEps * r));
        }
    }
    std::printf("Taylor starts: %d impacts, %d extrema; largest error %.2f of the bound; on average %.1f digits "
                "closer than the parabola\n",
                checked[0], checked[1], worst, gain_sum / (checked[0] + checked[1]));
    EXPECT_GT(checked[0], 1000);
    EXPECT_GT(checked[1], 3000);
    EXPECT_GE(gain_sum / (checked[0] + checked[1]), 3.3);
}

// A rebound leaving theta = 0 at omega on a piece a0 + c1 u (sigma omega >
// 0, sigma lin < 0): its landing, from the bounce form, against the
// long-double root of theta / u by bisection.  The tolerances: g's rounding,
// a few ulps of omega and its corrections over |g'| ~ p^2 |lin| / 2, on the
// time; theta''s rounding and the time's error on the velocity.  Returns the
// larger error as a fraction of its tolerance, -1 where there is no landing
// before u_max (and none found), NaN after a failed expectation.
double check_landing(double p, double lin, double omega, double c1, double u_max, const std::string& what) {
    const Bounce<double> b{p, omega, lin, c1};
    const auto land = b.landing(u_max);
    const Closed<Ld> g{Ld(p), 0, Ld(omega), Ld(lin), Ld(omega) + Ld(c1)};
    auto over_u = [&](Ld u) { return g.at(u).theta / u; };
    // The first sign change of theta / u on a geometric scan of (0, u_max),
    // from 1e-3 of the parabola's landing.
    Ld lo = Ld(-2 * omega / (p * p * lin)) * 1e-3L, hi = lo;
    bool bracket = false;
    while (hi < u_max && !bracket) {
        lo = hi;
        hi = std::min(Ld(u_max), hi * 1.05L);
        bracket = (over_u(lo) < 0) != (over_u(hi) < 0);
    }
    if (!bracket) {
        EXPECT_TRUE(std::isnan(land.u)) << what << ": no landing before u_max, yet one found";
        return std::isnan(land.u) ? -1.0 : NAN;
    }
    EXPECT_FALSE(std::isnan(land.u)) << what << ": landing not found";
    if (std::isnan(land.u)) return NAN;
    const Ld ref = bisect(over_u, lo, hi);
    const auto at_ref = g.at(ref);
    const Closed<double> f = b.closed();
    const double k1 = f.k1_bound(double(ref));
    const double s = std::fabs(double(at_ref.omega)) / double(ref);
    const double tol_u = 4 * kEps * double(ref) + 8 * kEps * (std::fabs(omega) + std::fabs(c1) * double(ref)) / s;
    const double e_u = std::fabs(land.u - double(ref)) / tol_u;
    EXPECT_LT(e_u, 1.0) << what;
    const double du = std::fabs(land.u - double(ref));
    const double e_om = std::fabs(land.q.omega - double(at_ref.omega)) /
                        (2 * f.omega_noise(double(ref), k1) + p * p * std::fabs(double(at_ref.curvature)) * du * 1.01);
    EXPECT_LT(e_om, 1.0) << what;
    return std::max(e_u, e_om);
}

// A rebound drawn for a test of landing(), with its description.
struct Rebound {
    double omega, c1;
    std::string what;
};

// 4000 bounces on pieces with p from 0.5 to 20 rad/s and sigma lin < 0 up to
// 0.3 rad, each rebound drawn by draw(rng, unit, n, p, lin) and checked by
// check_landing: how many landed, and the largest error as a fraction of
// its tolerance.
struct Landings {
    int landed = 0;
    double worst = 0;
};

template <class Draw>
Landings check_landings(std::uint64_t seed, Draw draw) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Landings out;
    for (int n = 0; n < 4000; ++n) {
        const double p = 0.5 * std::pow(40.0, unit(rng)), sigma = unit(rng) < 0.5 ? 1.0 : -1.0;
        const double lin = -sigma * (0.01 + 0.3 * unit(rng));
        const auto [omega, c1, what] = draw(rng, unit, n, p, lin);
        const double e = check_landing(p, lin, omega, c1, 0.1 / p, what);
        if (e >= 0) ++out.landed;
        out.worst = std::max(out.worst, e);
    }
    return out;
}

TEST(ClosedPiece, BounceLandsWhereTheClosedFormReturnsToTheGround) {
    // Bounces from p u = 1e-7 (the end of a cascade) to 0.09 (near the 0.1 / p
    // the kernel allows), where the start from g's series is off by ~1e-4
    // relative and Newton needs more than one step.
    const Landings r = check_landings(11, [](auto& rng, auto& unit, int n, double p, double lin) {
        const double x_target = std::pow(10.0, -7.0 + 5.95 * unit(rng));
        const double omega = -p * lin * x_target / 2;  // the parabola's landing at u = x_target / p
        const double c1 = 50.0 * (2 * unit(rng) - 1);
        return Rebound{omega, c1, "n " + std::to_string(n) + ", p u " + std::to_string(x_target)};
    });
    std::printf("landing(): %d bounces; largest error %.2f of the tolerance\n", r.landed, r.worst);
    EXPECT_GT(r.landed, 3500);
}

TEST(ClosedPiece, AShortBounceLandsByItsSeriesAsByNewton) {
    // The bounces short_bounce() takes (|beta| <= 1e-3, delta <= 1e-5, in
    // double): beta and delta drawn over the whole region, a tenth of them on
    // its edges, where the series' truncation is largest, against the same
    // long-double root and tolerances as above.  A term wrong or left out
    // above rounding fails here (without e's delta^3 term, 9e-15 relative at
    // the edge: 3.4 times the tolerance); the coefficients themselves are
    // checked exactly against their derivation by ctest landing_series.
    const Landings r = check_landings(12, [](auto& rng, auto& unit, int n, double p, double lin) {
        const bool edge = n % 10 == 0;
        const double delta = edge ? kShortDelta * (1 - 1e-9) : kShortDelta * std::pow(10.0, -8 * unit(rng));
        const double beta = (unit(rng) < 0.5 ? -1 : 1) * (edge ? kShortBeta * (1 - 1e-9)
                                                               : kShortBeta * std::pow(10.0, -6 * unit(rng)));
        // beta and delta as Bounce::landing forms them: u0 = -2 omega / (p^2 lin),
        // delta = (p u0)^2 / 12, beta = W u0 / (3 lin).
        const double u0 = std::sqrt(12 * delta) / p, omega = -p * p * lin * u0 / 2;
        return Rebound{omega, 3 * lin * beta / u0 - omega,
                       "n " + std::to_string(n) + ", beta " + std::to_string(beta) + ", delta " +
                           std::to_string(delta)};
    });
    std::printf("short bounces: %d; largest error %.2f of the tolerance\n", r.landed, r.worst);
    EXPECT_EQ(r.landed, 4000);
}
