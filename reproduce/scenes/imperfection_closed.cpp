// The imperfection scene's first half: each corner of an imperfect block,
// and the paper's closed forms toward each corner (qfactor/imperfect_q.hpp)
// against the perfect block's.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "dynamics/model.hpp"
#include "imperfection.hpp"
#include "pulse/pulse_train.hpp"
#include "qfactor/imperfect_q.hpp"
#include "qfactor/superposition.hpp"

namespace rocking::scenes::imperfection_scene {

namespace {

using dynamics::Imperfection;

// A slender block (alpha 0.05) beside the fragility scene's four: a lean
// takes the largest share of the smallest alpha.  The table against x holds
// alpha = 0.1 alone (the file's size); the summary every block.
const std::vector<std::pair<double, double>> kClosedBlocks = {{0.05, 3.0}, {0.1, 1.5}, {0.1, 3.0}, {0.2, 1.5},
                                                              {0.2, 3.0}};
// The paper's Figure 5 range (0.2-0.8) and beyond it.
const std::vector<double> kX = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.5, 2.0};
constexpr double kTableAlpha = 0.1;

struct Case {
    std::string name;  // as the rows print it
    PulseTrain train;
};

// Cases 1, 2 and 4 (eqs. 12, 15, 22: Figures 4, 5 and 7) and eq. 27 (case 2, 6 + 1 pulses).
std::vector<Case> cases() {
    return {{"case 1", pulse_case(1)}, {"case 2", pulse_case(2)}, {"case 4", pulse_case(4)},
            {"eq. 27", repeated_case(2, 6)}};
}

std::string fixed(double v, int digits) {
    char b[32];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}

}  // namespace

