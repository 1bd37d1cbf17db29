// The stochastic generator of synthetic.hpp: Rezaeian & Der Kiureghian's
// modulated, filtered white noise (docs/synthetic.md); the pulse is in synthetic.cpp.
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

using namespace synthetic_detail;

namespace {
// The largest alpha2 taken (check_modulation): 1e5, shape 2 alpha2 - 1 = 199,999.
constexpr double kMaxAlpha2 = 1e5;
}  // namespace


StochasticParameters default_stochastic_parameters() {
    using D = StochasticDefaults;
    StochasticParameters p;
    p.omega_mid = 2 * M_PI * D::fmid_hz;
    p.omega_prime = 2 * M_PI * D::fprime_hz_s;
    p.zeta_f = D::zeta_f;
    p.omega_c = 2 * M_PI * D::fc_hz;
    return with_arias_modulation(p, D::Ia_s_g * kGravity, D::D5_95_s, D::tmid_s);
}

const std::vector<std::string>& stochastic_parameter_names() {
    static const std::vector<std::string> names = {"alpha1", "alpha2", "alpha3", "Ia",     "D5_95",
                                                   "tmid",   "fmid",   "fprime", "zeta", "fc"};
    return names;
}

StochasticParameters stochastic_parameters_from(const std::map<std::string, double>& values) {
    const std::vector<std::string>& names = stochastic_parameter_names();
    for (const auto& [key, value] : values)
        if (std::find(names.begin(), names.end(), key) == names.end()) {
            std::string known;
            for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
            throw std::invalid_argument("unknown key '" + key + "' (keys: " + known + ")");
        }
    auto given = [&](const char* key) { return static_cast<int>(values.count(key)); };
    const int alphas = given("alpha1") + given("alpha2") + given("alpha3");
    const int arias = given("Ia") + given("D5_95") + given("tmid");
    if (alphas && arias) throw std::invalid_argument("give the alphas or Ia, D5_95, tmid, not both");
    if (alphas && alphas != 3) throw std::invalid_argument("alpha1, alpha2 and alpha3 go together");
    // Each key's range in its own unit, so that fc = -1 is not refused as omega_c = -6.28.
    auto given_in = [&](const char* key, bool (*inside)(double), const char* rule) {
        if (values.count(key) && !inside(values.at(key))) refuse(key, rule, values.at(key));
    };
    given_in("fmid", [](double v) { return v > 0 && std::isfinite(v); }, "> 0 and finite");
    given_in("fprime", [](double v) { return static_cast<bool>(std::isfinite(v)); }, "finite");
    given_in("zeta", [](double v) { return v > 0 && v < 1; }, "in (0, 1)");
    given_in("fc", [](double v) { return v > 0 && std::isfinite(v); }, "> 0 and finite");
    StochasticParameters p = default_stochastic_parameters();
    if (values.count("fmid")) p.omega_mid = 2 * M_PI * values.at("fmid");
    if (values.count("fprime")) p.omega_prime = 2 * M_PI * values.at("fprime");
    if (values.count("zeta")) p.zeta_f = values.at("zeta");
    if (values.count("fc")) p.omega_c = 2 * M_PI * values.at("fc");
    if (alphas) {
        p.alpha1 = values.at("alpha1"), p.alpha2 = values.at("alpha2"), p.alpha3 = values.at("alpha3");
    } else if (arias) {
        auto value = [&](const char* key, double fallback) { return values.count(key) ? values.at(key) : fallback; };
        using D = StochasticDefaults;
        p = with_arias_modulation(p, value("Ia", D::Ia_s_g * kGravity), value("D5_95", D::D5_95_s),
                                  value("tmid", D::tmid_s));
    }
    return p;
}

