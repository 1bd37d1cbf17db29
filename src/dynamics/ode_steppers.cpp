// General-purpose ODE solvers on the full or the linearised equation:
// Boost.Odeint Dormand-Prince 5(4) with dense output (MATLAB's ode45),
// Fehlberg 7(8), Bulirsch-Stoer with dense output, and GSL's rk8pd.
// Solvers without dense output locate events by re-stepping from the start of
// the last step with a shorter step (explicit Runge-Kutta steps are exact
// functions of the step size).
//
// A record's acceleration is piecewise linear: a kink at every sample, where
// theta''' jumps.  A step across a kink has a local error of order h^3 that
// only an error estimate evaluated inside the step can see.  Fehlberg 7(8)'s
// cannot: its estimate, (41/840) h (k1 + k11 - k12 - k13), uses only stages
// at the ends of the step (c = 0, 1, 0, 1), so it is blind to any term of the
// equation that depends on t alone, the input; and Bulirsch-Stoer's
// extrapolation assumes the smooth error expansion a kink breaks.  Stepping
// across the kinks, neither converged on a record (Norcia, p = 2, alpha = 0.2:
// rkf78's error 3e-4 alpha at rtol 1e-6 and 1.5e-6 alpha at 1e-12; on a
// synthetic record at rtol 1e-10 it missed an overturning).  So these two, and
// rk8pd (the cross-check, which converged, but slowly: 9e-11 alpha at 1e-12
// in 770,000 evaluations), end their steps on the kinks (next_kink), where
// each step's input is linear and the estimates hold.  Dormand-Prince steps
// across them, as MATLAB's ode45 does in the paper's integration: its
// estimate uses interior stages and converges there (what the speed
// comparison of bench/ measures).
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "dynamics/stepper.hpp"

namespace rocking::dynamics {

namespace odeint = boost::numeric::odeint;
using State = std::array<double, 2>;

namespace {

// The equation of motion on one corner, as an Odeint system.  The input is
// evaluated on the pieces left of t_stop, so that no stage sees the jump at
// the end of the segment.
struct RockingSystem {
    const Model* model = nullptr;
    const GroundInput* input = nullptr;
    long* counter = nullptr;
    int sigma = 1;
    double t_stop = INFINITY;

    // A new segment on corner sigma; returns the first trial step: 1e-3 / p,
    // shortened to where the input alone (its value and rate at t) would
    // move theta by 1e-3 alpha, and at least 16 ulps of t (p t > 3e11): GSL
    // refuses a step that leaves t where it was ("failure"), Odeint takes it
    // in vain.  The input's bound is below 1e-3 / p only for inputs above
    // 2000 alpha g or rates above 6e6 alpha p g/s.  Without it, under a ramp
    // of 1e30 g, Bulirsch-Stoer's first step took theta to 1e17 rad, and its
    // interpolant's rounding there (~10 rad) put the fall at the uplift.
    double start(int corner, double t, double stop) {
        sigma = corner;
        t_stop = stop;
        const InputPiece piece = input->piece_from(t);
        const double p = model->p_on(corner), p2 = p * p, move = 1e-3 * model->alpha_on(corner);
        const double a = std::fabs(piece.at(t)), rate = std::fabs(piece.rate(t));
        double h = 1e-3 / p;
        if (p2 * a * h * h > 2 * move) h = std::sqrt(2 * move / (p2 * a));
        if (p2 * rate * h * h * h > 6 * move) h = std::cbrt(6 * move / (p2 * rate));
        return std::min(std::max(h, 16 * std::numeric_limits<double>::epsilon() * std::fabs(t)), stop - t);
    }

    // Where a step that must not straddle a kink of the input ends: the
    // input's next break (a record's next sample: its piecewise-linear
    // acceleration has a kink at every sample) or the segment's end.  A
    // break that t sits on up to rounding is behind it.
    double next_kink(double t) const { return std::min(input->piece_from(t).t1, t_stop); }

