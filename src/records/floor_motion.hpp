// The motion of a floor, for an element at height (a parapet on a roof rocks on
// the floor's motion, not the ground's): the building idealised as its first
// mode, a linear oscillator driven by the ground record.  The model, its limits,
// the numbers and the tests: docs/floor_motion.md.
//
// The model (modal analysis of a linear building under a ground acceleration
// a_g; Chopra, Dynamics of Structures, the chapters on the earthquake analysis
// of linear systems): the displacement relative to the ground at a height z is
// sum_n Gamma_n phi_n(z) D_n(t), where D_n is the relative displacement of the
// n-th mode's single-degree-of-freedom oscillator,
//
//     D'' + 2 zeta w D' + w^2 D = -a_g(t),   w = 2 pi / T1,  D(0) = D'(0) = 0,
//
// and Gamma_n phi_n(z) its participation at z.  Keeping the first mode only,
// with G = Gamma_1 phi_1(z), the floor's absolute acceleration is
//
//     a_f = a_g + G D'' = (1 - G) a_g + G a_1,   a_1 = a_g + D'' = -(2 zeta w D' + w^2 D),
//
// a_1 being the oscillator's absolute acceleration (the second form by the
// equation of motion).  G = 0 is the ground itself (the base, where phi = 0);
// G = 1 the oscillator's mass; the roof
// of a building with a linear first mode and equal storey masses has
// G = 3N/(2N + 1) for N storeys (1.5 as N grows).
//
// The solution: a_g is read linear between the record's samples (as the rocking
// engine reads it), and for a linear input over each step the oscillator's state
// (D, D') at the samples follows the exact recurrence of Nigam & Jennings
// (1969, BSSA 59(2), 909-922):
//
//     (D, D')_{k+1} = A (D, D')_k + B (a_g,k, a_g,k+1),
//
// A and B the exact matrices for the step dt (oscillator_step).  Exact for the
// piecewise-linear input up to rounding, at any dt; the floor record holds a_f
// at the record's own samples, the same count and dt: it ends with the ground
// record, and the building's free vibration after that is left out (its size
// at the end is stated: FloorResponse::end_amplitude).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "records/record.hpp"

namespace rocking::records {

// The floor's model: the building's first-mode period, its damping ratio and
// the floor's participation Gamma phi(z) in that mode.
struct FloorModel {
    double T1 = 0;       // s
    double G = 0;        // Gamma_1 phi_1(z), dimensionless
    double zeta = 0.05;  // of critical
};

// A FloorModel's parameter out of its range: what() says which and why;
// `parameter` is its name ("T1", "G", "zeta"), for a front end to name its option.
struct FloorModelError : std::invalid_argument {
    FloorModelError(const std::string& what, std::string parameter)
        : std::invalid_argument(what), parameter(std::move(parameter)) {}
    std::string parameter;
};

// Refuses (FloorModelError) T1 not > 0 or not finite, zeta outside [0, 1) (from
// 1 on the oscillator no longer oscillates, and A and B below take other forms)
// and G not finite.  Any finite G is taken: a first mode's Gamma phi lies mostly
// from 0 to 1.6 (docs/floor_motion.md), and a floor beyond a node of the mode
// shape has it negative.
void check_floor_model(const FloorModel& m);
// The same, and refuses T1 <= 2 dt for a record of step dt: the building's
// frequency 1/T1 would lie at or above the record's Nyquist frequency 1/(2 dt),
// where the record holds no motion of the ground's (only the kinks of its linear
// reading) and a floor record sampled at dt cannot hold the resonance.  So stiff a
// building's floor moves with the ground: the ground record is its floor's.
void check_floor_model(const FloorModel& m, double dt);

// "T1,G[,zeta]" (s, -, -; zeta defaults to 0.05): a shared record loader's option
// text.  Throws std::invalid_argument naming what is wrong (the count of values,
// the piece that is not a number, or check_floor_model's refusal).
FloorModel parse_floor_model(const std::string& text);

// The exact one-step maps of the oscillator for a step dt, input linear over it:
// A takes (D, D') at t_k to its free part at t_k + dt, B the input's samples
// (a_g,k, a_g,k+1) to the forced part.  Nigam & Jennings' A and B, evaluated
// through the complex root lambda = -zeta w + i w_d (docs/floor_motion.md): their
// printed B loses digits as w dt falls (terms of size 1/(w^3 dt) cancel to
// O(dt^2)); this form keeps every entry to a few ulps at any w dt < pi.  Its
// arguments are not checked here: floor_response and oscillator_response check them.
struct OscillatorStep {
    double A[2][2];
    double B[2][2];
};
OscillatorStep oscillator_step(double T1, double zeta, double dt);

// The oscillator's relative displacement D and velocity D' at the samples t_k = k dt,
// from rest at t = 0 (a_g(0) != 0 is a jump at t = 0), under a_g read linear
// between samples.  Same length as a_g.
struct OscillatorResponse {
    std::vector<double> D, V;  // the unit of a_g times s^2, times s
};
OscillatorResponse oscillator_response(const std::vector<double>& a_g, double dt, double T1, double zeta);

struct FloorResponse {
    std::vector<double> accel;  // a_f at t_k = k dt, in a_g's unit, as many samples as a_g
    // |G| w^2 |C|, where D = Re(C e^(lambda (t - t_end))) is the free vibration left at the
    // last sample: the amplitude of the floor's acceleration that the record leaves out,
    // decaying as exp(-zeta w (t - t_end)).
    double end_amplitude = 0;
};
// a_f = (1 - G) a_g + G a_1 at the samples.  Refuses (std::invalid_argument) dt not
// > 0 and finite, no samples, a sample not finite and the model as check_floor_model(m, dt)
// does; (std::overflow_error) an a_f beyond a double's range, naming its sample.
// a_g scaled by 2 gives a_f scaled by 2, bit for bit; G = 0 gives a_g's values (==).
FloorResponse floor_response(const std::vector<double>& a_g, double dt, const FloorModel& m);

// The floor record of a ground record: the same dt and count, in m/s^2 as every
// Record; format "floor motion", the ground's path; a name stating the model
// ("<ground's name>, floor T1=0.5 s zeta=0.05 G=1.5"); a header stating the model,
// the method, each parameter, the ground's name, path and format, the end amplitude,
// and a "warning" (warnings_of) when T1 is below 10 steps: the floor's resonant
// motion, sampled at dt, then peaks up to 1 - cos(pi dt/T1) below its crest.
Record floor_record(const Record& ground, const FloorModel& m);

// The sentence the command states the model in: "first-mode
// oscillator T1 = 0.5 s, zeta = 0.05, G = Gamma phi = 1.5; a_f = a_g + G D''".
std::string describe(const FloorModel& m);
// What a study's inputs are when every record is replaced by its floor's
// motion: "every record replaced by its floor's motion, <describe(m)>: q =
// PGA/(alpha g) and to_k are the floor's" (studies::IdaOptions::input_note).
std::string describe_as_input(const FloorModel& m);

}  // namespace rocking::records
