// rocking q: the closed-form q of a case or a train (eqs. 12-28, (S2)).
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

int cmd_q(int argc, char** argv) {
    const Args a = parse(argc, argv, 2, {"--case", "--train", "--x", "--pulses"});
    std::string equation;
    const PulseTrain train = train_from(a, equation);
    const double x = x_from(a);
    const QFactor r = q_factor(train, x);
    const Excursion e = collapse_excursion(train, x);
    if (a.json) {
        std::cout << json_text(json::q_json(train, x, r, equation, e)) << "\n";
    } else {
        std::printf("q = %.10g\n", r.q);
        std::printf("  input %s (%zu pulses, t_fin = %g to), x = p*to = %g, %s\n", train.name().c_str(), train.size(),
                    train.t_fin(), x, equation.c_str());
        std::printf("  model: %s\n", json::kClosedFormModel);
        print_validity(e, "  ");
    }
    return 0;
}

}  // namespace rocking::cli