namespace {

void check_modulation(const StochasticParameters& p) {
    if (!(p.alpha1 > 0) || !std::isfinite(p.alpha1)) refuse("alpha1", "> 0 and finite", p.alpha1);
    // alpha2 > 1 makes q(0) = 0: the record starts at rest, as the sum's nu(0) = 0 assumes.
    // GSL's gamma inverse (arias_time) fails to converge from the shape 2 alpha2 - 1 = 998,373
    // on at P = 0.95, and its default handler aborts the process: alpha2 up to kMaxAlpha2 keeps
    // the shape 5 times below that, and above the 1e5 with_arias_modulation can give.
    if (!(p.alpha2 > 1 && p.alpha2 <= kMaxAlpha2)) refuse("alpha2", "in (1, 100000]", p.alpha2);
    if (!(p.alpha3 > 0) || !std::isfinite(p.alpha3)) refuse("alpha3", "> 0 and finite", p.alpha3);
}

// omega_f(tau) = omega_mid + omega_prime (tau - t_mid).
double filter_frequency(const StochasticParameters& p, double t_mid, double tau) {
    return p.omega_mid + p.omega_prime * (tau - t_mid);
}

// The filter's frequencies over the record [0, t_end], in Hz.  omega_f is linear in t, so
// its largest is at an end: omega_mid - omega_prime t_mid at t = 0 when omega_prime < 0, at
// t_end otherwise; omega_mid itself is reached (at t_mid) when t_mid is in the record.
// Around omega_f the filtered noise's spectrum is |H|^2 = omega_f^4 / ((omega_f^2 - w^2)^2
// + 4 zeta^2 omega_f^2 w^2) (h is omega_f^2 times an oscillator's displacement response),
// whose half-power band ends above at w_u = omega_f sqrt(1 - 2 zeta^2 + 2 zeta sqrt(1 - zeta^2))
// for zeta <= 1/sqrt(2) (w_u >= omega_f: zeta widens the band); for a larger zeta |H|^2
// falls from w = 0 and omega_f bounds the band.  Past w_u, |H|^2 falls as (omega_f/w)^4.
std::vector<Frequency> filter_frequencies(const StochasticParameters& p, double t_mid, double t_end) {
    std::vector<Frequency> out;
    const double hz = 1 / (2 * M_PI);
    if (t_mid <= t_end)
        out.push_back({"fmid", "the filter's frequency at tmid = " + short_text(t_mid) + " s", p.omega_mid * hz,
                       {"fmid"}, "lower fmid"});
    const double t_top = p.omega_prime < 0 ? 0 : t_end, top = filter_frequency(p, t_mid, t_top) * hz;
    out.push_back({"fmid + fprime (t - tmid)",
                   "the filter's highest frequency over the record, at t = " + short_text(t_top) +
                       " s (fmid = " + short_text(p.omega_mid * hz) + " Hz, fprime = " +
                       short_text(p.omega_prime * hz) + " Hz/s, tmid = " + short_text(t_mid) + " s)",
                   top,
                   {"fmid", "fprime"},
                   p.omega_prime < 0 ? "lower fmid or raise fprime" : "lower fmid or fprime, or shorten the record"});
    const double z = p.zeta_f, widening = std::sqrt(std::max(1.0, 1 - 2 * z * z + 2 * z * std::sqrt(1 - z * z)));
    out.push_back({"the filter's band edge",
                   "the upper half-power frequency of its band around " + short_text(top) + " Hz, widened by zeta = " +
                       text_of(z) + " (a factor sqrt(1 - 2 zeta^2 + 2 zeta sqrt(1 - zeta^2)) = " +
                       short_text(widening) + ")",
                   top * widening,
                   {"zeta", "fmid", "fprime"},
                   "lower zeta or the filter's frequency"});
    return out;
}

Frequency corner_frequency(const StochasticParameters& p) {
    return {"fc", "the post-filter's corner", p.omega_c / (2 * M_PI), {"fc"}, "lower fc"};
}

// The filter must stay a damped oscillator above 0 Hz over the record (a falling
// omega_f crosses 0 on a long record).
void check_filter_range(const StochasticParameters& p, double t_mid, double t_end) {
    if (!std::isfinite(p.omega_mid)) refuse("omega_mid", "finite", p.omega_mid);
    if (!std::isfinite(p.omega_prime)) refuse("omega_prime", "finite", p.omega_prime);
    if (!(p.zeta_f > 0 && p.zeta_f < 1)) refuse("zeta_f", "in (0, 1)", p.zeta_f);
    if (!(p.omega_c > 0) || !std::isfinite(p.omega_c)) refuse("omega_c", "> 0 and finite", p.omega_c);
    for (double tau : {0.0, t_end}) {
        const double w = filter_frequency(p, t_mid, tau);
        if (!(w > 0))
            throw std::invalid_argument("the filter's frequency fmid + fprime (t - tmid) is " +
                                        short_text(w / (2 * M_PI)) + " Hz at t = " + short_text(tau) + " s (fmid = " +
                                        text_of(p.omega_mid / (2 * M_PI)) + " Hz, fprime = " +
                                        text_of(p.omega_prime / (2 * M_PI)) + " Hz/s, tmid = " + short_text(t_mid) +
                                        " s): it must stay > 0 over the record (" +
                                        (tau == 0 ? "lower fprime or raise fmid"
                                                  : "shorten the record, bring fprime closer to 0 or raise fmid") +
                                        ")");
    }
}

// ... and its band below the Nyquist frequency.
void check_filter(const StochasticParameters& p, double t_mid, double dt, double t_end) {
    check_filter_range(p, t_mid, t_end);
    refuse_unsampled(filter_frequencies(p, t_mid, t_end), dt);
}

// q(t) = alpha1 t^(alpha2 - 1) exp(-alpha3 t) is evaluated as written, and alpha1 t^(alpha2 - 1)
// grows with t: finite at the record's end, it is finite throughout.  A large alpha2 (a
// tmid many times D5_95: a narrow burst long after t = 0) overflows it, and q would be
// inf times 0.
void check_modulation_over(const StochasticParameters& p, double t_end) {
    if (std::isfinite(p.alpha1 * std::pow(t_end, p.alpha2 - 1))) return;
    const double t_mid = arias_time(p, 0.45), d5_95 = arias_time(p, 0.95) - arias_time(p, 0.05);
    throw std::invalid_argument(
        "q(t) = alpha1 t^(alpha2 - 1) exp(-alpha3 t) overflows a double before the record's end at " +
        short_text(t_end) + " s (alpha1 = " + short_text(p.alpha1) + ", alpha2 = " + short_text(p.alpha2) +
        ", alpha3 = " + short_text(p.alpha3) + " 1/s): its tmid = " + short_text(t_mid) + " s is " +
        short_text(t_mid / d5_95) + " times its D5_95 = " + short_text(d5_95) +
        " s, a burst so narrow and late that alpha2 is this large; bring tmid closer to D5_95 (or lower alpha2), or "
        "shorten the record");
}

// The sum below runs each sample's term until its envelope exp(-zeta_f omega_f s) falls
// below 1e-30, ln(1e30) / (zeta_f omega_f dt) steps, or to the record's end: quadratic in
// the samples within that memory.  At dt = 1e-6 over 5 s (5e6 samples, under kMaxSamples,
// a memory of ~9 s) that was 1e13 terms, hours without a word; at about 5e8 terms a second,
// kMaxSumTerms is a few minutes.  The count is the loop's own, to within a percent.
constexpr double kMaxSumTerms = 1e11;
void check_sum_cost(const StochasticParameters& p, double t_mid, double dt, std::size_t n) {
    const double per_rate = std::log(1e30) / (p.zeta_f * dt);  // steps times omega_f
    double terms = 0, longest = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double memory = per_rate / filter_frequency(p, t_mid, dt * i) + 1;
        longest = std::max(longest, memory);
        terms += std::min(static_cast<double>(n - i), memory);
    }
    if (terms > kMaxSumTerms) {
        char counts[120];
        std::snprintf(counts, sizeof counts, "spans up to %.3g of them: its sum would take %.3g terms", longest, terms);
        throw std::invalid_argument("duration/dt gives " + std::to_string(n) + " samples, and the filter's memory " +
                                    counts + ", more than 1e+11 (minutes); raise dt or shorten the duration");
    }
}

