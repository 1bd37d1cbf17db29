#include "records/cwt.hpp"

#include <gsl/gsl_fft_complex.h>

#include <cmath>
#include <stdexcept>

namespace rocking::records {

namespace {
// In-place complex FFT (forward sign -1) with GSL's mixed-radix routines.
void fft(std::vector<double>& data, bool inverse) {
    const std::size_t n = data.size() / 2;
    gsl_fft_complex_wavetable* table = gsl_fft_complex_wavetable_alloc(n);
    gsl_fft_complex_workspace* work = gsl_fft_complex_workspace_alloc(n);
    if (inverse) gsl_fft_complex_inverse(data.data(), 1, n, table, work);
    else gsl_fft_complex_forward(data.data(), 1, n, table, work);
    gsl_fft_complex_workspace_free(work);
    gsl_fft_complex_wavetable_free(table);
}
}  // namespace

CwtSummary morse_cwt(const std::vector<double>& x, double dt, double f_min, double f_max, int voices, double beta,
                     double gamma) {
    if (x.size() < 4 || !(dt > 0) || !(f_min > 0) || !(f_max > f_min) || voices < 1)
        throw std::invalid_argument("morse_cwt: bad arguments");
    // Zero padding to a power of two at least twice the length: no wrap-around
    // between the record's ends, and an FFT of cost n log n for any length.
    std::size_t n = 1;
    while (n < 2 * x.size()) n <<= 1;
    std::vector<double> X(2 * n, 0.0);
    for (std::size_t k = 0; k < x.size(); ++k) X[2 * k] = x[k];
    fft(X, false);
    const double wp = std::pow(beta / gamma, 1.0 / gamma);
    const double a_bg = 2.0 * std::exp((beta / gamma) * (1.0 + std::log(gamma / beta)));
    CwtSummary out;
    const int octaves_voices = static_cast<int>(std::ceil(voices * std::log2(f_max / f_min)));
    std::vector<double> W(2 * n);
    for (int j = 0; j <= octaves_voices; ++j) {
        const double f = f_max * std::pow(2.0, -static_cast<double>(j) / voices);
        const double s = wp / (2.0 * M_PI * f);  // scale, s
        for (std::size_t k = 0; k < n; ++k) {
            // angular frequency of bin k (positive frequencies only: analytic wavelet)
            const double w = (k <= n / 2) ? 2.0 * M_PI * k / (n * dt) : -1.0;
            double psi = 0.0;
            if (w > 0) {
                const double sw = s * w;
                psi = a_bg * std::exp(beta * std::log(sw) - std::pow(sw, gamma));
            }
            W[2 * k] = X[2 * k] * psi;
            W[2 * k + 1] = X[2 * k + 1] * psi;
        }
        fft(W, true);
        double mx = 0, sum = 0, energy = 0;
        for (std::size_t k = 0; k < x.size(); ++k) {
            // the analytic signal: |W| of a sinusoid A cos(wt) at its scale is A
            const double m = std::hypot(W[2 * k], W[2 * k + 1]);
            mx = std::max(mx, m);
            sum += m;
            energy += m * m * dt;
        }
        out.frequency.push_back(f);
        out.max_amp.push_back(mx);
        out.mean_amp.push_back(sum / x.size());
        out.energy.push_back(energy);
    }
    return out;
}

}  // namespace rocking::records
