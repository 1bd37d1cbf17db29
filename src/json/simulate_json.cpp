#include "json/simulate_json.hpp"

#include "dynamics/stepper.hpp"
#include "json/pieces.hpp"

namespace rocking::json {

Json rocking_run_json(const RockingRun& run) {
    using dynamics::Criterion;
    const dynamics::SimulationResult& r = run.result;
    const double alpha = run.given.alpha;
    auto collapsed = [&](Criterion c) { return r.collapse(c, run.alpha_plus, run.alpha_minus); };
    Json o;
    o["model"] = run.model.describe();
    o["preset"] = run.paper ? "paper" : "physical";
    o["alpha"] = alpha;
    o["p"] = run.given.block.p;
    add_block(o, run.given);
    o["input"] = run.input.describe();
    o["solver"] = dynamics::solver_name(run.options.solver.kind);
    o["rtol"] = run.options.solver.rtol;
    o["atol_rad"] = run.options.solver.atol_alpha * alpha;
    o["criterion"] = dynamics::criterion_name(run.criterion);
    o["collapse"] = collapsed(run.criterion);
    o["t_fin"] = r.t_fin;
    // A block that fell during the input has no theta(t_fin) (overturned_during_input says why).
    o["theta_tfin_over_alpha"] = r.overturned_during_input ? Json(nullptr) : Json(r.theta_at_tfin / alpha);
    o["max_theta_input_over_alpha"] = r.max_abs_theta_input / alpha;
    o["input_lifts_block"] = dynamics::input_lifts(run.input, run.model);
    o["impacts"] = r.impacts;
    o["overturned"] = r.overturned;
    o["overturned_during_input"] = r.overturned_during_input;
    o["t_overturn"] = r.t_overturn;
    o["collapse_final_rotation"] = collapsed(Criterion::final_rotation);
    o["collapse_peak_rotation"] = collapsed(Criterion::peak_rotation);
    o["collapse_overturning"] = collapsed(Criterion::overturning);
    if (run.imperfection.any()) {
        o["imperfection"] = imperfection_json(run.imperfection, run.given.block, run.restitution_given);
        o["peak_over_own_alpha"] = dynamics::peak_over_own_alpha(r, run.model);
    }
    // Each side's peak where the corners differ (a setback alone keeps the block symmetric).
    if (!run.model.symmetric()) {
        o["peak_plus_over_alpha_plus"] = r.peak_plus_input / run.model.block.alpha;
        o["peak_minus_over_alpha_minus"] = r.peak_minus_input / run.model.minus.alpha;
    }
    return o;
}

Json sliding_run_json(const SlidingRun& run) {
    using dynamics::Criterion;
    using dynamics::sliding::Regime;
    const dynamics::sliding::SlidingResult& r = run.result;
    const double alpha = run.given.alpha;
    auto regime_time = [&](Regime k) { return r.time_in[static_cast<int>(k)]; };
    Json j;
    j["model"] = run.model.describe_model();
    j["friction"] = run.model.friction;
    j["alpha"] = alpha;
    j["p"] = run.given.block.p;
    j["R_from_p"] = run.block.R;
    add_block(j, run.given);
    j["input"] = run.input.describe();
    j["solver"] = run.options.describe();
    j["rtol"] = run.options.rtol;
    j["atol_rad"] = run.options.atol_alpha * alpha;
    j["criterion"] = dynamics::criterion_name(run.criterion);
    j["collapse"] = r.collapse(run.criterion, alpha);
    j["t_fin"] = r.t_fin;
    j["theta_tfin_over_alpha"] = r.overturned_during_input ? Json(nullptr) : Json(r.theta_at_tfin / alpha);
    j["max_theta_input_over_alpha"] = r.max_abs_theta_input / alpha;
    j["overturned"] = r.overturned;
    j["overturned_during_input"] = r.overturned_during_input;
    j["t_overturn"] = r.t_overturn;
    j["impacts"] = r.impacts;
    j["slipping_impacts"] = r.slipping_impacts;
    j["slip_tfin_m"] = r.slip_at_tfin;
    j["max_slip_m"] = r.max_abs_slip;
    j["final_slip_m"] = r.final_slip;
    j["time_in"] = {{"rest", regime_time(Regime::rest)}, {"slide", regime_time(Regime::slide)},
                    {"rock", regime_time(Regime::rock)}, {"slide_rock", regime_time(Regime::slide_rock)}};
    j["energy"] = {{"input_work", r.input_work}, {"friction_loss", r.friction_loss},
                   {"impact_loss", r.impact_loss}, {"balance_error_over_gR", r.balance_error}};
    j["collapse_final_rotation"] = r.collapse(Criterion::final_rotation, alpha);
    j["collapse_peak_rotation"] = r.collapse(Criterion::peak_rotation, alpha);
    j["collapse_overturning"] = r.collapse(Criterion::overturning, alpha);
    return j;
}

}  // namespace rocking::json
