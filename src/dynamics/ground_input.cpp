#include "dynamics/ground_input.hpp"

#include "numerics/roots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rocking::dynamics {

double InputPiece::at(double t) const {
    const double u = t - t0;
    return c0 + c1 * u + (s != 0.0 ? s * std::sin(w * u + phase) : 0.0);
}

double InputPiece::rate(double t) const { return c1 + (s != 0.0 ? s * w * std::cos(w * (t - t0) + phase) : 0.0); }

double InputPiece::next_sine_zero(double t) const {
    if (s == 0.0) return t1;
    // The phase at t rounds by ~eps (w t + |phase|): a zero that close to t is t's own.
    const double phi = w * (t - t0) + phase, slack = 8 * std::numeric_limits<double>::epsilon() * (std::fabs(phi) + 1);
    const double z = t0 + ((std::floor((phi + slack) / M_PI) + 1) * M_PI - phase) / w;
    return z > t && z < t1 ? z : t1;
}

PulseInput::PulseInput(PulseTrain train, double pga_g, double to_seconds)
    : train_(std::move(train)), pga_(pga_g), to_(to_seconds) {
    if (!(std::isfinite(pga_) && pga_ > 0)) throw std::invalid_argument("pulse input: PGA must be > 0");
    if (!(std::isfinite(to_) && to_ > 0)) throw std::invalid_argument("pulse input: to must be > 0 s");
    for (std::size_t k = 0; k <= train_.size(); ++k) starts_.push_back(train_.start(k) * to_);
    end_ = starts_.back();
}

std::string PulseInput::describe() const {
    std::ostringstream os;
    os << train_.name() << ", PGA = " << pga_ << " g, to = " << to_ << " s";
    return os.str();
}

InputPiece GroundInput::piece_from(double t) const {
    const InputPiece piece = piece_at(t);
    if (std::isfinite(piece.t1) && piece.t1 - t <= 2 * std::numeric_limits<double>::epsilon() * piece.t1)
        return piece_at(piece.t1);
    return piece;
}

InputPiece PulseInput::piece_at(double t) const {
    if (t >= end_) return {end_, INFINITY};
    const auto k = std::max<std::ptrdiff_t>(
        0, std::upper_bound(starts_.begin(), starts_.end(), t) - starts_.begin() - 1);
    InputPiece p{starts_[k], starts_[k + 1]};
    p.c0 = pga_ * train_.pulses()[k].amplitude;
    return p;
}

std::vector<double> PulseInput::discontinuities() const {
    return std::vector<double>(starts_.begin() + 1, starts_.end());
}

SampledInput::SampledInput(std::vector<double> samples_g, double dt, std::string name)
    : samples_(std::move(samples_g)), dt_(dt), name_(std::move(name)) {
    if (!(std::isfinite(dt_) && dt_ > 0)) throw std::invalid_argument(name_ + ": time step must be > 0");
    if (samples_.size() < 2) throw std::invalid_argument(name_ + ": needs at least 2 samples");
    for (std::size_t k = 0; k < samples_.size(); ++k) {
        if (!std::isfinite(samples_[k]))
            throw std::invalid_argument(name_ + ": sample " + std::to_string(k + 1) + " is not finite");
        peak_ = std::max(peak_, std::fabs(samples_[k]));
    }
    block_peak_.assign((samples_.size() + kBlock - 1) / kBlock, 0.0);
    for (std::size_t k = 0; k < samples_.size(); ++k) {
        block_peak_[k / kBlock] = std::max(block_peak_[k / kBlock], std::fabs(samples_[k]));
        if (k % kBlock == 0 && k > 0)  // a block's last piece ends on the next block's first sample
            block_peak_[k / kBlock - 1] = std::max(block_peak_[k / kBlock - 1], std::fabs(samples_[k]));
    }
    tail_peak_ = block_peak_;
    for (std::size_t j = tail_peak_.size() - 1; j-- > 0;) tail_peak_[j] = std::max(tail_peak_[j], tail_peak_[j + 1]);
}

SampledInput SampledInput::scaled_by(double factor, std::string name) const {
    SampledInput out;
    out.samples_ = samples_;
    for (double& a : out.samples_) a *= factor;
    out.dt_ = dt_;
    out.name_ = std::move(name);
    out.peak_ = peak_ * factor;
    out.block_peak_ = block_peak_;
    for (double& a : out.block_peak_) a *= factor;
    out.tail_peak_ = tail_peak_;
    for (double& a : out.tail_peak_) a *= factor;
    return out;
}

