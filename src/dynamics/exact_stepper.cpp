// The exact solver of the linearised equation.  On one corner and one input
// piece, theta'' - p^2 theta = p^2 (c0 - sigma alpha + c1 u + s sin(w u + phase))
// (u = t - t0) has the closed-form solution
//   theta(u) = C cosh(pu) + D sinh(pu) - (c0 - sigma alpha) - c1 u + B sin(w u + phase),
//   B = -p^2 s / (p^2 + w^2),
//   C = theta0 + (c0 - sigma alpha) - B sin(phase),  D = (omega0 + c1 - B w cos(phase)) / p,
// exact up to rounding; a step is one input piece (split to keep p h <= max_step_p).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dynamics/stepper.hpp"

namespace rocking::dynamics {

namespace {

class ExactStepper : public Stepper {
public:
    ExactStepper(const Model& model, const GroundInput& input, const SolverOptions& options)
        : model_(model), input_(input), options_(options), sampled_(dynamic_cast<const SampledInput*>(&input)) {}

    void set_batching(bool on, double overturn_angle) override {
        batching_ = on && sampled_ != nullptr;
        overturn_ = overturn_angle;
    }

    void reset(double t, double theta, double omega, int sigma, double t_stop) override {
        t0_ = t1_ = t;
        theta_ = theta;
        omega_ = omega;
        sigma_ = sigma;
        t_stop_ = t_stop;
    }

    bool advance() override {
        if (!advance_piece()) return false;
        if (batching_) run_quiet_pieces();
        return true;
    }

    // One input piece (or part of one), from the state at t1_.
    bool advance_piece() {
        if (t1_ >= t_stop_) return false;
        t0_ = t1_;
        piece_ = input_.piece_at(t0_);
        if (!(piece_.t1 > t0_)) throw std::logic_error("exact solver: input piece ends at its start");
        const double p = model_.block.p;
        double h = std::min({t_stop_, piece_.t1}) - t0_;
        double h_max = options_.max_step_p / p;
        if (piece_.s != 0.0) h_max = std::min(h_max, options_.max_step_p / piece_.w);
        if (h > h_max) h = h_max;
        t1_ = (t0_ + h >= std::min(t_stop_, piece_.t1)) ? std::min(t_stop_, piece_.t1) : t0_ + h;
        // Coefficients of the closed form from the state at t0.
        const double p2 = p * p, c = piece_.c0 - sigma_ * model_.block.alpha;
        const double u0 = t0_ - piece_.t0;  // offset into the piece
        const double lin = c + piece_.c1 * u0;  // polynomial part at t0
        const double B = piece_.s != 0.0 ? -p2 * piece_.s / (p2 + piece_.w * piece_.w) : 0.0;
        const double ph = piece_.w * u0 + piece_.phase;
        th0_ = theta_;
        om0_ = omega_;
        C_ = theta_ + lin - B * std::sin(ph);
        D_ = (omega_ + piece_.c1 - B * piece_.w * std::cos(ph)) / p;
        lin_ = lin;
        B_ = B;
        ph_ = ph;
        // A record's pieces share one length: cosh(p h) and sinh(p h) are
        // computed once, which makes a step a handful of flops.  (k+1) dt - k dt
        // varies in its last bits: lengths within 8 ulps share the cache, an
        // error of 1e-15 relative, below the rounding of the step itself.
        const double hstep = t1_ - t0_;
        if (std::fabs(hstep - cached_h_) > 8 * std::numeric_limits<double>::epsilon() * hstep) {
            cached_h_ = hstep;
            cached_ch_ = std::cosh(p * hstep);
            cached_sh_ = std::sinh(p * hstep);
        }
        theta_ = C_ * cached_ch_ + D_ * cached_sh_ - lin_ - piece_.c1 * hstep;
        omega_ = p * (C_ * cached_sh_ + D_ * cached_ch_) - piece_.c1;
        if (B_ != 0.0) {
            theta_ += B_ * std::sin(piece_.w * hstep + ph_);
            omega_ += B_ * piece_.w * std::cos(piece_.w * hstep + ph_);
        }
        ++steps_;
        return true;
    }

