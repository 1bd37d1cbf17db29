// The command line's shared pieces (options.hpp).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/pool.hpp"
#include "cli/options.hpp"

#include "records/synthetic.hpp"

#include "records/floor_motion.hpp"
#include "harness/output_paths.hpp"
#include "studies/overturning_set.hpp"
#include "harness/table.hpp"
#include "numerics/number_text.hpp"

namespace rocking::cli {

// The one number reader's rules and messages (numerics/number_text.hpp), under the option's name.
double number(const std::string& flag, const std::string& text) {
    try {
        return numerics::parameter_number(text);
    } catch (const std::invalid_argument& e) {
        throw UsageError(flag + ": " + e.what());
    }
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

int integer(const std::string& flag, const std::string& text, int lo, int hi) {
    try {
        return static_cast<int>(numerics::whole_number(text, lo, hi));
    } catch (const std::invalid_argument& e) {
        throw UsageError(flag + ": " + e.what());
    }
}

namespace {
std::vector<std::string> comma_pieces(const std::string& text) {
    std::vector<std::string> pieces;
    std::size_t from = 0;
    for (std::size_t at; (at = text.find(',', from)) != std::string::npos; from = at + 1)
        pieces.push_back(text.substr(from, at - from));
    pieces.push_back(text.substr(from));
    return pieces;
}
}  // namespace

std::vector<double> number_list(const std::string& flag, const std::string& text) {
    std::vector<double> values;
    for (const std::string& piece : comma_pieces(text)) values.push_back(number(flag, piece));
    return values;
}

std::map<std::string, double> key_values(const std::string& flag, const std::string& text,
                                         const std::vector<std::string>& keys) {
    std::string known;
    for (const auto& k : keys) known += (known.empty() ? "" : ", ") + k;
    std::map<std::string, double> values;
    for (const std::string& piece : comma_pieces(text)) {
        const std::size_t eq = piece.find('=');
        if (eq == std::string::npos) throw UsageError(flag + ": '" + piece + "' is not key=value");
        const std::string key = piece.substr(0, eq);
        bool ok = false;
        for (const auto& k : keys) ok = ok || k == key;
        if (!ok) throw UsageError(flag + ": unknown key '" + key + "' (keys: " + known + ")");
        if (values.count(key)) throw UsageError(flag + ": " + key + " given twice");
        values[key] = number(flag + " " + key, piece.substr(eq + 1));
    }
    return values;
}

// The whole-number rule of every option (numerics::whole_number: "7", "7.0" and "7e0" are
// 7), in mt19937's range: it reads 32 bits and takes 0 as its default seed.
std::uint64_t seed_option(const std::string& flag, const std::string& text) {
    try {
        return static_cast<std::uint64_t>(numerics::whole_number(text, 1, 0xFFFFFFFFll));
    } catch (const std::invalid_argument& e) {
        throw UsageError(flag + ": the seed " + e.what());
    }
}

Bootstrap bootstrap_options(const Args& a) {
    Bootstrap b;
    if (a.values.count("--bootstrap")) {
        const std::string& text = a.values.at("--bootstrap");
        try {
            b.resamples = static_cast<int>(numerics::whole_number(text, 0, 100000));
        } catch (const std::invalid_argument&) {
            b.resamples = -1;
        }
        if (b.resamples < 0 || b.resamples == 1)
            throw UsageError("--bootstrap: must be 0 (none) or from 2 to 100000 resamples (got " + text + ")");
    }
    if (a.values.count("--seed") && !a.values.count("--bootstrap")) throw UsageError("--seed goes with --bootstrap");
    if (b.resamples > 0 && !a.values.count("--seed"))
        throw UsageError("--bootstrap needs --seed (the interval is reproducible only from a stated seed)");
    if (a.values.count("--seed")) b.seed = seed_option("--seed", a.values.at("--seed"));
    return b;
}

MethodChoice method_options(const Args& a, const std::string& unit) {
    MethodChoice m;
    if (a.values.count("--method")) {
        const std::string& name = a.values.at("--method");
        if (name != "grid" && name != "refine") throw UsageError("--method: grid or refine (got '" + name + "')");
        m.refine = name == "refine";
    }
    for (const char* flag : {"--width", "--robust-width"})
        if (a.values.count(flag) && !m.refine) throw UsageError(std::string(flag) + " goes with --method refine");
    if (a.values.count("--width")) {
        m.width = number("--width", a.values.at("--width"));
        if (!studies::in_width_range(m.width))
            throw UsageError(std::string("--width: must be in ") + studies::kWidthRange + " (in ln " + unit + ")");
    }
    if (a.values.count("--robust-width")) {
        m.robust_width = number("--robust-width", a.values.at("--robust-width"));
        if (!studies::in_robust_width_range(m.robust_width))
            throw UsageError(std::string("--robust-width: must be in ") + studies::kRobustWidthRange + " (in ln " + unit +
                             ")");
    }
    return m;
}

int jobs_option(const Args& a) {
    if (!a.values.count("--jobs")) return batch::default_threads();
    try {
        return batch::parse_threads(a.values.at("--jobs"));
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

// The FILE a subcommand takes first: an option there (rocking collapse
// --alpha 0.15 FILE) was read as the file, and its value as an unknown option.
std::string file_argument(int argc, char** argv, int at, const std::string& usage) {
    if (argc <= at) throw UsageError(usage);
    const std::string path = argv[at];
    if (path.rfind("--", 0) == 0) throw UsageError("FILE comes first, before '" + path + "': " + usage);
    return path;
}

std::vector<std::string> file_arguments(int argc, char** argv, int& first_option, const std::string& usage) {
    std::vector<std::string> files;
    int i = 2;
    for (; i < argc && std::string(argv[i]).rfind("--", 0) != 0; ++i) files.push_back(argv[i]);
    if (files.empty())
        throw UsageError(argc > 2 ? "FILE comes first, before '" + std::string(argv[2]) + "': " + usage : usage);
    first_option = i;
    return files;
}

void check_outputs(const Args& a, const std::vector<std::string>& output_flags, const std::vector<std::string>& inputs,
                   const std::string& input_role) {
    std::vector<harness::NamedPath> outputs, files;
    for (const std::string& flag : output_flags)
        if (a.values.count(flag)) outputs.push_back({flag, a.values.at(flag)});
    for (const std::string& path : inputs) files.push_back({input_role, path});
    try {
        for (const harness::NamedPath& out : outputs) harness::refuse_empty_name(out);
        harness::refuse_outputs_over_inputs(outputs, files);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    for (const harness::NamedPath& out : outputs) harness::check_writable(out);
}

void refuse_unresolvable_run(double p, double duration, const Args& a, const std::vector<std::string>& culprits,
                             const std::string& path) {
    const std::string why = dynamics::unresolvable_run(p, duration);
    if (why.empty()) return;
    std::string given;
    for (const std::string& flag : culprits)
        if (a.values.count(flag)) given += (given.empty() ? "" : ", ") + flag + " " + a.values.at(flag);
    if (given.empty()) throw std::runtime_error(path + ": " + why);
    throw UsageError(given + ": " + why);
}

void write_output(const harness::Table& table, const std::string& path) {
    try {
        table.write(path);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string("--output: ") + e.what());
    }
}

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

std::vector<char*> without_engine_switches(int argc, char** argv, bool& resume, bool& quiet) {
    std::vector<char*> args(argv, argv + argc);
    for (auto it = args.begin() + (argc > 2 ? 2 : argc); it != args.end();) {
        const std::string flag = *it;
        if (flag == "--resume") resume = true, it = args.erase(it);
        else if (flag == "--quiet") quiet = true, it = args.erase(it);
        else ++it;
    }
    return args;
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
            // The mirror image of a leaning block leans the other way.
            const bool leans = (a.values.count("--lean") || a.values.count("--out-of-plumb")) &&
                               std::string(e.what()).find("first pulse must be positive") != std::string::npos;
            throw UsageError(std::string("--train: ") + e.what() +
                             (leans ? "; flip the signs of --lean and --out-of-plumb with it" : ""));
        }
    }
    const int which = integer("--case", a.values.at("--case"), 1, 5);
    const int n = a.values.count("--pulses") ? integer("--pulses", a.values.at("--pulses"), 1, 1000) : 2;
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
std::string significant(double v, int n) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*g", n, v);
    return text;
}

std::string four(double v) {
    char buf[64];
    // Four decimals would print a tiny PGA as 0.0000: below 1e-3, four significant digits.
    const bool wide = std::fabs(v) >= 1e9 || (v != 0 && std::fabs(v) < 1e-3);
    std::snprintf(buf, sizeof buf, wide ? "%.4e" : "%.4f", v);
    return buf;
}

namespace {

// The first of the half-periods' measures that is not finite, or null.
const char* first_not_finite(const records::HalfPeriods& h) {
    if (!std::isfinite(h.pga)) return "PGA";
    if (!std::isfinite(h.pgv)) return "PGV";
    if (!std::isfinite(h.amax)) return "Amax";
    static const char* to[] = {"to_1", "to_2", "to_3", "to_4", "to_5", "to_6", "to_7", "to_8", "to_9", "to_10", "to_11"};
    for (int k = 0; k < 11; ++k)
        if (!std::isfinite(h.to[k])) return to[k];
    return nullptr;
}

}  // namespace

// The record's half-periods; a record they cannot be measured on is refused
// with its file's name.  Samples near the largest double overflow once
// integrated: PGV and to_4 came out inf and to_3 nan, and with a longer step
// the measures crashed; the sum of |a| dt bounds the velocity and every
// pulse's area, so it is checked before and each measure after.
void refuse_overflowing_velocity(const records::Record& r, const std::string& path) {
    double bound = 0;
    for (double a : r.accel) bound += std::fabs(a) * r.dt;
    if (!std::isfinite(bound))
        throw std::runtime_error(path + ": the record's velocity overflows a double (the sum of |a| dt exceeds "
                                        "1.8e308 m/s); scale the record down");
}

records::HalfPeriods half_periods_of(const records::Record& r, const std::string& path) {
    refuse_overflowing_velocity(r, path);
    records::HalfPeriods h;
    try {
        h = records::half_periods(r);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
    if (const char* which = first_not_finite(h))
        throw std::runtime_error(path + ": the record's " + which +
                                 " overflows a double; its samples are too large to measure (scale the record down)");
    return h;
}

// A record file by content; --unit (and, for one column, the sampling step
// under dt_flag) reads a plain-text one, and leaves an ESM or AT2 file, which
// states its own, to its format: a study may mix the three.
// --unit and --dt apply to plain-text records only (records::read_with_unit): a file that
// states its own unit and step (ESM, AT2) is read as it says, with them or without, in
// every command alike, so that `record info r.AT2 --dt 0.01` reads r.AT2 as fragility and
// eq27 read it beside a text record; only a plain-text file needs --unit.
namespace {

records::Record read_ground(const std::string& path, const Args& a, const std::string& dt_flag) {
    if (!a.values.count("--unit") && !a.values.count(dt_flag)) return records::read_any(path);
    if (a.values.count("--unit")) {
        const std::string& unit = a.values.at("--unit");
        if (unit != "g" && unit != "m/s2" && unit != "cm/s2")
            throw UsageError("--unit: '" + unit + "' is not a unit it knows (g, m/s2, cm/s2)");
    }
    const double dt = a.values.count(dt_flag) ? number(dt_flag, a.values.at(dt_flag)) : 0.0;
    // 0 would read as "not given" (a two-column file), and a negative
    // step was reported against the file's line 0.
    if (a.values.count(dt_flag) && !(dt > 0)) throw UsageError(dt_flag + ": must be > 0 (got " + a.values.at(dt_flag) + ")");
    if (a.values.count("--unit")) return records::read_with_unit(path, a.values.at("--unit"), dt);
    const std::string text = records::read_text(path);
    if (records::states_its_units(text)) return records::parse_any(text, path);
    throw UsageError("--unit is required for a plain-text record (g, m/s2, cm/s2), as " + path + " is (" + dt_flag +
                     " sets its step, and applies to plain-text records only)");
}

}  // namespace

// --floor T1,G[,zeta] (issue 40): the floor's motion of the building's first
// mode in place of the ground's, the record's name stating the model, so that
// every output that names its input names the floor.
void write_record_samples(harness::AtomicFile& out, const records::Record& r) {
    out.write("# columns: t (s), acceleration (m/s^2); read with --unit m/s2\n");
    std::string lines;
    for (std::size_t k = 0; k < r.accel.size(); ++k) {
        lines += harness::format_number(r.dt * k) + "," + harness::format_number(r.accel[k]) + "\n";
        if (lines.size() > (1u << 20)) out.write(lines), lines.clear();
    }
    out.write(lines);
}

std::string floor_input_note(const Args& a) {
    if (!a.values.count("--floor")) return "";
    records::FloorModel m;
    try {
        m = records::parse_floor_model(a.values.at("--floor"));
    } catch (const std::invalid_argument& e) {
        throw UsageError("--floor: " + std::string(e.what()));
    }
    return records::describe_as_input(m);
}

double friction_option(const Args& a) {
    const std::string& text = a.values.at("--friction");
    const double mu = number("--friction", text);
    if (!(mu > 0 && mu <= 1e6))
        throw UsageError("--friction: the friction coefficient must be in (0, 1e6] (got " + text + ")");
    return mu;
}

void friction_into(const Args& a, records::CollapseOptions& model) {
    if (!a.values.count("--friction")) return;
    if (a.values.count("--restitution"))
        throw UsageError("--restitution does not apply with --friction: the sliding-rocking model's impacts follow "
                         "from impulse and momentum (Housner's restitution where the corner sticks)");
    model.friction = friction_option(a);
}

void restitution_into(const Args& a, records::CollapseOptions& model) {
    if (!a.values.count("--restitution")) return;
    const double e = restitution_option(a.values.at("--restitution"));
    model.housner_restitution = std::isnan(e);
    if (!model.housner_restitution) model.restitution = e;
}

records::Record load_record(const std::string& path, const Args& a, const std::string& dt_flag) {
    records::Record ground = read_ground(path, a, dt_flag);
    if (!a.values.count("--floor")) return ground;
    records::FloorModel m;
    try {
        m = records::parse_floor_model(a.values.at("--floor"));
    } catch (const std::invalid_argument& e) {
        throw UsageError("--floor: " + std::string(e.what()) + " (T1,G[,zeta]: the building's first period in s, the "
                         "floor's participation Gamma phi, the damping ratio)");
    }
    try {
        records::Record floor = records::floor_record(ground, m);
        // record floor prints these; every other command read the floor without them.
        for (const std::string& w : records::warnings_of(floor))
            std::fprintf(stderr, "rocking: warning: %s: --floor %s: %s\n", path.c_str(), a.values.at("--floor").c_str(),
                         w.c_str());
        return floor;
    } catch (const std::overflow_error& e) {
        throw std::runtime_error(path + ": --floor " + a.values.at("--floor") + ": " + e.what());
    } catch (const std::invalid_argument& e) {
        throw UsageError("--floor " + a.values.at("--floor") + " on " + path + ": " + e.what());
    }
}

std::string rows_note(double dt, double t_fin, double last_t) {
    return "t = k dt for k = 0, 1, ... while the run lasts (dt = " + significant(dt, 6) + " s; the input to t_fin = " +
           significant(t_fin, 6) + " s, then the free rocking to rest, a fall or its limit); the last row at t = " +
           significant(last_t, 6) + " s";
}

}  // namespace rocking::cli