// The discrete process's expected Arias intensity is (pi/2g) sum_k q(t_k)^2 dt (nu has unit
// variance at k >= 1), the model's (pi/2g) int q^2: a modulation a few steps wide falls
// between the samples (D5_95 = 0.001 s at dt = 0.01 s gave a PGA of 1e-5 m/s^2 under a
// header stating Ia = 0.46 m/s: issue 38).  Their ratio over the record, sum over
// integral, both of q^2's gamma density (shape 2 alpha2 - 1, rate 2 alpha3).
double sampled_arias_share(const StochasticParameters& p, double dt, std::size_t n) {
    const double k = 2 * p.alpha2 - 1, rate = 2 * p.alpha3, log_scale = k * std::log(rate) - gsl_sf_lngamma(k);
    double sum = 0;
    for (std::size_t j = 1; j < n; ++j) {
        const double t = dt * j;
        sum += std::exp((k - 1) * std::log(t) + log_scale - rate * t);
    }
    return sum * dt / gsl_cdf_gamma_P(dt * (n - 1), k, 1 / rate);
}

// More than kRefusedArias from 1, the samples are not the model's record: refused; more
// than kWarnedArias, warned of.  At dt = D5_95/20 the share is within 7.4 % of 1 for every
// shape (the worst, alpha2 -> 1, loses the half step after t = 0, where q^2 starts at its
// peak; narrower shapes converge faster: docs/synthetic.md, "Sampling").
constexpr double kRefusedArias = 0.10, kWarnedArias = 0.01;

