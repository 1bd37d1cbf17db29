// Figure 7: the q-factor of cases 1, 2 and 4 repeated to N pulses.
#include <cmath>
#include <string>

#include "pulse/pulse_train.hpp"
#include "qfactor/superposition.hpp"
#include "scene.hpp"

namespace rocking::scenes {

namespace {
const int kCases[] = {1, 2, 4};
const int kPulses[] = {2, 4, 6, 8, 10, 12};
}  // namespace

void run_fig07(SceneContext& ctx) {
    std::vector<std::string> columns = {"x"};
    for (int c : kCases)
        for (int n : kPulses) columns.push_back("case" + std::to_string(c) + "_N" + std::to_string(n));
    columns.push_back("worst_condition");
    harness::Table curves(columns);
    curves.note("scene", "fig07 (Figure 7 of the paper)");
    curves.note("model", "linearised eq. 3, no impact, collapse theta(t_fin) = alpha at the onset of pulse N + 1");
    curves.note("solver", "superposition engine (S3); relative error below worst_condition * 1e-16");
    curves.note("inputs", "cases 1, 2, 4 repeated to N pulses (case2_N6 is eq. 27, case4_N6 eq. 28, case1_N6 Coccia & Como)");
    for (double x : x_grid()) {
        curves.row().add(x);
        double worst = 0.0;
        for (int c : kCases)
            for (int n : kPulses) {
                const QFactor r = q_factor(repeated_case(c, n), x);
                curves.add(r.q);
                worst = std::fmax(worst, r.condition);
            }
        curves.add(worst);
    }
    ctx.write(curves, "fig07.csv");

    // How q falls and settles with N: the change from N - 2 to N pulses.
    harness::Table settling({"case", "N", "x", "q", "change_from_N_minus_2"});
    settling.note("scene", "fig07: settling of q with the number of pulses N");
    settling.note("model", "linearised eq. 3, no impact, collapse theta(t_fin) = alpha at the onset of pulse N + 1");
    settling.note("solver", "superposition engine (S3); relative error below condition * 1e-16 (condition: fig07.csv's worst_condition)");
    settling.note("inputs", "cases 1, 2, 4 repeated to N = 2, 4, ..., 12 pulses at x = 0.25, 0.5, 1, 1.5; change_from_N_minus_2 = q(N) / q(N - 2) - 1 (0 at N = 2)");
    for (int c : kCases)
        for (double x : {0.25, 0.5, 1.0, 1.5})
            for (int n = 2; n <= 12; n += 2) {
                const double q = q_factor(repeated_case(c, n), x).q;
                const double change = n == 2 ? 0.0 : q / q_factor(repeated_case(c, n - 2), x).q - 1.0;
                settling.row().add(c).add(n).add(x).add(q).add(change);
            }
    ctx.write(settling, "fig07_settling.csv");
}

}  // namespace rocking::scenes
