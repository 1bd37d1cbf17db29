// The exact solver of the linearised equation.  On one corner and one input
// piece, theta'' - p^2 theta = p^2 (c0 - sigma alpha + c1 u + s sin(w u + phase))
// (u = t - t0) has the closed-form solution
//   theta(u) = C cosh(pu) + D sinh(pu) - (c0 - sigma alpha) - c1 u + B sin(w u + phase),
//   B = -p^2 s / (p^2 + w^2),
//   C = theta0 + (c0 - sigma alpha) - B sin(phase),  D = (omega0 + c1 - B w cos(phase)) / p,
// exact up to rounding; a step is one input piece (split to keep p h <= max_step_p).
// It is evaluated as increments on the state (W = p D, the even series of
// cosh and sinh as the record kernel's, closed_piece.hpp):
//   theta(u) = theta0 + omega0 u + C (cosh pu - 1) + W (sinh pu - pu) / p
//              + B (sin(w u + phase) - sin(phase) - w u cos(phase)),
//   theta'(u) = omega0 + C p sinh pu + W (cosh pu - 1) + B w (cos(w u + phase) - cos(phase)),
// so that the rounding is relative to the motion, not to the input: the
// form above cancels C cosh against c0 - sigma alpha, which rounds at
// eps (q alpha) -- under a short strong pulse (x = p to = 1e-4, q ~ 1e8) an
// error of 1e-8 alpha in theta(t_fin), where the increments keep 1e-16.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dynamics/closed_piece.hpp"
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
        const double p = model_.p_on(sigma_);
        double h = std::min({t_stop_, piece_.t1}) - t0_;
        double h_max = options_.max_step_p / p;
        if (piece_.s != 0.0) h_max = std::min(h_max, options_.max_step_p / piece_.w);
        if (h > h_max) h = h_max;
        t1_ = (t0_ + h >= std::min(t_stop_, piece_.t1)) ? std::min(t_stop_, piece_.t1) : t0_ + h;
        // Coefficients of the closed form from the state at t0.
        const double p2 = p * p, c = piece_.c0 - sigma_ * model_.alpha_on(sigma_);
        const double u0 = t0_ - piece_.t0;  // offset into the piece
        const double lin = c + piece_.c1 * u0;  // polynomial part at t0
        const double B = piece_.s != 0.0 ? -p2 * piece_.s / (p2 + piece_.w * piece_.w) : 0.0;
        const double ph = piece_.w * u0 + piece_.phase;
        th0_ = theta_;
        om0_ = omega_;
        C_ = theta_ + lin - B * std::sin(ph);
        W_ = omega_ + piece_.c1 - B * piece_.w * std::cos(ph);
        B_ = B;
        ph_ = ph;
        // A record's pieces share one length: the series of cosh(p h) and
        // sinh(p h) are evaluated once, which makes a step a handful of flops.
        // (k+1) dt - k dt varies in its last bits: lengths within 8 ulps share
        // the cache, an error of 1e-15 relative, below the rounding of the step itself.
        const double hstep = t1_ - t0_;
        if (std::fabs(hstep - cached_h_) > 8 * std::numeric_limits<double>::epsilon() * hstep || p != cached_p_) {
            cached_h_ = hstep;
            cached_p_ = p;
            cached_y_ = (p * hstep) * (p * hstep);
            closed_piece::series(cached_y_, cached_ch1_, cached_sh1_);
        }
        point_at(hstep, cached_y_, cached_ch1_, cached_sh1_, theta_, omega_);
        ++steps_;
        return true;
    }

    // Whole record pieces, a 2x2 update each on the raw samples, while no
    // event can be inside: at both ends of each piece sigma theta > 0, theta'
    // and theta'' keep their signs, sigma theta stays on one side of alpha
    // and below the fall angle.  The last piece (the one that may hold an event, or the
    // last before t_stop) is left as the step, with its closed form.
    void run_quiet_pieces() {
        const std::vector<double>& a = sampled_->samples();
        const double dt = sampled_->dt(), p = model_.p_on(sigma_), alpha = model_.alpha_on(sigma_);
        if (std::fabs((t1_ - t0_) - dt) > 8 * std::numeric_limits<double>::epsilon() * dt) return;
        // The increments of a whole piece (closed_piece::Closed::from_series).
        // k1 = cosh p dt - 1, sh = p sinh p dt, q_dt = (sinh p dt - p dt) / p.
        const double y = cached_y_, k1 = y * cached_ch1_, sh = p * p * dt * (1 + y * cached_sh1_),
                     q_dt = dt * y * cached_sh1_;
        // e0, e1: theta''/p^2 at the ends.  Of one sign, with theta' of one
        // sign, theta' is monotone (theta''/p^2 = C cosh pu + D sinh pu has
        // one root at most) and theta has no extremum inside; theta' of one
        // sign alone allows two, and the block could leave the ground and
        // come back, or cross alpha and come back, unseen.
        auto quiet = [&](double th0, double om0, double e0, double th1, double om1, double e1) {
            const double s0 = sigma_ * th0, s1 = sigma_ * th1;
            return s1 > 0 && ((om0 < 0) == (om1 < 0)) && om0 != 0 && om1 != 0 && e0 * e1 > 0 &&
                   ((s0 < alpha) == (s1 < alpha)) && s1 < overturn_;
        };
        double th_prev = 0, om_prev = 0;
        state_at(t0_, th_prev, om_prev);
        // The step just taken, a whole piece: its input is a(t0) + c1 u,
        // and C = theta(t0) + a(t0) - sigma alpha (B = 0 on a record).
        if (!quiet(th_prev, om_prev, C_, theta_, omega_, theta_ + (C_ - th0_) + piece_.c1 * (t1_ - t0_))) return;
        std::size_t k = static_cast<std::size_t>(std::llround(t1_ / dt));  // the piece starting at t1_
        const double sa = sigma_ * alpha;
        double th_start = theta_, om_start = omega_;
        bool moved = false;
        while (k + 1 < a.size() && dt * (k + 1) <= t_stop_) {
            const double c0 = a[k] - sa, c1 = (a[k + 1] - a[k]) / dt;
            const double C = theta_ + c0, W = omega_ + c1;
            const double th = theta_ + omega_ * dt + C * k1 + W * q_dt;
            const double om = omega_ + C * sh + W * k1;
            if (!quiet(theta_, omega_, C, th, om, th + a[k + 1] - sa)) break;  // leave this piece to advance_piece()
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
            B_ = 0.0;
            ph_ = 0.0;
            C_ = th_start + piece_.c0 - sa;
            W_ = om_start + piece_.c1;
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
        const double p = model_.p_on(sigma_), u = t - t0_, y = (p * u) * (p * u);
        double ch1, sh1;
        closed_piece::series(y, ch1, sh1);
        point_at(u, y, ch1, sh1, theta, omega);
    }

private:
    // The closed form at u into the step, from its series there (y = (p u)^2,
    // ch1 and sh1 as closed_piece::series): the increments of the header.
    void point_at(double u, double y, double ch1, double sh1, double& theta, double& omega) const {
        const closed_piece::Closed<double>::Point q =
            closed_piece::Closed<double>{model_.p_on(sigma_), th0_, om0_, C_, W_}.from_series(u, y, ch1, sh1);
        theta = q.theta;
        omega = q.omega;
        if (B_ != 0.0) {
            const double w = piece_.w;
            theta += B_ * (std::sin(w * u + ph_) - std::sin(ph_) - w * u * std::cos(ph_));
            omega += B_ * w * (std::cos(w * u + ph_) - std::cos(ph_));
        }
    }

    const Model& model_;
    const GroundInput& input_;
    SolverOptions options_;
    InputPiece piece_{0, 0};
    double theta_ = 0, omega_ = 0, t_stop_ = 0;
    int sigma_ = 1;
    double C_ = 0, W_ = 0, B_ = 0, ph_ = 0;  // the closed form's C, p D, B and phase at t0
    double cached_h_ = -1, cached_p_ = 0, cached_y_ = 0, cached_ch1_ = 0.5, cached_sh1_ = 1.0 / 6;
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
