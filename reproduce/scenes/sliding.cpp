// The sliding scene (issue 41, items 4-5): the paper's claims retested on a
// base with Coulomb friction.  This file holds what the parts share (the
// runs and the rule of sliding_scene.hpp) and the scene's entry point.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "dynamics/model.hpp"
#include "dynamics/sliding/sliding_simulate.hpp"
#include "scene.hpp"
#include "records_analysis.hpp"
#include "sliding_scene.hpp"

namespace rocking::scenes {

namespace sliding_scene {

double half_diagonal(double alpha) { return 0.5 * kHeight / std::cos(alpha); }

std::optional<SceneRecords> scene_records(SceneContext& ctx, const std::vector<std::string>& outputs) {
    const std::string root = records_dir();
    const std::vector<std::string> files = record_files(root);
    if (files.empty()) {
        for (const std::string& f : outputs) ctx.skip(f, kNoRecords);
        return std::nullopt;
    }
    SceneRecords out;
    for (const std::string& f : files) {
        out.read.push_back(records::read_any(f));
        const records::Record& r = out.read.back();
        out.inputs.push_back(std::make_unique<dynamics::SampledInput>(r.in_g(kGravity), r.dt, r.name));
        out.labels.push_back(f.substr(root.size() + 1));
    }
    return out;
}

double pulsation(double alpha) { return std::sqrt(3 * kGravity / (4 * half_diagonal(alpha))); }

std::string number_label(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

std::string digits10(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.10g", v);
    return b;
}

bool Run::collapse(dynamics::Criterion c) const {
    switch (c) {
        case dynamics::Criterion::final_rotation: return final_rotation;
        case dynamics::Criterion::peak_rotation: return peak_rotation;
        default: return overturned;
    }
}

namespace {

using dynamics::Criterion;

template <class Result>
Run run_of(const Result& r, double alpha) {
    Run out;
    out.overturned = r.collapse(Criterion::overturning, alpha);
    out.fell_during_input = r.overturned_during_input;
    out.final_rotation = r.collapse(Criterion::final_rotation, alpha);
    out.peak_rotation = r.collapse(Criterion::peak_rotation, alpha);
    out.peak = r.max_abs_theta_input / alpha;
    out.theta_tfin = r.theta_at_tfin / alpha;
    out.impacts = r.impacts;
    return out;
}

}  // namespace

Run rocking_run(const dynamics::GroundInput& input, double alpha, double p, double rtol) {
    dynamics::Model m;
    m.equation = dynamics::Equation::full;
    m.block = dynamics::Block::from_p(p, alpha);
    m.restitution = dynamics::housner_restitution(alpha);
    dynamics::SimulationOptions o;
    o.solver.kind = dynamics::SolverKind::dopri5;
    o.solver.rtol = rtol;
    o.solver.atol_alpha = rtol;
    return run_of(dynamics::simulate(m, input, o), alpha);
}

Run friction_run(const dynamics::GroundInput& input, double alpha, double p, double mu, double rtol) {
    const dynamics::sliding::FrictionBlock block{alpha, 3 * kGravity / (4 * p * p), mu};
    dynamics::sliding::SlidingOptions o;
    o.rtol = o.atol_alpha = rtol;
    Run out;
    try {
        const dynamics::sliding::SlidingResult r = dynamics::sliding::simulate_sliding(block, input, o);
        out = run_of(r, alpha);
        out.slid = r.slid;
        out.max_slip = r.max_abs_slip;
        out.slipping_impacts = r.slipping_impacts;
    } catch (const dynamics::sliding::FreeFlight&) {
        out = Run{};
        out.outside = true;
    } catch (const std::domain_error&) {  // no consistent contact force (friction_block.hpp)
        out = Run{};
        out.outside = true;
    }
    return out;
}

Effect classify(const std::array<Run, 4>& rocking, const std::array<Run, 2>& friction) {
    for (const Run& r : rocking)
        if (r.outside) return Effect::outside_control;
    for (const Run& r : friction)
        if (r.outside) return Effect::outside;
    const bool o = rocking[0].overturned;
    for (const Run& r : rocking)
        if (r.overturned != o) return Effect::rocking_tie;
    double lo = INFINITY, hi = 0;
    for (const Run& r : rocking) lo = std::min(lo, r.peak), hi = std::max(hi, r.peak);
    if (!o && hi > (1 + kPeakChange) * lo) return Effect::rocking_tie;
    if (friction[0].overturned != friction[1].overturned) return Effect::sliding_tie;
    if (friction[0].overturned != o) return Effect::outcome;
    if (o) return Effect::same;
    int above = 0, below = 0, pairs = 0;
    for (const Run& f : friction)
        for (const Run& r : rocking) {
            ++pairs;
            // A block that never lifts has peak 0: any lift is then a change.
            if (f.peak > (1 + kPeakChange) * r.peak) ++above;
            else if (f.peak < (1 - kPeakChange) * r.peak) ++below;
        }
    if (above == pairs || below == pairs) return Effect::peak;
    return above + below > 0 ? Effect::peak_tie : Effect::same;
}

const char* effect_name(Effect e) {
    switch (e) {
        case Effect::same: return "same";
        case Effect::outcome: return "outcome changed";
        case Effect::peak: return "peak changed";
        case Effect::rocking_tie: return "rocking near-tie";
        case Effect::sliding_tie: return "sliding near-tie";
        case Effect::peak_tie: return "peak near-tie";
        case Effect::outside: return "outside the model";
        case Effect::outside_control: return "outside the model at mu 1e6";
    }
    return "?";
}

}  // namespace sliding_scene

void run_sliding(SceneContext& ctx) {
    sliding_scene::write_truth(ctx);
    sliding_scene::write_fig05(ctx);
    sliding_scene::write_claim(ctx);
    sliding_scene::write_eq27(ctx);
}

}  // namespace rocking::scenes
