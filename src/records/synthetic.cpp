#include "records/synthetic.hpp"
#include "records/synthetic_sampling.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_gamma.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace rocking::records {

namespace synthetic_detail {

// The shortest %g text that reads back as v: the header states each parameter
// exactly, and 0.213 rather than 0.21299999999999999.
std::string text_of(double v) {
    char buf[40];
    for (int digits = 15; digits <= 17; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

[[noreturn]] void refuse(const std::string& name, const std::string& rule, double got) {
    throw std::invalid_argument(name + " must be " + rule + " (got " + text_of(got) + ")");
}

// A derived value in a message (a limit, a count, a ratio): four digits, where text_of
// would write 1/(2 dt) = 24.999999999999996.
std::string short_text(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}


// A frequency at or above 1/(2 dt) is refused: its samples alias it to a lower one (at
// 1/(2 dt) itself a sine is sampled at two phases only, its amplitude lost).  The first
// such frequency is named; the step offered is below 1/(2 f) for the highest f of all.
void refuse_unsampled(const std::vector<Frequency>& frequencies, double dt) {
    const double nyquist = 0.5 / dt;
    double highest = 0;
    for (const Frequency& f : frequencies) highest = std::max(highest, f.hz);
    for (const Frequency& f : frequencies)
        if (!(f.hz < nyquist))
            throw SamplingError(f.name + " = " + short_text(f.hz) + " Hz, " + f.role +
                                    ", is at or above the Nyquist frequency 1/(2 dt) = " + short_text(nyquist) +
                                    " Hz of dt = " + text_of(dt) + " s: " + f.remedy + ", or take dt below " +
                                    short_text(0.5 / highest) + " s",
                                f.parameters);
}

// Below 1/(2 dt) a frequency is represented, but with n = 1/(f dt) samples a period the
// samples of a sine miss its crest by up to 1 - cos(pi/n): the record's PGA, and the
// block's input read linear between samples, fall short of the motion's.  The pulse's
// sampled PGA, measured, falls up to 3.4 % short at n = 10 (docs/synthetic.md, "Sampling").
std::vector<std::string> sampling_warnings(const std::vector<Frequency>& frequencies, double dt) {
    std::vector<std::string> out;
    for (const Frequency& f : frequencies) {
        const double per_period = 1 / (f.hz * dt);
        if (!(per_period < kWarnSamplesPerPeriod)) continue;
        out.push_back(f.name + " = " + short_text(f.hz) + " Hz, " + f.role + ", has " + short_text(per_period) +
                      " samples per period at dt = " + text_of(dt) + " s, fewer than " +
                      short_text(kWarnSamplesPerPeriod) + ": a sine of that frequency so sampled peaks up to " +
                      short_text(100 * (1 - std::cos(M_PI / per_period))) + " % below its crest (take dt at most " +
                      short_text(1 / (kWarnSamplesPerPeriod * f.hz)) + " s)");
    }
    return out;
}

// The header's "warning": the sentences, "; " between them (sampling_warnings writes none
// with "; " inside).
void state_warnings(Record& r, const std::vector<std::string>& warnings) {
    std::string all;
    for (const std::string& w : warnings) all += (all.empty() ? "" : "; ") + w;
    if (!all.empty()) r.header["warning"] = all;
}

// n - 1 = floor(duration/dt): the last sample at or just before `duration`
// (1e-9 of a step forgives duration/dt landing a rounding below an integer).
std::size_t sample_count(double dt, double duration) {
    if (!(dt > 0) || !std::isfinite(dt)) refuse("dt", "> 0 and finite", dt);
    if (!(duration > 0) || !std::isfinite(duration)) refuse("duration", "> 0 and finite", duration);
    const double steps = std::floor(duration / dt + 1e-9);
    if (!(steps + 1 <= static_cast<double>(kMaxSamples)))
        throw std::invalid_argument("duration/dt gives " + text_of(steps + 1) + " samples, more than " +
                                    std::to_string(kMaxSamples));
    if (steps < 3) throw std::invalid_argument("duration/dt gives fewer than 4 samples");
    return static_cast<std::size_t>(steps) + 1;
}

}  // namespace synthetic_detail

using namespace synthetic_detail;

namespace {

void check_pulse(const PulseParameters& p) {
    if (!std::isfinite(p.A) || p.A == 0) refuse("A", "finite and not 0", p.A);
    if (!(p.fp > 0) || !std::isfinite(p.fp)) refuse("fp", "> 0 and finite", p.fp);
    if (!std::isfinite(p.nu)) refuse("nu", "finite", p.nu);
    // gamma = 1 is the paper's limit where the envelope holds a single cycle
    // and the displacement's closed form changes; the issue asks gamma > 1.
    if (!(p.gamma > 1) || !std::isfinite(p.gamma)) refuse("gamma", "> 1 and finite", p.gamma);
    if (!std::isfinite(p.t0)) refuse("t0", "finite", p.t0);
}

double half_width(const PulseParameters& p) { return p.gamma / (2 * p.fp); }

// v = A [cos(b s + nu)/2 + cos((b + c) s + nu)/4 + cos((b - c) s + nu)/4], b = 2 pi fp,
// c = b/gamma: the carrier fp and the sidebands fp -+ fp/gamma that the envelope, of
// frequency fp/gamma, puts around it; a = v' holds the same three.  The highest is
// fp + fp/gamma: the envelope alone (fp/gamma < fp, gamma > 1) never reaches 1/(2 dt)
// before the carrier does, but it widens the carrier's band by its own frequency.  (The
// support's ends, where a' jumps, add a tail falling as 1/f^3 that no step removes.)
Frequency pulse_carrier(const PulseParameters& p) {
    return {"fp", "the pulse's carrier frequency", p.fp, {"fp"}, "lower fp"};
}
Frequency pulse_highest(const PulseParameters& p) {
    return {"fp + fp/gamma",
            "the pulse's highest frequency (the carrier fp = " + text_of(p.fp) +
                " Hz widened by its envelope's frequency fp/gamma = " + short_text(p.fp / p.gamma) + " Hz)",
            p.fp + p.fp / p.gamma,
            {"fp", "gamma"},
            "raise gamma or lower fp"};
}

}  // namespace

std::vector<std::string> warnings_of(const Record& r) {
    std::vector<std::string> out;
    const auto found = r.header.find("warning");
    if (found == r.header.end()) return out;
    const std::string& all = found->second;
    for (std::size_t start = 0;;) {
        const std::size_t end = all.find("; ", start);
        out.push_back(all.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) break;
        start = end + 2;
    }
    return out;
}

namespace {
// cos and sin of x + nu, by the sum's formulas: x + nu rounded to a double loses x's digits
// as |nu| grows (at nu = -1e17, whose ulp is 16 rad, the "pulse" had a PGV of 3 A:
// issue 38), while libm's cos(nu) and sin(nu) are exact for any double nu.
struct Phased {
    double cos, sin;
};
Phased phased(double x, double nu) {
    const double c = std::cos(x), s = std::sin(x), cn = std::cos(nu), sn = std::sin(nu);
    return {c * cn - s * sn, s * cn + c * sn};
}
}  // namespace

double pulse_velocity(const PulseParameters& p, double t) {
    const double s = t - p.t0;
    if (std::fabs(s) > half_width(p)) return 0;
    const double w = 2 * M_PI * p.fp;
    return 0.5 * p.A * (1 + std::cos(w * s / p.gamma)) * phased(w * s, p.nu).cos;
}

double pulse_acceleration(const PulseParameters& p, double t) {
    const double s = t - p.t0;
    if (std::fabs(s) > half_width(p)) return 0;
    const double w = 2 * M_PI * p.fp, envelope = w * s / p.gamma;
    const Phased carrier = phased(w * s, p.nu);
    return -(p.A * M_PI * p.fp / p.gamma) *
           (std::sin(envelope) * carrier.cos + p.gamma * carrier.sin * (1 + std::cos(envelope)));
}

double pulse_displacement(const PulseParameters& p, double t) {
    const double h = half_width(p), s = std::max(-h, std::min(h, t - p.t0));
    if (t - p.t0 < -h) return 0;
    const double b = 2 * M_PI * p.fp, g = p.gamma;
    auto F = [&](double x) {
        return p.A / (4 * M_PI * p.fp) *
               (phased(b * x, p.nu).sin + g / (2 * (g - 1)) * phased(b * (g - 1) / g * x, p.nu).sin +
                g / (2 * (g + 1)) * phased(b * (g + 1) / g * x, p.nu).sin);
    };
    return F(s) - F(-h);
}

Record pulse_record(const PulseParameters& p, double dt, double duration) {
    check_pulse(p);
    const std::size_t n = sample_count(dt, duration);
    refuse_unsampled({pulse_carrier(p), pulse_highest(p)}, dt);
    if (p.t0 - half_width(p) < 0)
        throw std::invalid_argument("t0 must be >= gamma/(2 fp) = " + text_of(half_width(p)) +
                                    " s, so that the pulse starts at or after t = 0 (got " + text_of(p.t0) + ")");
    if (p.t0 + half_width(p) > dt * (n - 1))
        throw std::invalid_argument("the pulse ends at t0 + gamma/(2 fp) = " + text_of(p.t0 + half_width(p)) +
                                    " s, after the record's last sample at " + text_of(dt * (n - 1)) +
                                    " s: lengthen the duration");
    Record r;
    r.format = "synthetic";
    r.path = "(synthetic)";
    r.name = "MP2003 pulse A=" + text_of(p.A) + " fp=" + text_of(p.fp) + " nu=" + text_of(p.nu) +
             " gamma=" + text_of(p.gamma) + " t0=" + text_of(p.t0);
    r.dt = dt;
    r.accel.resize(n);
    for (std::size_t k = 0; k < n; ++k) r.accel[k] = pulse_acceleration(p, dt * k);
    r.header = {{"generator", "Mavroeidis & Papageorgiou (2003) velocity pulse, acceleration its exact derivative"},
                {"A_m_s", text_of(p.A)},
                {"fp_hz", text_of(p.fp)},
                {"Tp_s", text_of(1 / p.fp)},
                {"nu_rad", text_of(p.nu)},
                {"gamma", text_of(p.gamma)},
                {"t0_s", text_of(p.t0)},
                {"dt_s", text_of(dt)},
                {"duration_s", text_of(duration)}};
    state_warnings(r, sampling_warnings({pulse_highest(p)}, dt));
    return r;
}

}  // namespace rocking::records
