// One block under a pulse train, a one-sine pulse or a record (rocking
// simulate), and the block's geometry (eqs. 2, 4): src/dynamics.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "common.hpp"
#include "json/simulate_json.hpp"
#include "dynamics/ground_input.hpp"
#include "dynamics/sliding/sliding_simulate.hpp"
#include "records/collapse.hpp"
#include "study_arguments.hpp"
#include "qfactor/superposition.hpp"

namespace rocking::python {

namespace {

using namespace rocking::dynamics;

// What the command line refuses before the run: a theta(t) record that could
// exceed its rows (the refusal's message, empty when it does not), or
// rotations that overflow once divided by alpha.
std::string rows_refusal(const Model& model, const GroundInput& input, const SimulationOptions& options) {
    const double rows = max_record_rows(model, input, options);
    if (rows <= kMaxRecordRows) return "";
    const double latest = latest_run_time(model, input, options);
    char text[400];
    std::snprintf(text, sizeof text,
                  "dt: %g s could give %.3g rows (t_fin = %.4g s and up to %.4g s of free rocking after it), more "
                  "than the limit of %.0f rows; give dt >= %.3g s",
                  options.record_dt, rows, input.t_end(), latest - input.t_end(), kMaxRecordRows,
                  smallest_record_dt(model, input, options));
    return text;
}


// The record as simulate --record reads it, scaled to scaled_to g if given:
// built without the GIL, the Record being immutable.
std::unique_ptr<GroundInput> record_input(const records::Record& r, const std::optional<double>& scaled_to) {
    std::vector<double> g = r.in_g(kGravity);
    const double peak = r.pga() / kGravity;
    std::string name = r.name + " (" + std::to_string(g.size()) + " samples, dt = " + significant(r.dt, 6) + " s, PGA " +
                       significant(peak, 6) + " g";
    if (scaled_to) {
        if (!(peak > 0)) throw std::invalid_argument(label_of(r) + ": the record is zero throughout and cannot be scaled");
        for (double& v : g) v *= *scaled_to / peak;
        name += ", scaled to " + significant(*scaled_to, 6) + " g";
    }
    return std::make_unique<SampledInput>(std::move(g), r.dt, name + ")");
}

// simulate(friction=MU), as rocking simulate --friction --json (src/cli/simulate_friction.cpp).
py::dict sliding_result(const dynamics::GivenBlock& given, const GroundInput& input, Criterion criterion,
                        const records::CollapseOptions& m, double record_dt) {
    const double alpha = given.alpha, p = given.block.p;
    const sliding::FrictionBlock block{alpha, 3 * kGravity / (4 * p * p), m.friction};
    sliding::SlidingOptions o;
    o.rtol = o.atol_alpha = m.sliding_rtol;
    o.record_dt = record_dt;
    sliding::SlidingResult r;
    {
        py::gil_scoped_release unlocked;
        r = sliding::simulate_sliding(block, input, o);
    }
    records::CollapseOptions stated = m;
    stated.criterion = criterion;
    const json::Json doc = json::sliding_run_json({stated, given, block, input, o, criterion, r});
    py::dict out = to_python(doc);
    // The module's own order (the block's members before alpha, the tolerances after the slips), None for a NaN
    // t_overturn, time_in and energy as dicts.
    out = with_keys_before(out, {"given", "thickness", "height", "R"}, "alpha");
    out = with_keys_before(out, {"rtol", "atol_rad"}, "time_in");
    out["t_overturn"] = none_if_nan(r.t_overturn);
    out["time_in"] = to_python(doc["time_in"], Dicts::plain);
    out["energy"] = to_python(doc["energy"], Dicts::plain);
    // theta(t) and the slip every dt, as --output's rows.
    std::vector<double> t, theta, omega, slip, rate;
    py::list regime;
    for (const sliding::SlidingSample& s : r.samples) {
        t.push_back(s.t);
        theta.push_back(s.theta);
        omega.push_back(s.omega);
        slip.push_back(s.slip);
        rate.push_back(s.slip_rate);
        regime.append(sliding::regime_name(s.regime));
    }
    out["t"] = to_array(t);
    out["theta"] = to_array(theta);
    out["omega"] = to_array(omega);
    // As the rocking-only result's and --output's columns.
    std::vector<double> theta_a, omega_ap;
    for (const sliding::SlidingSample& s : r.samples) {
        theta_a.push_back(s.theta / alpha);
        omega_ap.push_back(s.omega / (alpha * p));
    }
    out["theta_over_alpha"] = to_array(theta_a);
    out["omega_over_alpha_p"] = to_array(omega_ap);
    out["slip_m"] = to_array(slip);
    out["slip_rate_m_s"] = to_array(rate);
    out["regime"] = regime;
    return out;
}

py::dict simulate_of(const std::optional<Real>& alpha_given, const std::optional<Real>& p_given,
                     const std::optional<Real>& half_height_given, const std::optional<Real>& height_given,
                     const std::optional<Real>& thickness_given, const std::optional<Whole>& which_case,
                     const std::optional<Whole>& pulses, const py::object& train, const std::optional<Real>& to_given,
                     const std::optional<Real>& x_given, const std::optional<Real>& pga_given,
                     const std::optional<Real>& q_given, const std::optional<Real>& rd_given, const Flag& one_sine_given,
                     const std::optional<Real>& ap_given, const std::optional<Real>& wp_given, const py::object& record,
                     const Text& model_given, const std::optional<Text>& solver_given,
                     const std::optional<Real>& rtol_given, const std::optional<Real>& atol_given,
                     const std::optional<Text>& criterion_given, const py::object& restitution_given,
                     const Flag& paper_given, const std::optional<Real>& dt_given, const Real& free_time_given,
                     const std::optional<Text>& floor_given, const py::object& friction_given,
                     const py::object& imperfection_given, const py::kwargs& extra) {
    no_other_keywords(extra, "simulate", "simulate");
    // Each argument converted, or refused naming it, in the signature's order.
    const dynamics::GivenBlock given = block_argument(thickness_given, height_given, half_height_given, alpha_given, p_given);
    const double alpha = given.alpha;
    const std::optional<double> to = number(to_given, "to"),
                                x = number(x_given, "x"), pga = number(pga_given, "pga"), q = number(q_given, "q"),
                                rd = number(rd_given, "rd");
    const bool one_sine = flag(one_sine_given, "one_sine");
    const std::optional<double> ap = number(ap_given, "ap"), wp = number(wp_given, "wp");
    const std::string model_name = string_argument(model_given, "model");
    const std::optional<std::string> solver = string_argument(solver_given, "solver");
    const std::optional<double> rtol = number(rtol_given, "rtol"), atol = number(atol_given, "atol");
    const bool paper = flag(paper_given, "paper");
    const std::optional<std::string> criterion_name_ = string_argument(criterion_given, "criterion");
    const std::optional<double> dt = number(dt_given, "dt");
    const double free_time = number(free_time_given, "free_time");

    Model model;
    model.block = given.block;
    if (model_name == "full") model.equation = Equation::full;
    else if (model_name != "linearised") refuse("model: linearised or full (got '" + model_name + "')");
    // One model by default (issue 40), as `rocking simulate`: Housner's restitution and
    // overturning; paper=True is the paper's Section 3 setting.
    if (paper && (!restitution_given.is_none() || criterion_name_))
        refuse("paper=True sets restitution 1 and the final-rotation criterion: give it without restitution and criterion");
    const double e = restitution_given.is_none() ? (paper ? 1.0 : NAN) : restitution_argument(restitution_given);
    model.restitution = std::isnan(e) ? housner_restitution(alpha) : e;
    // An imperfect block (as rocking simulate --lean ...): each corner's own
    // restitution unless one is given; the criteria by each side's alpha.
    records::CollapseOptions refusal;
    if (!friction_given.is_none()) refusal.friction = 1;  // imperfection_argument refuses the two together
    const dynamics::Imperfection imp = imperfection_argument(imperfection_given, refusal);
    if (imp.any()) {
        try {
            model = dynamics::imperfect_model(model.equation, given.block, imp, e);
        } catch (const std::invalid_argument& err) {
            refuse(std::string(err.what()) + " (imperfection on the block given)");
        }
    }
    const double alpha_plus = imp.any() ? model.block.alpha : alpha, alpha_minus = model.symmetric() ? 0.0 : model.minus.alpha;
    SimulationOptions options;
    try {
        options.solver.kind = solver ? parse_solver(*solver)
                                     : (model.equation == Equation::full ? SolverKind::dopri5 : SolverKind::exact);
    } catch (const std::invalid_argument& err) {
        refuse(std::string("solver: ") + err.what());
    }
    tolerance_arguments(rtol, atol, alpha, options.solver);
    Criterion criterion = paper ? Criterion::final_rotation : Criterion::overturning;
    try {
        if (criterion_name_) criterion = parse_criterion(*criterion_name_);
    } catch (const std::invalid_argument& err) {
        refuse(std::string("criterion: ") + err.what());
    }
    const bool has_train = which_case.has_value() || !train.is_none(), has_record = !record.is_none();
    if (one_sine + has_record + has_train != 1)
        refuse("give exactly one input: case or train, one_sine=True, or record");
    if (!one_sine && (ap || wp)) refuse("ap and wp go with one_sine=True");
    if (!has_record && floor_given) refuse("floor goes with record");

    std::unique_ptr<GroundInput> input;
    RecordPtr kept;  // the record stays alive while the run reads it
    std::optional<double> scaled_to;  // g
    if (has_record) {
        if (rd) refuse("rd does not apply to record");
        if (to) refuse("to does not apply to record");
        if (x) refuse("x does not apply to record");
        if (pulses) refuse("pulses does not apply to record");
        if (pga && q) refuse("give at most one of pga and q");
        kept = with_floor(record_argument(record, "record"), floor_given);
        if (pga || q) {
            scaled_to = pga ? *pga : *q * alpha;
            if (!(*scaled_to > 0)) refuse("the PGA must be > 0");
        }
        // The input is made from the record without the GIL (record_input below): a copy of every sample.
    } else if (one_sine) {
        if (!ap || !wp) refuse("one_sine needs ap and wp");
        const double slowest = OneSinePulse::slowest_wp_over_p * model.block.p;
        const double strongest = OneSinePulse::strongest_ap_over_threshold * model.uplift_threshold_on(1);
        if (*wp > 0 && *wp < slowest)
            refuse("wp: must be at least 1e-6 p = " + significant(slowest, 6) + " rad/s (got " + significant(*wp, 17) +
                   "): slower pulses lift the block by less than the rounding of the input");
        if (*ap > strongest)
            refuse("ap: must be at most 1e9 times the uplift threshold, " + significant(strongest, 6) + " g (got " +
                   significant(*ap, 17) + "): above it the fall time drifts from the closed form");
        try {
            input = std::make_unique<OneSinePulse>(*ap, *wp, model.uplift_threshold_on(1));
        } catch (const std::invalid_argument& err) {
            refuse(err.what());
        }
    } else {
        std::string equation;
        const PulseTrain t = train_argument(which_case, pulses, train, equation);
        if (to.has_value() == x.has_value()) refuse("give exactly one of to and x");
        const char* to_name = to ? "to" : "x";
        if (!((to ? *to : *x) > 0)) refuse(std::string(to_name) + ": must be > 0");
        const double to_s = to ? *to : *x / given.block.p;
        // A finite to > 0 is its own to_s; only x / p can leave the double range (the message
        // read *x, an empty optional, when to was given).
        if (!to && (!(to_s > 0) || !std::isfinite(to_s)))
            refuse("x: x / p = " + significant(*x, 17) + " / " + significant(given.block.p, 17) +
                   " s is outside the range of double");
        if (pga.has_value() + q.has_value() + rd.has_value() != 1) refuse("give exactly one of pga, q and rd");
        const char* amplitude_name = rd ? "rd" : q ? "q" : "pga";
        if (!((rd ? *rd : q ? *q : *pga) > 0)) refuse(std::string(amplitude_name) + ": must be > 0");
        const double peak_g = rd ? *rd * q_factor(t, model.block.p * to_s).q * alpha_plus : pga ? *pga : *q * alpha;
        if (!(peak_g > 0) || !std::isfinite(peak_g))
            refuse(std::string(amplitude_name) + ": the PGA it gives, " + significant(peak_g, 17) +
                   " g, is outside the range of double");
        input = std::make_unique<PulseInput>(t, peak_g, to_s);
    }
    if (dt) {
        if (!(*dt > 0)) refuse("dt: must be > 0 (got " + significant(*dt, 17) + ")");
        options.record_dt = *dt;
        if (!(free_time >= 0) || !std::isfinite(free_time)) refuse("free_time: must be >= 0 s");
        options.free_record_time = free_time;
    } else if (free_time != 0) {
        refuse("free_time goes with dt");
    }

    // The arguments that set p and the input's duration, as rocking simulate names its options.
    std::string culprits = !p_given ? (thickness_given || height_given ? "height" : "half_height") : "p";
    if (thickness_given) culprits = "thickness, " + culprits;
    for (const auto& [name, has] : {std::pair<const char*, bool>{"to", to.has_value()}, {"x", x.has_value()},
                                    {"wp", wp.has_value()}})
        if (has) culprits += std::string(", ") + name;
    if (kept) culprits += ", record " + label_of(*kept);

    if (!friction_given.is_none()) {
        if (model_name != "linearised" || solver || !restitution_given.is_none() || paper || atol)
            refuse("friction: model, solver, restitution, paper and atol do not apply with it (the sliding-rocking "
                   "model has its full equations, impact law and event-driven solver, at one tolerance, rtol)");
        records::CollapseOptions sliding;
        friction_into(friction_given, restitution_given, sliding);
        if (rtol) sliding.sliding_rtol = *rtol;
        if (kept) input = record_input(*kept, scaled_to);
        refuse_unresolvable_run(model.block.p, input->t_end(), culprits);
        // dt as the command's --dt with --output: the rows to the run's end.
        if (free_time != 0) refuse("free_time does not apply with friction (the rows go to the run's end)");
        SimulationOptions rows;
        if (dt) {
            if (!(*dt > 0)) refuse("dt: must be > 0 (got " + significant(*dt, 17) + ")");
            rows.record_dt = *dt;
            const std::string why = rows_refusal(model, *input, rows);
            if (!why.empty()) refuse(why);
        }
        return sliding_result(given, *input, criterion, sliding, rows.record_dt);
    }
    SimulationResult r;
    std::string too_many_rows;
    {
        py::gil_scoped_release unlocked;
        if (kept) input = record_input(*kept, scaled_to);
        refuse_unresolvable_run(model.block.p, input->t_end(), culprits);
        too_many_rows = options.record_dt > 0 ? rows_refusal(model, *input, options) : "";
        if (too_many_rows.empty()) {
            r = simulate(model, *input, options);
            dynamics::refuse_overflow_in_alpha(r, alpha);
        }
    }
    if (!too_many_rows.empty()) refuse(too_many_rows);
    char atol_rad[48];
    std::snprintf(atol_rad, sizeof atol_rad, " = %g rad", options.solver.atol_alpha * alpha);
    const std::string tolerance = options.solver.kind == SolverKind::exact
                                      ? std::string(" (closed form between events)")
                                      : " (" + tolerance_text(options.solver) + atol_rad + ")";
    const json::RockingRun run{model, given, *input, options, criterion, r, paper, alpha_plus, alpha_minus, imp, e};
    const json::Json doc = json::rocking_run_json(run);
    py::dict out = to_python(doc);
    // The module's own: alpha and p after the fields below, None for a NaN t_overturn, imperfection as dicts.
    out.attr("pop")("alpha");
    out.attr("pop")("p");
    out["t_overturn"] = none_if_nan(r.t_overturn);
    if (imp.any()) out["imperfection"] = to_python(doc["imperfection"], Dicts::plain);
    // What the text output and --output's notes state beside the JSON's fields.
    out["solver_description"] = solver_name(options.solver.kind) + tolerance;
    out["alpha"] = alpha;
    out["p"] = given.block.p;
    out["restitution"] = model.restitution;
    out["impact_times"] = to_array(r.impact_times);
    // theta(t) every dt, as --output's rows (t, theta/alpha, theta'/(alpha p)), and in rad and rad/s.
    const std::size_t n = r.samples.size();
    py::array_t<double> t(n), theta(n), omega(n), theta_a(n), omega_ap(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Sample& s = r.samples[k];
        t.mutable_at(k) = s.t;
        theta.mutable_at(k) = s.theta;
        omega.mutable_at(k) = s.omega;
        theta_a.mutable_at(k) = s.theta / alpha;
        omega_ap.mutable_at(k) = s.omega / (alpha * model.block.p);
    }
    out["t"] = t;
    out["theta"] = theta;
    out["omega"] = omega;
    out["theta_over_alpha"] = theta_a;
    out["omega_over_alpha_p"] = omega_ap;
    return out;
}

}  // namespace

void init_dynamics(py::module_& m) {
    using namespace py::literals;
    m.def("simulate", gsl_checked(&simulate_of), py::kw_only(), "alpha"_a = py::none(), "p"_a = py::none(),
          "half_height"_a = py::none(), "height"_a = py::none(), "thickness"_a = py::none(), "case"_a = py::none(), "pulses"_a = py::none(), "train"_a = py::none(),
          "to"_a = py::none(), "x"_a = py::none(), "pga"_a = py::none(), "q"_a = py::none(), "rd"_a = py::none(),
          "one_sine"_a = false, "ap"_a = py::none(), "wp"_a = py::none(), "record"_a = py::none(),
          "model"_a = "linearised", "solver"_a = py::none(), "rtol"_a = py::none(), "atol"_a = py::none(),
          "criterion"_a = py::none(), "restitution"_a = py::none(), "paper"_a = false, "dt"_a = 0.01, "free_time"_a = 0.0, "floor"_a = py::none(), "friction"_a = py::none(), "imperfection"_a = py::none(),
          R"(`rocking simulate --json`: one block under a pulse train, a one-sine pulse or a record.

Geometry: thickness and height (m, full dimensions: alpha = atan(B/H), eqs. 2, 4), or alpha with
p (rad/s), half_height (m, eq. 2's H) or height (m); given both ways they must agree to 0.1 %.
Model: Housner's restitution and overturning by default; paper=True is the paper's setting
(restitution 1, final rotation).
Input: case (1..5, with pulses) or train, with to (s) or x = p*to, and pga (g), q (PGA = q alpha g)
or rd (PGA = q_I(x) rd alpha g); or one_sine=True with ap (g) and wp (rad/s); or record
(a Record or a path), as recorded or scaled to pga (g) or q.
model "linearised" | "full"; solver "exact" | "dopri5" | "rkf78" | "bulirsch-stoer" | "gsl-rk8pd";
rtol, atol (rad); criterion "final-rotation" | "peak-rotation" | "overturning"; restitution a
factor or "housner".  dt: theta(t) every dt seconds as t, theta, omega (rad, rad/s) and
theta_over_alpha, omega_over_alpha_p (as --output; None: no record of theta(t), as simulate
without --output: the record kernel then runs, whose last digits may differ), free_time: seconds
of free rocking after t_fin to keep.  friction=MU: the sliding-rocking model (docs/sliding.md), as
rocking simulate --friction MU --json: the slip, the time in each regime and the energy balance;
no theta(t), and without model, solver, restitution, paper and atol.  Releases the GIL.)");
    m.def(
        "block",
        [](const std::optional<Real>& alpha, const std::optional<Real>& p, const std::optional<Real>& half_height,
           const std::optional<Real>& height, const std::optional<Real>& thickness, const py::kwargs& extra) {
            no_other_keywords(extra, "block", "block");
            const dynamics::GivenBlock g = block_argument(thickness, height, half_height, alpha, p);
            const Block& b = g.block;
            py::dict out = result();
            out["alpha"] = b.alpha;
            out["p"] = b.p;
            add_block_members(out, g);
            out["R"] = b.R;
            out["half_height"] = b.R > 0 ? py::object(py::float_(b.R * std::cos(b.alpha))) : py::object(py::none());
            out["housner_restitution"] = housner_restitution(b.alpha);
            out["uplift_threshold_linearised"] = b.alpha;
            out["uplift_threshold_full"] = std::tan(b.alpha);
            out["text"] = dynamics::describe_block(g);
            return out;
        },
        py::kw_only(), "alpha"_a = py::none(), "p"_a = py::none(), "half_height"_a = py::none(), "height"_a = py::none(),
        "thickness"_a = py::none(),
        "A block's alpha, p (rad/s, eqs. 2, 4), R (m; 0 when given by p), half-height, Housner's restitution and uplift "
        "thresholds (g): from thickness and height (m, full dimensions), or alpha with p, half_height or height.");
}

}  // namespace rocking::python
