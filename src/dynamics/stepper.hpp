// Segment steppers: each advances the block on one corner, between two
// events where its state or the input jumps, one step at a time, and gives
// the state anywhere inside its last step (for event location).  The driver
// (simulate.hpp) does the rest: impacts, rest and uplift, criteria.
#pragma once

#include <limits>
#include <memory>
#include <string>

#include "dynamics/ground_input.hpp"
#include "dynamics/model.hpp"

namespace rocking::dynamics {

enum class SolverKind { exact, dopri5, rkf78, bulirsch_stoer, gsl_rk8pd };

// The ODE solvers' tolerances (rtol, atol_alpha) must lie in [100 eps, 1):
// 100 eps = 2.2e-14 is MATLAB's floor for ode45's RelTol (which it raises
// there with a warning; here it is an error).  Below it rounding decides the
// steps: at 1e-17 Bulirsch-Stoer gave up ("a new step size was not found"),
// at 1e-30 Dormand-Prince and Fehlberg had not finished one pulse in a minute.
constexpr double kSmallestTolerance = 100 * std::numeric_limits<double>::epsilon();

struct SolverOptions {
    SolverKind kind = SolverKind::exact;
    double rtol = 1e-6;  // relative tolerance (ODE solvers)
    // Absolute tolerance, in units of alpha: atol_alpha * alpha rad on theta
    // and the same number in rad/s on theta' (Odeint and GSL take one
    // absolute tolerance for the whole state, (theta, theta'), as ode45's
    // scalar AbsTol does).  1e-6 alpha is tighter than ode45's default
    // AbsTol, 1e-6 rad, for every alpha below 1 rad.
    double atol_alpha = 1e-6;
    // Largest step times p: keeps the closed form's series within 1e-21
    // (closed_piece.hpp) and the events of a step few.  It does not keep a
    // step to one extremum of theta: where theta'' changes sign inside a step,
    // theta' can vanish twice, and the driver splits the step there (simulate.cpp).
    double max_step_p = 0.5;
    // The exact solver on a record runs the record kernel (exact_record.hpp)
    // unless this is off: the general path, kept for cross-checks.
    bool record_kernel = true;
};

std::string solver_name(SolverKind kind);
// The tolerances a run of an ODE solver keeps, for the outputs that state
// it: "rtol 1e-06, atol 1e-06 alpha" (%g: "rtol 1e-08", never "0.000000").
std::string tolerance_text(const SolverOptions& options);
// Parses exact, dopri5, rkf78, bulirsch-stoer, gsl-rk8pd; throws std::invalid_argument.
SolverKind parse_solver(const std::string& name);

class Stepper {
public:
    virtual ~Stepper() = default;
    // Start a segment at (t, theta, omega) on corner sigma; no step goes beyond t_stop.
    virtual void reset(double t, double theta, double omega, int sigma, double t_stop) = 0;
    // One step; false when the segment is already at t_stop.
    virtual bool advance() = 0;
    // A stepper may cover several input pieces in one step when nothing
    // happens in them: no zero, extremum, alpha crossing or fall of theta
    // at their ends (the driver then sees only the last piece).  Off while a
    // record of theta(t) is kept.
    virtual void set_batching(bool /*on*/, double /*overturn_angle*/) {}
    double t_begin() const { return t0_; }
    double t_end() const { return t1_; }
    // State at t in [t_begin, t_end] of the last step.
    virtual void state_at(double t, double& theta, double& omega) = 0;
    long rhs_evaluations() const { return rhs_; }
    long steps() const { return steps_; }

protected:
    double t0_ = 0, t1_ = 0;
    long rhs_ = 0, steps_ = 0;
};

// Throws std::invalid_argument when the exact solver is asked for the full
// equation, or an ODE solver for a tolerance outside [kSmallestTolerance, 1).
std::unique_ptr<Stepper> make_stepper(const Model& model, const GroundInput& input, const SolverOptions& options);

}  // namespace rocking::dynamics
