// rocking response: theta(t)/alpha on the linearised equation at a q.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "cli/validity.hpp"
#include "harness/table.hpp"

namespace rocking::cli {

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


}  // namespace rocking::cli
