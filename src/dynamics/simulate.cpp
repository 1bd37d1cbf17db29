#include "dynamics/simulate.hpp"

#include "dynamics/exact_record.hpp"
#include "dynamics/run_rules.hpp"
#include "numerics/roots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
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

bool SimulationResult::collapse(Criterion c, double alpha, double alpha_minus) const {
    if (overturned_during_input) return true;
    const bool imperfect = alpha_minus > 0;
    switch (c) {
        case Criterion::final_rotation:
            return imperfect ? theta_at_tfin >= alpha || -theta_at_tfin >= alpha_minus : std::fabs(theta_at_tfin) >= alpha;
        case Criterion::peak_rotation:
            return imperfect ? peak_plus_input >= alpha || peak_minus_input >= alpha_minus : max_abs_theta_input >= alpha;
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

double latest_run_time(const Model& model, const GroundInput& input, const SimulationOptions& options) {
    const double free = options.free_rocking ? kFreeRockingTimesP / model.p_min() : 0.0;
    return input.t_end() + std::max(options.free_record_time, free);
}

std::string unresolvable_run(double p, double duration) {
    const double pt = p * duration;
    if (pt <= kLongestRunTimesP) return "";
    char text[320];
    std::snprintf(text, sizeof text,
                  "p t = %.3g (p = %.6g rad/s over %.6g s) exceeds %.0e: the solvers cannot follow so long a run "
                  "(each step at most %.3g/p s, below the resolution of t)",
                  pt, p, duration, kLongestRunTimesP, SolverOptions{}.max_step_p);
    return text;
}

// As Driver::sample_until takes them: k record_dt <= t_limit (1 + 1e-12), k = 0, 1, ...
double max_record_rows(const Model& model, const GroundInput& input, const SimulationOptions& options) {
    if (!(options.record_dt > 0)) return 0;
    return std::floor(latest_run_time(model, input, options) * (1 + 1e-12) / options.record_dt) + 1;
}

double rest_threshold(const SimulationOptions& options) {
    return std::max(options.rest_velocity,
                    options.solver.kind == SolverKind::exact ? 0.0 : 10.0 * options.solver.atol_alpha);
}

namespace {

// A part of a step: [ta, tb] with the states at its ends.
struct Part {
    double ta, tha, oma, tb, thb, omb;
};

// The general path's run (any solver, any input).  A run is a sequence of
// passes, each beginning with the rules of run_rules.hpp (the end of the
// input, the uplift from rest, the free rocking's end), then one segment:
// the solver's steps from the run's state to its next event (impact, rest,
// fall) or to the input's next discontinuity.  Each step is cut into parts
// holding at most one extremum of theta, and a part is either quiet (nothing
// can happen inside it) or analysed for its events.
class Driver {
public:
    Driver(const Model& model, const GroundInput& input, const SimulationOptions& options)
        : model_(model),
          input_(input),
          options_(options),
          p_(model.p_max()),
          t_fin_(input.t_end()),
          noise_(1e-12 * model.alpha_min()),
          breaks_(input.discontinuities()),
          result_(rules::new_result(options, input.t_end())),
          stepper_(make_stepper(model, input, options.solver)),
          run_(options, input.t_end()) {
        breaks_.push_back(t_fin_);
        std::sort(breaks_.begin(), breaks_.end());
        stepper_->set_batching(options.record_dt <= 0.0, options.overturn_angle);
    }

    SimulationResult run() {
        while (!done_ && rules::begin_pass(
                             run_, result_, model_, input_, [&](double s) { return input_.accel(s); }, options_, t_fin_,
                             [&](double when, double value) { note_theta(when, value); },
                             [&](double until) { rest_until(until); }))
            segment();
        rules::decide_by_energy(run_, result_, model_, options_, t_fin_);
        result_.rhs_evaluations = stepper_->rhs_evaluations();
        result_.steps = stepper_->steps();
        return std::move(result_);
    }

private:
    // --- the theta(t) record and the largest |theta| ---------------------------

    void sample_until(double until, const std::function<void(double, double&, double&)>& at) {
        if (options_.record_dt <= 0) return;
        // Sample times k dt; the last one may overshoot t_limit by rounding.
        for (double ts = next_sample_ * options_.record_dt; ts <= until && ts <= run_.t_limit * (1 + 1e-12);
             ts = ++next_sample_ * options_.record_dt) {
            double th, om;
            at(std::min(ts, until), th, om);
            result_.samples.push_back({ts, th, om});
        }
    }
    void sample_step_until(double until) {
        sample_until(until, [&](double s, double& th, double& om) { stepper_->state_at(s, th, om); });
    }
    void rest_until(double until) {
        sample_until(until, [](double, double& th, double& om) { th = om = 0.0; });
    }
    void note_theta(double when, double value) {
        if (!(when <= t_fin_)) return;
        result_.max_abs_theta_input = std::max(result_.max_abs_theta_input, std::fabs(value));
        if (model_.symmetric()) return;
        if (value > 0) result_.peak_plus_input = std::max(result_.peak_plus_input, value);
        else result_.peak_minus_input = std::max(result_.peak_minus_input, -value);
    }
    // The corner's slenderness (an imperfect block's differ).
    double alpha_() const { return model_.alpha_on(sigma_); }
    double theta_at(double s) {
        double th, om;
        stepper_->state_at(s, th, om);
        return th;
    }
    double omega_at(double s) {
        double th, om;
        stepper_->state_at(s, th, om);
        return om;
    }

    // --- a segment: the steps from the run's state to its next event ----------

    // The segment's end: the input's next discontinuity, or, after the
    // input, the end of the free rocking followed (t_limit).
    double segment_end(double t) const {
        if (t >= t_fin_) return run_.t_limit;
        for (double b : breaks_)
            if (b > t) return b;
        return run_.t_limit;
    }

    void segment() {
        sigma_ = run_.sigma;
        stepper_->reset(run_.t, run_.theta, run_.omega, sigma_, segment_end(run_.t));
        ta_ = run_.t;
        tha_ = run_.theta;
        oma_ = run_.omega;
        stalled_ = 0;
        // A block lifted from rest with an acceleration just above the threshold
        // rises from theta = 0 by less than rounding at first; a return to 0
        // before it has risen above that noise is no impact: it stays at rest.
        rose_ = std::fabs(run_.theta) > noise_ || std::fabs(run_.omega) > 0.0;
        bool event = false;
        while (!event && stepper_->advance())
            if (moved()) event = step();
        if (!event) {
            run_.t = stepper_->t_end();
            stepper_->state_at(run_.t, run_.theta, run_.omega);
        }
    }

    // Whether the last step moved t.  A step shorter than half an ulp of t
    // leaves t where it was, and there is nothing to analyse (a dense
    // output's interpolant over it is 0/0).  An ODE solver's first steps may,
    // and grow; where even max_step_p / p is that short (p t beyond double's
    // resolution) no step ever moves t, and the run would never end.
    bool moved() {
        if (stepper_->t_end() > stepper_->t_begin()) {
            stalled_ = 0;
            return true;
        }
        if (++stalled_ <= 100) return false;
        char text[320];
        std::snprintf(text, sizeof text,
                      "%s solver: no progress at t = %.17g s in 100 steps: its step (at most max_step_p / p = "
                      "%.3g s) is below double's resolution there: p t = %.3g (p = %.6g rad/s) is too large",
                      solver_name(options_.solver.kind).c_str(), stepper_->t_begin(), options_.solver.max_step_p / p_,
                      p_ * stepper_->t_begin(), p_);
        throw std::runtime_error(text);
    }

    // --- a step and its events ---------------------------------------------------

    // One step of the solver, cut into parts that each hold at most one
    // extremum of theta (next_part); true when an event ends the segment.
    bool step() {
        // The step may have started after the last one seen (a batched run);
        // at the segment's start the state is known exactly (an interpolant
        // may put theta' = 0 a rounding error off and fake an extremum).
        if (stepper_->t_begin() != ta_) {
            ta_ = stepper_->t_begin();
            stepper_->state_at(ta_, tha_, oma_);
        }
        const double tb = stepper_->t_end();
        double thb, omb;
        stepper_->state_at(tb, thb, omb);
        if (!std::isfinite(thb) || !std::isfinite(omb)) {
            char text[240];
            std::snprintf(text, sizeof text, "%s solver: the state is not finite at t = %.17g s (theta %g, theta' %g)",
                          solver_name(options_.solver.kind).c_str(), tb, thb, omb);
            throw std::runtime_error(text);
        }
        Part part{ta_, tha_, oma_, tb, thb, omb};
        bool event = false;
        while (!event && part.ta < tb) {
            part.tb = tb;
            part.thb = thb;
            part.omb = omb;
            if (next_part(part)) {
                sample_step_until(part.tb);
                note_theta(part.tb, part.thb);
                rose_ = true;
            } else {
                event = part_events(part);
            }
            part.ta = part.tb;
            part.tha = part.thb;
            part.oma = part.omb;
        }
        if (!event) {
            ta_ = tb;
            tha_ = thb;
            oma_ = omb;
        }
        return event;
    }

    // Ends the part from part.ta (at most at the step's end, part.tb) so
    // that it holds at most one extremum of theta, which part_events
    // assumes; true when nothing can happen inside it (quiet).
    //
    // A part first ends at the input's next kink (a record's sample;
    // Dormand-Prince steps across them) and, on a sinusoidal piece, where the
    // sine crosses 0.  On a part where the input is linear, theta'' (a
    // combination of cosh and sinh on eq. 3) changes sign once at most; on a
    // sinusoidal one it can change sign twice, and the part is first cut
    // between the two (cut_at_curvature_turn).  theta' then vanishes at most
    // twice, and only when theta'' changes sign while theta' keeps its sign
    // at the ends, or starts from 0 (the uplift from rest): the part is then
    // cut where theta'' = 0 (cut_at_inflection).  Missing this put a block at
    // rest where it flew out and back within one step, or let it pass
    // through the ground unseen (docs/solvers.md, hidden excursions).
    bool next_part(Part& part) {
        const InputPiece piece = input_.piece_from(part.ta);
        part.tb = std::min(piece.t1 > part.ta && piece.t1 < part.tb ? piece.t1 : part.tb,
                           piece.next_sine_zero(part.ta));
        if (part.tb < stepper_->t_end()) stepper_->state_at(part.tb, part.thb, part.omb);
        const bool from_rest = part.oma == 0.0;
        const double oma = part.oma;
        auto keeps_sign = [&] { return from_rest || ((oma < 0) == (part.omb < 0) && oma != 0.0 && part.omb != 0.0); };
        if (piece.s == 0.0 && !keeps_sign()) return false;
        const double ea = model_.acceleration(part.tha, sigma_, piece.at(part.ta));
        double eb = model_.acceleration(part.thb, sigma_, piece.at(part.tb));
        if (piece.s != 0.0 && ea * eb > 0.0) cut_at_curvature_turn(part, piece, ea, eb);
        // theta' and theta'' of one sign: sigma theta is monotone, and
        // nothing happens inside when it ends above the ground's noise,
        // below the fall and on the side of alpha it started.
        const double sa = sigma_ * part.tha, sb = sigma_ * part.thb;
        const bool quiet = keeps_sign() && ea * eb > 0.0 && sa >= 0.0 && sb > noise_ && sb < options_.overturn_angle &&
                           !(std::isnan(result_.t_first_alpha) && sa < alpha_() && sb >= alpha_());
        if (keeps_sign() && (ea < 0) != (eb < 0) && ea != 0.0 && eb != 0.0) cut_at_inflection(part, piece, from_rest);
        return quiet;
    }

    // On a sinusoidal piece, eq. 3 gives theta'' = p^2 (H + K sin(w u + ph)),
    // H = C cosh pu + D sinh pu, K = s w^2 / (p^2 + w^2), so (theta'')'' -
    // p^2 theta'' = -(p^2 + w^2) p^2 K sin(w u + ph), of one sign on the
    // part.  Where it is <= 0, theta'' has no negative interior minimum
    // (there it would be > 0); where >= 0, no positive interior maximum.
    // Ends of opposite signs then hold one root, ends of one sign (ea eb > 0
    // here) none or two: two when theta'' turns back inside (its rate towards
    // 0 at the start, away from it at the end) and reaches the other sign at
    // the turn.  The part is then cut at the turn, each side holding one
    // root.  (On the full equation the same check runs without that proof,
    // measured instead: FullEquationOnOneSinePulsesJustAboveTheThreshold...)
    void cut_at_curvature_turn(Part& part, const InputPiece& piece, double ea, double& eb) {
        const double ja = model_.jerk(part.tha, part.oma, sigma_, piece.at(part.ta), piece.rate(part.ta)),
                     jb = model_.jerk(part.thb, part.omb, sigma_, piece.at(part.tb), piece.rate(part.tb));
        if (!(ja * ea < 0.0 && jb * eb > 0.0)) return;
        auto jerk_at = [&](double s) {
            double th, om;
            stepper_->state_at(s, th, om);
            return model_.jerk(th, om, sigma_, piece.at(s), piece.rate(s));
        };
        const double tx = locate(jerk_at, part.ta, part.tb);
        double thx, omx;
        stepper_->state_at(tx, thx, omx);
        const double ex = model_.acceleration(thx, sigma_, piece.at(tx));
        if (tx > part.ta && tx < part.tb && ex * ea < 0.0) {
            part.tb = tx;
            part.thb = thx;
            part.omb = omx;
            eb = ex;
        }
    }

    // theta'' changes sign on the part while theta' keeps its sign at the
    // ends, or starts from rest: cut where theta'' = 0 when theta' has
    // turned there (any sign after an uplift), each side then holding one
    // extremum at most.
    void cut_at_inflection(Part& part, const InputPiece& piece, bool from_rest) {
        auto curvature_at = [&](double s) {
            double th, om;
            stepper_->state_at(s, th, om);
            return model_.acceleration(th, sigma_, piece.at(s));
        };
        const double ti = locate(curvature_at, part.ta, part.tb);
        double thi, omi;
        stepper_->state_at(ti, thi, omi);
        if (ti > part.ta && ti < part.tb && (from_rest || (omi < 0) != (part.oma < 0)) && omi != 0.0) {
            part.tb = ti;
            part.thb = thi;
            part.omb = omi;
        }
    }

    // The events of a part holding at most one extremum of theta: the
    // extremum, the impact (sigma theta reaches 0), the fall, the first
    // |theta| = alpha.  True when one ends the segment (a fall, a rest, an
    // impact), which it applies to the run.
    bool part_events(const Part& part) {
        const double ta = part.ta, tha = part.tha, tb = part.tb, thb = part.thb;
        // Extremum of theta inside the part (theta' changes sign, once).
        double t_ext = NAN, th_ext = NAN;
        if ((part.oma < 0) != (part.omb < 0) && part.oma != 0.0 && part.omb != 0.0) {
            t_ext = locate([&](double s) { return omega_at(s); }, ta, tb);
            th_ext = theta_at(t_ext);
        }
        const bool has_ext = !std::isnan(t_ext);
        // The first root of sigma theta in the part: before the extremum
        // when theta dips below 0 there, after it otherwise.
        double t_impact = INFINITY, t_fall = INFINITY;
        auto impact_in = [&](double lo, double hi) {
            return locate([&](double s) { return sigma_ * theta_at(s); }, lo, hi);
        };
        if (has_ext && sigma_ * th_ext < 0.0) t_impact = impact_in(ta, t_ext);
        else if (sigma_ * thb < 0.0) t_impact = impact_in(has_ext ? t_ext : ta, tb);
        if (sigma_ * thb >= options_.overturn_angle)
            t_fall = locate([&](double s) { return sigma_ * theta_at(s) - options_.overturn_angle; }, ta, tb);
        const double t_cut = std::min({t_impact, t_fall, tb});
        first_alpha(ta, tha, t_cut, t_ext, th_ext);
        if (has_ext && t_ext <= t_cut) note_theta(t_ext, th_ext);
        if (sigma_ * thb > noise_ || (has_ext && t_ext <= t_cut && sigma_ * th_ext > noise_)) rose_ = true;
        sample_step_until(t_cut);
        if (t_fall <= t_cut && t_fall < INFINITY) {
            fall(t_fall);
            return true;
        }
        if (t_impact <= t_cut && t_impact < INFINITY) {
            if (rose_) impact(t_impact);
            else rest_on_ground(tb);
            return true;
        }
        note_theta(tb, thb);
        return false;
    }

    // The first time |theta| = alpha, when it lies in [ta, t_cut]: theta at
    // t_cut, or at the extremum before it, at or above alpha.
    void first_alpha(double ta, double tha, double t_cut, double t_ext, double th_ext) {
        const double alpha = alpha_();
        if (!std::isnan(result_.t_first_alpha) || !(sigma_ * tha < alpha)) return;
        auto from_alpha = [&](double s) { return sigma_ * theta_at(s) - alpha; };
        if (sigma_ * theta_at(t_cut) >= alpha) result_.t_first_alpha = locate(from_alpha, ta, t_cut);
        else if (!std::isnan(t_ext) && t_ext < t_cut && sigma_ * th_ext >= alpha)
            result_.t_first_alpha = locate(from_alpha, ta, t_ext);
    }

    // --- the events that end a segment -----------------------------------------

    void fall(double t_fall) {
        result_.overturned = true;
        result_.t_overturn = t_fall;
        result_.overturned_during_input = t_fall <= t_fin_;
        note_theta(t_fall, sigma_ * options_.overturn_angle);
        done_ = true;
    }

    // A return to the ground before the block rose above the noise: it is
    // still within rounding of it, so at rest to the end of the step
    // (progress is guaranteed), then the uplift rule again.
    void rest_on_ground(double tb) {
        run_.t = tb;
        run_.theta = run_.omega = 0.0;
        run_.resting = true;
    }

    // An impact: the block passes to the other corner with the restitution;
    // a rebound below the rest threshold, or a second impact within 1e-6/p of
    // the last (a bounce too small to resolve), ends the cascade with the
    // block at rest, which the input may lift again at once.  The cascade's
    // rebounds are the next segments.
    void impact(double t_impact) {
        double th_i, om_i;
        stepper_->state_at(t_impact, th_i, om_i);
        note_theta(t_impact, 0.0);
        rules::impact(run_, result_, model_, options_, t_impact, om_i, rest_threshold(options_));
    }

    const Model& model_;
    const GroundInput& input_;
    const SimulationOptions& options_;
    const double p_, t_fin_, noise_;
    std::vector<double> breaks_;  // the input's discontinuities and t_fin, in order
    SimulationResult result_;
    std::unique_ptr<Stepper> stepper_;
    rules::RunState<double> run_;
    long next_sample_ = 0;  // the next sample's index (record_dt)
    bool done_ = false;     // the block has fallen
    // The segment's: its corner, the state at the last step's end seen, the
    // steps in a row that left t where it was, and whether the block has
    // risen above the ground's noise.
    int sigma_ = 1;
    double ta_ = 0, tha_ = 0, oma_ = 0;
    int stalled_ = 0;
    bool rose_ = false;
};

}  // namespace

SimulationResult simulate(const Model& model, const GroundInput& input, const SimulationOptions& options) {
    if (const auto* sine = dynamic_cast<const OneSinePulse*>(&input)) {
        const double slowest = OneSinePulse::slowest_wp_over_p * model.p_max();
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
    return Driver(model, input, options).run();
}

double smallest_record_dt(const Model& model, const GroundInput& input, const SimulationOptions& options) {
    const double dt = latest_run_time(model, input, options) * (1 + 1e-12) / (kMaxRecordRows - 1);
    const double unit = std::pow(10.0, std::floor(std::log10(dt)) - 2);
    return std::ceil(dt / unit) * unit;
}

void refuse_overflow_in_alpha(const SimulationResult& r, double alpha) {
    auto check = [&](const char* what, double value, double in_rad) {
        if (std::isfinite(value)) return;
        char text[240];
        std::snprintf(text, sizeof text, "%s overflows a double (%.6g rad at alpha = %g): the rotation is beyond "
                      "what this output can express", what, in_rad, alpha);
        throw std::runtime_error(text);
    };
    check("max |theta|/alpha during the input", r.max_abs_theta_input / alpha, r.max_abs_theta_input);
    if (!r.overturned_during_input) check("theta(t_fin)/alpha", r.theta_at_tfin / alpha, r.theta_at_tfin);
}

}  // namespace rocking::dynamics