    // Whole record pieces, a 2x2 update each on the raw samples, while no
    // event can be inside: at both ends of each piece sigma theta > 0, theta'
    // keeps its sign, sigma theta stays on one side of alpha and below the
    // fall angle.  The last piece (the one that may hold an event, or the
    // last before t_stop) is left as the step, with its closed form.
    void run_quiet_pieces() {
        const std::vector<double>& a = sampled_->samples();
        const double dt = sampled_->dt(), p = model_.block.p, alpha = model_.block.alpha;
        const double ch = cached_ch_, sh = cached_sh_;
        if (std::fabs((t1_ - t0_) - dt) > 8 * std::numeric_limits<double>::epsilon() * dt) return;
        auto quiet = [&](double th0, double om0, double th1, double om1) {
            const double s0 = sigma_ * th0, s1 = sigma_ * th1;
            return s1 > 0 && ((om0 < 0) == (om1 < 0)) && om0 != 0 && om1 != 0 && ((s0 < alpha) == (s1 < alpha)) &&
                   s1 < overturn_;
        };
        double th_prev = 0, om_prev = 0;
        state_at(t0_, th_prev, om_prev);
        if (!quiet(th_prev, om_prev, theta_, omega_)) return;
        std::size_t k = static_cast<std::size_t>(std::llround(t1_ / dt));  // the piece starting at t1_
        const double sa = sigma_ * alpha;
        double th_start = theta_, om_start = omega_;
        bool moved = false;
        while (k + 1 < a.size() && dt * (k + 1) <= t_stop_) {
            const double c0 = a[k] - sa, c1 = (a[k + 1] - a[k]) / dt;
            const double C = theta_ + c0, D = (omega_ + c1) / p;
            const double th = C * ch + D * sh - c0 - c1 * dt;
            const double om = p * (C * sh + D * ch) - c1;
            if (!quiet(theta_, omega_, th, om)) break;  // leave this piece to advance_piece()
            th_start = theta_;
            om_start = omega_;
            theta_ = th;
            omega_ = om;
            ++k;
            ++steps_;
            moved = true;
        }
        if (moved) {  // the last quiet piece becomes the step the driver sees
            t0_ = dt * (k - 1);
            t1_ = dt * k;
            piece_ = input_.piece_at(t0_);
            lin_ = piece_.c0 - sa;
            B_ = 0.0;
            ph_ = 0.0;
            C_ = th_start + lin_;
            D_ = (om_start + piece_.c1) / p;
            th0_ = th_start;
            om0_ = om_start;
        }
    }

    void state_at(double t, double& theta, double& omega) override {
        if (t == t1_) {  // the ends of the step: already known exactly
            theta = theta_;
            omega = omega_;
            return;
        }
        if (t == t0_) {
            theta = th0_;
            omega = om0_;
            return;
        }
        const double p = model_.block.p, u = t - t0_;
        const double e = std::exp(p * u), ie = 1.0 / e;
        const double ch = 0.5 * (e + ie), sh = (u < 1e-3 / p) ? std::sinh(p * u) : 0.5 * (e - ie);
        theta = C_ * ch + D_ * sh - lin_ - piece_.c1 * u;
        omega = p * (C_ * sh + D_ * ch) - piece_.c1;
        if (B_ != 0.0) {
            theta += B_ * std::sin(piece_.w * u + ph_);
            omega += B_ * piece_.w * std::cos(piece_.w * u + ph_);
        }
    }

private:
    const Model& model_;
    const GroundInput& input_;
    SolverOptions options_;
    InputPiece piece_{0, 0};
    double theta_ = 0, omega_ = 0, t_stop_ = 0;
    int sigma_ = 1;
    double C_ = 0, D_ = 0, lin_ = 0, B_ = 0, ph_ = 0;
    double cached_h_ = -1, cached_ch_ = 1, cached_sh_ = 0;
    double th0_ = 0, om0_ = 0;
    const SampledInput* sampled_;
    bool batching_ = false;
    double overturn_ = M_PI / 2;
};

}  // namespace

std::unique_ptr<Stepper> make_exact_stepper(const Model& model, const GroundInput& input, const SolverOptions& options) {
    return std::make_unique<ExactStepper>(model, input, options);
}

}  // namespace rocking::dynamics
