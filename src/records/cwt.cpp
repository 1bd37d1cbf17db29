#include "records/cwt.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "records/fft.hpp"

namespace rocking::records {

namespace {

constexpr double kBeta = 27.0, kGamma = 3.0;
// w_p and a_{beta,gamma} of cwt.hpp, written as the single-transform code wrote
// them, so that every Psi value keeps its bits.
const double kWp = std::pow(kBeta / kGamma, 1.0 / kGamma);
const double kABetaGamma = 2.0 * std::exp((kBeta / kGamma) * (1.0 + std::log(kGamma / kBeta)));

// Bins where Psi(s w) is below 1e-30 of its peak (2) are left out: their share of
// W is below 2e-30 max|X| <= 2e-30 N max|x|, far below W's rounding at any N.
constexpr double kPsiFloor = 2e-30;
// |psi(t)| of this wavelet at scale s is 1.4e-12 at |t| = 30 s and 3.2e-21 at
// |t| = 40 s, against its peak of 0.18 (mpmath, 50 digits; beyond, it falls as
// t^-28, from the w^27 at w = 0): a kernel cut at 40 s changes W by less than its
// rounding, whatever the record.
constexpr double kHalfWidthInScales = 40.0;
// A block of 16 half-lengths keeps 7/8 of its outputs; (M / kept) log M is then
// within a few per cent of its minimum over M (8: 3/4 kept; 32: log M one more).
constexpr double kBlockInHalfLengths = 16.0;
constexpr std::size_t kSmallestBlock = 256;

// Psi(s w) of eq. 32, peak 2 at s w = w_p.
double morse(double sw) { return kABetaGamma * std::exp(kBeta * std::log(sw) - std::pow(sw, kGamma)); }

// Psi(s w_k) on the positive bins k = 1..n/2 of an n-point transform of step dt,
// w_k = 2 pi k / (n dt), where it is at least kPsiFloor.  Psi rises to its peak and
// falls after it, so these bins are one run around the peak's bin.
struct Band {
    std::size_t first = 1;    // its first bin
    std::vector<double> psi;  // Psi at bins first, first + 1, ...
};

Band morse_band(double s, std::size_t n, double dt) {
    const std::size_t last = n / 2;
    auto psi = [&](std::size_t k) { return morse(s * (2.0 * M_PI * k / (n * dt))); };
    const double at_peak = kWp / (s * 2.0 * M_PI / (n * dt));
    const std::size_t peak = at_peak < 1 ? 1 : at_peak > last ? last : static_cast<std::size_t>(std::llround(at_peak));
    Band band;
    if (!(psi(peak) >= kPsiFloor)) return band;
    std::size_t lo = peak, hi = peak;
    while (lo > 1 && psi(lo - 1) >= kPsiFloor) --lo;
    while (hi < last && psi(hi + 1) >= kPsiFloor) ++hi;
    band.first = lo;
    for (std::size_t k = lo; k <= hi; ++k) band.psi.push_back(psi(k));
    return band;
}

// The smallest power of two >= n.
std::size_t power_of_two(double n) {
    std::size_t p = 1;
    while (p < n) p <<= 1;
    return p;
}

// FFTs of length m over the record: the outputs [start, start + valid) come from the
// segment [start - lead, start - lead + m), zero outside the record.  One segment of
// the record's padded length with lead 0 is the definition itself.
struct Pass {
    std::size_t m = 0, lead = 0, valid = 0;
    std::size_t first = 0, end = 0;  // its scales
};

// Scales that share a block length share their passes (and each block's forward
// transform); a group's lead is its longest kernel's.
std::vector<Pass> passes_for(const std::vector<double>& scales, std::size_t samples, double dt) {
    std::vector<Pass> passes;
    for (std::size_t j = 0; j < scales.size(); ++j) {
        const std::size_t lead = morse_half_length(scales[j], dt), m = morse_block_length(lead, samples);
        if (passes.empty() || passes.back().m != m) passes.push_back({m, 0, 0, j, j});
        Pass& p = passes.back();
        p.end = j + 1;
        p.lead = std::max(p.lead, lead);
    }
    for (Pass& p : passes) {
        if (p.m == power_of_two(2.0 * samples)) p.lead = 0, p.valid = samples;  // the whole record at once
        else p.valid = p.m - 2 * p.lead;
    }
    return passes;
}

// One scale's max, sum and energy of |W|, summed in the samples' order.
struct Sums {
    double max = 0, sum = 0, energy = 0;
};

void add_outputs(const std::vector<double>& w, std::size_t from, std::size_t count, double dt, Sums& s) {
    double max = s.max, sum = s.sum, energy = s.energy;  // in registers: s might alias w
    for (std::size_t i = from; i < from + count; ++i) {
        const double m = std::sqrt(w[2 * i] * w[2 * i] + w[2 * i + 1] * w[2 * i + 1]);
        max = std::max(max, m);
        sum += m;
        energy += m * m * dt;
    }
    s = {max, sum, energy};
}

void run_pass(const Pass& p, const std::vector<double>& x, double dt, const std::vector<double>& scales,
              std::vector<Sums>& sums) {
    const Fft fft(p.m);
    std::vector<Band> bands;
    for (std::size_t j = p.first; j < p.end; ++j) bands.push_back(morse_band(scales[j], p.m, dt));
    const std::size_t n = x.size();
    std::vector<double> segment(2 * p.m), w(2 * p.m);
    for (std::size_t start = 0; start < n; start += p.valid) {
        std::fill(segment.begin(), segment.end(), 0.0);
        const std::size_t from = start >= p.lead ? 0 : p.lead - start;  // the segment's first sample in the record
        const std::size_t t0 = start + from - p.lead;
        const std::size_t inside = std::min(p.m - from, n - t0);
        for (std::size_t i = 0; i < inside; ++i) segment[2 * (from + i)] = x[t0 + i];
        fft.forward(segment);
        const std::size_t outputs = std::min(p.valid, n - start);
        for (std::size_t b = 0; b < bands.size(); ++b) {
            const Band& band = bands[b];
            if (band.psi.empty()) continue;  // W = 0 at this scale
            std::fill(w.begin(), w.end(), 0.0);
            for (std::size_t i = 0; i < band.psi.size(); ++i) {
                const std::size_t k = band.first + i;
                w[2 * k] = segment[2 * k] * band.psi[i];
                w[2 * k + 1] = segment[2 * k + 1] * band.psi[i];
            }
            fft.inverse(w);
            add_outputs(w, p.lead, outputs, dt, sums[p.first + b]);
        }
    }
}

}  // namespace

std::size_t morse_half_length(double s, double dt) {
    const double half = std::ceil(kHalfWidthInScales * s / dt);
    return half < 0x1p62 ? static_cast<std::size_t>(half) : std::size_t(1) << 62;  // beyond: the whole record anyway
}

std::size_t morse_block_length(std::size_t half_length, std::size_t samples) {
    const std::size_t whole = power_of_two(2.0 * samples);
    const double wanted = kBlockInHalfLengths * static_cast<double>(half_length);
    return wanted >= whole ? whole : std::min(whole, std::max(kSmallestBlock, power_of_two(wanted)));
}

CwtSummary morse_cwt(const std::vector<double>& x, double dt, double f_min, double f_max, int voices) {
    if (x.size() < 4 || !(dt > 0) || !(f_min > 0) || !(f_max > f_min) || voices < 1)
        throw std::invalid_argument("morse_cwt: bad arguments");
    CwtSummary out;
    std::vector<double> scales;
    const int last = static_cast<int>(std::ceil(voices * std::log2(f_max / f_min)));
    for (int j = 0; j <= last; ++j) {
        const double f = f_max * std::pow(2.0, -static_cast<double>(j) / voices);
        out.frequency.push_back(f);
        scales.push_back(kWp / (2.0 * M_PI * f));
    }
    std::vector<Sums> sums(scales.size());
    for (const Pass& p : passes_for(scales, x.size(), dt)) run_pass(p, x, dt, scales, sums);
    for (const Sums& s : sums) {
        out.max_amp.push_back(s.max);
        out.mean_amp.push_back(s.sum / x.size());
        out.energy.push_back(s.energy);
    }
    return out;
}

}  // namespace rocking::records
