// Synthetic ground motions whose answers are known: a near-fault velocity pulse
// in closed form (Mavroeidis & Papageorgiou 2003) and a seeded stochastic
// far-field record (Rezaeian & Der Kiureghian 2008, with the post-filter and
// the default parameters of their 2010 work).  Each comes back as a
// Record in m/s^2 whose header names the generator and every parameter, so
// that a study run on it can state its inputs.  Derivations, the parameters'
// sources and what was checked: docs/synthetic.md.
//
// Every function refuses a parameter outside its model with
// std::invalid_argument naming the parameter, and a frequency the step cannot
// represent with SamplingError (below).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "records/record.hpp"

namespace rocking::records {

// ---- What the step can represent ----
//
// A generator's record holds frequencies its parameters set (the pulse's carrier and
// sidebands, the stochastic filter's band and the post-filter's corner); sampled at dt, a
// frequency at or above the Nyquist frequency 1/(2 dt) is aliased into a record that is
// not the motion asked for (an fp of 100 Hz at dt = 0.02 s gave a PGA of 1e-14 m/s^2).
// pulse_record and stochastic_record refuse such a frequency with a SamplingError; one
// with fewer than kWarnSamplesPerPeriod samples per period is kept, and the record's
// header says so under "warning" (warnings_of).  Why 10: docs/synthetic.md ("Sampling").

// A frequency at or above the Nyquist frequency: what() names it, its value, the limit and
// dt; `parameters` are the names (as --pulse and stochastic_parameter_names spell them)
// whose values set it, so that a front end can name the option to change.
struct SamplingError : std::invalid_argument {
    SamplingError(const std::string& what, std::vector<std::string> parameters)
        : std::invalid_argument(what), parameters(std::move(parameters)) {}
    std::vector<std::string> parameters;
};

// Fewer samples than this per period of a generator's frequency: the record is warned of
// (at 10, the pulse's sampled PGA falls up to 3.4 % below its closed-form peak, measured;
// more below).
constexpr double kWarnSamplesPerPeriod = 10;

// A generated record's warnings, one sentence each (its header's "warning", "; " between
// them); none for a record sampled finely enough or not generated here.
std::vector<std::string> warnings_of(const Record& r);

// ---- The near-fault pulse of Mavroeidis & Papageorgiou (2003, BSSA 93(3)) ----

struct PulseParameters {
    double A = 0;      // m/s: the envelope's amplitude (its sign is the pulse's)
    double fp = 0;     // Hz: the carrier's frequency; the pulse period is T_p = 1/fp
    double nu = 0;     // rad: the carrier's phase
    double gamma = 0;  // > 1: the envelope spans gamma carrier periods
    double t0 = 0;     // s: the envelope's peak
};

// v(t) = (A/2) [1 + cos(2 pi fp (t - t0)/gamma)] cos(2 pi fp (t - t0) + nu)
// for |t - t0| <= gamma/(2 fp), 0 outside: the paper's velocity pulse (its
// mathematical model, v(t) with support t0 +- gamma/(2 fp)).
double pulse_velocity(const PulseParameters& p, double t);
// a(t) = dv/dt = -(A pi fp/gamma) [sin(2 pi fp s/gamma) cos(2 pi fp s + nu)
//                + gamma sin(2 pi fp s + nu) (1 + cos(2 pi fp s/gamma))],  s = t - t0,
// on the same support, 0 outside: v's exact derivative (not a finite
// difference), continuous at the support's ends where both brackets vanish.
double pulse_acceleration(const PulseParameters& p, double t);
// The displacement from rest before the pulse: int v from t0 - gamma/(2 fp) to t,
// by the paper's closed form (gamma != 1), s = t - t0, b = 2 pi fp:
//   F(s) = A/(4 pi fp) [sin(b s + nu) + gamma/(2 (gamma - 1)) sin(b (gamma - 1)/gamma s + nu)
//                       + gamma/(2 (gamma + 1)) sin(b (gamma + 1)/gamma s + nu)],
// D(t) = F(s) - F(-gamma/(2 fp)) on the support, 0 before it, and after it the
// residual displacement F(h) - F(-h) = A cos(nu) sin(pi gamma) / (2 pi fp (1 - gamma^2)), h = gamma/(2 fp).
double pulse_displacement(const PulseParameters& p, double t);
// a(k dt), k = 0 .. n - 1 with n - 1 = floor(duration/dt): the whole pulse
// must lie in [0, duration] (t0 - gamma/(2 fp) >= 0, t0 + gamma/(2 fp) <= duration),
// so that the velocity integrated from rest at t = 0 is the pulse's; and its highest
// frequency fp (1 + 1/gamma) must lie below 1/(2 dt) (SamplingError).
Record pulse_record(const PulseParameters& p, double dt, double duration);

// ---- The stochastic model of Rezaeian & Der Kiureghian (2008, EESD 37) ----

struct StochasticParameters {
    // The gamma modulating function q(t) = alpha1 t^(alpha2 - 1) exp(-alpha3 t), m/s^2.
    double alpha1 = 0;  // m/s^2 per s^(alpha2 - 1)
    double alpha2 = 0;  // in (1, 1e5]: beyond, GSL's gamma inverse fails (check_modulation)
    double alpha3 = 0;  // 1/s
    // The filter: omega_f(tau) = omega_mid + omega_prime (tau - t_mid), damping zeta_f;
    // t_mid is q's 45 % Arias time (arias_time).
    double omega_mid = 0;    // rad/s
    double omega_prime = 0;  // rad/s^2
    double zeta_f = 0;       // in (0, 1)
    // The post-filter's corner: a critically damped oscillator at omega_c.
    double omega_c = 0;  // rad/s
};

// The defaults' physical values: meant to be the sample means of the parameters
// Rezaeian & Der Kiureghian (2010) fitted to NGA far-field records on firm ground
// (PEER 2010/02, pp. 93-94), and the post-filter's corner.  D5-95, t_mid, fmid,
// fprime and zeta_f agree with the means of the fitted marginal distributions
// within 2 %; Ia and fc are unverified.  Each one's source and status:
// docs/synthetic.md ("Parameters and defaults").
struct StochasticDefaults {
    static constexpr double Ia_s_g = 0.0468;          // expected Arias intensity, s g (x 9.81 for m/s)
    static constexpr double D5_95_s = 17.3;           // 5-95 % duration, s
    static constexpr double tmid_s = 12.4;            // 45 % Arias time, s
    static constexpr double fmid_hz = 5.87;           // omega_mid / 2 pi, Hz
    static constexpr double fprime_hz_s = -0.089;     // omega' / 2 pi, Hz/s
    static constexpr double zeta_f = 0.213;           // filter damping
    static constexpr double fc_hz = 0.2;              // post-filter corner omega_c / 2 pi, Hz
};

// StochasticDefaults as model parameters (the alphas through with_arias_modulation).
StochasticParameters default_stochastic_parameters();

// q(t) = alpha1 t^(alpha2 - 1) exp(-alpha3 t) for t >= 0.
double modulating_function(const StochasticParameters& p, double t);
// The time at which the expected Arias intensity, (pi/2g) int_0^t q^2, reaches
// `fraction` of its total: q^2 is a gamma density of shape 2 alpha2 - 1 and rate
// 2 alpha3, so t = P^-1(fraction; 2 alpha2 - 1) / (2 alpha3).  t_mid = arias_time(p, 0.45).
double arias_time(const StochasticParameters& p, double fraction);
// The alphas of the q whose expected Arias intensity is Ia (m/s), whose 5-95 %
// duration is d5_95 (s) and whose 45 % time is t_mid (s): the shape from
// t_mid / d5_95 (a function of the shape alone), then alpha3 from d5_95, then
// alpha1 from Ia = (pi/2g) alpha1^2 Gamma(k) / (2 alpha3)^k, k = 2 alpha2 - 1.
// The filter's fields of `base` are kept.  Refusals name Ia, D5_95 and tmid (the keys
// of stochastic_parameters_from), also when it is a derived alpha that leaves a double's range.
StochasticParameters with_arias_modulation(StochasticParameters base, double Ia, double d5_95, double t_mid);

// The names stochastic_parameters_from takes, as `rocking record synth --params`
// and rocking_q.record_synth(params=...) spell them.
const std::vector<std::string>& stochastic_parameter_names();
// default_stochastic_parameters() with the values given by name replaced: the
// modulation as alpha1, alpha2, alpha3 (all three) or as Ia (m/s), D5_95 (s), tmid (s)
// (those missing from the defaults, through with_arias_modulation); the filter as fmid
// (Hz), fprime (Hz/s), zeta; the post-filter's corner fc (Hz).  Throws
// std::invalid_argument for an unknown name, the alphas mixed with Ia/D5_95/tmid,
// fewer than three alphas, or a value outside its range, naming the key as given (fc,
// not omega_c; tmid, not the alpha1 it gives): one front end's spelling, one set of checks.
StochasticParameters stochastic_parameters_from(const std::map<std::string, double>& values);

// n standard normal numbers: GSL's gsl_rng_mt19937 seeded with `seed`, through
// gsl_ran_gaussian_ziggurat.  seed in [1, 2^32 - 1]: mt19937 reads the low 32 bits
// and takes 0 as its default seed 4357, so other values would repeat a stream.
std::vector<double> white_noise(std::uint64_t seed, std::size_t n);

// The normalized filtered noise at t_k = k dt (the paper's discretized process):
//   nu(t_k) = sum_{i <= k} h(t_k - t_i; tau = t_i) u_i / sqrt(sum_{i <= k} h(t_k - t_i; t_i)^2),
//   h(s; tau) = omega_f(tau)/sqrt(1 - zeta_f^2) exp(-zeta_f omega_f(tau) s) sin(omega_f(tau) sqrt(1 - zeta_f^2) s),
// unit variance at every k >= 1; nu(0) = 0, where every h vanishes.
std::vector<double> filtered_noise(const StochasticParameters& p, const std::vector<double>& u, double dt);

// The high-pass post-filter: the acceleration z'' of the critically damped oscillator
//   z'' + 2 omega_c z' + omega_c^2 z = x(t),  z(0) = z'(0) = 0,
// with x linear between samples (the engine's reading of a record), integrated
// exactly step by step; z''(t_k) = x_k - 2 omega_c z'_k - omega_c^2 z_k.  Stable for
// every omega_c > 0: as omega_c -> 0 the output tends to x (docs/synthetic.md).
std::vector<double> critically_damped_high_pass(const std::vector<double>& x, double dt, double omega_c);

// q(t_k) nu(t_k) for the seed's noise, before the post-filter: n - 1 = floor(duration/dt).
// Refused when alpha1 t^(alpha2 - 1) overflows a double within the record (q could not be
// evaluated as written), naming tmid and D5_95 as well as the alphas.
std::vector<double> modulated_noise(const StochasticParameters& p, std::uint64_t seed, double dt, double duration);

// The record: modulated_noise through critically_damped_high_pass.  Refused
// (SamplingError) when, over the record, the filter's frequency omega_f(t), the upper
// edge of its half-power band or the post-filter's corner omega_c reaches 1/(2 dt).
Record stochastic_record(const StochasticParameters& p, std::uint64_t seed, double dt, double duration);

}  // namespace rocking::records