    double accel_g(double t) const {
        if (t < t_stop) return input->accel(t);
        return input->piece_at(std::nextafter(t_stop, -INFINITY)).at(t);
    }
    void operator()(const State& x, State& dxdt, double t) const {
        ++*counter;
        dxdt[0] = x[1];
        dxdt[1] = model->acceleration(x[0], sigma, accel_g(t));
    }
};

// Steppers with dense output: Dormand-Prince and Bulirsch-Stoer.
template <class Dense>
class DenseStepper : public Stepper {
public:
    DenseStepper(const Model& model, const GroundInput& input, const SolverOptions& options, Dense dense,
                 bool ends_at_kinks)
        : options_(options), dense_(std::move(dense)), sys_{&model, &input, &rhs_}, ends_at_kinks_(ends_at_kinks) {}
    void reset(double t, double theta, double omega, int sigma, double t_stop) override {
        const double h0 = sys_.start(sigma, t, t_stop);
        t0_ = t1_ = t;
        t_stop_ = t_stop;
        dense_.initialize(State{theta, omega}, t, h0 > 0 ? h0 : 1e-12);
    }
    bool advance() override {
        if (t1_ >= t_stop_) return false;
        if (ends_at_kinks_) {
            // A step proposed across the next kink is shortened to end on it
            // (initialize() is Odeint's only way to set the step; it costs
            // one evaluation).
            const double t = dense_.current_time(), kink = sys_.next_kink(t);
            if (t + dense_.current_time_step() > kink) {
                const State x = dense_.current_state();
                dense_.initialize(x, t, kink - t);
            }
        }
        const auto interval = dense_.do_step(sys_);
        ++steps_;
        t0_ = interval.first;
        t1_ = std::min(interval.second, t_stop_);
        return true;
    }
    void state_at(double t, double& theta, double& omega) override {
        State x;
        dense_.calc_state(t, x);
        theta = x[0];
        omega = x[1];
    }

private:
    SolverOptions options_;
    Dense dense_;
    RockingSystem sys_{};
    bool ends_at_kinks_;
    double t_stop_ = 0;
};

// Fehlberg 7(8) through Odeint's controlled stepper.
class Rkf78Stepper : public Stepper {
public:
    Rkf78Stepper(const Model& model, const GroundInput& input, const SolverOptions& options)
        : options_(options),
          controlled_(odeint::make_controlled(options.atol_alpha * model.alpha_min(), options.rtol,
                                              odeint::runge_kutta_fehlberg78<State>())),
          sys_{&model, &input, &rhs_} {}
    void reset(double t, double theta, double omega, int sigma, double t_stop) override {
        h_ = sys_.start(sigma, t, t_stop);
        t0_ = t1_ = t;
        t_stop_ = t_stop;
        x_ = {theta, omega};
    }
    bool advance() override {
        if (t1_ >= t_stop_) return false;
        const double h_max = options_.max_step_p / sys_.model->p_max();
        x0_ = x_;
        t0_ = t1_;
        double t = t1_;
        const double kink = sys_.next_kink(t);
        for (int tries = 0;; ++tries) {
            if (tries > 500) throw std::runtime_error("rkf78: step size underflow at t = " + std::to_string(t));
            const double proposal = std::min(h_, h_max);
            double h = std::min(proposal, kink - t);
            const bool last = (h == kink - t);
            if (controlled_.try_step(sys_, x_, t, h) == odeint::success) {
                t1_ = last ? kink : t;
                // A step shortened to end on the kink says nothing against the proposal.
                h_ = last ? std::max(h, proposal) : h;
                break;
            }
            h_ = h;
        }
        ++steps_;
        return true;
    }
    void state_at(double t, double& theta, double& omega) override {
        State out = x0_;
        if (t > t0_) controlled_.stepper().do_step(sys_, x0_, t0_, out, t - t0_);
        theta = out[0];
        omega = out[1];
    }

private:
    SolverOptions options_;
    odeint::controlled_runge_kutta<odeint::runge_kutta_fehlberg78<State>> controlled_;
    RockingSystem sys_{};
    State x_{}, x0_{};
    double h_ = 0, t_stop_ = 0;
};

// GSL's rk8pd (Prince-Dormand 8(9)) with GSL's standard step control.
class GslStepper : public Stepper {
public:
    GslStepper(const Model& model, const GroundInput& input, const SolverOptions& options)
        : options_(options), sys_{&model, &input, &rhs_} {
        gsl_sys_ = {&GslStepper::rhs, nullptr, 2, &sys_};
        step_ = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2);
        probe_ = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2);
        control_ = gsl_odeiv2_control_standard_new(options.atol_alpha * model.alpha_min(), options.rtol, 1.0, 1.0);
        evolve_ = gsl_odeiv2_evolve_alloc(2);
    }
    ~GslStepper() override {
        gsl_odeiv2_evolve_free(evolve_);
        gsl_odeiv2_control_free(control_);
        gsl_odeiv2_step_free(probe_);
        gsl_odeiv2_step_free(step_);
    }
    static int rhs(double t, const double y[], double dydt[], void* params) {
        State x{y[0], y[1]}, d;
        (*static_cast<RockingSystem*>(params))(x, d, t);
        dydt[0] = d[0];
        dydt[1] = d[1];
        return GSL_SUCCESS;
    }
    void reset(double t, double theta, double omega, int sigma, double t_stop) override {
        h_ = sys_.start(sigma, t, t_stop);
        t0_ = t1_ = t;
        t_stop_ = t_stop;
        y_[0] = theta;
        y_[1] = omega;
        gsl_odeiv2_evolve_reset(evolve_);
        gsl_odeiv2_step_reset(step_);
    }
    bool advance() override {
        if (t1_ >= t_stop_) return false;
        const double h_max = options_.max_step_p / sys_.model->p_max();
        y0_[0] = y_[0];
        y0_[1] = y_[1];
        t0_ = t1_;
        double t = t1_;
        h_ = std::min(h_, h_max);
        const int status = gsl_odeiv2_evolve_apply(evolve_, control_, step_, &gsl_sys_, &t, sys_.next_kink(t), &h_, y_);
        if (status != GSL_SUCCESS) {
            char text[320];
            // GSL fails where its step no longer moves t.
            const bool unresolved = t + h_ == t;
            std::snprintf(text, sizeof text, "gsl-rk8pd solver: failed at t = %.17g s with step %.3g s (GSL: %s)%s", t,
                          h_, gsl_strerror(status),
                          unresolved ? ": the step is below double's resolution there, the motion too fast for t" : "");
            throw std::runtime_error(text);
        }
        t1_ = t;
        ++steps_;
        return true;
    }
    void state_at(double t, double& theta, double& omega) override {
        double y[2] = {y0_[0], y0_[1]}, err[2];
        if (t > t0_) {
            gsl_odeiv2_step_reset(probe_);
            gsl_odeiv2_step_apply(probe_, t0_, t - t0_, y, err, nullptr, nullptr, &gsl_sys_);
        }
        theta = y[0];
        omega = y[1];
    }

private:
    SolverOptions options_;
    RockingSystem sys_{};
    gsl_odeiv2_system gsl_sys_{};
    gsl_odeiv2_step* step_;
    gsl_odeiv2_step* probe_;
    gsl_odeiv2_control* control_;
    gsl_odeiv2_evolve* evolve_;
    double y_[2] = {0, 0}, y0_[2] = {0, 0}, h_ = 0, t_stop_ = 0;
};

}  // namespace

