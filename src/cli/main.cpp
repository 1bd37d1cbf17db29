// rocking: the q-factor of a slender rigid block under step pulses, for engineers.
//
//   rocking q --case I --x X [--pulses N] [--json]
//   rocking q --train A:d,A:d,... --x X [--json]
//   rocking response --case I --x X [--pulses N] [--q Q] [--steps K] [--json]
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/table.hpp"
#include "pulse/pulse_train.hpp"
#include "qfactor/superposition.hpp"

using namespace rocking;

namespace {

const char* kUsage =
    "usage: rocking q --case I --x X [--pulses N] [--json]\n"
    "       rocking q --train A:d,A:d,... --x X [--json]\n"
    "       rocking response --case I --x X [--pulses N] [--q Q] [--steps K] [--json]\n"
    "\n"
    "  --case I     input of Figure 3, I = 1..5 (amplitudes in PGA, durations in to)\n"
    "  --pulses N   repeat the case's pattern to N pulses (case 2, N = 6 is eq. 27)\n"
    "  --train ...  any train: amplitude:duration pairs, in units of PGA and to\n"
    "  --x X        x = p*to, X > 0\n"
    "  --q Q        response at this q instead of the collapse q\n"
    "  --steps K    number of time steps over [0, t_fin] (default 20)\n"
    "  --json       machine-readable output\n"
    "Model: linearised eq. 3, rocking on one corner without impact, collapse theta(t_fin) = alpha.\n";

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

int integer(const std::string& flag, const std::string& text) {
    const double v = number(flag, text);
    if (v != std::floor(v) || std::fabs(v) > 1e6) throw UsageError(flag + ": '" + text + "' is not a whole number");
    return static_cast<int>(v);
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
    return x;
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
                  << ", \"rocking_starts\": " << (e.onset ? "true" : "false")
                  << ", \"impact_free\": " << (e.stays_positive() ? "true" : "false")
                  << ", \"motion_reverses\": " << (e.min_dphi < 0 ? "true" : "false") << "}\n";
    } else {
        std::printf("q = %.10g\n", r.q);
        std::printf("  input %s (%zu pulses, t_fin = %g to), x = p*to = %g, %s\n", train.name().c_str(), train.size(),
                    train.t_fin(), x, equation.c_str());
        std::printf("  model: %s\n", kModel);
        std::printf("  rocking starts: %s; impact-free up to t_fin: %s; motion reverses before t_fin: %s\n",
                    e.onset ? "yes" : "no (q A_0 <= 1)", e.stays_positive() ? "yes" : "no",
                    e.min_dphi < 0 ? "yes" : "no");
        if (!e.stays_positive())
            std::printf("  warning: theta reaches %.3g alpha before t_fin: the closed form does not apply\n", e.min_phi);
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
    if (a.json) std::cout << "{\"input\": " << json_string(train.name()) << ", \"x\": " << harness::format_number(x)
                          << ", \"q\": " << harness::format_number(q) << ", \"model\": " << json_string(kModel)
                          << ", \"samples\": [";
    else std::printf("# %s, x = %g, q = %.10g; %s\n# t/to,theta/alpha,theta'/(alpha p)\n", train.name().c_str(), x, q, kModel);
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

}  // namespace

int main(int argc, char** argv) {
    const std::string command = argc > 1 ? argv[1] : "";
    try {
        if (command == "q") return cmd_q(argc, argv);
        if (command == "response") return cmd_response(argc, argv);
        if (command == "help" || command == "--help" || command == "-h") {
            std::cout << kUsage;
            return 0;
        }
        throw UsageError(command.empty() ? "no command given" : "unknown command '" + command + "'");
    } catch (const UsageError& e) {
        std::cerr << "rocking " << command << ": " << e.what() << "\n" << kUsage;
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "rocking " << command << ": " << e.what() << "\n";
        return 1;
    }
}