void run_closed_forms(SceneContext& ctx) {
    const std::vector<NamedImperfection> imps = closed_form_imperfections();
    const std::string inputs =
        "the perfect blocks (alpha, p rad/s) (0.05, 3), (0.10, 1.5), (0.10, 3), (0.20, 1.5), (0.20, 3): R = 3 g / (4 p^2) "
        "(eq. 4, g = 9.81 m/s^2), b = R sin alpha, h = R cos alpha; imperfections: lean 0.01 and 0.02 rad, out of plumb "
        "0.01 and 0.02 rad (toward theta > 0), fc 1, 2 and 5 MPa at density 1800 kg/m3";

    std::vector<std::string> columns = kImperfectionColumns;
    for (const char* c : {"alpha", "p", "b", "h", "sigma0_kPa", "setback_mm", "setback_over_b", "alpha_plus",
                          "p_plus", "R_plus", "e_onto_plus", "alpha_minus", "p_minus", "R_minus", "e_onto_minus"})
        columns.push_back(c);
    harness::Table corners(columns);
    corners.note("scene", "imperfection: each corner of the imperfect blocks (dynamics::imperfect_geometry)");
    corners.note("model",
                 "lean: the rectangle on a bed inclined toward theta > 0; out of plumb: the parallelogram of a wall "
                 "built leaning toward theta > 0; setback: each pivot set back by half the compressed zone of NTC 2018 "
                 "eq. 7.8.2's stress block 0.85 fc under the block's own weight, sigma0 = 2 rho g h, u = b sigma0 / "
                 "(0.85 fc); per corner: alpha and R of the vector pivot -> centre of gravity, p^2 = g R / (k^2 + "
                 "R^2), the restitution of an impact onto it (k^2 + r+ . r-) / (k^2 + R^2)");
    corners.note("solver", "closed forms of dynamics/imperfect_block.hpp");
    corners.note("inputs", inputs);
    corners.note("columns", "alpha, p: the perfect block's; b, h: its half-width and half-height (m); sigma0_kPa: the "
                            "mean stress of its weight on its base; setback_mm, setback_over_b: the pivot's setback "
                            "u and u / b; *_plus, *_minus: the corners theta > 0 and theta < 0 (rad, rad/s, m)");

    std::vector<std::string> qcols = kImperfectionColumns;
    for (const char* c : {"alpha", "p", "case", "x", "q_plus", "min_phi_plus", "q_minus", "min_phi_minus", "q_block",
                          "weaker", "q_perfect", "overstatement"})
        qcols.push_back(c);
    harness::Table qt(qcols);
    qt.note("scene", "imperfection: the closed-form collapse PGA of an imperfect block toward each corner against x "
                     "(Figure 4's cases on imperfect blocks) and how far the perfect block's q overstates it");
    qt.note("model", "linearised eq. 3 on each corner with its own alpha and p, no impact (the paper's condition: the "
                     "excursion stays on the corner it started on), collapse theta(t_fin) = that corner's alpha");
    qt.note("solver", "qfactor::imperfect_collapse: each corner's (S2) at x_sigma = p_sigma to, times alpha_sigma; the "
                      "excursion by collapse_excursion");
    qt.note("inputs", inputs + "; this table: the blocks of alpha 0.10; cases 1, 2, 4 (eqs. 12, 15, 22) and eq. 27 "
                               "(case 2, 6 + 1 pulses); x = p to with p the perfect block's, x = 0.1, 0.2, 0.3, 0.4, "
                               "0.5, 0.6, 0.8, 1.0, 1.5, 2.0");
    qt.note("columns",
            "q_plus, q_minus: the collapse PGA toward each corner (the train as given, its mirror image) over alpha g, "
            "alpha the perfect block's; min_phi_*: the lowest theta / alpha_sigma between the end of the first pulse "
            "and t_fin at that PGA (the closed form holds while > 0); q_block = min(q_plus, q_minus), weaker its "
            "side (+1, -1); q_perfect: the perfect block's q at x; overstatement = q_perfect / q_block - 1, how far "
            "the paper's q overstates the imperfect block's capacity");

    std::vector<std::string> scols = kImperfectionColumns;
    for (const char* c : {"alpha", "p", "points", "overstatement_min", "overstatement_max", "overstatement_min_0.2_0.8",
                          "overstatement_max_0.2_0.8", "weaker_minus", "off_corner"})
        scols.push_back(c);
    harness::Table st(scols);
    st.note("scene", "imperfection: per block, how far the perfect block's q overstates the imperfect block's "
                     "capacity, over cases 1, 2, 4 and eq. 27 and the 10 x of imperfection_q.csv");
    st.note("model", "as imperfection_q.csv");
    st.note("solver", "as imperfection_q.csv, on every block (imperfection_q.csv lists those of alpha 0.10)");
    st.note("inputs", inputs);
    st.note("columns", "points: (case, x) pairs; overstatement_min..max: the range of q_perfect / q_block - 1 over them, "
                       "and over x = 0.2..0.8 (the range of the paper's Figure 5); weaker_minus: the points where "
                       "the corner theta < 0 is the weaker; off_corner: the points where an excursion leaves its "
                       "corner (min_phi <= 0 on either side: the closed form does not hold there)");

    for (const NamedImperfection& n : imps)
        for (const auto& [alpha, p] : kClosedBlocks) {
            const HalfDimensions d = half_dimensions(alpha, p);
            const dynamics::ImperfectGeometry g = dynamics::imperfect_geometry(d.b, d.h, n.imperfection);
            corners.row();
            add_imperfection_cells(corners, n);
            corners.add(fixed(alpha, 2)).add(fixed(p, 1)).add(d.b).add(d.h).add(g.sigma0 / 1e3).add(g.setback * 1e3);
            corners.add(g.setback / d.b);
            for (const dynamics::CornerGeometry* k : {&g.plus, &g.minus})
                corners.add(k->alpha).add(k->p).add(k->R).add(k->restitution_onto);
            double lo = INFINITY, hi = -INFINITY, lo_paper = INFINITY, hi_paper = -INFINITY;
            int points = 0, weaker_minus = 0, off_corner = 0;
            for (const Case& c : cases())
                for (double x : kX) {
                    const ImperfectCollapse ic =
                        imperfect_collapse(c.train, x / p, {g.plus.alpha, g.plus.p}, {g.minus.alpha, g.minus.p});
                    const double q_block = ic.pga_g() / alpha, q_perfect = q_factor(c.train, x).q;
                    const double over = q_perfect / q_block - 1;
                    ++points;
                    lo = std::min(lo, over);
                    hi = std::max(hi, over);
                    if (x >= 0.2 - 1e-12 && x <= 0.8 + 1e-12) {
                        lo_paper = std::min(lo_paper, over);
                        hi_paper = std::max(hi_paper, over);
                    }
                    weaker_minus += ic.weaker_side() < 0;
                    off_corner += !(ic.toward_plus.excursion.stays_positive() && ic.toward_minus.excursion.stays_positive());
                    if (alpha != kTableAlpha) continue;
                    qt.row();
                    add_imperfection_cells(qt, n);
                    qt.add(fixed(alpha, 2)).add(fixed(p, 1)).add(c.name).add(fixed(x, 1));
                    for (const DirectionalCollapse* s : {&ic.toward_plus, &ic.toward_minus})
                        qt.add(s->pga_g / alpha).add(s->excursion.min_phi);
                    qt.add(q_block).add(ic.weaker_side()).add(q_perfect).add(over);
                }
            st.row();
            add_imperfection_cells(st, n);
            st.add(fixed(alpha, 2)).add(fixed(p, 1)).add(points).add(lo).add(hi).add(lo_paper).add(hi_paper);
            st.add(weaker_minus).add(off_corner);
        }
    ctx.write(corners, "imperfection_corners.csv");
    ctx.write(qt, "imperfection_q.csv");
    ctx.write(st, "imperfection_capacity.csv");
}

}  // namespace rocking::scenes::imperfection_scene