std::unique_ptr<Stepper> make_exact_stepper(const Model&, const GroundInput&, const SolverOptions&);

std::unique_ptr<Stepper> make_stepper(const Model& model, const GroundInput& input, const SolverOptions& options) {
    const double atol = options.atol_alpha * model.alpha_min(), h_max = options.max_step_p / model.p_max();
    if (options.kind != SolverKind::exact)
        for (double tol : {options.rtol, options.atol_alpha})
            if (!(tol >= kSmallestTolerance && tol < 1)) {
                char text[160];
                std::snprintf(text, sizeof text, "%s: tolerance %.3g outside [2.2e-14, 1) (below 100 eps rounding decides the steps)",
                              solver_name(options.kind).c_str(), tol);
                throw std::invalid_argument(text);
            }
    // Bulirsch-Stoer breaks under absurd inputs: on a 0.01 s ramp at p = 2
    // rad/s, from 1e100 g its dense output over the first step (as short as
    // the input demands, 7e-36 s) is NaN (it scales derivatives by powers of
    // the step), and with longer first steps its fall came 3.6 times late from
    // 1e150 g and never at 1e300 g.  Verified to 1e95 g (tests: to 1e80 g);
    // beyond p^2 PGA = 1e90 it is refused.  The other solvers hold to 1.7e306 g.
    if (options.kind == SolverKind::bulirsch_stoer &&
        !(model.p_max() * model.p_max() * input.peak() <= 1e90)) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "bulirsch-stoer: p^2 PGA = %.3g (rad/s)^2 g is beyond its range, 1e90: use another solver",
                      model.p_max() * model.p_max() * input.peak());
        throw std::invalid_argument(text);
    }
    switch (options.kind) {
        case SolverKind::exact:
            if (model.equation != Equation::linearised)
                throw std::invalid_argument("the exact solver handles the linearised equation only");
            return make_exact_stepper(model, input, options);
        case SolverKind::dopri5: {
            auto dense = odeint::make_dense_output(atol, options.rtol, h_max, odeint::runge_kutta_dopri5<State>());
            return std::make_unique<DenseStepper<decltype(dense)>>(model, input, options, std::move(dense), false);
        }
        case SolverKind::bulirsch_stoer: {
            odeint::bulirsch_stoer_dense_out<State> dense(atol, options.rtol, 1.0, 1.0, h_max);
            return std::make_unique<DenseStepper<decltype(dense)>>(model, input, options, std::move(dense), true);
        }
        case SolverKind::rkf78:
            return std::make_unique<Rkf78Stepper>(model, input, options);
        case SolverKind::gsl_rk8pd:
            return std::make_unique<GslStepper>(model, input, options);
    }
    throw std::invalid_argument("unknown solver");
}

std::string solver_name(SolverKind kind) {
    switch (kind) {
        case SolverKind::exact: return "exact";
        case SolverKind::dopri5: return "dopri5";
        case SolverKind::rkf78: return "rkf78";
        case SolverKind::bulirsch_stoer: return "bulirsch-stoer";
        case SolverKind::gsl_rk8pd: return "gsl-rk8pd";
    }
    return "?";
}

std::string tolerance_text(const SolverOptions& options) {
    char text[64];
    std::snprintf(text, sizeof text, "rtol %g, atol %g alpha", options.rtol, options.atol_alpha);
    return text;
}

SolverKind parse_solver(const std::string& name) {
    for (SolverKind k : {SolverKind::exact, SolverKind::dopri5, SolverKind::rkf78, SolverKind::bulirsch_stoer,
                         SolverKind::gsl_rk8pd})
        if (solver_name(k) == name) return k;
    throw std::invalid_argument("unknown solver '" + name + "' (exact, dopri5, rkf78, bulirsch-stoer, gsl-rk8pd)");
}

}  // namespace rocking::dynamics
