#include "records/measures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "records/cwt.hpp"
#include "records/fft.hpp"

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

// The amplitude spectrum on the grid k / (n dt), n the power of two >= 8 N (the
// record zero-padded to 8 times its length), by P = n / L transforms of L points,
// L = min(n / 8, largest): bin k = P q + r is bin q of the L-point transform of
// y_u = sum over t = u mod L of x_t e^{-2 pi i r t / n}.  About the n log n
// operations of one transform of n points, in 48 L bytes (50 MB at L = 2^20) where
// that transform and its tables held 48 n (6.4 GB for 10^7 samples).
namespace {
class PaddedSpectrum {
public:
    PaddedSpectrum(const std::vector<double>& x, std::size_t largest)
        : x_(x), n_(8 * power_of_two(x.size())), l_(std::min(n_ / 8, largest)), fft_(l_), z_(2 * l_) {}

    std::size_t padded() const { return n_; }
    std::size_t passes() const { return n_ / l_; }
    std::size_t points() const { return l_; }
    // Bins P q + r, q = 0..L - 1, of the padded transform: amplitude(q) afterwards.
    void residue(std::size_t r) {
        if (r == r_) return;
        std::fill(z_.begin(), z_.end(), 0.0);
        // e^{-2 pi i r t / n} as e^{-2 pi i r 64 b / n} e^{-2 pi i r j / n}, t = 64 b + j:
        // two sines and cosines per 64 samples, each phase reduced exactly mod n.
        auto unit = [&](std::uint64_t m) {
            const double phase = 2.0 * M_PI * static_cast<double>(m % n_) / static_cast<double>(n_);
            return std::pair{std::cos(phase), -std::sin(phase)};
        };
        std::array<std::pair<double, double>, 64> within;
        for (std::size_t j = 0; j < 64; ++j) within[j] = unit(static_cast<std::uint64_t>(r) * j);
        for (std::size_t b = 0; 64 * b < x_.size(); ++b) {
            const auto [cb, sb] = unit(static_cast<std::uint64_t>(r) * 64 * b);
            for (std::size_t j = 0, t = 64 * b; j < 64 && t < x_.size(); ++j, ++t) {
                const auto [cj, sj] = within[j];
                const std::size_t u = t % l_;
                z_[2 * u] += x_[t] * (cb * cj - sb * sj);
                z_[2 * u + 1] += x_[t] * (cb * sj + sb * cj);
            }
        }
        fft_.forward(z_);
        r_ = r;
    }
    double amplitude(std::size_t q) const { return std::hypot(z_[2 * q], z_[2 * q + 1]); }
    double amplitude_at_bin(std::size_t k) {
        residue(k % passes());
        return amplitude(k / passes());
    }

private:
    static std::size_t power_of_two(std::size_t n) {
        std::size_t p = 1;
        while (p < n) p <<= 1;
        return p;
    }
    const std::vector<double>& x_;
    std::size_t n_, l_;
    Fft fft_;
    std::vector<double> z_;
    std::size_t r_ = SIZE_MAX;  // none yet
};
}  // namespace

double fourier_peak(const std::vector<double>& x, double dt, std::size_t largest_transform) {
    if (largest_transform < 1 || (largest_transform & (largest_transform - 1)))
        throw std::invalid_argument("fourier_peak: largest_transform must be a power of two");
    PaddedSpectrum spectrum(x, largest_transform);
    const std::size_t n = spectrum.padded(), passes = spectrum.passes();
    // The largest amplitude over bins 1..n/2 - 1, the lowest bin among equals.
    std::size_t best = 1;
    double best_amp = -1;
    for (std::size_t r = 0; r < passes; ++r) {
        spectrum.residue(r);
        for (std::size_t q = 0; q < spectrum.points(); ++q) {
            const std::size_t k = passes * q + r;
            if (k < 1 || k >= n / 2) continue;
            const double amp = spectrum.amplitude(q);
            if (amp > best_amp || (amp == best_amp && k < best)) best = k, best_amp = amp;
        }
    }
    double shift = 0.0;  // parabola through the three highest bins
    if (best > 1) {
        const double ym = spectrum.amplitude_at_bin(best - 1), y0 = best_amp, yp = spectrum.amplitude_at_bin(best + 1);
        const double den = ym - 2 * y0 + yp;
        if (den < 0) shift = 0.5 * (ym - yp) / den;
    }
    return (best + shift) / (n * dt);
}

