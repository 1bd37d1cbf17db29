// The simulation driver: composes an equation of motion (Model), a ground
// input and a solver, and handles what happens between the solver's steps:
// uplift from rest, impacts at theta = 0 with restitution (the block passes to
// the other corner), the end of an impact cascade, and the collapse criteria.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "dynamics/model.hpp"
#include "dynamics/stepper.hpp"

namespace rocking::dynamics {

// The collapse criteria (NOTES.md, Figure 5):
//   final_rotation: |theta(t_fin)| >= alpha, the paper's (eq. 11, 21);
//   peak_rotation:  |theta| reaches alpha at some time during the input;
//   overturning:    the block overturns at any time, the free rocking after
//                   the input included (ground at rest).
// A block that overturns during the input has collapsed under all three.
enum class Criterion { final_rotation, peak_rotation, overturning };
std::string criterion_name(Criterion c);
// Parses final-rotation, peak-rotation, overturning; throws std::invalid_argument.
Criterion parse_criterion(const std::string& name);

struct SimulationOptions {
    SolverOptions solver;
    bool free_rocking = true;         // decide overturning after the input (needed by Criterion::overturning)
    double record_dt = 0.0;           // > 0: keep (t, theta, omega) every record_dt seconds
    double free_record_time = 0.0;    // seconds of free rocking after t_fin to keep in the record
    double overturn_angle = M_PI / 2; // |theta| at which the block has fallen
    double rest_velocity = 1e-9;      // |theta'| below rest_velocity * alpha * p after an impact: the block rests
    // A guard on run time: beyond max_impacts, std::runtime_error.  The
    // micro-bounce rule ends every cascade, but with restitution 1 a block
    // lifted by a hair rocks on at that amplitude, an impact every few
    // microseconds, to the record's end (3.5e7 impacts in 3 s on one of
    // ../shared/records, p = 20 rad/s, alpha just below the PGA).
    int max_impacts = 1000000000;
    std::size_t max_impact_times = 1000000;  // impact_times keeps the first ones (8 bytes each)
    double initial_theta = 0.0;       // a block released from theta0 (free-rocking tests); 0: at rest
    double initial_omega = 0.0;
};

// A block that may still overturn after the input is followed for this many 1/p
// seconds of free rocking (run_rules.hpp, stop_after_input).
constexpr double kFreeRockingTimesP = 200.0;

// The longest run the solvers are asked to follow, in units of 1/p.  At
// p t = 1e9 a step (at most max_step_p / p = 0.5/p) spans 0.5/(1e9 eps) =
// 2.3e6 ulps of t, so rounding t moves a step's end by 4e-7 of the step,
// near the 1e-6 the studies bisect to, and the run takes 2e9 steps; at
// 4.5e15 no step moves t ("no progress").  No record or block comes near
// it: 1000 rad/s over a day is 8.6e7.
constexpr double kLongestRunTimesP = 1e9;
// Empty when p times duration (s) is within kLongestRunTimesP, otherwise why
// ("p t = 1.5e+301 (p = 30 rad/s over 5e+299 s) exceeds 1e9, ...").
std::string unresolvable_run(double p, double duration);

// The rows a theta(t) record at options.record_dt > 0 can hold: the samples k
// record_dt up to the latest time a run can reach, t_fin plus the free rocking
// followed (up to max(free_record_time, 200/p) seconds).  A double: a tiny
// record_dt gives more rows than any integer type holds.
double max_record_rows(const Model& model, const GroundInput& input, const SimulationOptions& options);
// That latest time, s.
double latest_run_time(const Model& model, const GroundInput& input, const SimulationOptions& options);

// The most rows a front end writes of a theta(t) record (simulate --output,
// rocking_q.simulate): they are held in memory before being written (about
// 270 bytes a row; --dt 1e-7 had grown to 4.9 GB in 8 s).
constexpr double kMaxRecordRows = 1e6;
// The smallest record_dt whose record stays within kMaxRecordRows up to
// latest_run_time, rounded up to three significant digits: what a refusal
// suggests instead.
double smallest_record_dt(const Model& model, const GroundInput& input, const SimulationOptions& options);

// The rest rule a run applies after an impact, as a fraction of alpha p: a
// rebound slower than rest_velocity, or, for the ODE solvers, than their own
// accuracy (10 atol), leaves the block at rest.
double rest_threshold(const SimulationOptions& options);

struct Sample {
    double t, theta, omega;
};

struct SimulationResult {
    double t_fin = 0;
    double theta_at_tfin = 0, omega_at_tfin = 0;  // 0 when the block fell before t_fin (overturned_during_input)
    double max_abs_theta_input = 0;  // largest |theta| on [0, t_fin]
    // An imperfect block's (Model::minus set; 0 for a symmetric one, whose
    // record kernel keeps the largest |theta| alone): the largest theta and
    // -theta on [0, t_fin].
    double peak_plus_input = 0, peak_minus_input = 0;
    double t_first_alpha = NAN;      // first time |theta| = alpha (any phase); imperfect: its side's alpha
    bool uplifted = false;
    bool overturned = false;         // at any time, the free rocking included
    bool overturned_during_input = false;
    double t_overturn = NAN;         // NaN when decided by energy without simulating the fall
    int impacts = 0;
    double t_first_impact = NAN, t_last_impact = NAN;
    std::vector<double> impact_times;  // the impacts in order, the first options.max_impact_times of them
    int rests = 0;                   // times an impact cascade ended with the block at rest
    long rhs_evaluations = 0, steps = 0;
    std::vector<Sample> samples;

    // Under criterion c for a block of slenderness alpha; an imperfect one
    // passes its corner theta < 0's as alpha_minus (> 0): theta is then
    // measured against the slenderness of its own side.
    bool collapse(Criterion c, double alpha, double alpha_minus = 0) const;
};

// Throws std::invalid_argument for an exact solver on the full equation, and
// std::runtime_error when a solver fails or impacts do not end.
SimulationResult simulate(const Model& model, const GroundInput& input, const SimulationOptions& options);

// The front ends give rotations in units of alpha: at alpha = 1e-300 under
// 1e300 g, max |theta|/alpha overflowed and was printed as inf.  Throws
// std::runtime_error naming the value when max |theta|/alpha or (if the
// block stood to t_fin) theta(t_fin)/alpha is not finite, rather than give
// an output with a hole in it.
void refuse_overflow_in_alpha(const SimulationResult& r, double alpha);

}  // namespace rocking::dynamics
