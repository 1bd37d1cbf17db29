// A run of the sliding-rocking block (friction_block.hpp) under a ground
// input: event-driven.  Inside a regime the state is integrated by
// Dormand-Prince 5(4) with dense output (Boost.Odeint, its steps ending on
// the input's kinks, as the ODE solvers of stepper.hpp on a record) to the
// stated tolerances; the regime changes are events found on the dense
// output and located on true steps (docs/sliding.md, Accuracy): an impact
// (theta reaching 0), the fall (|theta| reaching the overturn angle), a
// slip starting (|f| reaching mu n
// on a stuck corner) or stopping (the pivot's or the base's velocity
// reaching 0), a block at rest set going (|A| above g min(mu, tan alpha)),
// and free flight (n reaching 0: outside the model, an error).  Beside the
// state it integrates the input's work and the friction's loss, so that a
// run checks its own energy balance: E(t) - E(0) = W - D_friction - D_impacts.
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "dynamics/simulate.hpp"
#include "dynamics/sliding/friction_block.hpp"

namespace rocking::dynamics::sliding {

struct SlidingOptions {
    double rtol = 1e-9;        // Dormand-Prince's relative tolerance
    double atol_alpha = 1e-9;  // its absolute one, in units of alpha, on every state variable
                               // (theta rad, theta' rad/s, the slip and its rate over R, energies over g R)
    double max_step_p = 0.1;   // the longest step, times p: events inside one are few
    bool free_rocking = true;  // follow the block after the input until it rests, falls or 200/p s pass
    double overturn_angle = M_PI / 2;
    double rest_velocity = 1e-9;  // |theta'| below max(rest_velocity, 10 atol) alpha p after an impact, or
                                  // an impact within 1e-6/p of the last at |theta'| < 1e-6 alpha p (the
                                  // rocking-only driver's micro-bounce rule): the block lies flat, and its slip rate below
                                  // max(rest_velocity, 10 atol) alpha p R is 0
    long max_events = 1000000;    // a guard: beyond it, std::runtime_error (a second of events)
    std::size_t max_impact_times = 1000000;  // impact_times keeps the first ones (8 bytes each)
    // > 0: keep the state every record_dt seconds, k record_dt up to the
    // run's end (the fall, or the end of the free rocking followed), read on
    // the dense output (its interpolant, of the steps' accuracy).
    double record_dt = 0;
    std::string describe() const;
};

struct SlidingSample {
    double t, theta, omega;  // s, rad, rad/s
    double slip, slip_rate;  // the base's displacement on the ground and its rate, m and m/s
    Regime regime;
};

struct SlidingResult {
    double t_fin = 0;
    double max_abs_theta_input = 0;   // largest |theta| on [0, t_fin]
    double theta_at_tfin = 0;
    double slip_at_tfin = 0;          // the base's displacement on the ground at t_fin (or the fall before it), m
    double max_abs_slip = 0;          // largest |slip| over the run, m
    double final_slip = 0;            // at the run's end, m
    bool overturned = false, overturned_during_input = false;
    double t_overturn = NAN;
    bool uplifted = false, slid = false;  // rocked, slipped at some time
    int impacts = 0, slipping_impacts = 0;
    std::vector<double> impact_times;  // in order, the first options.max_impact_times of them
    long regime_changes = 0;
    double time_in[4] = {0, 0, 0, 0};  // seconds in each Regime (rest, slide, rock, slide-rock)
    // The energy balance per unit mass (J/kg): the input's work W = int A x_G' dt,
    // the friction's loss int mu n |x_p'| dt, the impacts' kinetic-energy loss,
    // E at the end against E(0) + W - losses (balance_error: the largest
    // |residual| seen at any event, over g R).
    double input_work = 0, friction_loss = 0, impact_loss = 0, final_energy = 0;
    double balance_error = 0;
    long steps = 0, rhs_evaluations = 0;
    std::vector<SlidingSample> samples;  // options.record_dt > 0
    // In a rocking run's terms (what the searches and the criteria read).
    SimulationResult as_rocking() const;
    bool collapse(Criterion c, double alpha) const { return as_rocking().collapse(c, alpha); }
};

// The block leaves the ground (n reaches 0 at its pivot) at time t: free
// flight, outside the model.  Its own type, so that a study can count the
// runs the model cannot follow apart from every other failure.
struct FreeFlight : std::runtime_error {
    double t;
    FreeFlight(const std::string& what, double when) : std::runtime_error(what), t(when) {}
};

// Throws std::invalid_argument for a bad block or tolerances outside
// [kSmallestTolerance, 1), FreeFlight (a std::runtime_error) when the block
// would fly, std::runtime_error when the events do not end, std::domain_error where the contact problem has no
// consistent solution (friction_block.hpp).
SlidingResult simulate_sliding(const FrictionBlock& block, const GroundInput& input, const SlidingOptions& options);

}  // namespace rocking::dynamics::sliding