ScalePeak scale_peak(const std::vector<double>& frequency, const std::vector<double>& values) {
    const std::size_t j = static_cast<std::size_t>(std::max_element(values.begin(), values.end()) - values.begin());
    double lf = std::log(frequency[j]);
    if (j > 0 && j + 1 < values.size()) {
        const double ym = values[j - 1], y0 = values[j], yp = values[j + 1], den = ym - 2 * y0 + yp;
        const double step = std::log(frequency[j - 1]) - lf;  // log-frequency falls with j
        if (den < 0) lf -= step * 0.5 * (ym - yp) / den;
    }
    return {std::exp(lf), j == 0 || j + 1 == values.size()};
}

PeakMotion peak_motion(const std::vector<double>& a, double dt) {
    if (a.size() < 4 || !(dt > 0)) throw std::invalid_argument("half_periods: a record needs >= 4 samples and dt > 0");
    PeakMotion m;
    for (double v : a) m.pga = std::max(m.pga, std::fabs(v));
    if (!(m.pga > 0)) throw std::invalid_argument("half_periods: the record is identically zero");
    for (double v : velocity_of(a, dt)) m.pgv = std::max(m.pgv, std::fabs(v));
    m.to5 = M_PI * m.pgv / m.pga;
    return m;
}

namespace {
// v less its least-squares line through (k, v_k): an integration offset would
// otherwise put the velocity's spectral peaks at 0 Hz.
std::vector<double> without_trend(const std::vector<double>& v) {
    const double n = static_cast<double>(v.size());
    double st = 0, sv = 0, stt = 0, stv = 0;
    for (std::size_t k = 0; k < v.size(); ++k) st += k, sv += v[k], stt += double(k) * k, stv += double(k) * v[k];
    const double slope = (n * stv - st * sv) / (n * stt - st * st), icpt = (sv - slope * st) / n;
    std::vector<double> vd(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) vd[k] = v[k] - (icpt + slope * k);
    return vd;
}
}  // namespace

HalfPeriods half_periods(const std::vector<double>& a, double dt) {
    const PeakMotion motion = peak_motion(a, dt);
    HalfPeriods h;
    h.pga = motion.pga;
    h.pgv = motion.pgv;
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
    h.to[4] = motion.to5;
    // The spectral peaks do not depend on the record's scale, and dividing by a power
    // of two changes no bit of them; near the PGA, |W|^2 stays in range for a
    // record near the largest double.
    const double unit = std::ldexp(1.0, std::ilogb(h.pga));
    std::vector<double> an(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) an[k] = a[k] / unit;
    const std::vector<double> vd = without_trend(velocity_of(an, dt));
    h.f_fourier_acc = fourier_peak(an, dt);
    h.f_fourier_vel = fourier_peak(vd, dt);
    h.to[5] = 1.0 / (2.0 * h.f_fourier_acc);
    h.to[6] = 1.0 / (2.0 * h.f_fourier_vel);
    const double f_max = std::min(25.0, 0.25 / dt), f_min = 0.1;
    if (!(f_max > f_min))
        throw std::invalid_argument("half_periods: a sampling step of 2.5 s or more leaves the CWT no band (0.1 Hz to 0.25/dt)");
    const CwtSummary ca = morse_cwt(an, dt, f_min, f_max, 16), cv = morse_cwt(vd, dt, f_min, f_max, 16);
    const ScalePeak peaks[4] = {scale_peak(ca.frequency, ca.max_amp), scale_peak(cv.frequency, cv.mean_amp),
                                scale_peak(ca.frequency, ca.energy), scale_peak(cv.frequency, cv.energy)};
    for (int k = 0; k < 4; ++k) {
        h.f_cwt[k] = peaks[k].f;
        h.cwt_at_band_edge[k] = peaks[k].at_edge;
        h.to[7 + k] = 1.0 / (2.0 * h.f_cwt[k]);
    }
    h.cwt_band_hz[0] = ca.frequency.back();
    h.cwt_band_hz[1] = ca.frequency.front();
    return h;
}

}  // namespace rocking::records
