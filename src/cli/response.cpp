// rocking response: theta(t)/alpha on the linearised equation at a q.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/json_text.hpp"
#include "cli/options.hpp"
#include "cli/validity.hpp"
#include "harness/table.hpp"
#include "json/qfactor_json.hpp"

namespace rocking::cli {

int cmd_response(int argc, char** argv) {
    const Args a = parse(argc, argv, 2, {"--case", "--train", "--x", "--pulses", "--q", "--steps"});
    std::string equation;
    const PulseTrain train = train_from(a, equation);
    const double x = x_from(a);
    // Without --q, the response at the collapse q itself: its rounding to
    // double alone would move theta(t_fin) off alpha by eps cosh(x t_fin).
    const bool at_collapse = !a.values.count("--q");
    const double q = at_collapse ? q_factor(train, x).q : number("--q", a.values.at("--q"));
    if (!(q > 0)) throw UsageError("--q: must be > 0");
    const int steps = a.values.count("--steps") ? integer("--steps", a.values.at("--steps"), 1, 1000000) : 20;
    const Excursion e = at_collapse ? collapse_excursion(train, x) : excursion(train, x, q);
    auto state = [&](double tau) { return at_collapse ? collapse_response(train, x, tau) : response(train, x, q, tau); };
    // A q off the collapse q makes theta grow like e^{x t/to}: past the double
    // range the rows stop, and the output says where, rather than print inf.
    // The rows are kept, so that each state is evaluated once.
    std::vector<ResponseState> rows;
    for (int k = 0; k <= steps; ++k) {
        const ResponseState s = state(train.t_fin() * k / steps);
        if (!std::isfinite(s.phi) || !std::isfinite(s.dphi)) break;
        rows.push_back(s);
    }
    const int last = static_cast<int>(rows.size()) - 1;
    const double t_end = last < steps ? train.t_fin() * (last + 1) / steps : NAN;
    if (a.json) {
        std::cout << json_text(json::response_json(train, x, q, at_collapse, e, rows, steps)) << "\n";
        return 0;
    }
    std::printf("# %s, x = %g, q = %.10g%s; %s\n", train.name().c_str(), x, q,
                at_collapse ? " (the collapse q, evaluated exactly)" : "", json::kClosedFormModel);
    print_validity(e, "# ");
    if (last < steps) std::printf("# rows end before t/to = %.6g: %s\n", t_end, json::kRowsEndReason);
    std::printf("# t/to,theta/alpha,theta'/(alpha p)\n");
    for (int k = 0; k <= last; ++k)
        std::printf("%.6g,%.12g,%.12g\n", train.t_fin() * k / steps, rows[k].phi, rows[k].dphi);
    return 0;
}

}  // namespace rocking::cli
