// A consumer of the installed rocking_q package: a q from the closed form and
// from the superposition engine, and a simulation of a block under case 2, as
// `rocking q --case 2 --pulses 6 --x 0.5` and `rocking simulate --case 2 --x 0.5
// --rd 0.9 --alpha 0.15 --p 2` compute them.  Prints key value lines, %.17g.
#include <cstdio>

#include "dynamics/simulate.hpp"
#include "qfactor/closed_forms.hpp"
#include "qfactor/superposition.hpp"

int main() {
    using namespace rocking;
    std::printf("q2_n6 %.17g\n", q2_n6(0.5));
    std::printf("q %.17g\n", q_factor(repeated_case(2, 6), 0.5).q);

    dynamics::Model model;
    model.block = dynamics::Block::from_p(2.0, 0.15);
    const PulseTrain train = repeated_case(2, 2);
    const double to = 0.5 / model.block.p;  // x = p to
    const double pga = 0.9 * q_factor(train, model.block.p * to).q * model.block.alpha;  // --rd 0.9
    const dynamics::PulseInput input(train, pga, to);
    const dynamics::SimulationResult r = dynamics::simulate(model, input, dynamics::SimulationOptions{});
    std::printf("theta_tfin_over_alpha %.17g\n", r.theta_at_tfin / model.block.alpha);
    std::printf("max_theta_input_over_alpha %.17g\n", r.max_abs_theta_input / model.block.alpha);
    std::printf("t_overturn %.17g\n", r.t_overturn);
    std::printf("impacts %d\n", r.impacts);
    std::printf("collapse_overturning %s\n", r.collapse(dynamics::Criterion::overturning, 0.15) ? "true" : "false");
    return 0;
}
