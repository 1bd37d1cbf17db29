#include "records/floor_motion.hpp"

#include <cmath>
#include <complex>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "numerics/number_text.hpp"
#include "records/synthetic.hpp"
#include "records/synthetic_sampling.hpp"

namespace rocking::records {

namespace {

using synthetic_detail::short_text;
using synthetic_detail::text_of;

[[noreturn]] void refuse(const std::string& parameter, const std::string& rule, double got) {
    throw FloorModelError(parameter + " must be " + rule + " (got " + text_of(got) + ")", parameter);
}

// The input's weights over one step, for a step's input linear from f_k to f_(k+1):
// int_0^dt e^(lambda (dt - s)) f(s) ds = dt [f_k W0(z) + f_(k+1) W1(z)], z = lambda dt, with
// W0(z) = int_0^1 e^(z s) s ds and W1(z) = int_0^1 e^(z s) (1 - s) ds.
struct StepWeights {
    std::complex<double> start, end;  // W0, W1
};

// |z| = w dt < pi, as T1 > 2 dt (check_floor_model).
StepWeights step_weights(std::complex<double> z) {
    if (std::abs(z) < 1) {
        // W1 = sum z^k/(k + 2)!, W0 = sum (k + 1) z^k/(k + 2)!: the closed forms below would
        // subtract 1 + z from e^z; 22 terms leave out at most 22/23! ~ 1e-21.
        std::complex<double> term = 0.5, start = 0, end = 0;
        for (int k = 0; k < 22; ++k) {
            start += static_cast<double>(k + 1) * term;
            end += term;
            term *= z / static_cast<double>(k + 3);
        }
        return {start, end};
    }
    // e^z - 1 with expm1 and cos y - 1 = -2 sin^2(y/2): no cancellation for any z.
    const double x = z.real(), y = z.imag(), half = std::sin(y / 2);
    const std::complex<double> em1(std::expm1(x) * std::cos(y) - 2 * half * half, std::exp(x) * std::sin(y));
    const std::complex<double> phi1 = em1 / z, phi2 = (phi1 - 1.0) / z;  // (e^z - 1)/z, (e^z - 1 - z)/z^2
    return {phi1 - phi2, phi2};
}

void check_samples(const std::vector<double>& a_g, double dt) {
    if (!(dt > 0) || !std::isfinite(dt)) throw std::invalid_argument("dt must be > 0 and finite (got " + text_of(dt) + ")");
    if (a_g.empty()) throw std::invalid_argument("the ground record has no samples");
    for (std::size_t k = 0; k < a_g.size(); ++k)
        if (!std::isfinite(a_g[k]))
            throw std::invalid_argument("the ground record's sample " + std::to_string(k) + " is not finite");
}

}  // namespace

void check_floor_model(const FloorModel& m) {
    if (!(m.T1 > 0) || !std::isfinite(m.T1)) refuse("T1", "> 0 and finite, in s", m.T1);
    if (!(m.zeta >= 0 && m.zeta < 1)) refuse("zeta", "in [0, 1): an oscillator below critical damping", m.zeta);
    if (!std::isfinite(m.G)) refuse("G", "finite", m.G);
    // The arithmetic holds beyond these, but no building's first mode does:
    // T1 = 1e308 s gave a floor of (1 - G) times the ground without a word,
    // G = 1e30 a margin of -2.6e35 %.  The tallest towers' first periods are
    // below 10 s; Gamma phi at a roof is about 1.2-1.6 (shear to bending).
    if (!(m.T1 <= 20)) refuse("T1", "at most 20 s: no building's first period is longer", m.T1);
    if (!(std::fabs(m.G) <= 5)) refuse("G", "in [-5, 5]: a first mode's Gamma phi is about 1.2-1.6 at a roof", m.G);
}

void check_floor_model(const FloorModel& m, double dt) {
    check_floor_model(m);
    if (!(dt > 0) || !std::isfinite(dt)) throw std::invalid_argument("dt must be > 0 and finite (got " + text_of(dt) + ")");
    if (!(m.T1 > 2 * dt))
        throw FloorModelError("T1 = " + text_of(m.T1) + " s is at most 2 dt = " + text_of(2 * dt) +
                                  " s: the building's frequency 1/T1 = " + short_text(1 / m.T1) +
                                  " Hz lies at or above the record's Nyquist frequency 1/(2 dt) = " +
                                  short_text(0.5 / dt) + " Hz (dt = " + text_of(dt) +
                                  " s), where the record holds no ground motion and a floor record sampled at dt "
                                  "cannot hold the resonance; so stiff a building's floor moves with the ground "
                                  "(use the ground record)",
                              "T1");
}

FloorModel parse_floor_model(const std::string& text) {
    const std::string where = "floor model '" + text + "': ";
    std::vector<std::string> pieces(1);
    for (char c : text) {
        if (c == ',') pieces.emplace_back();
        else pieces.back() += c;
    }
    if (pieces.size() != 2 && pieces.size() != 3)
        throw std::invalid_argument(where + "takes T1,G[,zeta] (s, -, -), got " + std::to_string(pieces.size()) +
                                    " values");
    static const char* names[] = {"T1", "G", "zeta"};
    double v[3] = {0, 0, FloorModel{}.zeta};
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        try {
            v[i] = numerics::parameter_number(pieces[i]);
        } catch (const std::invalid_argument& e) {
            throw FloorModelError(where + names[i] + ": " + e.what(), names[i]);
        }
    }
    const FloorModel m{v[0], v[1], v[2]};
    try {
        check_floor_model(m);
    } catch (const FloorModelError& e) {
        throw FloorModelError(where + e.what(), e.parameter);
    }
    return m;
}

