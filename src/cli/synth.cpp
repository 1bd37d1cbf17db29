// rocking record synth: a synthetic record (records/synthetic.hpp), summarized on
// standard output and, with --output, written as time,acceleration text that
// `record info FILE --unit m/s2` reads back.
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/json_text.hpp"
#include "json/record_json.hpp"
#include "cli/options.hpp"
#include "harness/atomic_file.hpp"
#include "harness/table.hpp"
#include "numerics/number_text.hpp"
#include "records/synthetic.hpp"

namespace rocking::cli {

namespace {

double positive(const Args& a, const std::string& flag) {
    if (!a.values.count(flag)) throw UsageError(flag + " is required");
    const double v = number(flag, a.values.at(flag));
    if (!(v > 0)) throw UsageError(flag + ": must be > 0 (got " + a.values.at(flag) + ")");
    return v;
}

// --pulse A,fp,nu,gamma[,t0]; t0 defaults to gamma/(2 fp), where the pulse starts at t = 0.
records::PulseParameters pulse_from(const std::string& text) {
    const std::vector<double> v = number_list("--pulse", text);
    if (v.size() != 4 && v.size() != 5)
        throw UsageError("--pulse: takes A,fp,nu,gamma[,t0] (m/s, Hz, rad, -, s), got " + std::to_string(v.size()) +
                         " values");
    records::PulseParameters p{v[0], v[1], v[2], v[3], 0};
    p.t0 = v.size() == 5 ? v[4] : (p.fp > 0 ? p.gamma / (2 * p.fp) : 0);
    return p;
}

// --params key=value,...: records::stochastic_parameters_from's names.
std::map<std::string, double> params_from(const Args& a) {
    if (!a.values.count("--params")) return {};
    return key_values("--params", a.values.at("--params"), records::stochastic_parameter_names());
}

// The option that set a frequency the step cannot represent: --pulse (fp, gamma), --params
// when it gave one of the frequency's parameters, else --dt (a default's frequency: the
// step is the user's only say in it).
std::string sampling_option(const records::SamplingError& e, bool pulse, const std::map<std::string, double>& params) {
    if (pulse) return "--pulse";
    const bool given = std::any_of(e.parameters.begin(), e.parameters.end(),
                                   [&](const std::string& key) { return params.count(key) > 0; });
    return given ? "--params" : "--dt";
}

// '#' lines naming the generator and every parameter, then t,a rows: the plain
// reader skips the '#' lines and takes the rest as two columns.
void write_two_columns(const records::Record& r, const std::string& path) {
    harness::AtomicFile out(path);
    out.write("# generator: " + r.header.at("generator") + "\n");
    out.write("# name: " + r.name + "\n");
    for (const auto& [key, value] : r.header)
        if (key != "generator") out.write("# " + key + ": " + value + "\n");
    write_record_samples(out, r);
    out.commit();
}

void print_summary(const records::Record& r, const records::PeakMotion& m, const std::string& output, bool json) {
    if (json) {
        std::cout << json_text(json::synthetic_record_json(r, m, output)) << "\n";
        return;
    }
    std::printf("%s (%s): %zu samples, dt = %g s, %.2f s\n", r.name.c_str(), r.format.c_str(), r.accel.size(), r.dt,
                r.duration());
    std::printf("  generator: %s\n", r.header.at("generator").c_str());
    for (const auto& [key, value] : r.header)
        if (key != "generator" && key != "warning") std::printf("  %s = %s\n", key.c_str(), value.c_str());
    std::printf("  PGA = %s m/s^2 (%s g), PGV = %s m/s, to_5 = %s s\n", four(m.pga).c_str(),
                four(m.pga / dynamics::kGravity).c_str(), four(m.pgv).c_str(), four(m.to5).c_str());
    if (!output.empty()) std::printf("  written to %s (t, acceleration in m/s^2)\n", output.c_str());
}

}  // namespace

int cmd_record_synth(int argc, char** argv) {
    const Args a = parse(argc, argv, 3, {"--pulse", "--stochastic", "--params", "--dt", "--duration", "--output"});
    const bool pulse = a.values.count("--pulse"), stochastic = a.values.count("--stochastic");
    if (pulse == stochastic) throw UsageError("give exactly one of --pulse A,fp,nu,gamma[,t0] and --stochastic SEED");
    if (pulse && a.values.count("--params")) throw UsageError("--params goes with --stochastic");
    const double dt = positive(a, "--dt"), duration = positive(a, "--duration");
    const std::string flag = pulse ? "--pulse" : a.values.count("--params") ? "--params" : "--stochastic";
    check_outputs(a, {"--output"}, {});
    const std::map<std::string, double> params = pulse ? std::map<std::string, double>{} : params_from(a);
    records::Record r;
    try {
        if (pulse) {
            r = records::pulse_record(pulse_from(a.values.at("--pulse")), dt, duration);
        } else {
            const std::uint64_t seed = seed_option("--stochastic", a.values.at("--stochastic"));
            r = records::stochastic_record(
                params.empty() ? records::default_stochastic_parameters() : records::stochastic_parameters_from(params),
                seed, dt, duration);
        }
    } catch (const records::SamplingError& e) {
        throw UsageError(sampling_option(e, pulse, params) + ": " + e.what());
    } catch (const std::invalid_argument& e) {
        // The option to change: the duration for the sample cap, else the generator's.
        const std::string what = e.what();
        throw UsageError((what.rfind("duration/dt", 0) == 0 ? "--duration" : flag) + ": " + what);
    }
    for (const std::string& w : records::warnings_of(r)) std::cerr << "rocking record: warning: " << w << "\n";
    const std::string output = a.values.count("--output") ? a.values.at("--output") : "";
    if (!output.empty()) write_two_columns(r, output);
    print_summary(r, records::peak_motion(r.accel, r.dt), output, a.json);
    return 0;
}

}  // namespace rocking::cli
