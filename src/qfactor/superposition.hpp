// The superposition engine: q and theta(t)/alpha for any train of
// piecewise-constant pulses, on the linearised equation of motion.
//
// Model (NOTES.md; the paper's eqs. 6, 9, 13, which fix the sign): rocking on
// the theta > 0 corner,
//     theta'' - p^2 theta = p^2 (a(t)/g - alpha),
// with theta(0) = theta'(0) = 0 and no impact.  In phi = theta/alpha and
// tau = t/to, with F(tau) = q A(tau) - 1 and x = p to:
//     phi'' = x^2 (phi + F).
// Each jump dF_j of F at tau_j adds dF_j (cosh(x (tau - tau_j)) - 1), so
//     phi(tau) = sum_{tau_j <= tau} dF_j (cosh(x (tau - tau_j)) - 1),      (S1)
// dF_0 = q A_0 - 1 and dF_j = q (A_j - A_{j-1}).  phi(t_fin) = 1 (eq. 11) is
// linear in q:
//     q = cosh(x T) / sum_j dA_j (cosh(x s_j) - 1),   s_j = T - tau_j.    (S2)
#pragma once

#include "pulse/pulse_train.hpp"

namespace rocking {

struct QFactor {
    double q;          // PGA / (alpha g) with theta(t_fin) = alpha (eq. 5, 11)
    double condition;  // sum |terms| / |sum| of the denominator of (S2):
                       // the relative error is at most a few times condition * 1e-16
};

// Smallest x accepted: below it q ~ 2/(M1 x^2) leaves the double range.
inline constexpr double kSmallestX = 1e-150;

// q from (S2), evaluated as
//     q = (1 + e^{-2xT}) / sum_j dA_j e^{-x tau_j} expm1(-x s_j)^2        (S3)
// ((S2) times 2 e^{-xT}), which has no overflow for any x and no cancellation
// inside a term as x -> 0.  Throws std::domain_error when x is not a finite
// number >= kSmallestX, or when the train cannot bring theta(t_fin) to alpha
// for any q > 0 (denominator <= 0).
QFactor q_factor(const PulseTrain& train, double x);

// M1 = sum_j dA_j s_j^2 = 2 * integral_0^T (T - s) A(s) ds: as x -> 0,
// q x^2 -> 2 / M1 (the leading term of (S3)).
double first_moment(const PulseTrain& train);
// As x -> infinity, q -> 1 / A_0: the input must only just start rocking.
double q_large_x_limit(const PulseTrain& train);

struct ResponseState {
    double phi;       // theta / alpha
    double dphi;      // (dtheta/dt) / (alpha p)
    double ddphi;     // (d2theta/dt2) / (alpha p^2)
    double magnitude; // sum of the |pieces| phi is summed from: its rounding
                      // error is at most a few (N + 4) eps times this
    double dmagnitude; // the same for dphi
};

// (S1) and its derivatives at tau = t/to for a given q.  After t_fin the
// input is zero (free rocking, still linearised and without impact).  Up to
// t_fin, at the collapse q, (S1)'s terms grow like e^{x(T + tau)} and cancel
// to O(e^{xT}); response() sums instead the per-jump forms (R1)-(R3) of
// superposition.cpp, where that cancellation is done exactly, scaled by
// 2 e^{-xT} as (S3): no overflow for any x, and an error of a few (N + 4) eps
// times magnitude (tests: ResponseAgreesWithMultiprecisionAtTheExtremes).
// At another q = r q_c it adds (r - 1)(cosh(x tau) - 1), the response's true
// growth; a value beyond the double range comes back as +-inf.
ResponseState response(const PulseTrain& train, double x, double q, double tau);
// The same at the collapse q itself, not at its rounding to double: at large
// x that rounding alone moves phi(t_fin) away from 1 by eps cosh(x t_fin).
// Throws std::domain_error where the train has no collapse q (as q_factor).
ResponseState collapse_response(const PulseTrain& train, double x, double tau);

// The lowest phi and phi' from the end of the first pulse to t_fin, and the
// highest phi before t_fin, found exactly (pulse ends and stationary points
// inside each pulse).  During the
// first pulse phi rises monotonically from 0 when rocking starts, so this is
// the lowest rotation the block comes back to.  The closed forms hold only
// while it stays > 0: at phi = 0 the block would hit the ground and change
// corner.
struct Excursion {
    bool onset;         // q A_0 > 1: the first pulse starts rocking at all
    double min_phi;     // lowest theta/alpha on [end of pulse 1, t_fin]
    double tau_at_min;  // where it occurs, in units of to
    double min_dphi;    // lowest (dtheta/dt)/(alpha p) on (0, t_fin]: < 0 means the
                        // motion reverses before t_fin (the paper assumes it does not)
    double max_phi;     // highest theta/alpha on (0, t_fin): >= 1 means theta passed
                        // alpha before the instant where the paper imposes it
    double tau_at_max;  // where it occurs, in units of to
    bool stays_positive() const { return onset && min_phi > 0.0; }
    bool passes_alpha() const { return max_phi >= 1.0; }
};
Excursion excursion(const PulseTrain& train, double x, double q);
// At the collapse q itself, as collapse_response.
Excursion collapse_excursion(const PulseTrain& train, double x);

}  // namespace rocking
