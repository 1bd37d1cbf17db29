#include "dynamics/simulate.hpp"

#include "dynamics/exact_record.hpp"
#include "dynamics/run_rules.hpp"
#include "numerics/roots.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <stdexcept>

namespace rocking::dynamics {

std::string criterion_name(Criterion c) {
    switch (c) {
        case Criterion::final_rotation: return "final-rotation";
        case Criterion::peak_rotation: return "peak-rotation";
        case Criterion::overturning: return "overturning";
    }
    return "?";
}

Criterion parse_criterion(const std::string& name) {
    for (Criterion c : {Criterion::final_rotation, Criterion::peak_rotation, Criterion::overturning})
        if (criterion_name(c) == name) return c;
    throw std::invalid_argument("unknown criterion '" + name + "' (final-rotation, peak-rotation, overturning)");
}

bool SimulationResult::collapse(Criterion c, double alpha) const {
    if (overturned_during_input) return true;
    switch (c) {
        case Criterion::final_rotation: return std::fabs(theta_at_tfin) >= alpha;
        case Criterion::peak_rotation: return max_abs_theta_input >= alpha;
        case Criterion::overturning: return overturned;
    }
    return false;
}

namespace {

// The root of f on [a, b], where the caller knows a sign change.  f(a) is
// re-evaluated from the step's closed form or interpolant, which at a root
// just located (theta = 0 after an impact) can come out with the sign of
// f(b) by rounding: the root is then at a itself.
template <class F>
double locate(F f, double a, double b) {
    const double fa = f(a), fb = f(b);
    if (fb == 0.0) return b;
    if (fa == 0.0 || (fa < 0) == (fb < 0)) return a;
    return numerics::root_of(f, a, b, fa, fb, 50);
}

}  // namespace

double rest_threshold(const SimulationOptions& options) {
    return std::max(options.rest_velocity,
                    options.solver.kind == SolverKind::exact ? 0.0 : 10.0 * options.solver.atol_alpha);
}

SimulationResult simulate(const Model& model, const GroundInput& input, const SimulationOptions& options) {
    if (const auto* sine = dynamic_cast<const OneSinePulse*>(&input)) {
        const double slowest = OneSinePulse::slowest_wp_over_p * model.block.p;
        if (!(sine->wp() >= slowest)) {
            char text[240];
            std::snprintf(text, sizeof text,
                          "one-sine pulse: w_p = %g rad/s is below 1e-6 p = %g rad/s: so slow a pulse lifts the block "
                          "by less than the rounding of the input (OneSinePulse::slowest_wp_over_p)",
                          sine->wp(), slowest);
            throw std::invalid_argument(text);
        }
    }
    if (record_kernel_applies(model, input, options))
        return simulate_record_kernel(model, static_cast<const SampledInput&>(input), options);
    const double alpha = model.block.alpha, p = model.block.p;
    const double t_fin = input.t_end();
    std::vector<double> breaks = input.discontinuities();
    breaks.push_back(t_fin);
    std::sort(breaks.begin(), breaks.end());

    SimulationResult result = rules::new_result(options, t_fin);
    auto stepper = make_stepper(model, input, options.solver);
    stepper->set_batching(options.record_dt <= 0.0, options.overturn_angle);

    rules::RunState<double> run(options, t_fin);
    long next_sample_index = 0;

    auto sample_until = [&](double until, const std::function<void(double, double&, double&)>& at) {
        if (options.record_dt <= 0) return;
        // Sample times k dt; the last one may overshoot t_limit by rounding.
        for (double ts = next_sample_index * options.record_dt;
             ts <= until && ts <= run.t_limit * (1 + 1e-12); ts = ++next_sample_index * options.record_dt) {
            double th, om;
            at(std::min(ts, until), th, om);
            result.samples.push_back({ts, th, om});
        }
    };
    auto note_theta = [&](double when, double value) {
        if (when <= t_fin) result.max_abs_theta_input = std::max(result.max_abs_theta_input, std::fabs(value));
    };
    auto rest_until = [&](double until) {
        sample_until(until, [](double, double& th, double& om) { th = om = 0.0; });
    };

    bool done = false;
    while (!done && rules::begin_pass(run, result, model, input, [&](double s) { return input.accel(s); }, options, t_fin,
                                               note_theta, rest_until)) {
        const double t = run.t, theta = run.theta, omega = run.omega;
        const int sigma = run.sigma;
        double t_stop = run.t_limit;
        for (double b : breaks)
            if (b > t) {
                t_stop = b;
                break;
            }
        if (t >= t_fin) t_stop = run.t_limit;
        stepper->reset(t, theta, omega, sigma, t_stop);
        double ta = t, tha = theta, oma = omega;
        bool event = false;
        int stalled = 0;  // steps in a row that left t where it was
        // A block lifted from rest with an acceleration just above the threshold
        // rises from theta = 0 by less than rounding at first; a return to 0
        // before it has risen above that noise is no impact: it stays at rest.
        const double noise = 1e-12 * alpha;
        bool rose = std::fabs(theta) > noise || std::fabs(omega) > 0.0;
        auto th_at = [&](double s) {
            double th, om;
            stepper->state_at(s, th, om);
            return th;
        };
        auto om_at = [&](double s) {
            double th, om;
            stepper->state_at(s, th, om);
            return om;
        };
        // The events of [ta, tb], a part of a step holding at most one
        // extremum of theta, from the states at its ends; true when one ends
        // the segment (impact, rest, fall), which it applies to run.
        auto analyse_part = [&](double ta, double tha, double oma, double tb, double thb, double omb) {
            // Extremum of theta inside the part (theta' changes sign, once).
            double t_ext = NAN, th_ext = NAN;
            if ((oma < 0) != (omb < 0) && oma != 0.0 && omb != 0.0) {
                t_ext = locate(om_at, ta, tb);
                th_ext = th_at(t_ext);
            }
            // Terminal events: impact (sigma theta reaches 0) and fall.
            double t_impact = INFINITY, t_fall = INFINITY;
            // The first root of sigma theta in the step: before the extremum
            // when theta dips below 0 there, after it otherwise.
            auto impact_in = [&](double lo, double hi) {
                return locate([&](double s) { return sigma * th_at(s); }, lo, hi);
            };
            const bool dips = !std::isnan(t_ext) && sigma * th_ext < 0.0;
            if (dips) t_impact = impact_in(ta, t_ext);
            else if (sigma * thb < 0.0) t_impact = impact_in(std::isnan(t_ext) ? ta : t_ext, tb);
            if (sigma * thb >= options.overturn_angle)
                t_fall = locate([&](double s) { return sigma * th_at(s) - options.overturn_angle; }, ta, tb);
            const double t_cut = std::min({t_impact, t_fall, tb});
            // First time |theta| = alpha.
            if (std::isnan(result.t_first_alpha) && sigma * tha < alpha) {
                if (sigma * th_at(t_cut) >= alpha)
                    result.t_first_alpha = locate([&](double s) { return sigma * th_at(s) - alpha; }, ta, t_cut);
                else if (!std::isnan(t_ext) && t_ext < t_cut && sigma * th_ext >= alpha)
                    result.t_first_alpha = locate([&](double s) { return sigma * th_at(s) - alpha; }, ta, t_ext);
            }
            if (!std::isnan(t_ext) && t_ext <= t_cut) note_theta(t_ext, th_ext);
            if (sigma * thb > noise || (!std::isnan(t_ext) && t_ext <= t_cut && sigma * th_ext > noise)) rose = true;
            sample_until(t_cut, [&](double s, double& th, double& om) { stepper->state_at(s, th, om); });
            if (t_fall <= t_cut && t_fall < INFINITY) {
                result.overturned = true;
                result.t_overturn = t_fall;
                result.overturned_during_input = t_fall <= t_fin;
                note_theta(t_fall, sigma * options.overturn_angle);
                done = true;
                return true;
            } else if (t_impact <= t_cut && t_impact < INFINITY && !rose) {
                // Still within rounding of the ground: at rest to the end of the
                // step (progress is guaranteed), then the uplift rule again.
                run.t = tb;
                run.theta = run.omega = 0.0;
                run.resting = true;
                return true;
            } else if (t_impact <= t_cut && t_impact < INFINITY) {
                double th_i, om_i;
                stepper->state_at(t_impact, th_i, om_i);
                note_theta(t_impact, 0.0);
                // The end of a cascade: a rebound below the rest threshold, or a
                // second impact within 1e-6/p of the last (a bounce too small to
                // resolve), leaves the block at rest; the input may lift it again at once.
                const bool micro = rules::record_impact(result, t_impact, options, p);
                rules::apply_impact(run, result, model, t_impact, om_i, micro, rest_threshold(options));
                return true;
            }
            note_theta(tb, thb);
            return false;
        };
        while (!event && stepper->advance()) {
            // A step shorter than half an ulp of t leaves t where it was, and
            // there is nothing to analyse (a dense output's interpolant over
            // it is 0/0).  An ODE solver's first steps may, and grow; where even
            // max_step_p / p is that short (p t beyond double's resolution) no
            // step ever moves t, and the run would never end.
            if (stepper->t_end() > stepper->t_begin()) {
                stalled = 0;
            } else if (++stalled <= 100) {
                continue;
            } else {
                char text[320];
                std::snprintf(text, sizeof text,
                              "%s solver: no progress at t = %.17g s in 100 steps: its step (at most max_step_p / p = "
                              "%.3g s) is below double's resolution there: p t = %.3g (p = %.6g rad/s) is too large",
                              solver_name(options.solver.kind).c_str(), stepper->t_begin(),
                              options.solver.max_step_p / p, p * stepper->t_begin(), p);
                throw std::runtime_error(text);
            }
            // The step may have started after the last one seen (a batched run);
            // at the segment's start the state is known exactly (an interpolant
            // may put theta' = 0 a rounding error off and fake an extremum).
            if (stepper->t_begin() != ta) {
                ta = stepper->t_begin();
                stepper->state_at(ta, tha, oma);
            }
            const double tb = stepper->t_end();
            double thb, omb;
            stepper->state_at(tb, thb, omb);
            if (!std::isfinite(thb) || !std::isfinite(omb)) {
                char text[240];
                std::snprintf(text, sizeof text, "%s solver: the state is not finite at t = %.17g s (theta %g, theta' %g)",
                              solver_name(options.solver.kind).c_str(), tb, thb, omb);
                throw std::runtime_error(text);
            }
            // The step's parts, each holding at most one extremum of theta,
            // which the analysis below assumes.  A part first ends at the
            // input's next kink (a record's sample; Dormand-Prince steps across
            // them) and, on a sinusoidal piece, where the sine crosses 0.  On
            // a part where the input is linear, theta'' (a combination of cosh
            // and sinh on eq. 3) changes sign once at most; on a sinusoidal one
            // it can change sign twice, and the part is first cut between the
            // two (below).  theta' then vanishes at most twice, and only when
            // theta'' changes sign while theta' keeps its sign at the ends, or
            // starts from 0 (the uplift from rest): the part is then split
            // where theta'' = 0 if theta' has the other sign there, or any sign
            // after an uplift.  Missing this put a block at rest where it flew
            // out and back within one step (an impact at the step's start, then
            // a micro-bounce, or a rest that the uplift's own step ended), or
            // let it pass through the ground unseen.
            double pa = ta, pha = tha, poa = oma;
            while (!event && pa < tb) {
                const InputPiece piece = input.piece_from(pa);
                double pb = std::min(piece.t1 > pa && piece.t1 < tb ? piece.t1 : tb, piece.next_sine_zero(pa));
                double phb = thb, pob = omb;
                if (pb < tb) stepper->state_at(pb, phb, pob);
                bool quiet = false;
                const bool from_rest = poa == 0.0;
                auto keeps_sign = [&] { return from_rest || ((poa < 0) == (pob < 0) && poa != 0.0 && pob != 0.0); };
                if (piece.s != 0.0 || keeps_sign()) {
                    // theta'' on this part, from the input's piece holding it.
                    auto curvature_at = [&](double s) {
                        double th, om;
                        stepper->state_at(s, th, om);
                        return model.acceleration(th, sigma, piece.at(s));
                    };
                    const double ea = model.acceleration(pha, sigma, piece.at(pa));
                    double eb = model.acceleration(phb, sigma, piece.at(pb));
                    // On a sinusoidal piece, eq. 3 gives theta'' = p^2 (H + K sin(w u
                    // + ph)), H = C cosh pu + D sinh pu, K = s w^2 / (p^2 + w^2), so
                    // (theta'')'' - p^2 theta'' = -(p^2 + w^2) p^2 K sin(w u + ph), of
                    // one sign on the part.  Where it is <= 0, theta'' has no
                    // negative interior minimum (there it would be > 0); where >= 0,
                    // no positive interior maximum.  Ends of opposite signs then hold
                    // one root, ends of one sign none or two: two when theta'' turns
                    // back inside (theta''' towards 0 at the start, away from it at
                    // the end) and reaches the other sign at the turn.  The part is
                    // then cut at the turn, each side holding one root.  (On the full
                    // equation the same check runs without that proof, measured
                    // instead: FullEquationOnOneSinePulsesJustAboveTheThreshold...)
                    if (piece.s != 0.0 && ea * eb > 0.0) {
                        auto jerk_at = [&](double s) {
                            double th, om;
                            stepper->state_at(s, th, om);
                            return model.jerk(th, om, sigma, piece.at(s), piece.rate(s));
                        };
                        const double ja = model.jerk(pha, poa, sigma, piece.at(pa), piece.rate(pa)),
                                     jb = model.jerk(phb, pob, sigma, piece.at(pb), piece.rate(pb));
                        if (ja * ea < 0.0 && jb * eb > 0.0) {
                            const double tx = locate(jerk_at, pa, pb);
                            double thx, omx;
                            stepper->state_at(tx, thx, omx);
                            const double ex = model.acceleration(thx, sigma, piece.at(tx));
                            if (tx > pa && tx < pb && ex * ea < 0.0) {
                                pb = tx;
                                phb = thx;
                                pob = omx;
                                eb = ex;
                            }
                        }
                    }
                    // theta' and theta'' of one sign: sigma theta is monotone, and
                    // nothing happens inside when it ends above the ground's noise,
                    // below the fall and on the side of alpha it started.
                    const double sa = sigma * pha, sb = sigma * phb;
                    quiet = keeps_sign() && ea * eb > 0.0 && sa >= 0.0 && sb > noise && sb < options.overturn_angle &&
                            !(std::isnan(result.t_first_alpha) && sa < alpha && sb >= alpha);
                    if (keeps_sign() && (ea < 0) != (eb < 0) && ea != 0.0 && eb != 0.0) {
                        const double ti = locate(curvature_at, pa, pb);
                        double thi, omi;
                        stepper->state_at(ti, thi, omi);
                        if (ti > pa && ti < pb && (from_rest || (omi < 0) != (poa < 0)) && omi != 0.0) {
                            pb = ti;
                            phb = thi;
                            pob = omi;
                        }
                    }
                }
                if (quiet) {
                    sample_until(pb, [&](double s, double& th, double& om) { stepper->state_at(s, th, om); });
                    note_theta(pb, phb);
                    rose = true;
                } else {
                    event = analyse_part(pa, pha, poa, pb, phb, pob);
                }
                pa = pb;
                pha = phb;
                poa = pob;
            }
            if (!event) {
                ta = tb;
                tha = thb;
                oma = omb;
            }
        }
        if (!event) {
            run.t = stepper->t_end();
            stepper->state_at(run.t, run.theta, run.omega);
        }
    }
    rules::decide_by_energy(run, result, model, options, t_fin);
    result.rhs_evaluations = stepper->rhs_evaluations();
    result.steps = stepper->steps();
    return result;
}

}  // namespace rocking::dynamics
