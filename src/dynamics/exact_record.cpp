#include "dynamics/exact_record.hpp"

#include "dynamics/closed_piece.hpp"
#include "dynamics/run_rules.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rocking::dynamics {

bool record_kernel_applies(const Model& model, const GroundInput& input, const SimulationOptions& options) {
    if (options.solver.kind != SolverKind::exact || !options.solver.record_kernel) return false;
    if (model.equation != Equation::linearised || options.record_dt > 0.0) return false;
    const auto* sampled = dynamic_cast<const SampledInput*>(&input);
    // Longer pieces are split by ExactStepper (max_step_p); the kernel keeps
    // to pieces it takes whole, as the general path does, on either corner
    // of an imperfect block (p_max: the faster one's).
    return sampled != nullptr && model.p_max() * sampled->dt() <= options.solver.max_step_p;
}

namespace {

using closed_piece::Bounce;
using closed_piece::Closed;
using closed_piece::series;

// What the kernel needs of the corner rocked on, fixed for a run: its
// slenderness and pulsation, and the constants of a whole record piece on
// it, cosh p dt - 1, sinh p dt and (sinh p dt - p dt) / p (the increments
// of the closed form, Closed), with p sinh p dt (the quiet loop's product).
template <class Real>
struct CornerConstants {
    Real alpha, p, inv_p, h_free, k1_dt, s_dt, q_dt, ps_dt;

    CornerConstants(double alpha_, double p_, Real dt, double max_step_p) : alpha(alpha_), p(p_) {
        inv_p = 1.0 / p;
        h_free = max_step_p / p;  // step of the free rocking (ground at rest)
        Real ch1_dt, sh1_dt;
        series(p * dt * p * dt, ch1_dt, sh1_dt);
        k1_dt = p * dt * p * dt * ch1_dt;
        s_dt = p * dt * (1 + p * dt * p * dt * sh1_dt);
        q_dt = dt * p * dt * p * dt * sh1_dt;
        ps_dt = p * s_dt;
    }
};

// The two corners of a block (docs/imperfect.md): on(sigma) is the corner
// rocked on while sgn theta = sigma.  kImperfect false: one set, the
// symmetric block's, and on() compiles to it (no test of sigma).
template <class Real, bool kImperfect>
struct Corners {
    CornerConstants<Real> plus, minus;