std::string modulation_text(const StochasticParameters& p, double dt, double share) {
    const double t05 = arias_time(p, 0.05), d5_95 = arias_time(p, 0.95) - t05;
    return "D5_95 = " + short_text(d5_95) + " s, the modulation's 5-95 % duration (tmid = " +
           short_text(arias_time(p, 0.45)) + " s), spans " + short_text(d5_95 / dt) + " steps of dt = " + text_of(dt) +
           " s: its samples of q(t)^2 hold " + short_text(100 * share) +
           " % of the record's expected Arias intensity";
}

// Refuses a modulation the step cannot hold; the warning, if any, for one it holds poorly.
std::vector<std::string> check_modulation_sampling(const StochasticParameters& p, double dt, std::size_t n) {
    const double share = sampled_arias_share(p, dt, n);
    if (!std::isfinite(share)) return {};  // nothing of q^2 within the record to compare
    const double d5_95 = arias_time(p, 0.95) - arias_time(p, 0.05);
    if (std::fabs(share - 1) > kRefusedArias)
        throw SamplingError(modulation_text(p, dt, share) + ", more than " + short_text(100 * kRefusedArias) +
                                " % from it: raise D5_95, or take dt at most D5_95/20 = " + short_text(d5_95 / 20) +
                                " s",
                            {"D5_95", "tmid", "alpha1", "alpha2", "alpha3"});
    if (std::fabs(share - 1) > kWarnedArias)
        return {modulation_text(p, dt, share) + ", more than " + short_text(100 * kWarnedArias) +
                " % from it (take dt at most about " + short_text(dt * kWarnedArias / std::fabs(share - 1)) + " s)"};
    return {};
}

// A GSL error aborts the process by default; here it becomes an exception.
struct GslErrorsAsCodes {
    gsl_error_handler_t* previous = gsl_set_error_handler_off();
    ~GslErrorsAsCodes() { gsl_set_error_handler(previous); }
};

// t_mid / d5_95 as a function of the shape k of q^2's gamma density.
double midpoint_ratio(double k, void*) {
    const double q05 = gsl_cdf_gamma_Pinv(0.05, k, 1), q45 = gsl_cdf_gamma_Pinv(0.45, k, 1),
                 q95 = gsl_cdf_gamma_Pinv(0.95, k, 1);
    return q45 / (q95 - q05);
}

struct RatioTarget {
    double ratio;
};
double ratio_gap(double k, void* target) { return midpoint_ratio(k, nullptr) - static_cast<RatioTarget*>(target)->ratio; }

constexpr double kHighestShape = 1e5;

// The shape k >= 1 with midpoint_ratio(k) = ratio (in its range, midpoint_ratio(1) to
// midpoint_ratio(kHighestShape)), by Brent's method to 1e-14 relative.
double shape_for_ratio(double ratio) {
    const double highest_k = kHighestShape;
    GslErrorsAsCodes guard;
    RatioTarget target{ratio};
    gsl_function f{&ratio_gap, &target};
    std::unique_ptr<gsl_root_fsolver, void (*)(gsl_root_fsolver*)> solver(gsl_root_fsolver_alloc(gsl_root_fsolver_brent),
                                                                           gsl_root_fsolver_free);
    gsl_root_fsolver_set(solver.get(), &f, 1, highest_k);
    double k = 1;
    for (int i = 0; i < 200; ++i) {
        gsl_root_fsolver_iterate(solver.get());
        k = gsl_root_fsolver_root(solver.get());
        if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()), gsl_root_fsolver_x_upper(solver.get()), 0,
                                   1e-14) == GSL_SUCCESS)
            break;
    }
    return k;
}

}  // namespace

