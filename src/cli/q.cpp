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

namespace rocking::cli {

int cmd_q(int argc, char** argv) {
    const Args a = parse(argc, argv, 2, {"--case", "--train", "--x", "--pulses"});
    std::string equation;
    const PulseTrain train = train_from(a, equation);
    const double x = x_from(a);
    const QFactor r = q_factor(train, x);
    const Excursion e = collapse_excursion(train, x);
    if (a.json) {
        Json o;
        o["input"] = train.name();
        o["pulses"] = train.size();
        o["x"] = x;
        o["q"] = r.q;
        o["condition"] = r.condition;
        o["equation"] = equation;
        o["model"] = kModel;
        add_validity(o, e);
        std::cout << json_text(o) << "\n";
    } else {
        std::printf("q = %.10g\n", r.q);
        std::printf("  input %s (%zu pulses, t_fin = %g to), x = p*to = %g, %s\n", train.name().c_str(), train.size(),
                    train.t_fin(), x, equation.c_str());
        std::printf("  model: %s\n", kModel);
        print_validity(e, "  ");
    }
    return 0;
}

}  // namespace rocking::cli
