// rocking: the q-factor of a slender rigid block under step pulses, for engineers.
//
//   rocking q --case I --x X [--pulses N] [--json]
//   rocking q --train A:d,A:d,... --x X [--json]
//   rocking response --case I --x X [--pulses N] [--q Q] [--steps K] [--json]
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/table.hpp"
#include "pulse/pulse_train.hpp"
#include "dynamics/simulate.hpp"
#include "qfactor/closed_forms.hpp"
#include "records/collapse.hpp"
#include "records/measures.hpp"
#include "records/record.hpp"
#include "qfactor/superposition.hpp"

using namespace rocking;

namespace {

const char* kUsage =
    "usage: rocking q --case I --x X [--pulses N] [--json]\n"
    "       rocking q --train A:d,A:d,... --x X [--json]\n"
    "       rocking response --case I --x X [--pulses N] [--q Q] [--steps K] [--json]\n"
    "       rocking simulate INPUT GEOMETRY [--model M] [--solver S] [--rtol R] [--atol A] [--criterion C]\n"
    "                        [--restitution E|housner] [--output FILE --dt DT] [--json]\n"
    "       rocking record info FILE [--json]\n"
    "       rocking collapse FILE --alpha A [--model M] [--solver S] [--rtol R] [--atol A] [--criterion C]\n"
    "                        [--restitution E|housner] [--json]\n"
    "       rocking assess FILE --alpha A (--height H | --half-height h) [--json]\n"
    "\n"
    "  --case I     input of Figure 3, I = 1..5 (amplitudes in PGA, durations in to)\n"
    "  --pulses N   repeat the case's pattern to N pulses (case 2, N = 6 is eq. 27)\n"
    "  --train ...  any train: amplitude:duration pairs, in units of PGA and to\n"
    "  --x X        x = p*to, X >= 1e-150\n"
    "  --q Q        response at this q instead of the collapse q\n"
    "  --steps K    number of time steps over [0, t_fin] (default 20)\n"
    "  --json       machine-readable output\n"
    "q and response: linearised eq. 3, one corner, no impact, collapse theta(t_fin) = alpha.\n"
    "\n"
    "simulate: INPUT is --case I [--pulses N] or --train A:d,...  with --to T (s) or --x X, and the\n"
    "  amplitude as --pga G (in g), --q Q (PGA = Q alpha g) or --rd R (PGA = q_I(x) R alpha g);\n"
    "  or --one-sine --ap A (in g) --wp W (rad/s);\n"
    "  or --record FILE (as for record FILE, with --record-dt for --dt), piecewise linear between\n"
    "  samples, as recorded or scaled to --pga G (in g) or --q Q (PGA = Q alpha g).\n"
    "  GEOMETRY is --alpha A with --p P (rad/s), --half-height h (m, the H of eq. 2) or --height H (m).\n"
    "  --model linearised|full (default linearised); --solver exact|dopri5|rkf78|bulirsch-stoer|gsl-rk8pd\n"
    "  (default exact for linearised, dopri5 for full); --rtol in [100 eps, 1) (default 1e-6);\n"
    "  --atol in rad on theta and rad/s on theta', as ode45's AbsTol (default rtol times alpha; ode45's\n"
    "  default is 1e-6), in [100 eps, 1) alpha; the ODE solvers' tolerances, stated in every output;\n"
    "  --criterion final-rotation|peak-rotation|overturning (default final-rotation, the paper's);\n"
    "  --restitution on angular velocity at impact (default 1) or housner (1 - 1.5 sin^2 alpha);\n"
    "  --output FILE writes t,theta/alpha,theta'/(alpha p) every --dt seconds (default 0.01).\n"
    "\n"
    "record FILE: ESM/ITACA ASCII or PEER AT2 (by content); a one-column (add --dt DT --unit U) or\n"
    "  two-column time,acceleration file (add --unit U), U = g, m/s2 or cm/s2.\n"
    "collapse: the first p (rad/s), raising p from 0.3 by 1 %, at which the record overturns a block of\n"
    "  slenderness A (Table 1's search; not a bound: a lower p may overturn it too). Defaults:\n"
    "  linearised, exact solver, Housner restitution, overturning.\n"
    "assess: the block's p (eqs. 2, 4), the record's to_5 (eq. 31), q from eq. 27, the record's\n"
    "  q = PGA/(alpha g), and the paper's check: it passes when the record's q < eq. 27's (not a proof\n"
    "  of safety: eq. 27 is not conservative everywhere; simulate --record follows the block).\n";

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

double number(const std::string& flag, const std::string& text) {
    std::size_t used = 0;
    double v;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        throw UsageError(flag + ": '" + text + "' is not a number");
    }
    if (used != text.size() || !std::isfinite(v)) throw UsageError(flag + ": '" + text + "' is not a finite number");
    return v;
}

