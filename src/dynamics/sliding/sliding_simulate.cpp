#include "dynamics/sliding/sliding_simulate.hpp"

#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>

#include "dynamics/stepper.hpp"

namespace rocking::dynamics::sliding {

namespace odeint = boost::numeric::odeint;

namespace {

constexpr double g = kGravity;

// theta, theta', the base's slip X and its rate (over R), the input's work
// and the friction's loss (over g R): one absolute tolerance fits them all.
using State = std::array<double, 6>;

int sign(double v) { return (v > 0) - (v < 0); }

// The run's regime between two events.
struct Phase {
    Regime regime = Regime::rest;
    int sigma = 0, s = 0;
};

// The ground's inertial acceleration (m/s^2) as a segment sees it: left of
// t_stop, so that no stage reads the jump at the segment's end.
struct Ground {
    const GroundInput* input = nullptr;
    double t_stop = INFINITY;
    double at(double t) const {
        if (t < t_stop) return g * input->accel(t);
        return g * input->piece_at(std::nextafter(t_stop, -INFINITY)).at(t);
    }
};

struct System {
    const FrictionBlock* block = nullptr;
    Ground ground;
    Phase phase;
    long* counter = nullptr;

    void operator()(const State& x, State& dxdt, double t) const {
        ++*counter;
        dxdt.fill(0);
        const double A = ground.at(t), R = block->R;
        switch (phase.regime) {
            case Regime::rest: return;
            case Regime::slide:
                dxdt[2] = x[3];
                dxdt[3] = sliding_accel(*block, phase.s, A) / R;
                dxdt[4] = A * x[3] / g;
                dxdt[5] = block->mu * std::fabs(x[3]);
                return;
            case Regime::rock: {
                const Contact c = stick_rocking(*block, x[0], x[1], phase.sigma, A);
                const Lever d = centroid_from_pivot(*block, x[0], phase.sigma);
                dxdt[0] = x[1];
                dxdt[1] = c.theta_dd;
                dxdt[4] = A * d.dy * x[1] / (g * R);
                return;
            }
            case Regime::slide_rock: {
                const Contact c = slip_rocking(*block, x[0], x[1], phase.sigma, phase.s, A);
                const Lever d = centroid_from_pivot(*block, x[0], phase.sigma);
                dxdt[0] = x[1];
                dxdt[1] = c.theta_dd;
                dxdt[2] = x[3];
                dxdt[3] = c.pivot_dd / R;
                dxdt[4] = A * (x[3] * R + d.dy * x[1]) / (g * R);
                dxdt[5] = block->mu * c.n * std::fabs(x[3]) / g;
                return;
            }
        }
    }
};

// E per unit mass over g R: kinetic (G's and about G) and potential.
double energy(const FrictionBlock& block, const Phase& phase, const State& x) {
    const double R = block.R;
    if (phase.regime == Regime::rest || phase.regime == Regime::slide)
        return (0.5 * x[3] * x[3] * R * R + g * block.h()) / (g * R);
    const Lever d = centroid_from_pivot(block, x[0], phase.sigma);
    const double xg = x[3] * R + d.dy * x[1], yg = -d.dx * x[1];
    return (0.5 * (xg * xg + yg * yg) + 0.5 * R * R / 3 * x[1] * x[1] + g * d.dy) / (g * R);
}

// An event's time and the state there.
struct Located {
    double t;
    State x;
};

// The events of a regime, each triggered where its value turns negative.
enum Event { impact, fall, slip_starts, slip_stops, flight, kEvents };

std::array<double, kEvents> events(const FrictionBlock& block, const Phase& phase, const State& x, double A,
                                   double overturn_angle) {
    std::array<double, kEvents> e;
    e.fill(1);
    switch (phase.regime) {
        case Regime::rest: break;
        case Regime::slide: e[slip_stops] = phase.s * x[3]; break;
        case Regime::rock: {
            const Contact c = stick_rocking(block, x[0], x[1], phase.sigma, A);
            e[impact] = phase.sigma * x[0];
            e[fall] = overturn_angle - phase.sigma * x[0];
            e[slip_starts] = block.mu * c.n - std::fabs(c.f);
            e[flight] = c.n;
            break;
        }
        case Regime::slide_rock: {
            const Contact c = slip_rocking(block, x[0], x[1], phase.sigma, phase.s, A);
            e[impact] = phase.sigma * x[0];
            e[fall] = overturn_angle - phase.sigma * x[0];
            e[slip_stops] = phase.s * x[3];
            e[flight] = c.n;
            break;
        }
    }
    return e;
}

// Dormand-Prince steps from the start (t0, x0) of the dense output's last
// step to any s inside it.  The dense output is an interpolant of order 4,
// its error of the size of the step's error estimate, while the step itself
// is of order 5: located on the interpolant, an event's time was off by the
// interpolant's error over the rate of the event's value (theta' at an
// impact), which set the rest of the run: on IT.AQK HNN at alpha 0.1, q 1.5,
// 70 to 100 times the error of the steps themselves (docs/sliding.md,
// "Accuracy").
// A step to s costs 6 evaluations, its end's derivative included.
class TrueStep {
public:
    TrueStep(const System& sys, const State& x0, double t0) : sys_(sys), x0_(x0), t0_(t0) { sys_(x0_, d0_, t0_); }
    // The state at s, its derivative there in dxdt.
    State at(double s, State& dxdt) {
        if (!(s > t0_)) {
            dxdt = d0_;
            return x0_;
        }
        State y;
        dopri5_.do_step(sys_, x0_, d0_, t0_, y, dxdt, s - t0_);
        return y;
    }

private:
    const System& sys_;
    State x0_, d0_;
    double t0_;
    odeint::runge_kutta_dopri5<State> dopri5_;
};

// Event k, found on the dense output at `guess` in the step [t0, t1], where
// the true steps put it: Newton's method on their state, its slope along the
// flow.  A correction within 1e-6 of the step h moves the state along its
// derivative (the neglected delta^2 x''/2 is below 1e-12 h^2 x''), a larger
// one takes another step.  Where the true trajectory
// does not reach the event (a grazing one, seen on the interpolant alone),
// its closest approach is kept.
Located locate_event(const System& sys, TrueStep& step, double t0, double t1, double guess, int k,
                     double overturn_angle) {
    auto value = [&](double s, const State& at) {
        return events(*sys.block, sys.phase, at, sys.ground.at(s), overturn_angle)[k];
    };
    const double near = 1e-6 * (t1 - t0);
    double s = std::clamp(guess, t0, t1);
    State dy, y = step.at(s, dy);
    Located best{s, y}, crossed{NAN, y};
    double best_v = INFINITY, crossed_v = INFINITY;
    for (int it = 0; it < 8; ++it) {
        const double v = value(s, y);
        if (v <= 0 && -v < crossed_v) crossed = {s, y}, crossed_v = -v;
        if (!(std::fabs(v) < best_v)) break;  // no closer: a grazing event, or rounding
        best = {s, y};
        best_v = std::fabs(v);
        if (v == 0) break;
        // Backwards at the step's end: beyond it the input may have a kink.
        const double e = s + near <= t1 ? near : -near;
        State ahead;
        for (std::size_t i = 0; i < y.size(); ++i) ahead[i] = y[i] + e * dy[i];
        const double slope = (value(s + e, ahead) - v) / e;
        if (!(std::isfinite(slope) && slope != 0)) break;
        const double next = std::clamp(s - v / slope, t0, t1), delta = next - s;
        if (std::fabs(delta) <= 4 * std::numeric_limits<double>::epsilon() * std::fabs(s)) break;
        if (std::fabs(delta) <= near) {
            for (std::size_t i = 0; i < y.size(); ++i) y[i] += delta * dy[i];
        } else {
            y = step.at(next, dy);
        }
        s = next;
    }
    // The event is applied where it has happened (its value <= 0): a state
    // on the near side set a slip going that the stuck corner's own friction
    // could still hold, which stopped at once and started again, a million
    // times in 0.1 s at mu 0.4 (Figure 5's case 3, alpha 0.1, x 0.3).  From
    // the closest approach, forward by steps doubling from 2 ulps.
    if (value(best.t, best.x) <= 0) return best;
    const double limit = std::isnan(crossed.t) ? t1 : crossed.t;
    for (double d = 2 * std::numeric_limits<double>::epsilon() * std::fabs(best.t); best.t + d < limit; d *= 2) {
        State at = step.at(best.t + d, dy);
        if (value(best.t + d, at) <= 0) return {best.t + d, at};
    }
    // An iterate that had crossed, or grazing: the true trajectory does not reach it in this step.
    return std::isnan(crossed.t) ? best : crossed;
}

void check_tolerance(const char* name, double v) {
    if (!(v >= kSmallestTolerance && v < 1))
        throw std::invalid_argument(std::string("sliding: ") + name + " must be in [2.2e-14, 1) (got " +
                                    std::to_string(v) + ")");
}

}  // namespace

std::string SlidingOptions::describe() const {
    char text[200];
    std::snprintf(text, sizeof text, "event-driven Dormand-Prince 5(4), rtol %g, atol %g alpha, steps at most %g/p",
                  rtol, atol_alpha, max_step_p);
    return text;
}

SimulationResult SlidingResult::as_rocking() const {
    SimulationResult out;
    out.t_fin = t_fin;
    out.theta_at_tfin = theta_at_tfin;
    out.max_abs_theta_input = max_abs_theta_input;
    out.uplifted = uplifted;
    out.overturned = overturned;
    out.overturned_during_input = overturned_during_input;
    out.t_overturn = t_overturn;
    out.impacts = impacts;
    out.impact_times = impact_times;
    if (!impact_times.empty()) out.t_first_impact = impact_times.front(), out.t_last_impact = impact_times.back();
    out.steps = steps;
    out.rhs_evaluations = rhs_evaluations;
    return out;
}

SlidingResult simulate_sliding(const FrictionBlock& block, const GroundInput& input, const SlidingOptions& o) {
    check_block(block);
    check_tolerance("rtol", o.rtol);
    check_tolerance("atol", o.atol_alpha);
    if (!(o.max_step_p > 0 && o.max_step_p <= 1)) throw std::invalid_argument("sliding: max_step_p must be in (0, 1]");
    const double alpha = block.alpha, p = block.p(), R = block.R, t_fin = input.t_end();
    SlidingResult out;
    out.t_fin = t_fin;
    long counter = 0;
    System sys{&block, Ground{&input, t_fin}, Phase{}, &counter};
    auto dense = odeint::make_dense_output(o.atol_alpha * alpha, o.rtol, o.max_step_p / p,
                                           odeint::runge_kutta_dopri5<State>());
    State x{};
    Phase phase;
    double t = 0;
    const double e0 = energy(block, phase, x);
    bool input_over = false;
    double t_limit = t_fin;  // raised to t_fin + 200/p while the block may still fall
    const double rest_threshold = std::min(block.mu, block.b() / block.h());
    const double rest_rate = std::max(o.rest_velocity, 10 * o.atol_alpha) * alpha * p;
    double t_last_impact = -INFINITY;

    auto balance = [&](const State& at, const Phase& ph) {
        const double residual = energy(block, ph, at) - (e0 + at[4] - at[5] - out.impact_loss / (g * R));
        out.balance_error = std::max(out.balance_error, std::fabs(residual));
    };
    // The samples k record_dt up to `until`, the state at s from state_at(s).
    long next_sample = 0;
    auto sample_until = [&](double until, const auto& state_at) {
        if (!(o.record_dt > 0)) return;
        for (double s = next_sample * o.record_dt; s <= until; s = ++next_sample * o.record_dt) {
            const State y = state_at(s);
            out.samples.push_back({s, y[0], y[1], y[2] * R, y[3] * R, phase.regime});
        }
    };
    auto track = [&](double when, const State& at) {
        out.max_abs_slip = std::max(out.max_abs_slip, std::fabs(at[2]) * R);
        if (when <= t_fin) out.max_abs_theta_input = std::max(out.max_abs_theta_input, std::fabs(at[0]));
    };
    auto set_phase = [&](const Start& st) {
        if (st.regime != phase.regime || st.sigma != phase.sigma || st.s != phase.s) ++out.regime_changes;
        phase = Phase{st.regime, st.sigma, st.s};
        out.uplifted = out.uplifted || st.regime == Regime::rock || st.regime == Regime::slide_rock;
        out.slid = out.slid || st.regime == Regime::slide || st.regime == Regime::slide_rock;
    };
    auto at_tfin = [&](const State& at) {
        input_over = true;
        out.theta_at_tfin = at[0];
        out.slip_at_tfin = at[2] * R;
        sys.ground.t_stop = INFINITY;  // the ground at rest from here
        t_limit = o.free_rocking ? t_fin + kFreeRockingTimesP / p : t_fin;
    };
    // After the input, a block that cannot reach the top (its energy below
    // the barrier, on the near side) is done: friction and impacts only take.
    auto may_still_fall = [&](const State& at) {
        if (phase.regime == Regime::rest) return false;
        if (phase.regime == Regime::slide) return true;  // until it stops
        return phase.sigma * at[0] > alpha || energy(block, phase, at) >= 1.0;
    };

    for (long count = 0;; ++count) {
        if (count > o.max_events) {
            char text[200];
            std::snprintf(text, sizeof text, "sliding: more than %ld regime changes by t = %.9g s (in %s): the events "
                          "do not end", o.max_events, t, regime_name(phase.regime));
            throw std::runtime_error(text);
        }
        if (!input_over && t >= t_fin) at_tfin(x);
        if (input_over && (t >= t_limit || !may_still_fall(x))) break;
        if (phase.regime == Regime::rest) {
            if (input_over) break;
            // Where |A| first exceeds g min(mu, tan alpha), moved on by ulps until
            // the forces there leave rest (start_flat's own test, as it rounds).
            const double go = move_until(input.first_above(t, t_fin, rest_threshold), t_fin, [&](double s) {
                return start_flat(block, g * input.accel(s), 0).regime != Regime::rest;
            });
            out.time_in[0] += std::min(go, t_fin) - t;
            sample_until(std::min(go, t_fin), [&](double) { return x; });
            t = std::min(go, t_fin);
            if (t >= t_fin) continue;
            set_phase(start_flat(block, g * input.accel(t), 0));  // rest again: move_until ran out of tries
            continue;
        }
        // One segment of the regime, to the input's end or the run's limit.
        const double t_stop = input_over ? t_limit : t_fin;
        sys.phase = phase;
        dense.initialize(x, t, std::min(1e-3 / p, t_stop - t));
        bool changed = false;
        while (!changed && t < t_stop) {
            const double kink = std::min(input.piece_from(t).t1, t_stop);
            if (dense.current_time() + dense.current_time_step() > kink) dense.initialize(x, t, kink - t);
            const auto step = dense.do_step(sys);
            ++out.steps;
            const double t0 = step.first, t1 = std::min(step.second, t_stop);
            auto state = [&](double s) {
                State y;
                dense.calc_state(s, y);
                return y;
            };
            auto values = [&](double s) { return events(block, phase, state(s), sys.ground.at(s), o.overturn_angle); };
            // Bisections on the dense output stop at 1e-7 of the step (22 halvings of
            // a quarter, not 37 to rounding): what they find is read on true steps.
            const double width = 1e-7 * (t1 - t0);
            std::optional<TrueStep> from_t0;
            auto true_step = [&]() -> TrueStep& {
                if (!from_t0) from_t0.emplace(sys, dense.previous_state(), t0);
                return *from_t0;
            };
            // Four looks inside the step: an event that comes and goes between
            // the step's ends (theta back over 0 within it) is still seen.
            double lo = t0, found = INFINITY;
            int which = -1;
            for (int j = 1; j <= 4 && which < 0; ++j) {
                const double hi = j == 4 ? t1 : t0 + (t1 - t0) * j / 4;
                const std::array<double, kEvents> v = values(hi);
                if (*std::min_element(v.begin(), v.end()) >= 0) {
                    // The peak of |theta| inside: where theta' turns.
                    const State ya = state(lo), yb = state(hi);
                    if (ya[1] * yb[1] < 0 && lo < t_fin) {
                        // To `width` (at most 1e-8/p): theta there is off the peak by theta''
                        // width^2/2 < 1e-16 (1 + |A|/g) rad.  A peak above the largest so far
                        // is read on a true step.
                        double a = lo, b = hi;
                        for (int it = 0; it < 200 && b - a > std::max(width, 2 * std::numeric_limits<double>::epsilon() * std::fabs(b)); ++it) {
                            const double m = 0.5 * (a + b);
                            (state(m)[1] * ya[1] > 0 ? a : b) = m;
                        }
                        State peak = state(a), unused;
                        if (std::fabs(peak[0]) > out.max_abs_theta_input) peak = true_step().at(a, unused);
                        track(std::min(a, t_fin), peak);
                    }
                    track(hi, yb);
                }
                for (int k = 0; k < kEvents; ++k) {
                    if (!(v[k] < 0)) continue;
                    // Bisect for the first time its value turns negative, to `width`:
                    // locate_event takes it from there.
                    double a = lo, b = hi;
                    for (int it = 0; it < 200 && b - a > std::max(width, 2 * std::numeric_limits<double>::epsilon() * std::fabs(b)); ++it) {
                        const double m = 0.5 * (a + b);
                        (values(m)[k] < 0 ? b : a) = m;
                    }
                    if (b < found) found = b, which = k;
                }
                lo = hi;
            }
            if (which < 0) {
                sample_until(t1, state);
                out.time_in[static_cast<int>(phase.regime)] += t1 - t;
                t = t1;
                x = t1 == step.second ? dense.current_state() : state(t1);
                continue;
            }
            // The event: the state there, the time in the regime, the transition.
            const Located event = locate_event(sys, true_step(), t0, t1, found, which, o.overturn_angle);
            found = event.t;
            sample_until(std::nextafter(found, -INFINITY), state);
            out.time_in[static_cast<int>(phase.regime)] += found - t;
            t = found;
            x = event.x;
            track(t, x);
            balance(x, phase);
            changed = true;
            const double A = sys.ground.at(t);
            switch (which) {
                case fall:
                    // At the fall angle, as simulate() puts it; theta(t_fin) 0 for a block
                    // that fell during the input, as there.
                    x[0] = phase.sigma * o.overturn_angle;
                    track(t, x);
                    out.overturned = true;
                    out.overturned_during_input = t <= t_fin;
                    if (!input_over) out.slip_at_tfin = x[2] * R;  // at the fall, where the run ends
                    out.t_overturn = t;
                    out.final_slip = x[2] * R;
                    out.input_work = x[4] * g * R;
                    out.friction_loss = x[5] * g * R;
                    out.final_energy = energy(block, phase, x) * g * R;
                    out.rhs_evaluations = counter;
                    return out;
                case flight: {
                    char text[200];
                    std::snprintf(text, sizeof text,
                                  "sliding: the block leaves the ground at t = %.9g s (n = 0 at its pivot): free flight "
                                  "is outside the sliding-rocking model", t);
                    throw FreeFlight(text, t);
                }
                case slip_starts: {
                    const Contact c = stick_rocking(block, x[0], x[1], phase.sigma, A);
                    set_phase({Regime::slide_rock, phase.sigma, -sign(c.f)});
                    break;
                }
                case slip_stops:
                    x[3] = 0;
                    if (phase.regime == Regime::slide) set_phase(start_flat(block, A, 0));
                    else set_phase(start_on_corner(block, x[0], x[1], phase.sigma, A));
                    break;
                case impact: {
                    const double e_before = energy(block, phase, x);
                    const Lever d = centroid_from_pivot(block, 0, phase.sigma);
                    const double xg = x[3] * R + d.dy * x[1], yg = -d.dx * x[1];
                    const Impact hit = corner_impact(block, phase.sigma, x[1], xg, yg);
                    ++out.impacts;
                    if (out.impact_times.size() < o.max_impact_times) out.impact_times.push_back(t);
                    out.slipping_impacts += hit.slipped;
                    // The rocking-only driver's micro-bounce rule (run_rules.hpp,
                    // record_impact): an impact within 1e-6/p of the last ends the
                    // cascade.  Without it the rest rate alone ended it ~45 rebounds
                    // later (e = 0.91), all within 1e-5/p and below 1e-13 rad, each
                    // costing a segment: 131 impacts against 86 on NRC 2016-10-26
                    // 19:18 HGE, 0.25 x 1 m, at 3.7 times the rocking-only run's time.
                    // There a stuck arc of T < 1e-6/p, decelerated by at most p^2 (sin alpha
                    // + |A|/g cos alpha) <= 2 p^2 sin alpha while the block can rest, strikes
                    // at |theta'| < 1e-6 p sin alpha: the rule is kept to such slow impacts.
                    // A slipping impact may reverse theta' (theta'+ against its new pivot):
                    // the next impact then follows at once at that speed, 0.04 rad/s on NRC
                    // 2016-08-24 01:36 HGE, alpha 0.5, q 4, mu 0.6, no bounce to neglect.
                    const bool micro = t - t_last_impact < 1e-6 / p && std::fabs(x[1]) < 1e-6 * alpha * p;
                    t_last_impact = t;
                    x[0] = 0;
                    // As the rocking-only ODE runs (rest_threshold): below rest_velocity or
                    // the solver's own accuracy, 10 atol, a rebound is noise.
                    if (micro || std::fabs(hit.omega) < rest_rate) {
                        // Lies flat: what moves on is G's velocity along the ground,
                        // unless below the same rest rule in velocity (alpha p R): a
                        // residue of 1e-13 m/s set the block slide-rocking, stopping
                        // and striking again without end (Zeno, at p = 1 on Norcia).
                        // After a micro-bounce, the base's: the cascade's tail (under 1e-5/p
                        // s at e = 0.9) takes the rotation's share of G's velocity, h theta'+,
                        // which set the base of a stuck block sliding (at mu = 1e6: slide-rock,
                        // then Painleve's case).
                        x[1] = 0;
                        x[3] = micro ? hit.pivot_v / R : (xg + hit.p_t) / R;
                        if (std::fabs(x[3]) < rest_rate) x[3] = 0;
                        phase = Phase{Regime::rest, 0, 0};
                        const Start st = start_flat(block, A, x[3] * R);
                        set_phase(st);
                        if (st.regime == Regime::rest) x[3] = 0;
                    } else {
                        x[1] = hit.omega;
                        x[3] = hit.pivot_v / R;
                        const int pivot = -phase.sigma;
                        if (hit.slipped) set_phase({Regime::slide_rock, pivot, sign(hit.pivot_v)});
                        else set_phase(start_on_corner(block, 0, hit.omega, pivot, A));
                    }
                    out.impact_loss += (e_before - energy(block, phase, x)) * g * R;
                    break;
                }
                default: break;
            }
        }
    }
    out.final_slip = x[2] * R;
    out.input_work = x[4] * g * R;
    out.friction_loss = x[5] * g * R;
    out.final_energy = energy(block, phase, x) * g * R;
    out.rhs_evaluations = counter;
    balance(x, phase);
    return out;
}

}  // namespace rocking::dynamics::sliding
