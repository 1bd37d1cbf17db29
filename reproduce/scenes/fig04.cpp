// Figure 4: the five closed forms, their minimum and where it changes case.
#include <cmath>

#include "numerics/roots.hpp"
#include "qfactor/closed_forms.hpp"
#include "scene.hpp"

namespace rocking::scenes {

using numerics::root_of;

void run_fig04(SceneContext& ctx) {
    harness::Table curves({"x", "q1", "q2", "q3", "q4", "q5", "q_min", "case_min"});
    curves.note("scene", "fig04 (Figure 4 of the paper)");
    curves.note("model", "linearised eq. 3, rocking on one corner without impact, collapse theta(t_fin) = alpha");
    curves.note("solver", "closed forms eqs. 12, 15, 19, 22, 24 (closed_forms.hpp), relative error < 1e-15");
    curves.note("inputs", "the five step pulses of Figure 3 (NOTES.md), x = p*to from 0.05 to 2.00");
    for (double x : x_grid()) {
        curves.row().add(x);
        double q_min = INFINITY;
        int which = 0;
        for (int i = 1; i <= 5; ++i) {
            const double q = q_case(i, x);
            curves.add(q);
            if (q < q_min) q_min = q, which = i;
        }
        curves.add(q_min).add(which);
    }
    ctx.write(curves, "fig04.csv");

    harness::Table points({"point", "x", "q"});
    points.note("scene", "fig04: the marked points of Figure 4");
    points.note("model", "linearised eq. 3, rocking on one corner without impact, collapse theta(t_fin) = alpha");
    points.note("solver", "TOMS 748 root bracketing to 52 bits on the closed forms");
    points.note("inputs", "closed forms q1..q5 (eqs. 12, 15, 19, 22, 24) as in fig04.csv; q2 = q4 bracketed on x in [0.1, 2], q1, q2, q4 = 2 on [0.05, 5]; q3, q5 evaluated at x = 50");
    const double x24 = root_of([](double x) { return q2(x) - q4(x); }, 0.1, 2.0);
    points.row().add("q2 = q4 (minimum changes from case 4 to case 2)").add(x24).add(q2(x24));
    for (int i : {1, 2, 4}) {
        const double x2 = root_of([i](double x) { return q_case(i, x) - 2.0; }, 0.05, 5.0);
        points.row().add("q" + std::to_string(i) + " = 2").add(x2).add(2.0);
    }
    // Cases 3 and 5 start with a half pulse: they need q >= 2 to rock at all,
    // and q3, q5 -> 2 from above as x -> infinity (they never reach it).
    for (int i : {3, 5}) points.row().add("q" + std::to_string(i) + " at x = 50 (limit 2)").add(50.0).add(q_case(i, 50.0));
    ctx.write(points, "fig04_points.csv");
}

}  // namespace rocking::scenes