// --restitution: "housner" (1 - 1.5 sin^2 alpha) or a factor in [0, 1];
// NaN stands for housner.
double restitution_option(const std::string& text) {
    if (text == "housner") return NAN;
    const double e = number("--restitution", text);
    if (!(e >= 0 && e <= 1)) throw UsageError("--restitution: must be in [0, 1] or housner (got " + text + ")");
    return e;
}

// The tolerances' floor, 100 eps, to every digit: "2.2e-14" read back is
// below it, and a user who typed the bound the message gave was refused.
std::string smallest_tolerance() {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", dynamics::kSmallestTolerance);
    return text;
}

// --rtol: a relative tolerance in [100 eps, 1), used as the absolute one in units of alpha too.
double rtol_option(const std::string& text) {
    const double r = number("--rtol", text);
    if (!(r >= dynamics::kSmallestTolerance && r < 1))
        throw UsageError("--rtol: must be in [100 eps, 1) = [" + smallest_tolerance() + ", 1) (got " + text + ")");
    return r;
}

// --rtol and --atol into the solver's options: --atol in rad (and rad/s on
// theta', one number for the whole state, as ode45's AbsTol), kept in units
// of alpha and held to the same range as --rtol there.
void tolerance_options(const std::map<std::string, std::string>& values, double alpha,
                       dynamics::SolverOptions& solver) {
    if (values.count("--rtol")) solver.rtol = solver.atol_alpha = rtol_option(values.at("--rtol"));
    if (!values.count("--atol")) return;
    const std::string& text = values.at("--atol");
    const double atol = number("--atol", text), in_alpha = atol / alpha;
    if (!(in_alpha >= dynamics::kSmallestTolerance && in_alpha < 1)) {
        char range[200];
        std::snprintf(range, sizeof range, "[%.17g, %g) rad, [100 eps, 1) alpha at alpha = %g",
                      dynamics::kSmallestTolerance * alpha, alpha, alpha);
        throw UsageError("--atol: must be in " + std::string(range) + " (got " + text + ")");
    }
    solver.atol_alpha = in_alpha;
}

int integer(const std::string& flag, const std::string& text) {
    const double v = number(flag, text);
    if (v != std::floor(v) || std::fabs(v) > 1e6) throw UsageError(flag + ": '" + text + "' is not a whole number");
    return static_cast<int>(v);
}

// The FILE a subcommand takes first: an option there (rocking collapse
// --alpha 0.15 FILE) was read as the file, and its value as an unknown option.
std::string file_argument(int argc, char** argv, int at, const std::string& usage) {
    if (argc <= at) throw UsageError(usage);
    const std::string path = argv[at];
    if (path.rfind("--", 0) == 0) throw UsageError("FILE comes first, before '" + path + "': " + usage);
    return path;
}

struct Args {
    std::map<std::string, std::string> values;
    bool json = false;
};

Args parse(int argc, char** argv, int first, const std::vector<std::string>& allowed) {
    Args a;
    for (int i = first; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--json") {
            a.json = true;
            continue;
        }
        bool ok = false;
        for (const auto& f : allowed) ok = ok || f == flag;
        if (!ok) throw UsageError("unknown option '" + flag + "'");
        if (i + 1 >= argc) throw UsageError(flag + " needs a value");
        if (a.values.count(flag)) throw UsageError(flag + " given twice");
        a.values[flag] = argv[++i];
    }
    return a;
}

PulseTrain train_from(const Args& a, std::string& equation) {
    const bool has_case = a.values.count("--case"), has_train = a.values.count("--train");
    if (has_case == has_train) throw UsageError("give exactly one of --case and --train");
    if (has_train) {
        if (a.values.count("--pulses")) throw UsageError("--pulses goes with --case");
        equation = "superposition (S2)";
        try {
            return parse_train(a.values.at("--train"));
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--train: ") + e.what());
        }
    }
    const int which = integer("--case", a.values.at("--case"));
    if (which < 1 || which > 5) throw UsageError("--case: must be 1, 2, 3, 4 or 5 (got " + a.values.at("--case") + ")");
    const int n = a.values.count("--pulses") ? integer("--pulses", a.values.at("--pulses")) : 2;
    if (n < 1 || n > 1000) throw UsageError("--pulses: must be between 1 and 1000");
    static const char* eq[] = {"", "eq. 12", "eq. 15", "eq. 19", "eq. 22", "eq. 24"};
    equation = n == 2 ? eq[which] : (n == 6 && which == 2) ? "eq. 27" : (n == 6 && which == 4) ? "eq. 28 (corrected)"
                                                                                             : "superposition (S2)";
    return repeated_case(which, n);
}