double modulating_function(const StochasticParameters& p, double t) {
    if (t <= 0) return 0;
    return p.alpha1 * std::pow(t, p.alpha2 - 1) * std::exp(-p.alpha3 * t);
}

double arias_time(const StochasticParameters& p, double fraction) {
    check_modulation(p);
    if (!(fraction > 0 && fraction < 1)) refuse("fraction", "in (0, 1)", fraction);
    return gsl_cdf_gamma_Pinv(fraction, 2 * p.alpha2 - 1, 1 / (2 * p.alpha3));
}

namespace {
// e^x as the power of ten in a message: "-46451" for alpha1 = e^-106958.
std::string power_of_ten(double log_value) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.0f", log_value / std::log(10.0));
    return buf;
}
}  // namespace

StochasticParameters with_arias_modulation(StochasticParameters base, double Ia, double d5_95, double t_mid) {
    if (!(Ia > 0) || !std::isfinite(Ia)) refuse("Ia", "> 0 and finite", Ia);
    if (!(d5_95 > 0) || !std::isfinite(d5_95)) refuse("D5_95", "> 0 and finite", d5_95);
    if (!(t_mid > 0) || !std::isfinite(t_mid)) refuse("tmid", "> 0 and finite", t_mid);
    const std::string given = "tmid = " + text_of(t_mid) + " s and D5_95 = " + text_of(d5_95) + " s";
    const double ratio = t_mid / d5_95, lowest = midpoint_ratio(1, nullptr),
                 highest = midpoint_ratio(kHighestShape, nullptr);
    if (!(ratio > lowest) || !(ratio < highest))
        throw std::invalid_argument("tmid/D5_95 must be in (" + short_text(lowest) + ", " + short_text(highest) +
                                    ") for a gamma modulating function with alpha2 > 1 (got " + short_text(ratio) +
                                    ": " + given + ")");
    const double k = shape_for_ratio(ratio);
    base.alpha2 = (k + 1) / 2;
    base.alpha3 = (gsl_cdf_gamma_Pinv(0.95, k, 1) - gsl_cdf_gamma_Pinv(0.05, k, 1)) / (2 * d5_95);
    // int_0^inf q^2 = alpha1^2 Gamma(k) / (2 alpha3)^k = 2 g Ia / pi, in logarithms:
    // Gamma(k) and (2 alpha3)^k overflow long before their ratio does.
    const double log_alpha1 =
        0.5 * (std::log(2 * kGravity * Ia / M_PI) + k * std::log(2 * base.alpha3) - gsl_sf_lngamma(k));
    base.alpha1 = std::exp(log_alpha1);
    // The alphas are what the model uses; one out of a double's range is the user's
    // Ia, D5_95 and tmid out of its reach, and is refused in their names.
    if (!(base.alpha3 > 0) || !std::isfinite(base.alpha3))
        throw std::invalid_argument(given + " give alpha3 = " + short_text(base.alpha3) +
                                    " 1/s, outside a double's range: take D5_95 and tmid in seconds");
    if (!(base.alpha1 >= DBL_MIN) || !std::isfinite(base.alpha1))
        throw std::invalid_argument(
            given + " (Ia = " + text_of(Ia) + " m/s) give alpha1 = 10^" + power_of_ten(log_alpha1) +
            ", outside a double's range: with tmid " + short_text(ratio) +
            " times D5_95, q(t) = alpha1 t^(alpha2 - 1) exp(-alpha3 t) needs alpha2 = " + short_text(base.alpha2) +
            ", a burst so narrow and late that alpha1 leaves a double; bring tmid closer to D5_95" +
            (ratio < 3 ? std::string(" or take D5_95 and tmid in seconds") : std::string()));
    return base;
}

std::vector<double> white_noise(std::uint64_t seed, std::size_t n) {
    if (seed < 1 || seed > 0xFFFFFFFFu) refuse("seed", "in [1, 4294967295]", static_cast<double>(seed));
    std::unique_ptr<gsl_rng, void (*)(gsl_rng*)> rng(gsl_rng_alloc(gsl_rng_mt19937), gsl_rng_free);
    gsl_rng_set(rng.get(), static_cast<unsigned long>(seed));
    std::vector<double> u(n);
    for (double& x : u) x = gsl_ran_gaussian_ziggurat(rng.get(), 1.0);
    return u;
}

