// Ground inputs for the dynamics engine, in the paper's sign (a > 0 drives
// theta > 0) and in units of g.  Each input is a sequence of pieces on which
//     a(t)/g = c0 + c1 (t - t0) + s sin(w (t - t0) + phase),
// which is what the exact solver needs (its particular solutions are closed
// forms of exactly these terms) and what the ODE solvers evaluate.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "pulse/pulse_train.hpp"

namespace rocking::dynamics {

struct InputPiece {
    double t0, t1;         // the piece, in seconds
    double c0 = 0, c1 = 0; // polynomial part, in g and g/s
    double s = 0, w = 0, phase = 0;  // sinusoidal part, in g, rad/s, rad
    double at(double t) const;       // a/g at t in [t0, t1]
    double rate(double t) const;     // (a/g)' at t: c1 + s w cos(w (t - t0) + phase)
    // The first time after t (by more than rounding) where the sinusoidal
    // part crosses 0, w (t - t0) + phase = k pi; t1 when none comes before
    // it or there is no sinusoidal part.
    double next_sine_zero(double t) const;
};

class GroundInput {
public:
    virtual ~GroundInput() = default;
    virtual std::string describe() const = 0;
    // Duration of the input: the paper's t_fin; the ground is at rest after it.
    virtual double t_end() const = 0;
    // The piece containing t (for t in [0, t_end)); pieces are closed on the
    // left.  For t >= t_end, a zero piece [t_end, inf).
    virtual InputPiece piece_at(double t) const = 0;
    // Times in (0, t_end] where a(t) jumps: an ODE solver must restart there.
    virtual std::vector<double> discontinuities() const = 0;
    // The end of the piece containing t (t_end or inf beyond).
    double next_break(double t) const { return piece_at(t).t1; }
    // The piece that goes on from t: piece_at(t), or the next one when t
    // sits on its end up to rounding (2 ulps), so that a step or a part
    // starting there is not cut to nothing.
    InputPiece piece_from(double t) const;
    double accel(double t) const { return piece_at(t).at(t); }
    // Largest |a|/g: the PGA in units of g.
    virtual double peak() const = 0;
    // The first time in [t, t_end) at which |a|/g > thr, or its crossing of
    // +-thr located in a piece (INFINITY when there is none): where a block
    // at rest can uplift.  Walks the pieces; a record overrides it with a
    // scan of its raw samples.
    virtual double first_above(double t, double t_end, double thr) const;
};

// t moved forward until exceeds(t) holds, at most 64 tries, stopping at
// t_end: one ulp, then steps doubling from 1e-15 |t| (1e-15 s at t = 0).
// What makes a crossing located on one evaluation of the input hold for
// another, whose rounding differs (uplift_time).  The steps are relative to
// t: an absolute floor (1e-15 s, before 2026-11-21) put the uplift of an
// input of 1e35 g or more, at 1e-37 s, at 1e-15 s, and its fall there too.
template <class Exceeds>
double move_until(double t, double t_end, Exceeds exceeds) {
    const double scale = t != 0.0 ? 1e-15 * std::fabs(t) : 1e-15;
    for (int k = 0; k < 64 && t < t_end && !exceeds(t); ++k)
        t = std::max(std::nextafter(t, INFINITY), t + scale * std::ldexp(1.0, std::min(k, 40)));
    return t;
}

// The uplift time from rest: first_above(), moved forward by ulps until
// |at(t)| > thr, so that the block never leaves the ground with an
// acceleration pushing it back (>= t_end: no uplift before t_end).  at(t) is
// the input as the integrator that goes on from there evaluates it
// (input.accel(t) for the steppers; the record kernel interpolates on the
// exact grid k dt, whose rounding differs from accel()'s by ~ c1 ulp(t),
// enough to start a block pressed into the ground).
template <class At>
double uplift_time(const GroundInput& input, double t, double t_end, double thr, At at) {
    return move_until(input.first_above(t, t_end, thr), t_end, [&](double s) { return std::fabs(at(s)) > thr; });
}

// The first time in [t, t_end) at which a/g > up or a/g < -down (up, down >
// 0), or the crossing located in a piece (INFINITY when there is none): where
// an imperfect block at rest can uplift, onto the corner +1 or -1.  Skips
// with input.first_above(min(up, down)), then walks the pieces.
double first_beyond(const GroundInput& input, double t, double t_end, double up, double down);

// uplift_time for an imperfect block: a/g > up lifts it onto corner +1,
// a/g < -down onto -1.
template <class At>
double uplift_time(const GroundInput& input, double t, double t_end, double up, double down, At at) {
    return move_until(first_beyond(input, t, t_end, up, down), t_end, [&](double s) {
        const double a = at(s);
        return a > up || -a > down;
    });
}

// A pulse train (amplitudes in PGA, durations in to) scaled to real units.
class PulseInput : public GroundInput {
public:
    PulseInput(PulseTrain train, double pga_g, double to_seconds);
    std::string describe() const override;
    double t_end() const override { return end_; }
    InputPiece piece_at(double t) const override;
    std::vector<double> discontinuities() const override;
    double peak() const override { return pga_ * train_.peak(); }
    const PulseTrain& train() const { return train_; }

private:
    PulseTrain train_;
    double pga_, to_, end_;
    std::vector<double> starts_;
};

// Samples a_k at t = k dt, linear in between (a record), in units of g.
class SampledInput : public GroundInput {
public:
    // Throws std::invalid_argument when dt is not finite and > 0, there are
    // fewer than 2 samples, or a sample is not finite.
    SampledInput(std::vector<double> samples_g, double dt, std::string name);
    std::string describe() const override { return name_; }
    double t_end() const override { return dt_ * (samples_.size() - 1); }
    InputPiece piece_at(double t) const override;
    std::vector<double> discontinuities() const override { return {}; }
    double peak() const override { return peak_; }
    double first_above(double t, double t_end, double thr) const override;
    double dt() const { return dt_; }
    // The piece k with k dt <= t < (k + 1) dt, exactly (0 <= k <= size - 2).
    std::size_t piece_index(double t) const;
    std::size_t size() const { return samples_.size(); }
    const std::vector<double>& samples() const { return samples_; }
    // The record times `factor` (finite, > 0; not checked here, the caller's
    // contract), named `name`.  Equal to SampledInput(samples times factor,
    // dt, name) bit for bit: a positive factor keeps every maximum's place and
    // rounding is monotone, so the peaks scale as the samples do.  An IDA
    // scales one record hundreds of times, and rebuilding (checking every
    // sample, finding the peaks) cost more than the run itself.
    SampledInput scaled_by(double factor, std::string name) const;

private:
    SampledInput() = default;
    std::vector<double> samples_;
    double dt_ = 0;
    std::string name_;
    double peak_ = 0;
    // Largest |a| over samples [kBlock j, kBlock (j + 1)]: first_above()
    // skips a quiet block at one comparison; over samples kBlock j and
    // after (tail_peak_): it stops at once where the record stays quiet to
    // its end (a block at rest after the strong motion, which walked the
    // whole coda block by block: 2.6% of Norcia's run, bench/).
    static constexpr std::size_t kBlock = 32;
    std::vector<double> block_peak_, tail_peak_;
};

// The one-sine pulse of Zhang & Makris (2001), NOTES.md, in the paper's sign:
//     a(t) = a_p sin(w_p t + psi),   0 <= t <= (2 pi - psi) / w_p,
// psi = asin(threshold / a_p) so that rocking starts at t = 0 (threshold =
// alpha for the linearised equation, tan alpha for the full one).  Throws
// std::invalid_argument when a_p <= threshold or w_p <= 0.
class OneSinePulse : public GroundInput {
public:
    OneSinePulse(double ap_g, double wp, double threshold_g);
    std::string describe() const override;
    double t_end() const override { return end_; }
    InputPiece piece_at(double t) const override;
    std::vector<double> discontinuities() const override { return {end_}; }
    double peak() const override { return ap_; }
    double psi() const { return psi_; }
    double wp() const { return wp_; }
    // The slowest pulse simulate() takes, w_p / p: a pulse far slower than
    // the block lifts it by a_p w_p t cos psi over t ~ 1/p, which below w_p
    // = 1e-16 p is under the rounding of a_p sin(...) itself, and the fall
    // comes at the rounding's time (w_p = 1e-20 rad/s, p = 2: 35.2 s with
    // the exact solver, 2795 s with rk8pd, where the closed form gives
    // 24.4 s).  1e-6 keeps far from that edge.
    static constexpr double slowest_wp_over_p = 1e-6;
    // The strongest pulse, a_p over the uplift threshold.  The closed form
    // between events holds terms ~ a_p p^2/(p^2 + w_p^2) that cancel to the
    // rotation (at most pi/2), so the fall time drifts from the exact one by
    // ~ eps a_p^{2/3}: within 1e-12 up to 1e9 (four blocks, against the
    // closed form in 80 digits), 6e-11 at 1e12, 6e-6 at 1e20 g, and from
    // 1e35 g on it was returned as the uplift's floor, 1e-15 s.  Real pulses
    // stay below 1e2.  Test: AOneSinePulseFallsWhenItsClosedFormSays.
    static constexpr double strongest_ap_over_threshold = 1e9;

private:
    double ap_, wp_, psi_, end_;
};

}  // namespace rocking::dynamics