std::size_t SampledInput::piece_index(double t) const {
    const std::size_t last = samples_.size() - 1;
    // t / dt can round either way at a sample time: the piece must satisfy
    // k dt <= t < (k + 1) dt exactly, or a stepper starting at its end makes no progress.
    std::size_t k = std::min(last - 1, static_cast<std::size_t>(std::max(0.0, std::floor(t / dt_))));
    while (k + 1 < last && dt_ * (k + 1) <= t) ++k;
    while (k > 0 && dt_ * k > t) --k;
    return k;
}

InputPiece SampledInput::piece_at(double t) const {
    const std::size_t last = samples_.size() - 1;
    if (t >= dt_ * last) return {dt_ * last, INFINITY};
    const std::size_t k = piece_index(t);
    InputPiece p{dt_ * k, dt_ * (k + 1)};
    p.c0 = samples_[k];
    p.c1 = (samples_[k + 1] - samples_[k]) / dt_;
    return p;
}

namespace {

// Where a linear piece a(t) = c0 + c1 (t - t0), within [-thr, thr] at t,
// leaves it before end: at the level it moves toward, at or after t.  A
// crossing that rounds below t (one just located, from which the walk
// starts again) is t itself: it was skipped to the next piece, 2.5 ms late
// on a record (ImperfectBlock.UpliftTimeOnARecordAgainstAScan).
double linear_crossing(double t0, double c0, double c1, double t, double end, double thr) {
    if (c1 == 0.0) return INFINITY;
    const double tc = std::max(t, t0 + ((c1 > 0.0 ? thr : -thr) - c0) / c1);
    return tc < end ? tc : INFINITY;
}

// Whether a linear piece at a (rate c1) is at or beyond +-thr and moving
// away from 0: it exceeds thr at once after this point.  A sample exactly at
// the threshold, rising through it, is such a point; the strict tests (|a| >
// thr there, a crossing strictly after it) passed it by, and the uplift came
// a sample later (RunRules.ARecordReachingAlphaExactlyAtASampleLiftsTheBlockThere).
bool leaving(double a, double c1, double thr) { return std::fabs(a) >= thr && a * c1 > 0.0; }

// On a sinusoidal piece, the first time in (t, end] where beyond(a) holds:
// bracketed on a grid of 256 points, then the root of gap_for(a at the
// bracket's end), a function of time; INFINITY when there is none.
template <class Beyond, class GapFor>
double sine_crossing(const InputPiece& piece, double t, double end, Beyond beyond, GapFor gap_for) {
    const int n = 256;
    double prev = t;
    for (int k = 1; k <= n; ++k) {
        const double tk = t + (end - t) * k / n;
        const double ak = piece.at(tk);
        if (beyond(ak)) {
            const auto f = gap_for(ak);
            return numerics::root_of(f, prev, tk, f(prev), f(tk), 50);
        }
        prev = tk;
    }
    return INFINITY;
}

}  // namespace

double GroundInput::first_above(double t, double t_end, double thr) const {
    while (t < t_end) {
        const InputPiece piece = piece_at(t);
        const double end = std::min(piece.t1, t_end);
        const double a = piece.at(t);
        if (std::fabs(a) > thr) return t;
        if (piece.s == 0.0) {
            if (leaving(a, piece.c1, thr)) return t;
            const double tc = linear_crossing(piece.t0, piece.c0, piece.c1, t, end, thr);
            if (tc < end) return tc;
        } else {
            const double tc = sine_crossing(piece, t, end, [&](double v) { return std::fabs(v) > thr; },
                                            [&](double) { return [&](double s) { return std::fabs(piece.at(s)) - thr; }; });
            if (tc < INFINITY) return tc;
        }
        t = end;
    }
    return INFINITY;
}

