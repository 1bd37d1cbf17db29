// rocking collapse: Table 1's search for the first overturning p.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/geometry.hpp"
#include "cli/help.hpp"
#include "cli/imperfection.hpp"
#include "cli/json_text.hpp"
#include "json/collapse_json.hpp"
#include "cli/options.hpp"
#include "records/collapse.hpp"
#include "harness/table.hpp"
#include "studies/search_alpha.hpp"

namespace rocking::cli {

namespace {

// The run of the same block under the same model: every flag the search
// read, --dt being simulate's --record-dt.
std::string simulate_command(const std::string& path, const Args& a) {
    // Quoted for the shell where the path needs it.
    const bool plain = path.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789._/+-") ==
                       std::string::npos;
    std::string quoted = "'";
    for (char c : path) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    std::string text = "rocking simulate --record " + (plain ? path : quoted + "'");
    for (const char* f : {"--thickness", "--height", "--model", "--solver", "--criterion", "--restitution", "--rtol", "--atol", "--unit", "--floor",
                          "--friction"})
        if (a.values.count(f)) text += std::string(" ") + f + " " + a.values.at(f);
    if (a.values.count("--dt")) text += " --record-dt " + a.values.at("--dt");
    return text + imperfection_flags_text(a);
}

}  // namespace

int cmd_collapse(int argc, char** argv) {
    using namespace rocking::dynamics;
    const std::string path =
        file_argument(argc, argv, 2, usage_line("collapse"));
    const Args a = parse(argc, argv, 3,
                         {"--alpha", "--thickness", "--height", "--half-height", "--model", "--solver", "--criterion",
                          "--restitution", "--rtol", "--atol", "--unit", "--dt", "--floor", "--friction", "--lean", "--out-of-plumb", "--fc", "--density"});
    // The search is over p: of a block given as built only its alpha counts,
    // and its own p is printed beside the search's.
    std::optional<GivenBlock> given;
    if (a.values.count("--thickness")) given = block_option(a);
    else if (a.values.count("--height") || a.values.count("--half-height"))
        throw UsageError("--height and --half-height go with --thickness here: the search is over p, alpha alone is --alpha");
    else if (!a.values.count("--alpha")) throw UsageError("give --alpha A, or the block as --thickness B --height H (m)");
    const double alpha = given ? given->block.alpha : number("--alpha", a.values.at("--alpha"));
    const std::string alpha_text = given ? significant(alpha, 6) + " (atan(B/H))" : a.values.at("--alpha");
    if (!studies::in_search_alpha_range(alpha))
        throw UsageError("--alpha: must be in " + std::string(studies::kSearchAlphaRange) + " (got " + alpha_text + ")");
    records::CollapseOptions o;
    if (a.values.count("--model")) {
        const std::string m = a.values.at("--model");
        if (m == "full") o.equation = Equation::full, o.solver.kind = SolverKind::dopri5;
        else if (m != "linearised") throw UsageError("--model: linearised or full");
    }
    try {
        if (a.values.count("--solver")) o.solver.kind = parse_solver(a.values.at("--solver"));
        if (a.values.count("--criterion")) o.criterion = parse_criterion(a.values.at("--criterion"));
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    tolerance_options(a.values, alpha, o.solver);
    restitution_into(a, o);
    friction_into(a, o);
    imperfection_into(a, o);
    if (o.friction > 0 && (a.values.count("--model") || a.values.count("--solver")))
        throw UsageError("--model and --solver do not apply with --friction: the sliding-rocking model has its full "
                         "equations and its event-driven solver");
    if (o.friction > 0 && a.values.count("--rtol")) o.sliding_rtol = o.solver.rtol;
    if (o.equation == Equation::full && o.solver.kind == SolverKind::exact)
        throw UsageError("the exact solver handles the linearised equation only");
    const records::Record r = load_record(path, a);
    const SampledInput input(r.in_g(kGravity), r.dt, r.name);
    refuse_unresolvable_run(o.p_max, input.t_end(), a, {"--dt"}, path);
    const records::CollapseResult c = records::smallest_collapse_p(input, alpha, o);
    if (a.json) {
        std::cout << json_text(json::collapse_json(path, alpha, c, o, given ? &*given : nullptr)) << "\n";
    } else {
        if (c.below_range())
            std::printf("p <= %.6f rad/s: %s overturns the block (alpha = %g) already at the search's lowest "
                        "pulsation; the smallest one that overturns it lies at or below that, outside the search\n",
                        c.p, r.name.c_str(), alpha);
        else if (c.found)
            std::printf("p = %.6f rad/s: the first pulsation of the search at which %s overturns the block "
                        "(alpha = %g); it does not at %.6f. Not a bound: the overturning p do not form an interval, "
                        "and a lower p may overturn it too (docs/findings.md, T1b)\n",
                        c.p, r.name.c_str(), alpha, c.p_safe);
        else {
            // Below the uplift threshold no p can move the block: say so, or the
            // scan's "up to 30 rad/s" reads as if a larger p might.
            Model m;  // any p: the threshold depends on alpha and the equation only
            m.equation = o.equation;
            m.block = Block::from_p(1.0, alpha);
            const double pga_g = r.pga() / kGravity, thr = m.uplift_threshold();
            if (o.imperfection.any() && !records::input_lifts_any(input, alpha, o.p_min, o))
                std::printf("no collapse for p up to %g rad/s: the record never lifts the block at all (it stays within "
                            "each corner's uplift threshold, the searched blocks' lowest)\n", o.p_max);
            else if (o.imperfection.any()) std::printf("no collapse for p up to %g rad/s\n", o.p_max);
            else if (pga_g <= thr)
                std::printf("no collapse for p up to %g rad/s: the record never lifts the block at all (PGA %.6g g <= "
                            "the uplift threshold %s g = %.6g g)\n",
                            o.p_max, pga_g, o.equation == Equation::full ? "tan alpha" : "alpha", thr);
            else std::printf("no collapse for p up to %g rad/s\n", o.p_max);
        }
        std::printf("  %s; %d simulations\n", o.describe().c_str(), c.simulations);
        if (given)
            std::printf("  the block: %s; whether this record overturns it at its own p: %s\n",
                        describe_block(*given).c_str(), simulate_command(path, a).c_str());
    }
    return 0;
}

}  // namespace rocking::cli