std::vector<double> filtered_noise(const StochasticParameters& p, const std::vector<double>& u, double dt) {
    const std::size_t n = u.size();
    const double t_mid = arias_time(p, 0.45);
    check_filter(p, t_mid, dt, dt * (n ? n - 1 : 0));
    check_sum_cost(p, t_mid, dt, n);
    const double root = std::sqrt(1 - p.zeta_f * p.zeta_f);
    // nu is a ratio: a factor common to every h cancels.  h's own gain w/root times
    // Im z^(k - i), of order w (k - i) sin(w root dt), underflowed as w fell (at fmid =
    // 1e-100 Hz, h^2 = 0 and nu = 0/0: issue 38); divided by w_top sin(w_top root dt),
    // w_top the largest omega_f over the record, it tends to (k - i) as w -> 0.
    const double t_end = dt * (n ? n - 1 : 0);
    const double w_top = std::max(filter_frequency(p, t_mid, 0), filter_frequency(p, t_mid, t_end));
    const double top_sine = std::sin(w_top * root * dt);
    std::vector<double> sum(n, 0.0), norm(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const double w = filter_frequency(p, t_mid, dt * i), gain = w / w_top / top_sine;
        // h(t_k - t_i) = gain Im z^(k - i), z = exp((-zeta w + i w root) dt): one
        // complex product a step instead of an exp and a sine.
        const double decay = std::exp(-p.zeta_f * w * dt), c = decay * std::cos(w * root * dt),
                     s = decay * std::sin(w * root * dt);
        double re = 1, im = 0;
        for (std::size_t k = i; k < n; ++k) {
            const double h = gain * im;
            sum[k] += h * u[i];
            norm[k] += h * h;
            const double next_re = re * c - im * s;
            im = re * s + im * c;
            re = next_re;
            // Past 1e-30 of its start a term is 1e-14 below the rounding of the
            // sum it joins (whose own i = k - 1 term is of its size or larger).
            if (std::fabs(re) + std::fabs(im) < 1e-30) break;
        }
    }
    std::vector<double> nu(n, 0.0);
    for (std::size_t k = 1; k < n; ++k) nu[k] = sum[k] / std::sqrt(norm[k]);
    return nu;
}

namespace {
// g_n(a) = int_0^1 u^n e^(-a u) du for n = 1, 2, a = omega_c dt >= 0: the step's weights.
// Below a = 1 by their series (the recurrence g_n = (n g_(n-1) - e^-a)/a cancels as a
// falls); above it by that recurrence, which there loses at most a digit.
struct StepWeights {
    double g1, g2;
};
StepWeights step_weights(double a) {
    if (a < 1) {
        // sum_m (-a)^m / (m! (n + m + 1)): 25 terms leave 1/25! < 1e-25.
        double g1 = 0, g2 = 0, term = 1;
        for (int m = 0; m < 25; ++m) {
            g1 += term / (m + 2), g2 += term / (m + 3);
            term *= -a / (m + 1);
        }
        return {g1, g2};
    }
    const double e = std::exp(-a), g0 = -std::expm1(-a) / a, g1 = (g0 - e) / a;
    return {g1, (2 * g1 - e) / a};
}
}  // namespace

