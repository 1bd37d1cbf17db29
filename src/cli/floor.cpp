// rocking record floor: the motion of a floor of a building idealised as its first mode
// (records/floor_motion.hpp, docs/floor_motion.md), from a ground record; summarized on
// standard output and, with --output, written as time,acceleration text that
// `record info FILE --unit m/s2` and `simulate --record FILE --unit m/s2` read back.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>

#include "cli/help.hpp"
#include "cli/json_text.hpp"
#include "json/record_json.hpp"
#include "cli/options.hpp"
#include "harness/atomic_file.hpp"
#include "harness/table.hpp"
#include "records/floor_motion.hpp"
#include "records/synthetic.hpp"

namespace rocking::cli {

namespace {

// The option that sets each of FloorModel's parameters.
std::string option_of(const std::string& parameter) {
    if (parameter == "T1") return "--period";
    if (parameter == "zeta") return "--damping";
    return "--participation";
}

records::FloorModel model_from(const Args& a) {
    for (const char* flag : {"--period", "--participation"})
        if (!a.values.count(flag)) throw UsageError(std::string(flag) + " is required: " + usage_line("record floor"));
    records::FloorModel m;
    m.T1 = number("--period", a.values.at("--period"));
    m.G = number("--participation", a.values.at("--participation"));
    if (a.values.count("--damping")) m.zeta = number("--damping", a.values.at("--damping"));
    try {
        records::check_floor_model(m);
    } catch (const records::FloorModelError& e) {
        throw UsageError(option_of(e.parameter) + ": " + e.what());
    }
    return m;
}

// A header's value on one '#' line: a file's name or a record's name may hold a line break,
// which would end the comment and leave the rest as a sample line the reader refuses.
std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s;
}

// '#' lines stating the model, the method and every parameter, then t,a rows: the plain
// reader skips the '#' lines and takes the rest as two columns.
void write_floor(const records::Record& r, const std::string& path) {
    harness::AtomicFile out(path);
    out.write("# model: " + r.header.at("model") + "\n");
    out.write("# method: " + r.header.at("method") + "\n");
    out.write("# name: " + one_line(r.name) + "\n");
    for (const auto& [key, value] : r.header)
        if (key != "model" && key != "method") out.write("# " + key + ": " + one_line(value) + "\n");
    out.write("# samples: as many as the ground record's, at its dt: the floor record ends with it, without the "
              "building's free vibration after it (end_amplitude_m_s2)\n");
    write_record_samples(out, r);
    out.commit();
}

void print_summary(const std::string& path, const records::Record& ground, const records::Record& floor,
                   const records::FloorModel& m, const std::string& output, bool json) {
    const double pga_g = ground.pga(), pga_f = floor.pga();
    const double ratio = pga_g > 0 ? pga_f / pga_g : NAN;  // a ground at rest has no ratio
    const double end = std::stod(floor.header.at("end_amplitude_m_s2"));
    if (json) {
        std::cout << json_text(json::floor_record_json(path, ground, floor, m, output)) << "\n";
        return;
    }
    std::printf("floor of %s (%s): %zu samples, dt = %g s, %.2f s\n", ground.name.c_str(), ground.format.c_str(),
                floor.accel.size(), floor.dt, floor.duration());
    std::printf("  model: %s (docs/floor_motion.md)\n", records::describe(m).c_str());
    std::printf("  solution: %s\n", floor.header.at("method").c_str());
    std::printf("  ground PGA = %s m/s^2 (%s g); floor PGA = %s m/s^2 (%s g); floor/ground = %s\n", four(pga_g).c_str(),
                four(pga_g / dynamics::kGravity).c_str(), four(pga_f).c_str(), four(pga_f / dynamics::kGravity).c_str(),
                pga_g > 0 ? four(ratio).c_str() : "undefined (the ground is at rest)");
    std::printf("  at the record's end the floor still swings at %s m/s^2, decaying as exp(-zeta w t): the building's "
                "free vibration, not in the floor record\n",
                four(end).c_str());
    if (!output.empty()) std::printf("  written to %s (t, acceleration in m/s^2; read with --unit m/s2)\n", output.c_str());
}

}  // namespace

int cmd_record_floor(int argc, char** argv) {
    const std::string path = file_argument(argc, argv, 3, usage_line("record floor"));
    const Args a = parse(argc, argv, 4, {"--period", "--damping", "--participation", "--unit", "--dt", "--output"});
    const records::FloorModel m = model_from(a);
    check_outputs(a, {"--output"}, {path});
    const records::Record ground = load_record(path, a);
    records::Record floor;
    try {
        floor = records::floor_record(ground, m);
    } catch (const records::FloorModelError& e) {
        throw UsageError(option_of(e.parameter) + ": " + e.what());
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": " + e.what());  // a record whose floor overflows: the input's
    }
    for (const std::string& w : records::warnings_of(floor)) std::cerr << "rocking record: warning: " << w << "\n";
    const std::string output = a.values.count("--output") ? a.values.at("--output") : "";
    if (!output.empty()) write_floor(floor, output);
    print_summary(path, ground, floor, m, output, a.json);
    return 0;
}

}  // namespace rocking::cli
