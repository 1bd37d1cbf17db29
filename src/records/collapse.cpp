#include "records/collapse.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "dynamics/sliding/sliding_simulate.hpp"

namespace rocking::records {

using namespace dynamics;

namespace {

// "; imperfect block: lean 0.02 rad, ..." or nothing for a perfect block.
std::string imperfection_words(const Imperfection& imp, bool housner) {
    if (!imp.any()) return "";
    char text[480];
    int n = std::snprintf(text, sizeof text, "; imperfect block (docs/imperfect.md):");
    if (imp.lean != 0) n += std::snprintf(text + n, sizeof text - n, " lean %g rad,", imp.lean);
    if (imp.out_of_plumb != 0) n += std::snprintf(text + n, sizeof text - n, " out of plumb %g rad,", imp.out_of_plumb);
    if (imp.fc != 0)
        n += std::snprintf(text + n, sizeof text - n,
                           " pivots set back by fc %g MPa at density %g kg/m3 (a scan over p starts above the blocks "
                           "that crush under their own weight),",
                           imp.fc / 1e6, imp.density);
    if (n > 0 && text[n - 1] == ',') text[n - 1] = '\0';
    if (!housner) std::snprintf(text + n - 1, sizeof text - n + 1, ", the restitution given on both corners");
    return text;
}

}  // namespace

std::string CollapseOptions::describe_model() const {
    char number[40];
    if (friction > 0) {
        std::snprintf(number, sizeof number, "%g", friction);
        std::string text = "sliding-rocking on Coulomb friction mu = " + std::string(number) +
                           " (full equations; rest, slide, rock, slide-rock; impacts without rebound, stuck or "
                           "slipping), criterion " + criterion_name(criterion);
        std::snprintf(number, sizeof number, "%g", sliding_rtol);
        return text + ", solver event-driven dopri5 (rtol " + number + ", atol " + number + " alpha)";
    }
    std::snprintf(number, sizeof number, "%g", restitution);  // std::to_string printed 1e-7 as 0.000000
    std::string text = equation == Equation::linearised ? "linearised eq. 3" : "full eq. 1";
    text += ", restitution ";
    text += housner_restitution ? std::string(imperfection.any() ? "Housner's law on each corner's geometry"
                                                                : "Housner 1 - 1.5 sin^2 alpha")
                                : std::string(number);
    text += ", criterion " + criterion_name(criterion) + ", solver " + solver_name(solver.kind);
    if (solver.kind != SolverKind::exact) text += " (" + tolerance_text(solver) + ")";
    return text + imperfection_words(imperfection, housner_restitution);
}

std::string CollapseOptions::describe() const {
    std::ostringstream os;
    if (friction > 0) os << describe_model();
    else {
        // Its own bytes since before the studies' describe_model: "solver dopri5 rtol ..." without parentheses.
        os << (equation == Equation::linearised ? "linearised eq. 3" : "full eq. 1") << ", restitution ";
        if (housner_restitution)
            os << (imperfection.any() ? "Housner's law on each corner's geometry" : "Housner 1 - 1.5 sin^2 alpha");
        else os << restitution;
        os << ", criterion " << criterion_name(criterion) << ", solver " << solver_name(solver.kind)
           << (solver.kind == SolverKind::exact ? std::string("") : " " + tolerance_text(solver))
           << imperfection_words(imperfection, housner_restitution);
    }
    os << ", p scanned from " << p_min << " by x" << growth << ", refined to " << rel_tol;
    return os.str();
}

Model model_of(double alpha, double p, const CollapseOptions& options) {
    if (options.imperfection.any())
        return imperfect_model(options.equation, Block::from_p(p, alpha), options.imperfection,
                               options.housner_restitution ? NAN : options.restitution);
    Model model;
    model.equation = options.equation;
    model.restitution = options.housner_restitution ? housner_restitution(alpha) : options.restitution;
    model.block = Block::from_p(p, alpha);
    return model;
}

namespace {

// A sliding-rocking run in a rocking run's terms: what the searches and
// their outputs read (the criteria's inputs, impacts, uplift).
SimulationResult sliding_run(const GroundInput& input, double alpha, double p, const CollapseOptions& options,
                             bool free_rocking) {
    const sliding::FrictionBlock block{alpha, 3 * kGravity / (4 * p * p), options.friction};
    sliding::SlidingOptions o;
    o.rtol = o.atol_alpha = options.sliding_rtol;
    o.free_rocking = free_rocking;
    return sliding::simulate_sliding(block, input, o).as_rocking();
}

SimulationResult run_block(const GroundInput& input, double alpha, double p, const CollapseOptions& options,
                           bool free_rocking) {
    if (options.friction > 0) {
        if (options.imperfection.any())
            throw std::invalid_argument("friction and an imperfect block together: the sliding-rocking model's block is "
                                        "a perfect rectangle");
        return sliding_run(input, alpha, p, options, free_rocking);
    }
    const Model model = model_of(alpha, p, options);
    SimulationOptions sim;
    sim.solver = options.solver;
    sim.free_rocking = free_rocking;
    return simulate(model, input, sim);
}

}  // namespace

bool run_collapses(const SimulationResult& r, Criterion c, double alpha, double p, const CollapseOptions& options) {
    if (!options.imperfection.any()) return r.collapse(c, alpha);
    const Model m = model_of(alpha, p, options);
    return r.collapse(c, m.block.alpha, m.symmetric() ? 0.0 : m.minus.alpha);
}

bool input_lifts_any(const GroundInput& input, double alpha, double p_min, const CollapseOptions& options) {
    const double p = std::max(p_min, lowest_standing_p(alpha, options.imperfection));
    return dynamics::input_lifts(input, model_of(alpha, std::isfinite(p) ? p : p_min, options));
}

bool collapses_at(const GroundInput& input, double alpha, double p, const CollapseOptions& options) {
    return run_collapses(run_block(input, alpha, p, options, options.criterion == Criterion::overturning),
                         options.criterion, alpha, p, options);
}

SimulationResult simulate_block(const GroundInput& input, double alpha, double p, const CollapseOptions& options) {
    return run_block(input, alpha, p, options, true);
}

CollapseResult smallest_collapse_p(const GroundInput& input, double alpha, const CollapseOptions& options) {
    CollapseResult out;
    auto collapses = [&](double p) {
        ++out.simulations;
        return collapses_at(input, alpha, p, options);
    };
    // Blocks that crush under their own weight (pivots set back) are left
    // out: the scan starts just above them.
    double lo = 0.0, p = std::max(options.p_min, lowest_standing_p(alpha, options.imperfection));
    while (p <= options.p_max) {
        if (collapses(p)) break;
        lo = p;
        p *= options.growth;
    }
    if (p > options.p_max) return out;
    if (lo == 0.0) {  // collapses already at p_min
        out.found = true;
        out.p = p;
        return out;
    }
    double hi = p;
    while ((hi - lo) / hi > options.rel_tol) {
        const double mid = 0.5 * (lo + hi);
        if (collapses(mid)) hi = mid;
        else lo = mid;
    }
    out.found = true;
    out.p = hi;
    out.p_safe = lo;
    return out;
}

}  // namespace rocking::records
