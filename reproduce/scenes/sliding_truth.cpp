// The sliding scene's truth without the engine (sliding_truth.csv): what the
// Coulomb block does where a closed form says it, run through the whole
// engine (dynamics/sliding/simulate_sliding), beside that closed form.
//   regime   a flat block at rest under a constant acceleration a g: the
//            regime it enters (docs/sliding.md, "Where each regime starts");
//   newmark  a block that only slides (mu < tan alpha) under one or two
//            rectangular pulses: its slip when it stops (Newmark 1965);
//   no-rock  mu < tan alpha: the base cannot carry the force that tips the
//            block, so under any input it never lifts (Shenton 1996).
// expected/sliding/independent.py computes the same closed forms in Python.
#include <cmath>
#include <string>
#include <vector>

#include "dynamics/sliding/sliding_simulate.hpp"
#include "harness/table.hpp"
#include "pulse/pulse_train.hpp"
#include "sliding_scene.hpp"

namespace rocking::scenes::sliding_scene {

namespace {

using dynamics::sliding::FrictionBlock;
using dynamics::sliding::Regime;
using dynamics::sliding::SlidingOptions;
using dynamics::sliding::SlidingResult;

// The regime a flat block enters under a g, a > 0 (closed form).
std::string regime_closed_form(double alpha, double mu, double a) {
    const double t = std::tan(alpha);
    if (a <= std::min(mu, t)) return "rest";
    if (mu < t) return "slide";
    // Turning about the leading corner with it stuck: the friction and the
    // normal force it needs, per unit weight.
    const double turn = a * std::cos(alpha) - std::sin(alpha);
    const double f = 0.75 * std::cos(alpha) * turn - a, n = 1 + 0.75 * std::sin(alpha) * turn;
    return std::fabs(f) <= mu * n ? "rock" : "slide-rock";
}

// The regimes an engine run spent time in, joined by '+' (one name when the
// constant input keeps the block in one regime, as it should over 1e-4 s).
std::string regimes_of(const SlidingResult& r) {
    std::string out;
    for (int k = 0; k < 4; ++k)
        if (r.time_in[k] > 0) out += (out.empty() ? "" : "+") + std::string(regime_name(static_cast<Regime>(k)));
    return out.empty() ? "none" : out;
}

SlidingResult run(double alpha, double mu, const PulseTrain& train, double a, double to) {
    const FrictionBlock block{alpha, half_diagonal(alpha), mu};
    SlidingOptions o;
    o.rtol = o.atol_alpha = kRtol;
    return dynamics::sliding::simulate_sliding(block, dynamics::PulseInput(train, a, to), o);
}

// Newmark's rigid block on friction mu under pulses (a_k g for T_k s), from
// rest: piecewise constant accelerations, the slip when it stops (m).
double newmark_slip(double mu, const std::vector<std::pair<double, double>>& pulses) {
    const double g = kGravity;
    double v = 0, x = 0;
    auto advance = [&](double a, double T) {  // a: the ground's inertial acceleration over g
        while (T > 0) {
            if (v == 0 && std::fabs(a) <= mu) return;  // stuck for the rest of this pulse
            const double s = v != 0 ? (v > 0 ? 1 : -1) : (a > 0 ? 1 : -1);
            const double acc = (a - mu * s) * g;
            // Until the slip stops (acc against v) or the pulse ends.
            const double stop = v != 0 && acc * v < 0 ? -v / acc : INFINITY;
            const double dt = std::min(T, stop);
            x += v * dt + 0.5 * acc * dt * dt;
            v = dt == stop ? 0 : v + acc * dt;
            T -= dt;
        }
    };
    for (const auto& [a, T] : pulses) advance(a, T);
    if (v != 0) x += v * std::fabs(v) / (2 * mu * g);  // the ground at rest: friction stops it, either way
    return x;
}

}  // namespace

void write_truth(SceneContext& ctx) {
    harness::Table t({"check", "alpha", "mu", "a_g", "to_s", "train", "quantity", "closed_form", "engine"});
    t.note("scene", "sliding: the Coulomb block against closed forms, run through the whole engine");
    t.note("model", "sliding-rocking block on Coulomb friction mu (docs/sliding.md): full equations, four regimes");
    t.note("solver", "dynamics::sliding::simulate_sliding, event-driven Dormand-Prince 5(4) at rtol = atol = 1e-9 alpha");
    t.note("inputs", "blocks H = 2 m tall (R = (H/2)/cos(alpha)); rectangular pulses (the train, amplitudes in a_g, "
                     "durations in to_s seconds)");
    t.note("columns",
           "regime: a flat block at rest under a constant a g for 1e-4 s, the regime(s) the engine spent time in "
           "against the criteria of docs/sliding.md (rest while a <= min(mu, tan alpha); slide if mu < tan alpha; "
           "else rock while the stuck corner's friction (3/4) cos(alpha) (a cos(alpha) - sin(alpha)) - a lies "
           "within mu [1 + (3/4) sin(alpha) (a cos(alpha) - sin(alpha))], slide-rock otherwise); newmark: the "
           "slip (m) when a block that only slides (mu < tan alpha) stops, Newmark's piecewise-constant "
           "acceleration (a - mu s) g; no-rock: mu < tan alpha, the largest |theta|/alpha during the input "
           "(closed form 0: the base cannot carry the force that tips the block)");

    // The regime from rest: both sides of tan(alpha) and of mu, inside each regime
    // (independent.py checks every a lies 1e-3 or more from a criterion's edge).
    const PulseTrain step({{1.0, 1.0}}, "constant");
    for (double alpha : {0.1, 0.2, 0.3, 0.5})
        for (double mu : {0.15, 0.4, 0.8})
            for (double a : {0.05, 0.18, 0.25, 0.35, 0.6, 1.0, 2.0}) {
                const SlidingResult r = run(alpha, mu, step, a, 1e-4);
                t.row().add("regime").add(alpha).add(mu).add(a).add(1e-4).add("1:1").add("regime");
                t.add(regime_closed_form(alpha, mu, a)).add(regimes_of(r));
            }
    // Newmark's slip, one pulse and a pulse and its reverse (the friction's
    // direction turns with the slip's).
    for (double mu : {0.2, 0.3, 0.4})
        for (double a : {0.6, 1.0})
            for (double T : {0.1, 0.3}) {
                for (const char* text : {"1:1", "1:1,-1:1"}) {
                    const PulseTrain train = parse_train(text);
                    std::vector<std::pair<double, double>> pulses;
                    for (const Pulse& pl : train.pulses()) pulses.push_back({pl.amplitude * a, pl.duration * T});
                    const SlidingResult r = run(0.5, mu, train, a, T);
                    t.row().add("newmark").add(0.5).add(mu).add(a).add(T).add(text).add("final_slip_m");
                    t.add(newmark_slip(mu, pulses)).add(r.final_slip);
                }
            }
    // No rocking below tan(alpha): cases 1 and 2 at three times the sliding threshold.
    for (double alpha : {0.45, 0.6})
        for (int c : {1, 2}) {
            const double mu = 0.4;
            const SlidingResult r = run(alpha, mu, pulse_case(c), 3 * mu, 0.5);
            t.row().add("no-rock").add(alpha).add(mu).add(3 * mu).add(0.5);
            t.add(c == 1 ? "1:1,-1:1" : "1:1,-0.5:1").add("max_theta_over_alpha");
            t.add(0.0).add(r.max_abs_theta_input / alpha);
        }
    ctx.write(t, "sliding_truth.csv");
}

}  // namespace rocking::scenes::sliding_scene
