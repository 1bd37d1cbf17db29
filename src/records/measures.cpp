#include "records/measures.hpp"

#include <gsl/gsl_fft_complex.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "records/cwt.hpp"

namespace rocking::records {

std::vector<Pulse> pulses_of(const std::vector<double>& a, double dt) {
    std::vector<Pulse> out;
    if (a.size() < 2) return out;
    Pulse current{0.0, 0.0, 0.0, std::fabs(a[0])};
    auto close = [&](double t) {
        current.t_end = t;
        if (current.t_end > current.t_start && (current.area != 0.0 || current.peak != 0.0)) out.push_back(current);
        current = Pulse{t, t, 0.0, 0.0};
    };
    for (std::size_t k = 0; k + 1 < a.size(); ++k) {
        const double a0 = a[k], a1 = a[k + 1], t0 = dt * k;
        current.peak = std::max(current.peak, std::fabs(a0));
        if ((a0 > 0 && a1 < 0) || (a0 < 0 && a1 > 0)) {
            const double tau = dt * a0 / (a0 - a1);  // the zero of the linear piece
            current.area += 0.5 * a0 * tau;
            close(t0 + tau);
            current.area += 0.5 * a1 * (dt - tau);
        } else {
            if (a0 == 0.0 && a1 != 0.0) close(t0);  // a stretch of exact zeros ends: a new pulse starts
            current.area += 0.5 * (a0 + a1) * dt;
            if (a1 == 0.0 && a0 != 0.0) {
                current.peak = std::max(current.peak, std::fabs(a1));
                close(t0 + dt);
            }
        }
    }
    current.peak = std::max(current.peak, std::fabs(a.back()));
    close(dt * (a.size() - 1));
    return out;
}

std::vector<double> velocity_of(const std::vector<double>& a, double dt) {
    std::vector<double> v(a.size(), 0.0);
    for (std::size_t k = 1; k < a.size(); ++k) v[k] = v[k - 1] + 0.5 * (a[k - 1] + a[k]) * dt;
    return v;
}

double fourier_peak(const std::vector<double>& x, double dt) {
    std::size_t n = 1;
    while (n < 8 * x.size()) n <<= 1;
    std::vector<double> X(2 * n, 0.0);
    for (std::size_t k = 0; k < x.size(); ++k) X[2 * k] = x[k];
    gsl_fft_complex_wavetable* table = gsl_fft_complex_wavetable_alloc(n);
    gsl_fft_complex_workspace* work = gsl_fft_complex_workspace_alloc(n);
    gsl_fft_complex_forward(X.data(), 1, n, table, work);
    gsl_fft_complex_workspace_free(work);
    gsl_fft_complex_wavetable_free(table);
    std::vector<double> amp(n / 2 + 1);
    for (std::size_t k = 0; k <= n / 2; ++k) amp[k] = std::hypot(X[2 * k], X[2 * k + 1]);
    std::size_t best = 1;
    for (std::size_t k = 1; k < n / 2; ++k)
        if (amp[k] > amp[best]) best = k;
    double shift = 0.0;  // parabola through the three highest bins
    if (best > 1 && best + 1 <= n / 2) {
        const double ym = amp[best - 1], y0 = amp[best], yp = amp[best + 1];
        const double den = ym - 2 * y0 + yp;
        if (den < 0) shift = 0.5 * (ym - yp) / den;
    }
    return (best + shift) / (n * dt);
}

HalfPeriods half_periods(const std::vector<double>& a, double dt) {
    if (a.size() < 4 || !(dt > 0)) throw std::invalid_argument("half_periods: a record needs >= 4 samples and dt > 0");
    HalfPeriods h;
    for (double v : a) h.pga = std::max(h.pga, std::fabs(v));
    if (!(h.pga > 0)) throw std::invalid_argument("half_periods: the record is identically zero");
    const std::vector<double> v = velocity_of(a, dt);
    for (double x : v) h.pgv = std::max(h.pgv, std::fabs(x));
    const std::vector<Pulse> pulses = pulses_of(a, dt);
    const Pulse* largest = &pulses.front();
    const Pulse* with_pga = &pulses.front();
    for (const Pulse& p : pulses) {
        if (std::fabs(p.area) > std::fabs(largest->area)) largest = &p;
        if (p.peak > with_pga->peak) with_pga = &p;
    }
    h.amax = std::fabs(largest->area);
    h.to[0] = largest->t_end - largest->t_start;
    h.to[1] = with_pga->t_end - with_pga->t_start;
    h.to[2] = M_PI * h.amax / (2.0 * h.pga);
    h.to[3] = h.amax / h.pga;
    h.to[4] = M_PI * h.pgv / h.pga;
    // Spectral measures of velocity use it without its least-squares linear
    // trend (an integration offset would otherwise put the peak at 0 Hz).
    std::vector<double> vd = v;
    {
        const double n = static_cast<double>(v.size());
        double st = 0, sv = 0, stt = 0, stv = 0;
        for (std::size_t k = 0; k < v.size(); ++k) st += k, sv += v[k], stt += double(k) * k, stv += double(k) * v[k];
        const double slope = (n * stv - st * sv) / (n * stt - st * st), icpt = (sv - slope * st) / n;
        for (std::size_t k = 0; k < v.size(); ++k) vd[k] = v[k] - (icpt + slope * k);
    }
    h.f_fourier_acc = fourier_peak(a, dt);
    h.f_fourier_vel = fourier_peak(vd, dt);
    h.to[5] = 1.0 / (2.0 * h.f_fourier_acc);
    h.to[6] = 1.0 / (2.0 * h.f_fourier_vel);
    const double f_max = std::min(25.0, 0.25 / dt), f_min = 0.1;
    const CwtSummary ca = morse_cwt(a, dt, f_min, f_max, 16), cv = morse_cwt(vd, dt, f_min, f_max, 16);
    // The peak scale, refined by a parabola in log-frequency through the
    // three highest values (the grid is geometric, 16 voices per octave).
    auto peak_frequency = [](const CwtSummary& c, const std::vector<double>& values) {
        const std::size_t j = static_cast<std::size_t>(std::max_element(values.begin(), values.end()) - values.begin());
        double lf = std::log(c.frequency[j]);
        if (j > 0 && j + 1 < values.size()) {
            const double ym = values[j - 1], y0 = values[j], yp = values[j + 1], den = ym - 2 * y0 + yp;
            const double step = std::log(c.frequency[j - 1]) - lf;  // log-frequency falls with j
            if (den < 0) lf -= step * 0.5 * (ym - yp) / den;
        }
        return std::exp(lf);
    };
    h.f_cwt[0] = peak_frequency(ca, ca.max_amp);
    h.f_cwt[1] = peak_frequency(cv, cv.mean_amp);
    h.f_cwt[2] = peak_frequency(ca, ca.energy);
    h.f_cwt[3] = peak_frequency(cv, cv.energy);
    for (int k = 0; k < 4; ++k) h.to[7 + k] = 1.0 / (2.0 * h.f_cwt[k]);
    return h;
}

}  // namespace rocking::records
