// rocking record info: a record's PGA, PGV and its eleven half-periods;
// rocking record synth (synth.cpp): a synthetic record; rocking record floor
// (floor.cpp): a floor's motion from a ground record.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/help.hpp"
#include "cli/json_text.hpp"
#include "cli/options.hpp"
#include "harness/table.hpp"
#include "json/record_json.hpp"

namespace rocking::cli {

int cmd_record(int argc, char** argv) {
    if (argc > 2 && std::string(argv[2]) == "synth") return cmd_record_synth(argc, argv);
    if (argc > 2 && std::string(argv[2]) == "floor") return cmd_record_floor(argc, argv);
    if (argc < 3 || std::string(argv[2]) != "info")
        throw UsageError(argc < 3 ? std::string("give info, synth or floor")
                                  : "unknown record command '" + std::string(argv[2]) + "' (info, synth or floor)");
    const std::string path = file_argument(argc, argv, 3, usage_line("record info"));
    const Args a = parse(argc, argv, 4, {"--unit", "--dt"});
    const records::Record r = load_record(path, a);
    const records::HalfPeriods h = half_periods_of(r, path);
    if (a.json) {
        std::cout << json_text(json::record_info_json(path, r, h)) << "\n";
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
        // A CWT measure still rising at the last scale scanned has no peak inside the
        // band; its to is then the band's edge, which reads like a measured value.
        for (int k = 0; k < 4; ++k)
            if (h.cwt_at_band_edge[k])
                std::printf("  warning: to_%d is the edge of the CWT's band (%s to %s Hz), not a peak: its measure (%s) is "
                            "largest on the band's %s-frequency scale and may peak beyond the band\n",
                            8 + k, four(h.cwt_band_hz[0]).c_str(), four(h.cwt_band_hz[1]).c_str(), what[7 + k],
                            h.f_cwt[k] < std::sqrt(h.cwt_band_hz[0] * h.cwt_band_hz[1]) ? "lowest" : "highest");
    }
    return 0;
}

}  // namespace rocking::cli
