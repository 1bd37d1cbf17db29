// rocking simulate --friction MU (issue 41): the same block and input on the
// sliding-rocking model (dynamics/sliding/), which keeps its own impact law
// (impulse and momentum, no rebound; slipping where |p_t| > mu p_n) and its
// own solver (event-driven Dormand-Prince).  What it adds to a rocking run's
// answer: the slip of the base on the ground, the time in each regime, and
// the run's energy balance as a check of itself.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "cli/geometry.hpp"
#include "cli/json_text.hpp"
#include "json/simulate_json.hpp"
#include "cli/options.hpp"
#include "cli/simulate_friction.hpp"
#include "dynamics/sliding/sliding_simulate.hpp"
#include "harness/table.hpp"

namespace rocking::cli {

namespace {

using dynamics::sliding::Regime;

// The searches' words for the model (records::CollapseOptions), so that a
// run and a study on it read alike.
records::CollapseOptions model_options(double mu, dynamics::Criterion criterion, double rtol) {
    records::CollapseOptions m;
    m.friction = mu;
    m.criterion = criterion;
    m.sliding_rtol = rtol;
    return m;
}

std::string model_text(double mu, dynamics::Criterion criterion, double rtol) {
    return model_options(mu, criterion, rtol).describe_model();
}

}  // namespace

void print_criteria(const dynamics::SimulationResult& r, double alpha, double alpha_minus) {
    using dynamics::Criterion;
    std::printf("  final-rotation: %s; peak-rotation: %s; overturning: %s\n",
                r.collapse(Criterion::final_rotation, alpha, alpha_minus) ? "collapse" : "safe",
                r.collapse(Criterion::peak_rotation, alpha, alpha_minus) ? "collapse" : "safe",
                r.collapse(Criterion::overturning, alpha, alpha_minus) ? "collapse" : "safe");
}

int simulate_friction(const Args& a, const GivenBlock& given, const dynamics::GroundInput& input,
                      dynamics::Criterion criterion, double mu, double record_dt) {
    using namespace dynamics;
    const double alpha = given.alpha, p = given.block.p;
    // R from p (eq. 4) whatever way the block was given: the slip is in metres.
    const sliding::FrictionBlock block{alpha, 3 * kGravity / (4 * p * p), mu};
    sliding::SlidingOptions o;
    SolverOptions tolerances;
    tolerances.rtol = o.rtol;
    tolerances.atol_alpha = o.atol_alpha;
    tolerance_options(a.values, alpha, tolerances);
    o.rtol = tolerances.rtol;
    o.atol_alpha = tolerances.atol_alpha;
    o.record_dt = record_dt;
    const sliding::SlidingResult r = sliding::simulate_sliding(block, input, o);
    if (record_dt > 0) {
        harness::Table table({"t", "theta_over_alpha", "omega_over_alpha_p", "slip_m", "slip_rate_m_s", "regime"});
        table.note("model", model_text(mu, criterion, o.rtol));
        table.note("input", input.describe());
        table.note("solver", o.describe() + "; the rows read on its dense output (the steps' interpolant)");
        table.note("criterion", criterion_name(criterion));
        table.note("rows", rows_note(record_dt, r.t_fin, r.samples.empty() ? 0.0 : r.samples.back().t));
        for (const sliding::SlidingSample& s : r.samples)
            table.row().add(s.t).add(s.theta / alpha).add(s.omega / (alpha * p)).add(s.slip).add(s.slip_rate)
                .add(regime_name(s.regime));
        write_output(table, a.values.at("--output"));
    }
    const bool collapse = r.collapse(criterion, alpha);
    auto regime_time = [&](Regime k) { return r.time_in[static_cast<int>(k)]; };
    if (a.json) {
        const records::CollapseOptions model = model_options(mu, criterion, o.rtol);
        const json::SlidingRun run{model, given, block, input, o, criterion, r};
        std::cout << json_text(json::sliding_run_json(run)) << "\n";
        return 0;
    }
    std::printf("%s under %s\n", collapse ? "COLLAPSE" : "no collapse", criterion_name(criterion).c_str());
    std::printf("  model:  %s\n  block:  %s; R = 3 g/(4 p^2) = %s m\n  input:  %s\n  solver: %s\n", model_text(mu, criterion, o.rtol).c_str(),
                describe_block(given).c_str(), significant(block.R, 6).c_str(), input.describe().c_str(),
                o.describe().c_str());
    if (r.overturned_during_input)
        std::printf("  fell at t = %.10g s, before t_fin = %g s\n", r.t_overturn, r.t_fin);
    else
        std::printf("  theta(t_fin)/alpha = %.10g at t_fin = %g s; max |theta|/alpha during the input = %.10g\n",
                    r.theta_at_tfin / alpha, r.t_fin, r.max_abs_theta_input / alpha);
    std::printf("  slip of the base: %.6g m at %s, %.6g m at most, %.6g m at the end\n", r.slip_at_tfin,
                r.overturned_during_input ? "the fall" : "t_fin",
                r.max_abs_slip, r.final_slip);
    std::printf("  regimes: rest %.6g s, slide %.6g s, rock %.6g s, slide-rock %.6g s; impacts %d (%d slipping)\n",
                regime_time(Regime::rest), regime_time(Regime::slide), regime_time(Regime::rock),
                regime_time(Regime::slide_rock), r.impacts, r.slipping_impacts);
    std::printf("  energy (J/kg): input work %.6g, friction %.6g, impacts %.6g; balance to %.2g g R\n", r.input_work,
                r.friction_loss, r.impact_loss, r.balance_error);
    std::printf("  overturns (free rocking included): %s%s\n", r.overturned ? "yes" : "no",
                r.overturned ? (" (at t = " + significant(r.t_overturn, 10) + " s)").c_str() : "");
    print_criteria(r.as_rocking(), alpha);
    return 0;
}

}  // namespace rocking::cli
