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
        : model_(model), input_(input), options_(options) {}

    void reset(double t, double theta, double omega, int sigma, double t_stop) override {
        t0_ = t1_ = t;
        theta_ = theta;
        omega_ = omega;
        sigma_ = sigma;
        t_stop_ = t_stop;
    }

    bool advance() override {
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

    void state_at(double t, double& theta, double& omega) override {
        if (t == t1_) {  // the end of the step: already known
            theta = theta_;
            omega = omega_;
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
};

}  // namespace

std::unique_ptr<Stepper> make_exact_stepper(const Model& model, const GroundInput& input, const SolverOptions& options) {
    return std::make_unique<ExactStepper>(model, input, options);
}

}  // namespace rocking::dynamics