std::vector<double> critically_damped_high_pass(const std::vector<double>& x, double dt, double omega_c) {
    if (!(omega_c > 0) || !std::isfinite(omega_c)) refuse("omega_c", "> 0 and finite", omega_c);
    if (!(dt > 0) || !std::isfinite(dt)) refuse("dt", "> 0 and finite", dt);
    // The state is (p, r) = (z', omega_c z): p' = x - 2 w p - w r, r' = w p.  Written in z
    // itself, z ~ x/w^2 and the step's particular solution 2 slope/w^3 grow as the corner
    // falls, and their difference cancelled: at fc = 1e-14 Hz the record's PGV was 27 m/s
    // for 0.24 (issue 38).  Here every weight is bounded as w -> 0, where the filter passes
    // x unchanged.  A + w I is nilpotent for A = [[-2w, -w], [w, 0]], so
    // exp(A s) = e^(-w s) [[1 - w s, -w s], [w s, 1 + w s]], and with x = x_(k+1) - slope s
    // over the step the forced part is dt [x_(k+1) e^-a - dx (e^-a - g1)] for p and
    // a dt [x_(k+1) g1 - dx g2] for r (a = w dt, dx = x_(k+1) - x_k, g_n of step_weights).
    const double w = omega_c, a = w * dt, decay = std::exp(-a);
    const StepWeights g = step_weights(a);
    std::vector<double> out(x.size());
    double p = 0, r = 0;  // z' and omega_c z at t_k
    for (std::size_t k = 0; k < x.size(); ++k) {
        out[k] = x[k] - w * (2 * p + r);
        if (k + 1 == x.size()) break;
        const double next = x[k + 1], dx = next - x[k];
        const double p_next = decay * ((1 - a) * p - a * r) + dt * (next * decay - dx * (decay - g.g1));
        r = decay * (a * p + (1 + a) * r) + a * dt * (next * g.g1 - dx * g.g2);
        p = p_next;
    }
    return out;
}

std::vector<double> modulated_noise(const StochasticParameters& p, std::uint64_t seed, double dt, double duration) {
    check_modulation(p);
    const std::size_t n = sample_count(dt, duration);
    check_modulation_over(p, dt * (n - 1));
    std::vector<double> a = filtered_noise(p, white_noise(seed, n), dt);
    for (std::size_t k = 0; k < n; ++k) a[k] *= modulating_function(p, dt * k);
    return a;
}

Record stochastic_record(const StochasticParameters& p, std::uint64_t seed, double dt, double duration) {
    // Every frequency against the step before the sum's work; modulated_noise checks the rest.
    check_modulation(p);
    const double t_end = dt * (sample_count(dt, duration) - 1), t_mid = arias_time(p, 0.45);
    check_filter_range(p, t_mid, t_end);
    std::vector<Frequency> frequencies = filter_frequencies(p, t_mid, t_end);
    // The band's edge, the filter's last frequency, is its highest (fmid and the top lie below).
    const Frequency band = frequencies.back();
    frequencies.push_back(corner_frequency(p));
    refuse_unsampled(frequencies, dt);
    const std::vector<std::string> held_poorly = check_modulation_sampling(p, dt, sample_count(dt, duration));
    Record r;
    r.accel = critically_damped_high_pass(modulated_noise(p, seed, dt, duration), dt, p.omega_c);
    r.format = "synthetic";
    r.path = "(synthetic)";
    r.name = "RDK2008 stochastic seed=" + std::to_string(seed);
    r.dt = dt;
    const double t05 = arias_time(p, 0.05), t95 = arias_time(p, 0.95);
    const double k = 2 * p.alpha2 - 1;
    const double Ia = M_PI / (2 * kGravity) * p.alpha1 * p.alpha1 *
                      std::exp(gsl_sf_lngamma(k) - k * std::log(2 * p.alpha3));
    r.header = {{"generator", "Rezaeian & Der Kiureghian (2008) modulated filtered white noise, critically damped "
                              "high-pass post-filter (Rezaeian & Der Kiureghian 2010)"},
                {"rng", "gsl_rng_mt19937, gsl_ran_gaussian_ziggurat"},
                {"seed", std::to_string(seed)},
                {"alpha1", text_of(p.alpha1)},
                {"alpha2", text_of(p.alpha2)},
                {"alpha3_1_s", text_of(p.alpha3)},
                {"omega_mid_rad_s", text_of(p.omega_mid)},
                {"omega_prime_rad_s2", text_of(p.omega_prime)},
                {"zeta_f", text_of(p.zeta_f)},
                {"omega_c_rad_s", text_of(p.omega_c)},
                {"t_mid_s", text_of(t_mid)},
                {"expected_Ia_m_s", text_of(Ia)},
                {"expected_D5_95_s", text_of(t95 - t05)},
                {"dt_s", text_of(dt)},
                {"duration_s", text_of(duration)}};
    std::vector<std::string> warnings = sampling_warnings({band, corner_frequency(p)}, dt);
    warnings.insert(warnings.end(), held_poorly.begin(), held_poorly.end());
    state_warnings(r, warnings);
    return r;
}

}  // namespace rocking::records
