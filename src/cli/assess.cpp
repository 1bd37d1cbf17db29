// rocking assess: the paper's check of a block against a record (eq. 27).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/geometry.hpp"
#include "cli/options.hpp"
#include "qfactor/closed_forms.hpp"
#include "harness/table.hpp"

namespace rocking::cli {

namespace {
// PGA, PGV and to_5 alone: the CWT and the Fourier peaks of the eleven half-periods
// took 1.1 s of a 30,001-sample record and assess reports none of them.
records::PeakMotion peak_motion_of(const records::Record& r, const std::string& path) {
    refuse_overflowing_velocity(r, path);
    try {
        return records::peak_motion(r.accel, r.dt);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}
}  // namespace

int cmd_assess(int argc, char** argv) {
    using namespace rocking::dynamics;
    const std::string path = file_argument(
        argc, argv, 2, "usage: rocking assess FILE (--thickness B --height H | --alpha A (--height H | --half-height h | --p P))");
    std::vector<std::string> allowed = {"--unit", "--dt"};
    allowed.insert(allowed.end(), geometry_flags().begin(), geometry_flags().end());
    const Args a = parse(argc, argv, 3, allowed);
    const GivenBlock given = block_option(a);
    const Block b = given.block;
    const double alpha = b.alpha;
    const records::Record r = load_record(path, a);
    const records::PeakMotion m = peak_motion_of(r, path);
    const double to5 = m.to5, x = b.p * to5;
    if (!(x >= kSmallestX)) {
        char text[200];
        std::snprintf(text, sizeof text, "%s: the block's p (%.3g rad/s) times the record's to_5 (%.3g s) is below "
                      "1e-150, where eq. 27 overflows", a.values.count("--height") ? "--height" : a.values.count("--half-height") ? "--half-height" : "--p", b.p, to5);
        throw UsageError(text);
    }
    const double q27 = q2_n6(x), q_record = m.pga / (alpha * kGravity);
    // A PGA near the largest double over a tiny alpha printed "q_record": inf.
    if (!std::isfinite(q_record))
        throw std::runtime_error(path + ": the record's q = PGA/(alpha g) overflows a double at alpha = " +
                                 significant(alpha, 6) + " (PGA = " + four(m.pga) + " m/s^2)");
    const bool safe = q_record < q27;
    if (a.json) {
        std::cout << "{\"file\": " << json_string(path) << ", \"alpha\": " << json_number(alpha)
                  << ", \"p\": " << json_number(b.p) << ", " << block_json(given) << ", \"to5\": " << json_number(to5)
                  << ", \"x\": " << json_number(x) << ", \"q_eq27\": " << json_number(q27)
                  << ", \"q_record\": " << json_number(q_record) << ", \"passes\": " << (safe ? "true" : "false")
                  << "}\n";
    } else {
        std::printf("%s: %s\n", r.name.c_str(), safe ? "PASSES (the record's q is below eq. 27's)" : "FAILS");
        // four(): a tiny --height gives a p of 1e150, which %.4f printed in 150 digits.
        std::printf("  block: %s\n", describe_block(given).c_str());
        std::printf("  record: PGA = %s g, to_5 = pi PGV/PGA = %s s; x = p to_5 = %s\n", four(m.pga / kGravity).c_str(),
                    four(to5).c_str(), four(x).c_str());
        std::printf("  q from eq. 27 = %s; the record's q = PGA/(alpha g) = %s\n", four(q27).c_str(), four(q_record).c_str());
    }
    return 0;
}

}  // namespace rocking::cli
