// The continuous wavelet transform with the generalised Morse wavelet (eq. 32):
//     Psi(w) = U(w) a_{beta,gamma} w^beta exp(-w^gamma),  beta = 27, gamma = 3,
// a_{beta,gamma} = 2 (e gamma / beta)^{beta/gamma}, so that its peak is 2 at the
// peak frequency w_p = (beta/gamma)^{1/gamma} (the L1 normalisation of
// MATLAB's cwt, where a sinusoid of amplitude A shows |W| = A at its own scale).
//
// The definition: the record zero-padded to a power of two n at least twice its
// length (no wrap-around between its ends; edges: zero padding; the cone of
// influence is not removed), W(s, t) = IFFT_n[X(w) Psi(s w)] for each scale s, and
// per scale the max, mean and energy of |W| over the record's samples.  Scales:
// geometric, `voices` per octave, for frequencies from f_max down to f_min (Hz);
// the frequency of scale s is w_p / (2 pi s).
//
// Computed scale by scale, never holding the scalogram.  Where the wavelet is
// much shorter than the record, W is made by overlap-save blocks of M < n samples
// (cwt.cpp): the same W to rounding, at a cost of N log M per scale and memory
// O(M); otherwise by the n-point transform itself.
#pragma once

#include <cstddef>
#include <vector>

namespace rocking::records {

struct CwtSummary {
    std::vector<double> frequency;  // Hz, one per scale, decreasing
    std::vector<double> max_amp;    // max over time of |W|
    std::vector<double> mean_amp;   // mean over time of |W|
    std::vector<double> energy;     // sum over time of |W|^2 dt
};

// |W|^2 is summed as it is: give x of order 1 (half_periods divides the record by
// a power of two near its PGA, which changes no bit of the half-periods).
CwtSummary morse_cwt(const std::vector<double>& x, double dt, double f_min, double f_max, int voices = 32);

// The kernel's half-length in samples at scale s (s / dt samples per unit of s), and
// the length M of the blocks that cover a record of n samples at that scale (n
// itself, zero-padded, when blocks would be no shorter): exposed for the tests.
std::size_t morse_half_length(double s, double dt);
std::size_t morse_block_length(std::size_t half_length, std::size_t samples);

}  // namespace rocking::records
