// Ground-motion measures of a record (Section 4 of the paper): PGA, PGV, the
// pulse of largest area between zero crossings, and the eleven half-periods
// to_1..to_11.
//
// Conventions (the paper leaves them open; stated here once):
// - acceleration is linear between samples (as the dynamics engine sees it);
//   zero crossings and pulse areas are exact for that interpolation;
// - velocity is the exact integral of that interpolation (trapezoidal), from
//   rest, with no further baseline correction for PGV: ESM records are already
//   baseline-corrected and band-passed (records/README.md); its spectral
//   measures (to_7, to_9, to_11) use it without its least-squares linear trend;
// - Fourier spectra: the FFT of the record zero-padded to a power of two at
//   least 8 times its length (a frequency grid 8 times finer than 1/duration),
//   the peak refined by a parabola through the three highest bins (computed by
//   shorter transforms, measures.cpp);
// - the CWT uses the generalised Morse wavelet (eq. 32), beta = 27, gamma = 3,
//   see cwt.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "records/record.hpp"

namespace rocking::records {

struct Pulse {
    double t_start, t_end;  // zero crossings delimiting it, s
    double area;            // signed integral of a over it, m/s
    double peak;            // largest |a| inside, m/s^2
};

// The pulses of a(t) between successive zero crossings (the first and last
// pulses are delimited by the record's ends).
std::vector<Pulse> pulses_of(const std::vector<double>& a, double dt);
// Velocity samples: v_k = integral_0^{t_k} a (trapezoid = exact for linear a).
std::vector<double> velocity_of(const std::vector<double>& a, double dt);

// PGA = max |a|, PGV = max |v| and the half-period of the equivalent harmonic wave,
// to_5 = pi PGV / PGA (eq. 31): what assess needs, and half_periods' definition of
// the three.  Throws std::invalid_argument for fewer than 4 samples, dt <= 0 or a
// record that is zero throughout.
struct PeakMotion {
    double pga = 0, pgv = 0;  // m/s^2, m/s
    double to5 = 0;           // s
};
PeakMotion peak_motion(const std::vector<double>& a, double dt);

struct HalfPeriods {
    double pga = 0, pgv = 0;         // m/s^2, m/s
    double amax = 0;                 // area of the largest pulse, m/s
    std::array<double, 11> to{};     // to_1..to_11, s (to[0] is to_1)
    double f_fourier_acc = 0, f_fourier_vel = 0;  // Hz
    double f_cwt[4] = {0, 0, 0, 0};  // Hz: to_8, to_9, to_10, to_11
    // A CWT measure largest on the first or last scale of the band scanned: it may
    // grow beyond the band, and its to is then the band's edge, not a peak.
    bool cwt_at_band_edge[4] = {false, false, false, false};  // to_8, to_9, to_10, to_11
    double cwt_band_hz[2] = {0, 0};  // the band scanned: its lowest and highest scales' frequencies
};

// The eleven definitions (Section 4):
//  to_1  duration of the pulse of largest |area| Amax (zero crossing to zero crossing)
//  to_2  duration of the pulse that holds the PGA
//  to_3  pi Amax / (2 PGA)       (eq. 29: the sine of the same PGA and area)
//  to_4  Amax / PGA              (eq. 30: the constant of the same PGA and area)
//  to_5  pi PGV / PGA            (eq. 31)
//  to_6  1/(2 f) at the peak of the Fourier amplitude spectrum of acceleration
//  to_7  the same for velocity
//  to_8  1/(2 f) at the largest CWT amplitude of acceleration
//  to_9  1/(2 f) at the largest time-mean CWT amplitude of velocity
//  to_10 1/(2 f) at the largest CWT energy (sum over time of |W|^2) of acceleration
//  to_11 the same for velocity
HalfPeriods half_periods(const std::vector<double>& a, double dt);
inline HalfPeriods half_periods(const Record& r) { return half_periods(r.accel, r.dt); }

// Peak frequency (Hz) of the Fourier amplitude spectrum of x sampled at dt, made
// by transforms of at most largest_transform points (a power of two; the spectrum
// does not depend on it, its memory does: 48 bytes a point).
double fourier_peak(const std::vector<double>& x, double dt, std::size_t largest_transform = std::size_t(1) << 20);

// The frequency of the largest of `values` over the CWT's scales, refined by a
// parabola in log-frequency through it and its two neighbours; at_edge when it is
// on the first or last scale, which has no neighbour beyond.
struct ScalePeak {
    double f = 0;  // Hz
    bool at_edge = false;
};
ScalePeak scale_peak(const std::vector<double>& frequency, const std::vector<double>& values);

}  // namespace rocking::records
