// rocking simulate: one block under a pulse, a one-sine pulse or a record.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/geometry.hpp"
#include "cli/imperfection.hpp"
#include "cli/json_text.hpp"
#include "json/simulate_json.hpp"
#include "cli/options.hpp"
#include "cli/simulate_friction.hpp"
#include "dynamics/ground_input.hpp"
#include "qfactor/closed_forms.hpp"
#include "harness/table.hpp"

namespace rocking::cli {

namespace {


// Refused before the run: a --dt whose rows could exceed dynamics::kMaxRecordRows, counted
// up to the latest time the run can reach (dynamics::max_record_rows).
void check_output_rows(const dynamics::Model& model, const dynamics::GroundInput& input,
                       const dynamics::SimulationOptions& options) {
    const double rows = dynamics::max_record_rows(model, input, options);
    if (rows <= dynamics::kMaxRecordRows) return;
    const double latest = dynamics::latest_run_time(model, input, options);
    char text[400];
    std::snprintf(text, sizeof text,
                  "--dt: %g s could write %.3g rows to --output (t_fin = %.4g s and up to %.4g s of free rocking "
                  "after it), more than its limit of %.0f rows; give --dt >= %.3g s",
                  options.record_dt, rows, input.t_end(), latest - input.t_end(), dynamics::kMaxRecordRows,
                  dynamics::smallest_record_dt(model, input, options));
    throw UsageError(text);
}

}  // namespace

int cmd_simulate(int argc, char** argv) {
    using namespace rocking::dynamics;
    // --one-sine takes no value: handle it before the generic parser.
    // --one-sine and --paper take no value: handle them before the generic parser.
    std::vector<char*> args(argv, argv + argc);
    bool one_sine = false, paper = false;
    for (auto it = args.begin() + 2; it != args.end();)
        if (std::string(*it) == "--one-sine") one_sine = true, it = args.erase(it);
        else if (std::string(*it) == "--paper") paper = true, it = args.erase(it);
        else ++it;
    std::vector<std::string> allowed = {"--case", "--train", "--pulses", "--x", "--to", "--pga", "--q", "--rd", "--ap",
                                        "--wp", "--model", "--solver", "--rtol", "--atol", "--criterion", "--restitution",
                                        "--output", "--dt", "--record", "--unit", "--record-dt", "--floor", "--friction"};
    allowed.insert(allowed.end(), geometry_flags().begin(), geometry_flags().end());
    allowed.insert(allowed.end(), imperfection_flags().begin(), imperfection_flags().end());
    const Args a = parse(static_cast<int>(args.size()), args.data(), 2, allowed);
    auto has = [&](const char* f) { return a.values.count(f) > 0; };
    auto num = [&](const char* f) { return number(f, a.values.at(f)); };
    const GivenBlock given = block_option(a);
    const double alpha = given.alpha;
    Model model;
    model.block = given.block;
    const std::string model_name = has("--model") ? a.values.at("--model") : "linearised";
    if (model_name == "full") model.equation = Equation::full;
    else if (model_name != "linearised") throw UsageError("--model: linearised or full (got " + model_name + ")");
    // One model by default (issue 40): Housner's restitution and overturning,
    // as the studies; --paper is the paper's Section 3 setting.
    if (paper && (has("--restitution") || has("--criterion")))
        throw UsageError("--paper sets restitution 1 and the final-rotation criterion: give it without --restitution "
                         "and --criterion");
    // NaN: Housner's, which on an imperfect block is each corner's own from its geometry.
    const double e_given = paper ? 1.0 : has("--restitution") ? restitution_option(a.values.at("--restitution")) : NAN;
    model.restitution = std::isnan(e_given) ? housner_restitution(alpha) : e_given;
    const Imperfection imp = imperfection_option(a);
    if (imp.any()) model = imperfect_model_option(a, model.equation, given, e_given);
    // The criteria measure theta against the block's corners: an imperfect
    // block's own alphas, else the alpha given.
    const double alpha_plus = imp.any() ? model.block.alpha : alpha, alpha_minus = model.symmetric() ? 0.0 : model.minus.alpha;
    SimulationOptions options;
    try {
        options.solver.kind = has("--solver") ? parse_solver(a.values.at("--solver"))
                                              : (model.equation == Equation::full ? SolverKind::dopri5 : SolverKind::exact);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--solver: ") + e.what());
    }
    tolerance_options(a.values, alpha, options.solver);
    Criterion criterion = paper ? Criterion::final_rotation : Criterion::overturning;
    try {
        if (has("--criterion")) criterion = parse_criterion(a.values.at("--criterion"));
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--criterion: ") + e.what());
    }
    // The amplitude as --pga G (in g) or --q Q (PGA = Q alpha g).
    auto pga_or_q = [&] { return has("--pga") ? num("--pga") : num("--q") * alpha; };
    std::unique_ptr<GroundInput> input;
    if (one_sine + has("--record") + (has("--case") || has("--train")) != 1)
        throw UsageError("give exactly one input: --case or --train, --one-sine, or --record");
    if (!has("--record") && (has("--unit") || has("--record-dt") || has("--floor")))
        throw UsageError("--unit, --record-dt and --floor go with --record");
    if (has("--record")) {
        for (const char* f : {"--rd", "--to", "--x", "--pulses", "--ap", "--wp"})
            if (has(f)) throw UsageError(std::string(f) + " does not apply to --record");
        if (has("--pga") && has("--q")) throw UsageError("give at most one of --pga and --q");
        records::Record r = load_record(a.values.at("--record"), a, "--record-dt");
        std::vector<double> g = r.in_g(kGravity);
        const double peak = r.pga() / kGravity;
        std::string name = r.name + " (" + std::to_string(g.size()) + " samples, dt = " + significant(r.dt, 6) + " s, PGA " +
                           significant(peak, 6) + " g";
        if (has("--pga") || has("--q")) {
            const double pga = pga_or_q();
            if (!(pga > 0)) throw UsageError("the PGA must be > 0");
            if (!(peak > 0)) throw UsageError(a.values.at("--record") + ": the record is zero throughout and cannot be scaled");
            for (double& v : g) v *= pga / peak;
            name += ", scaled to " + significant(pga, 6) + " g";
        }
        input = std::make_unique<SampledInput>(std::move(g), r.dt, name + ")");
    } else if (one_sine) {
        if (!has("--ap") || !has("--wp")) throw UsageError("--one-sine needs --ap and --wp");
        // The pulse's bounds (why: ground_input.hpp), said in the options' terms.
        const double slowest = OneSinePulse::slowest_wp_over_p * model.block.p;
        const double strongest = OneSinePulse::strongest_ap_over_threshold * model.uplift_threshold_on(1);
        if (num("--wp") > 0 && num("--wp") < slowest)
            throw UsageError("--wp: must be at least 1e-6 p = " + significant(slowest, 6) + " rad/s (got " +
                             a.values.at("--wp") + "): slower pulses lift the block by less than the rounding of the input");
        if (num("--ap") > strongest)
            throw UsageError("--ap: must be at most 1e9 times the uplift threshold, " + significant(strongest, 6) +
                             " g (got " + a.values.at("--ap") + "): above it the fall time drifts from the closed form");
        try {
            input = std::make_unique<OneSinePulse>(num("--ap"), num("--wp"), model.uplift_threshold_on(1));
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
    } else {
        std::string equation;
        const PulseTrain train = train_from(a, equation);
        if (has("--to") == has("--x")) throw UsageError("give exactly one of --to and --x");
        const char* to_flag = has("--to") ? "--to" : "--x";
        if (!(num(to_flag) > 0)) throw UsageError(std::string(to_flag) + ": must be > 0");
        const double to = has("--to") ? num("--to") : num("--x") / given.block.p;
        // x / p leaving the double range read "must be > 0" for a positive x.
        if (!(to > 0) || !std::isfinite(to))
            throw UsageError(std::string("--x: x / p = ") + a.values.at("--x") + " / " + harness::format_number(given.block.p) +
                             " s is outside the range of double");
        const int amplitude = has("--pga") + has("--q") + has("--rd");
        if (amplitude != 1) throw UsageError("give exactly one of --pga, --q and --rd");
        const char* amplitude_flag = has("--rd") ? "--rd" : has("--q") ? "--q" : "--pga";
        if (!(num(amplitude_flag) > 0)) throw UsageError(std::string(amplitude_flag) + ": must be > 0");
        // An imperfect block rocks on its corner theta > 0 under the train
        // (its first pulse is positive): that corner's q, p and alpha.
        const double pga = has("--rd") ? num("--rd") * q_factor(train, model.block.p * to).q * alpha_plus : pga_or_q();
        // A positive amplitude whose PGA overflows or underflows read "must be > 0".
        if (!(pga > 0) || !std::isfinite(pga))
            throw UsageError(std::string(amplitude_flag) + ": the PGA it gives, " + harness::format_number(pga) +
                             " g, is outside the range of double");
        input = std::make_unique<PulseInput>(train, pga, to);
    }
    // The sliding-rocking model keeps its own equations, impact law and solver.
    if (has("--friction")) {
        for (const char* f : {"--model", "--solver", "--restitution"})
            if (has(f))
                throw UsageError(std::string(f) + " does not apply with --friction: the sliding-rocking model has its "
                                 "full equations, its impact law and its event-driven solver");
        if (paper) throw UsageError("--paper does not apply with --friction (the paper's block does not slide)");
        if (has("--atol"))
            throw UsageError("--atol does not apply with --friction: its runs take one tolerance, --rtol, on every state "
                             "variable (in units of alpha)");
        refuse_unresolvable_run(model.block.p, input->t_end(), a, {"--record-dt", "--to", "--x", "--p", "--height"},
                                has("--record") ? a.values.at("--record") : "the input");
        // theta(t) and the slip every --dt, to the run's end (at most t_fin + 200/p, as the rocking model's).
        if (has("--output")) options.record_dt = has("--dt") ? num("--dt") : 0.01;
        if (has("--output") && !(options.record_dt > 0)) throw UsageError("--dt: must be > 0");
        if (has("--output")) check_output_rows(model, *input, options);
        check_outputs(a, {"--output"}, has("--record") ? std::vector<std::string>{a.values.at("--record")} : std::vector<std::string>{},
                      "--record");
        return simulate_friction(a, given, *input, criterion, friction_option(a), options.record_dt);
    }
    if (has("--output")) options.record_dt = has("--dt") ? num("--dt") : 0.01;
    if (has("--output") && !(options.record_dt > 0)) throw UsageError("--dt: must be > 0");
    refuse_unresolvable_run(model.block.p, input->t_end(), a,
                            {"--record-dt", "--to", "--wp", "--x", "--p", "--half-height", "--height", "--thickness"},
                            has("--record") ? a.values.at("--record") : "the input");
    if (has("--output")) check_output_rows(model, *input, options);
    check_outputs(a, {"--output"}, has("--record") ? std::vector<std::string>{a.values.at("--record")} : std::vector<std::string>{},
                  "--record");
    const SimulationResult r = simulate(model, *input, options);
    dynamics::refuse_overflow_in_alpha(r, alpha);
    char atol_rad[48];
    std::snprintf(atol_rad, sizeof atol_rad, " = %g rad", options.solver.atol_alpha * alpha);
    const std::string tolerance = options.solver.kind == SolverKind::exact
                                      ? std::string(" (closed form between events)")
                                      : " (" + tolerance_text(options.solver) + atol_rad + ")";
    if (has("--output")) {
        harness::Table table({"t", "theta_over_alpha", "omega_over_alpha_p"});
        table.note("model", model.describe());
        table.note("input", input->describe());
        table.note("solver", solver_name(options.solver.kind) + tolerance);
        table.note("criterion", criterion_name(criterion));
        table.note("rows", rows_note(options.record_dt, r.t_fin, r.samples.empty() ? 0.0 : r.samples.back().t));
        for (const Sample& s : r.samples)
            table.row().add(s.t).add(s.theta / alpha).add(s.omega / (alpha * model.block.p));
        write_output(table, a.values.at("--output"));
    }
    auto collapsed = [&](Criterion c) { return r.collapse(c, alpha_plus, alpha_minus); };
    const bool collapse = collapsed(criterion);
    // The block starts at rest and rocks only once |a| > the threshold (eq. 3: alpha g; eq. 1: g tan alpha).
    const bool lifts = input_lifts(*input, model);
    if (a.json) {
        const json::RockingRun run{model, given, *input, options, criterion, r, paper, alpha_plus, alpha_minus, imp, e_given};
        std::cout << json_text(json::rocking_run_json(run)) << "\n";
    } else {
        std::printf("%s under %s\n", collapse ? "COLLAPSE" : "no collapse", criterion_name(criterion).c_str());
        std::printf("  model:  %s%s\n  block:  %s\n  input:  %s\n  solver: %s%s\n", model.describe().c_str(),
                    paper ? " (--paper: the paper's setting)"
                    : imp.any() ? ""
                    : model.restitution == housner_restitution(alpha) ? " (Housner's 1 - 1.5 sin^2 alpha)" : "",
                    describe_block(given).c_str(),
                    input->describe().c_str(), solver_name(options.solver.kind).c_str(), tolerance.c_str());
        if (imp.any()) {
            std::printf("  %s\n", describe_imperfection(imp, imperfect_geometry(given.block, imp), e_given).c_str());
            if (model.symmetric())
                std::printf("  largest |theta|/alpha' = %.10g during the input, alpha' = %.6g the set-back block's (below, "
                            "theta is in units of the alpha given)\n", peak_over_own_alpha(r, model), model.block.alpha);
            else
                std::printf("  largest theta/alpha_+ = %.10g, -theta/alpha_- = %.10g during the input (each side by its "
                            "own alpha; below, theta is in units of the alpha given)\n",
                            r.peak_plus_input / model.block.alpha, r.peak_minus_input / model.minus.alpha);
        }
        // A block that fell during the input has no theta(t_fin) to print: it lies on the ground.
        if (r.overturned_during_input)
            std::printf("  fell at t = %.10g s, before t_fin = %g s: |theta| reached the fall angle, %.10g alpha\n",
                        r.t_overturn, r.t_fin, options.overturn_angle / alpha);
        else
            std::printf("  theta(t_fin)/alpha = %.10g at t_fin = %g s; max |theta|/alpha during the input = %.10g\n",
                        r.theta_at_tfin / alpha, r.t_fin, r.max_abs_theta_input / alpha);
        const std::string when = !r.overturned ? ""
                                 : std::isnan(r.t_overturn)
                                     ? " (the free rocking followed, 200/p, ended before the fall; decided from its energy and side of the top)"
                                     : " (at t = " + harness::format_number(r.t_overturn) + " s)";
        // Without this line a zero theta reads like a result of the dynamics;
        // it is the input that stays at or below the uplift threshold.
        if (!lifts && model.symmetric())
            std::printf("  the input never lifts the block: its peak, %.6g g, is at or below the uplift threshold %s = %.6g g\n",
                        input->peak(), model.equation == Equation::full ? "tan alpha" : "alpha", model.uplift_threshold());
        else if (!r.uplifted)
            std::printf("  the input never lifts the block: it stays within the uplift thresholds %s, %.6g g toward "
                        "theta > 0 and %.6g g toward theta < 0\n",
                        model.equation == Equation::full ? "tan alpha" : "alpha", model.uplift_threshold_on(1),
                        model.uplift_threshold_on(-1));
        std::printf("  impacts: %d; overturns (free rocking included): %s%s\n", r.impacts, r.overturned ? "yes" : "no",
                    when.c_str());
        print_criteria(r, alpha_plus, alpha_minus);
    }
    return 0;
}

}  // namespace rocking::cli