OscillatorStep oscillator_step(double T1, double zeta, double dt) {
    const double w = 2 * M_PI / T1, wd = w * std::sqrt((1 - zeta) * (1 + zeta)), sw = zeta * w;
    // The free motion: D = D_k g(t) + D'_k h(t), h the impulse response e^(-zeta w t) sin(w_d t)/w_d,
    // g = h' + 2 zeta w h; D' = -w^2 h D_k + h' D'_k (g' = -w^2 h by the equation of motion).
    const double decay = std::exp(-sw * dt);
    const double h = decay * std::sin(wd * dt) / wd, hp = decay * std::cos(wd * dt) - sw * h;
    OscillatorStep s{};
    s.A[0][0] = hp + 2 * sw * h;
    s.A[0][1] = h;
    s.A[1][0] = -w * w * h;
    s.A[1][1] = hp;
    // The forced motion from rest under f = -a_g: D = Im(P)/w_d, D' = Im(lambda P)/w_d =
    // Re(P) - zeta w Im(P)/w_d, with P = int_0^dt e^(lambda (dt - s)) f(s) ds (step_weights).
    const StepWeights W = step_weights({-sw * dt, wd * dt});
    const std::complex<double> weight[2] = {W.start, W.end};
    for (int j = 0; j < 2; ++j) {
        const double im = weight[j].imag() / wd;
        s.B[0][j] = -dt * im;
        s.B[1][j] = -dt * (weight[j].real() - sw * im);
    }
    return s;
}

OscillatorResponse oscillator_response(const std::vector<double>& a_g, double dt, double T1, double zeta) {
    check_floor_model({T1, 0, zeta}, dt);
    check_samples(a_g, dt);
    const std::vector<double>& a = a_g;
    const OscillatorStep s = oscillator_step(T1, zeta, dt);
    OscillatorResponse r;
    r.D.assign(a.size(), 0.0);
    r.V.assign(a.size(), 0.0);
    for (std::size_t k = 0; k + 1 < a.size(); ++k) {
        const double D = r.D[k], V = r.V[k];
        r.D[k + 1] = s.A[0][0] * D + s.A[0][1] * V + s.B[0][0] * a[k] + s.B[0][1] * a[k + 1];
        r.V[k + 1] = s.A[1][0] * D + s.A[1][1] * V + s.B[1][0] * a[k] + s.B[1][1] * a[k + 1];
    }
    return r;
}

FloorResponse floor_response(const std::vector<double>& a_g, double dt, const FloorModel& m) {
    check_floor_model(m, dt);
    const OscillatorResponse o = oscillator_response(a_g, dt, m.T1, m.zeta);
    const double w = 2 * M_PI / m.T1, wd = w * std::sqrt((1 - m.zeta) * (1 + m.zeta));
    FloorResponse f;
    f.accel.resize(a_g.size());
    for (std::size_t k = 0; k < a_g.size(); ++k) {
        const double a1 = -(2 * m.zeta * w * o.V[k] + w * w * o.D[k]);
        f.accel[k] = (1 - m.G) * a_g[k] + m.G * a1;
        if (!std::isfinite(f.accel[k]))
            throw std::overflow_error("the floor's acceleration at sample " + std::to_string(k) + " (t = " +
                                      text_of(dt * k) + " s) overflows a double: scale the record down");
    }
    const double D = o.D.back(), V = o.V.back();
    f.end_amplitude = std::fabs(m.G) * w * w * std::hypot(D, (V + m.zeta * w * D) / wd);
    return f;
}

std::string describe(const FloorModel& m) {
    return "first-mode oscillator T1 = " + text_of(m.T1) + " s, zeta = " + text_of(m.zeta) +
           ", G = Gamma phi = " + text_of(m.G) + "; a_f = a_g + G D''";
}

Record floor_record(const Record& ground, const FloorModel& m) {
    FloorResponse f = floor_response(ground.accel, ground.dt, m);
    Record r;
    r.path = ground.path;
    r.format = "floor motion";
    r.name = ground.name + ", floor T1=" + text_of(m.T1) + " s zeta=" + text_of(m.zeta) + " G=" + text_of(m.G);
    r.dt = ground.dt;
    r.accel = std::move(f.accel);
    r.header = {{"model", "first-mode oscillator, floor absolute acceleration a_f = a_g + G D'' = (1 - G) a_g + G a_1"},
                {"method", "Nigam & Jennings (1969), exact for the ground record read linear between samples"},
                {"T1_s", text_of(m.T1)},
                {"zeta", text_of(m.zeta)},
                {"G", text_of(m.G)},
                {"ground_name", ground.name},
                {"ground_path", ground.path},
                {"ground_format", ground.format},
                {"dt_s", text_of(ground.dt)},
                {"end_amplitude_m_s2", text_of(f.end_amplitude)}};
    const double per_period = m.T1 / ground.dt;
    if (per_period < kWarnSamplesPerPeriod)
        r.header["warning"] = "T1 = " + text_of(m.T1) + " s has " + short_text(per_period) +
                              " samples per period at dt = " + text_of(ground.dt) + " s, fewer than " +
                              short_text(kWarnSamplesPerPeriod) +
                              ": the floor's resonant motion at 1/T1, sampled at dt, peaks up to " +
                              short_text(100 * (1 - std::cos(M_PI / per_period))) + " % below its crest";
    return r;
}

std::string describe_as_input(const FloorModel& m) {
    return "every record replaced by its floor's motion, " + describe(m) + ": q = PGA/(alpha g) and to_k are the floor's";
}

}  // namespace rocking::records