double first_beyond(const GroundInput& input, double t, double t_end, double up, double down) {
    auto beyond = [&](double a) { return a > up || -a > down; };
    const double lower = std::min(up, down);
    while (t < t_end) {
        t = input.first_above(t, t_end, lower);  // nothing beyond either level before it
        if (!(t < t_end)) return INFINITY;
        const InputPiece piece = input.piece_at(t);
        const double end = std::min(piece.t1, t_end);
        const double a = piece.at(t);
        if (beyond(a)) return t;
        if (piece.s == 0.0) {
            if ((a >= up && piece.c1 > 0.0) || (-a >= down && piece.c1 < 0.0)) return t;
            // Moving toward the level it faces, a reaches it at tc >= t; a
            // tc that rounds below t (a crossing first_above has just
            // located) is t itself, not a reason to skip the piece.
            const double target = piece.c1 > 0.0 ? up : -down;
            if (piece.c1 != 0.0) {
                const double tc = std::max(t, piece.t0 + (target - piece.c0) / piece.c1);
                if (tc < end) return tc;
            }
        } else {
            const double tc = sine_crossing(piece, t, end, beyond, [&](double ak) {
                const double level = ak > 0 ? up : -down;
                return [&piece, level](double s) { return piece.at(s) - level; };
            });
            if (tc < INFINITY) return tc;
        }
        // This piece stays within the two levels: the next one, where
        // first_above starts over (its quiet stretches skipped).
        if (!(end > t)) return INFINITY;
        t = end;
    }
    return INFINITY;
}

// The same walk on the raw samples: a piece whose two ends are below thr
// cannot exceed it (a is linear in between), which skips a quiet stretch at
// one comparison per sample.
double SampledInput::first_above(double t, double t_end, double thr) const {
    const std::size_t last = samples_.size() - 1;
    if (!(t < t_end) || t >= dt_ * last) return INFINITY;
    std::size_t k = piece_index(t);
    for (;;) {
        const double t0 = dt_ * k, end = std::min(dt_ * (k + 1), t_end);
        const double c0 = samples_[k], c1 = (samples_[k + 1] - samples_[k]) / dt_;
        const double a = c0 + c1 * (t - t0);
        if (std::fabs(a) > thr || leaving(a, c1, thr)) return t;
        const double tc = linear_crossing(t0, c0, c1, t, end, thr);
        if (tc < end) return tc;
        if (!(end < t_end) || k + 1 >= last) return INFINITY;
        ++k;  // |a_k| <= thr: the crossing would have been found
        if (std::fabs(samples_[k]) < thr) {
            for (;;) {
                // Pieces kBlock j .. kBlock (j + 1) - 1 all below thr: skip them;
                // every piece from there on below thr: no crossing.
                if (k % kBlock == 0 && k / kBlock < block_peak_.size() && block_peak_[k / kBlock] < thr) {
                    if (tail_peak_[k / kBlock] < thr) return INFINITY;
                    if (k + kBlock < last) {
                        k += kBlock;
                        continue;
                    }
                }
                if (k + 1 < last && std::fabs(samples_[k + 1]) < thr) {
                    ++k;
                    continue;
                }
                break;
            }
        }
        t = dt_ * k;
        if (!(t < t_end)) return INFINITY;
    }
}

OneSinePulse::OneSinePulse(double ap_g, double wp, double threshold_g) : ap_(ap_g), wp_(wp) {
    if (!(std::isfinite(wp_) && wp_ > 0)) throw std::invalid_argument("one-sine pulse: w_p must be > 0");
    if (!(std::isfinite(ap_) && ap_ > threshold_g))
        throw std::invalid_argument("one-sine pulse: a_p must exceed the uplift threshold (a_p/g > alpha or tan alpha)");
    if (!(ap_ <= strongest_ap_over_threshold * threshold_g)) {
        char text[300];
        std::snprintf(text, sizeof text,
                      "one-sine pulse: a_p must be at most 1e9 times the uplift threshold, %.6g g (got %.6g g): "
                      "above it the closed form between events cancels and the fall time drifts from it",
                      strongest_ap_over_threshold * threshold_g, ap_);
        throw std::invalid_argument(text);
    }
    psi_ = std::asin(threshold_g / ap_);
    end_ = (2.0 * M_PI - psi_) / wp_;
}

std::string OneSinePulse::describe() const {
    std::ostringstream os;
    os << "one-sine pulse a_p = " << ap_ << " g, w_p = " << wp_ << " rad/s, psi = " << psi_;
    return os.str();
}

InputPiece OneSinePulse::piece_at(double t) const {
    if (t >= end_) return {end_, INFINITY};
    InputPiece p{0.0, end_};
    p.s = ap_;
    p.w = wp_;
    p.phase = psi_;
    return p;
}

}  // namespace rocking::dynamics