    Corners(const Model& model, Real dt, double max_step_p)
        : plus(model.block.alpha, model.block.p, dt, max_step_p),
          minus(model.alpha_on(-1), model.p_on(-1), dt, max_step_p) {}
    const CornerConstants<Real>& on(int sigma) const {
        if constexpr (kImperfect) return sigma > 0 ? plus : minus;
        else return plus;
    }
};

// kObserved: observer is told of each flight's start (FlightStart); without
// it, the instantiation holds none of that code.  kImperfect: the block's
// corners differ (Model::minus set): each flight takes the constants of the
// corner it rocks on (Corners), an impact the restitution of the corner it
// lands on (rules::impact), and the run keeps the largest theta on each
// side, which the criteria measure against their own side's alpha.
template <class Real, bool kImperfect, bool kObserved = false>
SimulationResult run_kernel(const Model& model, const SampledInput& input, const SimulationOptions& options,
                            FlightObserver* observer = nullptr) {
    const std::vector<double>& a = input.samples();
    const Real dt = input.dt(), inv_dt = 1.0 / dt;
    const Real t_fin = input.t_end();
    const Corners<Real, kImperfect> corners(model, dt, options.solver.max_step_p);
    // The general path's "rose" rule (simulate.cpp), on the smaller alpha.
    const Real noise = 1e-12 * Real(model.alpha_min());
    const Real rest = options.rest_velocity;

    SimulationResult result = rules::new_result(options, t_fin);
    rules::RunState<Real> run(options, t_fin);
    // The state itself (run's fields), under the names of the equations.
    Real &t = run.t, &theta = run.theta, &omega = run.omega;
    int& sigma = run.sigma;
    bool done = false;
    std::size_t k = 0;  // the record piece holding t, while t < t_fin
    Real max_theta = 0;  // largest |theta| on [0, t_fin]
    // kImperfect: the largest theta and -theta on [0, t_fin].
    Real peak_plus = 0, peak_minus = 0;

    auto note_theta = [&](Real when, Real value) {
        if (when <= t_fin) {
            max_theta = std::max(max_theta, std::fabs(value));
            if constexpr (kImperfect) {
                if (value > 0) peak_plus = std::max(peak_plus, value);
                else peak_minus = std::max(peak_minus, -value);
            }
        }
    };
    // The largest sigma theta so far on side sigma: what an extremum there
    // must pass to change the run's peaks (the symmetric block's, the
    // largest |theta|; an imperfect block's, its side's, measured against
    // that side's alpha by the criteria).
    auto largest_on = [&](int s) -> Real {
        if constexpr (kImperfect) return s > 0 ? peak_plus : peak_minus;
        else return max_theta;
    };
    // A flight starts from the run's state (after an impact: unless it rests).
    auto flight_starts = [&]() {
        if constexpr (kObserved) {
            if (!run.resting)
                observer->flight({static_cast<double>(t), static_cast<double>(theta), static_cast<double>(omega), sigma});
        }
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
    // The input as this interpolation gives it, for the uplift from rest
    // (uplift_time): SampledInput::accel, on the rounded grid, can put it
    // ~ c1 ulp(t) higher, above the threshold where this is below, and the
    // block would start pressed into the ground, return to it within rounding
    // and rest to the piece's end, losing the motion there.
    auto accel_at = [&](double s) { return rest_of_piece_at(input.piece_index(s), s).a0; };

    // Theta at the extremum inside a whole piece from (theta0, omega0), with
    // C = theta0 + lin, W = omega0 + c1 and theta' = om1 at its end, of the
    // other sign.  Out of line: inlined, its root finder cost the quiet loop
    // below registers (9,000 more instructions on Norcia's 1,037 quiet pieces).
    auto theta_at_extremum = [&](Real theta0, Real omega0, Real C, Real W, Real om1) __attribute__((noinline)) {
        const CornerConstants<Real>& c = corners.on(sigma);
        const Closed<Real> f{c.p, theta0, omega0, C, W};
        return f.extremum({theta0, omega0, C}, 0, dt, om1, f.omega_noise(dt, c.k1_dt)).q.theta;
    };
    // Where the tangents at the ends of an arc of sigma theta meet, from
    // (0, s0) with slope w0 and (u, s1) with slope -w1 (w0, w1 > 0): above
    // the arc's maximum where it is concave, below its minimum where convex.
    auto tangents_meet = [](Real s0, Real w0, Real s1, Real w1, Real u) {
        return s0 + w0 * ((s1 - s0 + w1 * u) / (w0 + w1));
    };
    // The level that sigma theta, rising from s, must stay below for nothing
    // to happen: the first alpha (its side's) while it is to come, the fall angle.
    auto upper_from = [&](Real s) -> Real {
        const Real alpha = corners.on(sigma).alpha;
        return std::isnan(result.t_first_alpha) && s < alpha ? std::min(alpha, Real(options.overturn_angle))
                                                             : Real(options.overturn_angle);
    };
    // An impact and its cascade: the impact found at u on the closed form of
    // the piece from t, and the rebounds after it that land inside the same
    // record piece.
    auto impact_and_cascade = [&](const typename Closed<Real>::Found& hit) {
        const Real om_i = hit.q.omega;
        const Real t_impact = t + hit.u;
        note_theta(t_impact, 0.0);
        rules::impact(run, result, model, options, t_impact, om_i, rest);
        flight_starts();
        // The rebounds that land inside the same record piece (an impact
        // cascade) go by the bounce form, one Newton solve each, while it can
        // be shown that nothing else happens on the way: sigma theta'' < 0 at
        // both ends (theta'' has one sign change at most, so sigma theta is
        // concave: one rise, one fall, no dip), and the rise below the bound
        // of a concave arc, so below the largest |theta| so far and below
        // alpha when alpha has not been reached.  Otherwise the rest of the
        // piece goes back to the piece analysis.
        // The rest of the piece is taken from the grid once (rest_of_piece)
        // and then moved by each landing, a0 + c1 u_land and u1 - u_land:
        // from the grid again it would come through t + u_land rounded and
        // two fma library calls, on the path from one rebound to the next
        // (Norcia: 17.6 -> 17.0 us; impact times within 3.6e-15 s, ulp(t)).
        // (The loop and the shortcut below run only while the state is
        // inside the piece it starts in, as it is here when either runs.)
        // Each rebound flies on the corner just landed on (sigma after the
        // impact), with its own alpha and p.
        const bool inside = !run.resting && t < t_fin && t < dt * (k + 1);
        Rest piece = inside ? rest_of_piece() : Rest{0, 0, 0};
        Real lin_b = piece.a0 - sigma * corners.on(sigma).alpha;
        while (!run.resting && t < t_fin && t < dt * (k + 1)) {
            const CornerConstants<Real>& c = corners.on(sigma);
            const Real u_max = std::min(piece.u1, Real(0.1) * c.inv_p);
            if (!(sigma * lin_b < 0)) break;
            const typename Closed<Real>::Found landing = Bounce<Real>{c.p, omega, lin_b, piece.c1}.landing(u_max);
            const Real u_land = landing.u;
            if (std::isnan(u_land)) break;
            const typename Closed<Real>::Point& land = landing.q;
            const Real om_land = land.omega;
            if (!(sigma * land.curvature < 0 && sigma * om_land < 0)) break;
            // On the concave arc theta <= omega u and theta <= |omega_land| (u_land - u).
            const Real w0 = std::fabs(omega), w1 = std::fabs(om_land);
            if (!(w0 * w1 * u_land < largest_on(sigma) * (w0 + w1))) break;
            ++result.steps;
            const Real t_land = t + u_land;
            rules::impact(run, result, model, options, t_land, om_land, rest);
            flight_starts();
            // The next bounce's lin (sigma is the new corner's) with the move
            // added last: one product and an add after u_land, not two adds.
            lin_b = (piece.a0 - sigma * corners.on(sigma).alpha) + piece.c1 * u_land;
            piece.a0 += piece.c1 * u_land;
            piece.u1 -= u_land;
        }
        // The rebound that outlasts the piece goes on to the piece's end, as
        // the piece analysis would take it, without the analysis (which would
        // locate its top): nothing happens on the way when sigma theta is
        // concave (sigma theta'' < 0 at both ends), ends above noise, and the
        // tangents at the ends (tangents_meet) keep its top below the largest
        // |theta| so far, as in the loop above.
        if (!run.resting && t < t_fin && t < dt * (k + 1)) {
            const CornerConstants<Real>& c = corners.on(sigma);
            lin_b = piece.a0 - sigma * c.alpha;
            if (!(sigma * lin_b < 0)) return;
            const Closed<Real> f{c.p, 0, omega, lin_b, omega + piece.c1};
            const typename Closed<Real>::Point end = f.at(piece.u1);
            const Real s1 = sigma * end.theta, w0 = sigma * omega, w1 = -sigma * end.omega;
            if (!(sigma * end.curvature < 0 && s1 > noise && w0 > 0)) return;
            const Real top = w1 > 0 ? tangents_meet(0, w0, s1, w1, piece.u1) : s1;
            if (!(top < largest_on(sigma) * Real(1 - 1e-9))) return;
            ++result.steps;
            t = dt * (k + 1);
            theta = end.theta;
            omega = end.omega;
            if (t < t_fin) ++k;
        }
    };

    // Whether the block has left the ground since the pass began (the
    // general path's "rose" rule, simulate.cpp): a return to it before then
    // is rounding, and the block rests.
    bool rose = false;

    // Quiet whole pieces from t, a handful of flops each: nothing can happen
    // inside a piece whose ends have sigma theta > noise, theta' of one sign
    // and theta'' of one sign (theta' monotone: no extremum), sigma theta
    // below the fall angle and no first crossing of alpha.  Stops at the
    // first piece that may hold an event, with t, theta, omega and k at its
    // start.
    auto quiet_pieces = [&]() {
        if (!(dt * k <= t && t < dt * (k + 1))) k = input.piece_index(t);
        const CornerConstants<Real>& c = corners.on(sigma);
        const Real sa = sigma * c.alpha, k1_dt = c.k1_dt, q_dt = c.q_dt, ps_dt = c.ps_dt;
        const Real upper = upper_from(sigma * theta);
        const std::size_t k0 = k;
        Real peak = 0.0;
        if (t == dt * k) {
            // The state and the record in locals: theta and omega are
            // the run's fields, which the loads of a[] might alias.
            Real th0 = theta, om0 = omega, a_k = a[k], C = th0 + (a_k - sa);
            const Real sg = sigma;
            const double* const a_end = a.data() + a.size();
            const double* a_next = a.data() + k + 1;
            for (; a_next < a_end; ++a_next) {  // t_stop = t_fin here
                const Real a_k1 = *a_next;
                const Real c1 = (a_k1 - a_k) * inv_dt, W = om0 + c1;
                const Real th1 = th0 + om0 * dt + C * k1_dt + W * q_dt;
                const Real om1 = om0 + C * ps_dt + W * k1_dt;
                // theta''/p^2 at the end, eq. 3 at the point: the next piece's C.
                const Real e1 = th1 + (a_k1 - sa);
                const Real s1 = sg * th1;
                // C e1 > 0: theta'' of one sign at both ends, so theta'
                // is monotone (an underflow to 0 only sends the piece
                // to the full analysis).
                if (!(s1 > noise && s1 < upper && C * e1 > 0.0)) break;
                if (!(om0 * om1 > 0.0)) {
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
                    const Real s0 = sg * th0, w0 = sg * om0, w1 = -sg * om1;
                    if (!(s0 > noise && om0 * om1 < 0.0)) break;
                    const Real v = tangents_meet(s0, w0, s1, w1, dt);
                    if (sg * C < 0.0) {
                        if (!(v < upper * Real(1 - 1e-9))) break;
                        if (!(v < std::max(peak, largest_on(sigma)) * Real(1 - 1e-9))) {
                            peak = std::max(peak, sg * theta_at_extremum(th0, om0, C, W, om1));
                        }
                    } else if (!(v > 2 * noise)) {
                        break;
                    }
                }
                th0 = th1;
                om0 = om1;
                a_k = a_k1;
                C = e1;
                peak = std::max(peak, s1);
            }
            k = static_cast<std::size_t>(a_next - a.data()) - 1;
            theta = th0;
            omega = om0;
        }
        if (k != k0) {
            t = dt * k;
            rose = true;
            max_theta = std::max(max_theta, peak);
            if constexpr (kImperfect) (sigma > 0 ? peak_plus : peak_minus) = std::max(largest_on(sigma), peak);
            result.steps += static_cast<long>(k - k0);
        }
    };

    // The piece from t to its end te (the record's next sample, or a step
    // of the free rocking after the input) by its closed form, and its
    // events; true when one ends the segment.
    auto piece_events = [&](Real t_stop) -> bool {
        const CornerConstants<Real>& corner = corners.on(sigma);
        const Real alpha = corner.alpha, p = corner.p, h_free = corner.h_free;
        Real te, a0, c1;
        Real u1;
        if (t < t_fin) {
            // k holds t here: the quiet pieces set it (t = k dt) or left both as they were.
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
        const Real k1 = f.k1_bound(u1);  // for rounding levels
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
            impact_and_cascade(f.level(sigma, 0, 0, u1, s0, s1, f.theta_noise(u1, k1),
                                       f.ground_root(0, {theta, omega, f.C})));
            return true;
        } else {
            // Rounding levels of theta, theta' and theta''/p^2 on this piece.
            const Real e_noise = f.curvature_noise(u1, k1);
            const Real th_noise = f.theta_noise(u1, k1);
            const Real om_noise = f.omega_noise(u1, k1);

            // Where theta'' changes sign with theta' keeping its sign at both
            // ends, or starting from 0 (the uplift from rest), theta' may
            // vanish twice (or once more): split where theta'' = 0.
            Real u_split = u1;
            typename Closed<Real>::Point at_split = end;
            const Real e0 = f.C, e1 = end.curvature;
            const bool from_rest = omega == 0.0;
            if ((e0 < 0) != (e1 < 0) && e0 != 0.0 && e1 != 0.0 && (from_rest || (omega < 0) == (om1 < 0))) {
                const typename Closed<Real>::Found infl = f.inflection(0, u1, e0, e1, e_noise);
                if (infl.u > 0.0 && infl.u < u1 && infl.q.omega != 0.0 &&
                    (from_rest || (infl.q.omega < 0) != (omega < 0))) {
                    u_split = infl.u;
                    at_split = infl.q;
                }
            }
            // part_events: the parts [0, u_split] and [u_split, u1], each
            // holding one extremum of theta at most, and their events: the
            // extremum, the impact (sigma theta reaches 0), the fall, the
            // first |theta| = alpha.  An event that ends the segment (a
            // fall, a rest, an impact) is applied to the run.  (Written in
            // the loop, not as a lambda: as one, called for each part, it
            // cost 0.1 us of Norcia's 16.)
            Real ua = 0.0;
            typename Closed<Real>::Point at_a{theta, omega, f.C};
            for (;;) {
                const Real ub = u_split;
                const typename Closed<Real>::Point& at_b = at_split;
                const Real eps4 = 4 * std::numeric_limits<Real>::epsilon();
                const Real tha = at_a.theta, oma = at_a.omega, thb = at_b.theta, omb = at_b.omega;
                // Extremum of theta inside the part (theta' changes sign, once).
                typename Closed<Real>::Found ext{NAN, {NAN, NAN, NAN}};
                if ((oma < 0) != (omb < 0) && oma != 0.0 && omb != 0.0) ext = f.extremum(at_a, ua, ub, omb, om_noise);
                const Real u_ext = ext.u, th_ext = ext.q.theta;
                const bool has_ext = !std::isnan(u_ext);
                // Terminal events: impact (sigma theta reaches 0), fall.
                typename Closed<Real>::Found hit{INFINITY, {}}, fall{INFINITY, {}};
                // Next to an extremum theta is a parabola, nearly flat when the
                // rebound is small (the end of an impact cascade): the root finder
                // starts from the parabola's root, u_ext -+ sqrt(2 |theta_ext / theta''_ext|).
                auto beside_ext = [&](Real side) {
                    return u_ext + side * std::sqrt(std::fabs(2 * th_ext / (p * p * ext.q.curvature)));
                };
                if (has_ext && sigma * th_ext < 0.0)
                    hit = f.level(sigma, 0, ua, u_ext, sigma * tha, sigma * th_ext, th_noise, beside_ext(-1.0));
                else if (sigma * thb < 0.0)
                    hit = has_ext ? f.level(sigma, 0, u_ext, ub, sigma * th_ext, sigma * thb, th_noise, beside_ext(1.0))
                                  : f.level(sigma, 0, ua, ub, sigma * tha, sigma * thb, th_noise,
                                            f.ground_root(ua, at_a));
                if (sigma * thb >= options.overturn_angle)
                    fall = f.level(sigma, options.overturn_angle, ua, ub, sigma * tha - options.overturn_angle,
                                   sigma * thb - options.overturn_angle, th_noise + eps4 * options.overturn_angle);
                const Real u_impact = hit.u, u_fall = fall.u;
                const Real u_cut = std::min({u_impact, u_fall, ub});
                // First time |theta| = alpha.
                if (std::isnan(result.t_first_alpha) && sigma * tha < alpha) {
                    const Real th_cut = u_cut == ub ? thb : u_cut == u_impact ? hit.q.theta : fall.q.theta;
                    if (sigma * th_cut >= alpha)
                        result.t_first_alpha = t + f.level(sigma, alpha, ua, u_cut, sigma * tha - alpha,
                                                           sigma * th_cut - alpha, th_noise + eps4 * alpha)
                                                       .u;
                    else if (has_ext && u_ext < u_cut && sigma * th_ext >= alpha)
                        result.t_first_alpha = t + f.level(sigma, alpha, ua, u_ext, sigma * tha - alpha,
                                                           sigma * th_ext - alpha, th_noise + eps4 * alpha)
                                                       .u;
                }
                if (has_ext && u_ext <= u_cut) note_theta(t + u_ext, th_ext);
                if (sigma * thb > noise || (has_ext && u_ext <= u_cut && sigma * th_ext > noise)) rose = true;

                if (u_fall <= u_cut && u_fall < INFINITY) {
                    // The fall.
                    result.overturned = true;
                    result.t_overturn = t + u_fall;
                    result.overturned_during_input = result.t_overturn <= t_fin;
                    note_theta(result.t_overturn, sigma * options.overturn_angle);
                    done = true;
                    return true;
                }
                if (u_impact <= u_cut && u_impact < INFINITY) {
                    if (rose) {
                        impact_and_cascade(hit);
                    } else {
                        // Within rounding of the ground: at rest to the piece's end.
                        t = te;
                        theta = omega = 0.0;
                        run.resting = true;
                    }
                    return true;
                }
                note_theta(ub >= u1 ? te : t + ub, thb);
                if (ub >= u1) break;
                ua = ub;
                at_a = at_b;
                u_split = u1;
                at_split = end;
            }
        }
        t = te;
        theta = th1;
        omega = om1;
        if (t < t_fin && t >= dt * (k + 1)) ++k;
        return false;
    };

    // The run: the rules at the top of each pass (the end of the input, the
    // uplift from rest, the free rocking's end), then the pieces to the
    // next event.
    if (!run.resting) flight_starts();  // a block released (initial_theta, initial_omega)
    for (;;) {
        const bool was_resting = run.resting;
        if (done || !rules::begin_pass(run, result, model, input, accel_at, options, t_fin, note_theta, [](Real) {}))
            break;
        if (was_resting && !run.resting) flight_starts();  // the uplift
        const Real t_stop = t < t_fin ? t_fin : run.t_limit;
        rose = std::fabs(theta) > noise || std::fabs(omega) > 0.0;
        bool event = false;
        while (!event && t < t_stop) {
            if (t < t_fin) {
                quiet_pieces();
                if (!(t < t_stop)) break;
            }
            event = piece_events(t_stop);
        }
    }
    rules::decide_by_energy(run, result, model, options, t_fin);
    result.max_abs_theta_input = static_cast<double>(max_theta);
    if constexpr (kImperfect) {
        result.peak_plus_input = static_cast<double>(peak_plus);
        result.peak_minus_input = static_cast<double>(peak_minus);
    }
    return result;
}

}  // namespace

SimulationResult simulate_record_kernel(const Model& model, const SampledInput& input, const SimulationOptions& options) {
    return model.symmetric() ? run_kernel<double, false>(model, input, options)
                             : run_kernel<double, true>(model, input, options);
}

SimulationResult simulate_record_kernel(const Model& model, const SampledInput& input, const SimulationOptions& options,
                                        FlightObserver& observer) {
    return model.symmetric() ? run_kernel<double, false, true>(model, input, options, &observer)
                             : run_kernel<double, true, true>(model, input, options, &observer);
}

SimulationResult simulate_record_kernel_extended(const Model& model, const SampledInput& input,
                                                const SimulationOptions& options) {
    return model.symmetric() ? run_kernel<long double, false>(model, input, options)
                             : run_kernel<long double, true>(model, input, options);
}

}  // namespace rocking::dynamics
