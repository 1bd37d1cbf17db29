// The continuous wavelet transform with the generalised Morse wavelet (eq. 32):
//     Psi(w) = U(w) a_{beta,gamma} w^beta exp(-w^gamma),  beta = 27, gamma = 3,
// a_{beta,gamma} = 2 (e gamma / beta)^{beta/gamma}, so that its peak is 2 at the
// peak frequency w_p = (beta/gamma)^{1/gamma} (the L1 normalisation of
// MATLAB's cwt, where a sinusoid of amplitude A shows |W| = A at its own scale).
//
// Computed with FFTs (GSL, deterministic): the signal is padded with zeros to a
// power of two at least twice its length (edges: zero padding; the cone of influence
// is not removed), W(s, t) = IFFT[X(w) Psi(s w)] for each scale s.  Scales:
// geometric, `voices` per octave, for frequencies from f_min to f_max (Hz);
// the frequency of scale s is w_p / (2 pi s).
#pragma once

#include <vector>

namespace rocking::records {

struct CwtSummary {
    std::vector<double> frequency;  // Hz, one per scale, decreasing
    std::vector<double> max_amp;    // max over time of |W|
    std::vector<double> mean_amp;   // mean over time of |W|
    std::vector<double> energy;     // sum over time of |W|^2 dt
};

CwtSummary morse_cwt(const std::vector<double>& x, double dt, double f_min, double f_max, int voices = 32,
                     double beta = 27.0, double gamma = 3.0);

}  // namespace rocking::records