double x_from(const Args& a) {
    if (!a.values.count("--x")) throw UsageError("--x is required");
    const double x = number("--x", a.values.at("--x"));
    if (!(x > 0)) throw UsageError("--x: must be > 0 (got " + a.values.at("--x") + ")");
    if (x < kSmallestX)
        throw UsageError("--x: must be >= 1e-150, below which q ~ 2/(M1 x^2) overflows (got " + a.values.at("--x") + ")");
    return x;
}

// A value to 4 decimals, in exponent form from 1e9 on (a record scaled
// absurdly printed 300 digits).
std::string four(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, std::fabs(v) < 1e9 ? "%.4f" : "%.4e", v);
    return buf;
}

// The record's half-periods; a record they cannot be measured on is refused
// with its file's name.
records::HalfPeriods half_periods_of(const records::Record& r, const std::string& path) {
    try {
        return records::half_periods(r);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

const char* kModel = "linearised eq. 3, one corner, no impact, collapse theta(t_fin) = alpha";

// Where the closed forms hold at this q (Excursion), as q and response print
// it, each line after prefix: they hold only while the block rocks on one
// corner, from the first pulse lifting it to t_fin.
void print_validity(const Excursion& e, const char* prefix) {
    std::printf("%srocking starts: %s; impact-free up to t_fin: %s; motion reverses before t_fin: %s\n", prefix,
                e.onset ? "yes" : "no (q A_0 <= 1)", e.stays_positive() ? "yes" : "no", e.min_dphi < 0 ? "yes" : "no");
    if (!e.onset)
        std::printf("%swarning: the input does not lift the block (q A_0 <= 1), so the closed form does not apply: "
                    "its theta < 0 would press the block into the ground\n",
                    prefix);
    else if (!e.stays_positive())
        std::printf("%swarning: theta goes down to %.3g alpha (at t/to = %.4g): the block hits the ground before t_fin, "
                    "and the closed form does not apply from there (rocking simulate follows the impacts)\n",
                    prefix, e.min_phi, e.tau_at_min);
}

std::string json_validity(const Excursion& e) {
    return std::string(", \"rocking_starts\": ") + (e.onset ? "true" : "false") +
           ", \"impact_free\": " + (e.stays_positive() ? "true" : "false") +
           ", \"motion_reverses\": " + (e.min_dphi < 0 ? "true" : "false");
}

int cmd_q(int argc, char** argv) {
    const Args a = parse(argc, argv, 2, {"--case", "--train", "--x", "--pulses"});
    std::string equation;
    const PulseTrain train = train_from(a, equation);
    const double x = x_from(a);
    const QFactor r = q_factor(train, x);
    const Excursion e = excursion(train, x, r.q);
    if (a.json) {
        std::cout << "{\"input\": " << json_string(train.name()) << ", \"pulses\": " << train.size()
                  << ", \"x\": " << harness::format_number(x) << ", \"q\": " << harness::format_number(r.q)
                  << ", \"condition\": " << harness::format_number(r.condition)
                  << ", \"equation\": " << json_string(equation) << ", \"model\": " << json_string(kModel)
                  << json_validity(e) << "}\n";
    } else {
        std::printf("q = %.10g\n", r.q);
        std::printf("  input %s (%zu pulses, t_fin = %g to), x = p*to = %g, %s\n", train.name().c_str(), train.size(),
                    train.t_fin(), x, equation.c_str());
        std::printf("  model: %s\n", kModel);
        print_validity(e, "  ");
    }
    return 0;
}

int cmd_response(int argc, char** argv) {
    const Args a = parse(argc, argv, 2, {"--case", "--train", "--x", "--pulses", "--q", "--steps"});
    std::string equation;
    const PulseTrain train = train_from(a, equation);
    const double x = x_from(a);
    const double q = a.values.count("--q") ? number("--q", a.values.at("--q")) : q_factor(train, x).q;
    if (!(q > 0)) throw UsageError("--q: must be > 0");
    const int steps = a.values.count("--steps") ? integer("--steps", a.values.at("--steps")) : 20;
    if (steps < 1 || steps > 1000000) throw UsageError("--steps: must be between 1 and 1000000");
    const Excursion e = excursion(train, x, q);
    if (a.json) {
        std::cout << "{\"input\": " << json_string(train.name()) << ", \"x\": " << harness::format_number(x)
                  << ", \"q\": " << harness::format_number(q) << ", \"model\": " << json_string(kModel)
                  << json_validity(e) << ", \"samples\": [";
    } else {
        std::printf("# %s, x = %g, q = %.10g; %s\n", train.name().c_str(), x, q, kModel);
        print_validity(e, "# ");
        std::printf("# t/to,theta/alpha,theta'/(alpha p)\n");
    }
    for (int k = 0; k <= steps; ++k) {
        const double tau = train.t_fin() * k / steps;
        const ResponseState s = response(train, x, q, tau);
        if (a.json)
            std::cout << (k ? ", " : "") << "[" << harness::format_number(tau) << ", " << harness::format_number(s.phi)
                      << ", " << harness::format_number(s.dphi) << "]";
        else std::printf("%.6g,%.12g,%.12g\n", tau, s.phi, s.dphi);
    }
    if (a.json) std::cout << "]}\n";
    return 0;
}

// A record file by content, or a plain-text one when --unit (and, for one
// column, the sampling step under dt_flag) is given.
records::Record load_record(const std::string& path, const Args& a, const std::string& dt_flag = "--dt") {
    if (a.values.count("--unit") || a.values.count(dt_flag)) {
        if (!a.values.count("--unit")) throw UsageError("--unit is required for a plain-text record (g, m/s2, cm/s2)");
        const std::string unit = a.values.at("--unit");
        if (unit != "g" && unit != "m/s2" && unit != "cm/s2")
            throw UsageError("--unit: '" + unit + "' is not a unit it knows (g, m/s2, cm/s2)");
        const double dt = a.values.count(dt_flag) ? number(dt_flag, a.values.at(dt_flag)) : 0.0;
        // 0 would read as "not given" (a two-column file), and a negative
        // step was reported against the file's line 0.
        if (a.values.count(dt_flag) && !(dt > 0)) throw UsageError(dt_flag + ": must be > 0 (got " + a.values.at(dt_flag) + ")");
        return records::read_plain(path, unit, dt);
    }
    return records::read_any(path);
}

int cmd_simulate(int argc, char** argv) {
    using namespace rocking::dynamics;
    // --one-sine takes no value: handle it before the generic parser.
    std::vector<char*> args(argv, argv + argc);
    bool one_sine = false;
    for (auto it = args.begin() + 2; it != args.end();)
        if (std::string(*it) == "--one-sine") one_sine = true, it = args.erase(it);
        else ++it;
    const Args a = parse(static_cast<int>(args.size()), args.data(), 2,
                         {"--case", "--train", "--pulses", "--x", "--to", "--pga", "--q", "--rd", "--ap", "--wp",
                          "--alpha", "--p", "--half-height", "--height", "--model", "--solver", "--rtol", "--atol", "--criterion",
                          "--restitution", "--output", "--dt", "--record", "--unit", "--record-dt"});
    auto has = [&](const char* f) { return a.values.count(f) > 0; };
    auto num = [&](const char* f) { return number(f, a.values.at(f)); };
    if (!has("--alpha")) throw UsageError("--alpha is required");
    const double alpha = num("--alpha");
    const int geometry = has("--p") + has("--half-height") + has("--height");
    if (geometry != 1) throw UsageError("give exactly one of --p, --half-height and --height");
    Model model;
    try {
        model.block = has("--p") ? Block::from_p(num("--p"), alpha)
                                 : has("--half-height") ? Block::from_half_height(num("--half-height"), alpha)
                                                        : Block::from_full_height(num("--height"), alpha);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    const std::string model_name = has("--model") ? a.values.at("--model") : "linearised";
    if (model_name == "full") model.equation = Equation::full;
    else if (model_name != "linearised") throw UsageError("--model: linearised or full (got " + model_name + ")");
    if (has("--restitution")) {
        const double e = restitution_option(a.values.at("--restitution"));
        model.restitution = std::isnan(e) ? housner_restitution(alpha) : e;
    }
    SimulationOptions options;
    try {
        options.solver.kind = has("--solver") ? parse_solver(a.values.at("--solver"))
                                              : (model.equation == Equation::full ? SolverKind::dopri5 : SolverKind::exact);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--solver: ") + e.what());
    }
    tolerance_options(a.values, alpha, options.solver);
    Criterion criterion = Criterion::final_rotation;
    try {
        if (has("--criterion")) criterion = parse_criterion(a.values.at("--criterion"));
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--criterion: ") + e.what());
    }
    // The amplitude as --pga G (in g) or --q Q (PGA = Q alpha g).
    auto pga_or_q = [&] { return has("--pga") ? num("--pga") : num("--q") * alpha; };
    std::unique_ptr<GroundInput> input;
    if (one_sine + has("--record") + (has("--case") || has("--train")) != 1)
        throw UsageError("give exactly one input: --case or --train, --one-sine, or --record");
    if (!has("--record") && (has("--unit") || has("--record-dt")))
        throw UsageError("--unit and --record-dt go with --record");
    if (has("--record")) {
        for (const char* f : {"--rd", "--to", "--x", "--pulses", "--ap", "--wp"})
            if (has(f)) throw UsageError(std::string(f) + " does not apply to --record");
        if (has("--pga") && has("--q")) throw UsageError("give at most one of --pga and --q");
        records::Record r = load_record(a.values.at("--record"), a, "--record-dt");
        std::vector<double> g = r.in_g(kGravity);
        const double peak = r.pga() / kGravity;
        auto brief = [](double v) {
            char text[32];
            std::snprintf(text, sizeof text, "%.6g", v);
            return std::string(text);
        };
        std::string name = r.name + " (" + std::to_string(g.size()) + " samples, dt = " + brief(r.dt) + " s, PGA " +
                           brief(peak) + " g";
        if (has("--pga") || has("--q")) {
            const double pga = pga_or_q();
            if (!(pga > 0)) throw UsageError("the PGA must be > 0");
            if (!(peak > 0)) throw UsageError(a.values.at("--record") + ": the record is zero throughout and cannot be scaled");
            for (double& v : g) v *= pga / peak;
            name += ", scaled to " + brief(pga) + " g";
        }
        input = std::make_unique<SampledInput>(std::move(g), r.dt, name + ")");
    } else if (one_sine) {
        if (!has("--ap") || !has("--wp")) throw UsageError("--one-sine needs --ap and --wp");
        // simulate() refuses a pulse slower than OneSinePulse::slowest_wp_over_p
        // times p (why: ground_input.hpp); said here in the option's terms.
        const double slowest = OneSinePulse::slowest_wp_over_p * model.block.p;
        if (num("--wp") > 0 && num("--wp") < slowest) {
            char text[200];
            std::snprintf(text, sizeof text,
                          "--wp: must be at least 1e-6 p = %.3g rad/s (got %g): slower pulses lift the block by less "
                          "than the rounding of the input",
                          slowest, num("--wp"));
            throw UsageError(text);
        }
        try {
            input = std::make_unique<OneSinePulse>(num("--ap"), num("--wp"), model.uplift_threshold());
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
    } else {
        std::string equation;
        const PulseTrain train = train_from(a, equation);
        if (has("--to") == has("--x")) throw UsageError("give exactly one of --to and --x");
        const double to = has("--to") ? num("--to") : num("--x") / model.block.p;
        if (!(to > 0)) throw UsageError("--to/--x: must be > 0");
        const int amplitude = has("--pga") + has("--q") + has("--rd");
        if (amplitude != 1) throw UsageError("give exactly one of --pga, --q and --rd");
        const double pga = has("--rd") ? num("--rd") * q_factor(train, model.block.p * to).q * alpha : pga_or_q();
        if (!(pga > 0)) throw UsageError("the PGA must be > 0");
        input = std::make_unique<PulseInput>(train, pga, to);
    }
    if (has("--output")) options.record_dt = has("--dt") ? num("--dt") : 0.01;
    if (has("--output") && !(options.record_dt > 0)) throw UsageError("--dt: must be > 0");
    const SimulationResult r = simulate(model, *input, options);
    char atol_rad[48];
    std::snprintf(atol_rad, sizeof atol_rad, " = %g rad", options.solver.atol_alpha * alpha);
    const std::string tolerance = options.solver.kind == SolverKind::exact
                                      ? std::string(" (closed form between events)")
                                      : " (" + tolerance_text(options.solver) + atol_rad + ")";
    if (has("--output")) {
        harness::Table table({"t", "theta_over_alpha", "omega_over_alpha_p"});
        table.note("model", model.describe());
        table.note("input", input->describe());
        table.note("solver", solver_name(options.solver.kind) + tolerance);
        table.note("criterion", criterion_name(criterion));
        for (const Sample& s : r.samples)
            table.row().add(s.t).add(s.theta / alpha).add(s.omega / (alpha * model.block.p));
        table.write(a.values.at("--output"));
    }
    const bool collapse = r.collapse(criterion, alpha);
    // The block starts at rest and rocks only once |a| > the threshold (eq. 3: alpha g; eq. 1: g tan alpha).
    const bool lifts = input->peak() > model.uplift_threshold();
    if (a.json) {
        auto b = [](bool v) { return v ? "true" : "false"; };
        std::cout << "{\"model\": " << json_string(model.describe()) << ", \"input\": " << json_string(input->describe())
                  << ", \"solver\": " << json_string(solver_name(options.solver.kind))
                  << ", \"rtol\": " << harness::format_number(options.solver.rtol)
                  << ", \"atol_rad\": " << harness::format_number(options.solver.atol_alpha * alpha)
                  << ", \"criterion\": " << json_string(criterion_name(criterion)) << ", \"collapse\": " << b(collapse)
                  << ", \"t_fin\": " << harness::format_number(r.t_fin)
                  << ", \"theta_tfin_over_alpha\": "
                  << (r.overturned_during_input ? "null" : harness::format_number(r.theta_at_tfin / alpha))
                  << ", \"max_theta_input_over_alpha\": " << harness::format_number(r.max_abs_theta_input / alpha)
                  << ", \"input_lifts_block\": " << b(lifts)
                  << ", \"impacts\": " << r.impacts << ", \"overturned\": " << b(r.overturned)
                  << ", \"overturned_during_input\": " << b(r.overturned_during_input)
                  << ", \"t_overturn\": " << (std::isnan(r.t_overturn) ? "null" : harness::format_number(r.t_overturn))
                  << ", \"collapse_final_rotation\": " << b(r.collapse(Criterion::final_rotation, alpha))
                  << ", \"collapse_peak_rotation\": " << b(r.collapse(Criterion::peak_rotation, alpha))
                  << ", \"collapse_overturning\": " << b(r.collapse(Criterion::overturning, alpha)) << "}\n";
    } else {
        std::printf("%s under %s\n", collapse ? "COLLAPSE" : "no collapse", criterion_name(criterion).c_str());
        std::printf("  model:  %s\n  input:  %s\n  solver: %s%s\n", model.describe().c_str(), input->describe().c_str(),
                    solver_name(options.solver.kind).c_str(), tolerance.c_str());
        // A block that fell during the input has no theta(t_fin) to print: it lies on the ground.
        if (r.overturned_during_input)
            std::printf("  fell at t = %.10g s, before t_fin = %g s: |theta| reached the fall angle, %.10g alpha\n",
                        r.t_overturn, r.t_fin, options.overturn_angle / alpha);
        else
            std::printf("  theta(t_fin)/alpha = %.10g at t_fin = %g s; max |theta|/alpha during the input = %.10g\n",
                        r.theta_at_tfin / alpha, r.t_fin, r.max_abs_theta_input / alpha);
        const std::string when = !r.overturned ? ""
                                 : std::isnan(r.t_overturn)
                                     ? " (the free rocking followed, 200/p, ended before the fall; decided from its energy and side of the top)"
                                     : " (at t = " + harness::format_number(r.t_overturn) + " s)";
        // Without this line a zero theta reads like a result of the dynamics;
        // it is the input that stays at or below the uplift threshold.
        if (!lifts)
            std::printf("  the input never lifts the block: its peak, %.6g g, is at or below the uplift threshold %s = %.6g g\n",
                        input->peak(), model.equation == Equation::full ? "tan alpha" : "alpha", model.uplift_threshold());
        std::printf("  impacts: %d; overturns (free rocking included): %s%s\n", r.impacts, r.overturned ? "yes" : "no",
                    when.c_str());
        std::printf("  final-rotation: %s; peak-rotation: %s; overturning: %s\n",
                    r.collapse(Criterion::final_rotation, alpha) ? "collapse" : "safe",
                    r.collapse(Criterion::peak_rotation, alpha) ? "collapse" : "safe",
                    r.collapse(Criterion::overturning, alpha) ? "collapse" : "safe");
    }
    return 0;
}

int cmd_record(int argc, char** argv) {
    if (argc < 4 || std::string(argv[2]) != "info") throw UsageError("usage: rocking record info FILE [--json]");
    const std::string path = file_argument(argc, argv, 3, "usage: rocking record info FILE [--json]");
    const Args a = parse(argc, argv, 4, {"--unit", "--dt"});
    const records::Record r = load_record(path, a);
    const records::HalfPeriods h = half_periods_of(r, path);
    if (a.json) {
        std::cout << "{\"file\": " << json_string(path) << ", \"format\": " << json_string(r.format)
                  << ", \"name\": " << json_string(r.name) << ", \"samples\": " << r.accel.size()
                  << ", \"dt\": " << harness::format_number(r.dt) << ", \"pga_ms2\": " << harness::format_number(h.pga)
                  << ", \"pgv_ms\": " << harness::format_number(h.pgv) << ", \"amax_ms\": " << harness::format_number(h.amax)
                  << ", \"to\": [";
        for (int k = 0; k < 11; ++k) std::cout << (k ? ", " : "") << harness::format_number(h.to[k]);
        std::cout << "]}\n";
    } else {
        std::printf("%s (%s): %zu samples, dt = %g s, %.2f s\n", r.name.c_str(), r.format.c_str(), r.accel.size(), r.dt,
                    r.duration());
        std::printf("  PGA = %s m/s^2 (%s g), PGV = %s m/s, Amax = %s m/s\n", four(h.pga).c_str(),
                    four(h.pga / dynamics::kGravity).c_str(), four(h.pgv).c_str(), four(h.amax).c_str());
        static const char* what[] = {"largest-area pulse", "pulse holding the PGA", "sine of same PGA and area (eq. 29)",
                                     "constant of same PGA and area (eq. 30)", "pi PGV / PGA (eq. 31)",
                                     "Fourier peak, acceleration", "Fourier peak, velocity", "CWT max amplitude, acceleration",
                                     "CWT mean amplitude, velocity", "CWT energy, acceleration", "CWT energy, velocity"};
        for (int k = 0; k < 11; ++k) std::printf("  to_%-2d = %.4f s  %s\n", k + 1, h.to[k], what[k]);
    }
    return 0;
}

int cmd_collapse(int argc, char** argv) {
    using namespace rocking::dynamics;
    const std::string path = file_argument(argc, argv, 2, "usage: rocking collapse FILE --alpha A [options]");
    const Args a = parse(argc, argv, 3,
                         {"--alpha", "--model", "--solver", "--criterion", "--restitution", "--rtol", "--atol", "--unit", "--dt"});
    if (!a.values.count("--alpha")) throw UsageError("--alpha is required");
    const double alpha = number("--alpha", a.values.at("--alpha"));
    if (!(alpha > 0 && alpha < 0.7)) throw UsageError("--alpha: must be in (0, 0.7)");
    records::CollapseOptions o;
    if (a.values.count("--model")) {
        const std::string m = a.values.at("--model");
        if (m == "full") o.equation = Equation::full, o.solver.kind = SolverKind::dopri5;
        else if (m != "linearised") throw UsageError("--model: linearised or full");
    }
    try {
        if (a.values.count("--solver")) o.solver.kind = parse_solver(a.values.at("--solver"));
        if (a.values.count("--criterion")) o.criterion = parse_criterion(a.values.at("--criterion"));
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    tolerance_options(a.values, alpha, o.solver);
    if (a.values.count("--restitution")) {
        const double e = restitution_option(a.values.at("--restitution"));
        o.housner_restitution = std::isnan(e);
        if (!o.housner_restitution) o.restitution = e;
    }
    if (o.equation == Equation::full && o.solver.kind == SolverKind::exact)
        throw UsageError("the exact solver handles the linearised equation only");
    const records::Record r = load_record(path, a);
    const SampledInput input(r.in_g(kGravity), r.dt, r.name);
    const records::CollapseResult c = records::smallest_collapse_p(input, alpha, o);
    if (a.json) {
        std::cout << "{\"file\": " << json_string(path) << ", \"alpha\": " << harness::format_number(alpha)
                  << ", \"found\": " << (c.found ? "true" : "false")
                  << ", \"p\": " << (c.found ? harness::format_number(c.p) : std::string("null"))
                  << ", \"p_safe\": " << (c.found && !c.below_range() ? harness::format_number(c.p_safe) : std::string("null"))
                  << ", \"below_range\": " << (c.below_range() ? "true" : "false") << ", \"simulations\": " << c.simulations
                  << ", \"search\": " << json_string(o.describe()) << "}\n";
    } else {
        if (c.below_range())
            std::printf("p <= %.6f rad/s: %s overturns the block (alpha = %g) already at the search's lowest "
                        "pulsation; the smallest one that overturns it lies at or below that, outside the search\n",
                        c.p, r.name.c_str(), alpha);
        else if (c.found)
            std::printf("p = %.6f rad/s: the first pulsation of the search at which %s overturns the block "
                        "(alpha = %g); it does not at %.6f. Not a bound: the overturning p do not form an interval, "
                        "and a lower p may overturn it too (docs/findings.md, T1b)\n",
                        c.p, r.name.c_str(), alpha, c.p_safe);
        else {
            // Below the uplift threshold no p can move the block: say so, or the
            // scan's "up to 30 rad/s" reads as if a larger p might.
            Model m;  // any p: the threshold depends on alpha and the equation only
            m.equation = o.equation;
            m.block = Block::from_p(1.0, alpha);
            const double pga_g = r.pga() / kGravity, thr = m.uplift_threshold();
            if (pga_g <= thr)
                std::printf("no collapse for p up to %g rad/s: the record never lifts the block at all (PGA %.6g g <= "
                            "%s = %.6g)\n",
                            o.p_max, pga_g, o.equation == Equation::full ? "tan alpha" : "alpha", thr);
            else std::printf("no collapse for p up to %g rad/s\n", o.p_max);
        }
        std::printf("  %s; %d simulations\n", o.describe().c_str(), c.simulations);
    }
    return 0;
}

int cmd_assess(int argc, char** argv) {
    using namespace rocking::dynamics;
    const std::string path =
        file_argument(argc, argv, 2, "usage: rocking assess FILE --alpha A (--height H | --half-height h)");
    const Args a = parse(argc, argv, 3, {"--alpha", "--height", "--half-height", "--unit", "--dt"});
    if (!a.values.count("--alpha")) throw UsageError("--alpha is required");
    const double alpha = number("--alpha", a.values.at("--alpha"));
    if (a.values.count("--height") + a.values.count("--half-height") != 1)
        throw UsageError("give exactly one of --height and --half-height");
    Block b{};
    try {
        b = a.values.count("--height") ? Block::from_full_height(number("--height", a.values.at("--height")), alpha)
                                       : Block::from_half_height(number("--half-height", a.values.at("--half-height")), alpha);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    const records::Record r = load_record(path, a);
    const records::HalfPeriods h = half_periods_of(r, path);
    const double to5 = h.to[4], x = b.p * to5;
    if (!(x >= kSmallestX)) {
        char text[200];
        std::snprintf(text, sizeof text, "%s: the block's p (%.3g rad/s) times the record's to_5 (%.3g s) is below "
                      "1e-150, where eq. 27 overflows", a.values.count("--height") ? "--height" : "--half-height", b.p, to5);
        throw UsageError(text);
    }
    const double q27 = q2_n6(x), q_record = h.pga / (alpha * kGravity);
    const bool safe = q_record < q27;
    if (a.json) {
        std::cout << "{\"file\": " << json_string(path) << ", \"alpha\": " << harness::format_number(alpha)
                  << ", \"p\": " << harness::format_number(b.p) << ", \"to5\": " << harness::format_number(to5)
                  << ", \"x\": " << harness::format_number(x) << ", \"q_eq27\": " << harness::format_number(q27)
                  << ", \"q_record\": " << harness::format_number(q_record) << ", \"passes\": " << (safe ? "true" : "false")
                  << "}\n";
    } else {
        std::printf("%s: %s\n", r.name.c_str(), safe ? "PASSES (the record's q is below eq. 27's)" : "FAILS");
        std::printf("  block: alpha = %g, p = %.4f rad/s (eqs. 2, 4, half-height %.3f m)\n", alpha, b.p, b.R * std::cos(alpha));
        std::printf("  record: PGA = %s g, to_5 = pi PGV/PGA = %.4f s; x = p to_5 = %.4f\n", four(h.pga / kGravity).c_str(),
                    to5, x);
        std::printf("  q from eq. 27 = %s; the record's q = PGA/(alpha g) = %s\n", four(q27).c_str(), four(q_record).c_str());
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string command = argc > 1 ? argv[1] : "";
    // "rocking simulate --help" asks for the usage, not for an option named
    // --help (no option takes a value spelled like this).
    bool help = command == "help";
    for (int i = 1; i < argc; ++i) help = help || std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h";
    if (help) {
        std::cout << kUsage;
        return 0;
    }
    try {
        if (command == "q") return cmd_q(argc, argv);
        if (command == "response") return cmd_response(argc, argv);
        if (command == "simulate") return cmd_simulate(argc, argv);
        if (command == "record") return cmd_record(argc, argv);
        if (command == "collapse") return cmd_collapse(argc, argv);
        if (command == "assess") return cmd_assess(argc, argv);
        throw UsageError(command.empty() ? "no command given" : "unknown command '" + command + "'");
    } catch (const UsageError& e) {
        // The whole usage would bury the one line that says what is wrong.
        std::cerr << "rocking" << (command.empty() ? "" : " " + command) << ": " << e.what() << "\n";
        if (command.empty()) std::cerr << kUsage;
        else std::cerr << "run 'rocking --help' for the usage\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "rocking " << command << ": " << e.what() << "\n";
        return 1;
    }
}
