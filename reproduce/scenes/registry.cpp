#include <fstream>
#include <stdexcept>

#include "scene.hpp"

namespace rocking::scenes {

void SceneContext::write(const harness::Table& table, const std::string& file) {
    table.write(dir_ + "/" + file);
    written_.push_back(file);
}

std::vector<double> x_grid() {
    std::vector<double> x;
    for (int k = 5; k <= 200; ++k) x.push_back(k / 100.0);  // exact decimal abscissae
    return x;
}

const std::vector<Scene>& all_scenes() {
    static const std::vector<Scene> scenes = {
        {"fig04", "Figure 4: q1..q5 against x = p*to, their minimum, the q >= 2 limit of cases 3 and 5",
         "linearised eq. 3, no impact, collapse theta(t_fin) = alpha (eq. 11)",
         "closed forms eqs. 12, 15, 19, 22, 24 in overflow-free form (closed_forms.hpp); crossings by TOMS 748 to 1e-15",
         "", run_fig04},
        {"fig07", "Figure 7: q against x for cases 1, 2, 4 with N = 2..12 pulses",
         "linearised eq. 3, no impact, collapse theta(t_fin) = alpha at the onset of pulse N + 1",
         "superposition engine (S3), exact up to rounding (condition number printed in the CSV)",
         "", run_fig07},
        {"errata", "Errata: every printed closed form (eqs. 3, 6-8, 10, 12, 14-24, 27, 28) and textual claim checked",
         "linearised eq. 3 (sign of eqs. 6, 9, 13), no impact",
         "printed formulas evaluated as printed in double precision against the superposition engine on a grid",
         "", run_errata},
        {"fig05", "Figure 5: theta/alpha against t for cases 1, 2, 4 at PGA = q_i alpha g Rd, Rd < 1; collapse under three criteria",
         "linearised eq. 3 on either corner, impacts with restitution 1 (no dissipation), free rocking after the input",
         "exact event-driven solver (closed form between events, impacts located to machine precision)",
         "Odeint Fehlberg 7(8), rtol 1e-12, atol 1e-12 alpha", run_fig05},
        {"fig06", "Figure 6: theta(t_fin)/alpha of the full eq. 1 against the linearised eq. 3, against the height H",
         "full eq. 1 and linearised eq. 3, block of half-height H (eq. 2), case 2 at its collapse PGA q2 alpha g",
         "Odeint Fehlberg 7(8), rtol 1e-10 (full); exact solver (linearised)",
         "GSL rk8pd, rtol 1e-12", run_fig06},
        {"fig08", "Figure 8: eq. 27 against w/p beside the one-sine overturning curve of Makris and the Coccia & Como curve",
         "one-sine pulse (Zhang & Makris 2001), overturning at any time; linearised and full equation, restitution 1 and Housner's",
         "linearised: exact solver; full: Fehlberg 7(8) rtol 1e-10; threshold scanned by 1 % then bisected to 1e-5",
         "Odeint Fehlberg 7(8), rtol 1e-12", run_fig08},
        {"table1", "Table 1: q = PGA/(alpha g) of the paper's 20 records, and the collapse search on the available real records",
         "linearised eq. 3, Housner restitution, overturning at any time (free rocking included)",
         "q: arithmetic (g = 981 cm/s^2); p: exact solver, p raised by 1% from 0.3 rad/s, bisection to 1e-4",
         "the same search, each final bracket confirmed by GSL rk8pd at rtol 1e-13", run_table1},
        {"table2", "Table 2: to_5 from Table 1's PGA and PGV; the eleven half-periods of the available real records",
         "ground-motion measures of Section 4 (records/measures.hpp)",
         "exact integrals of the piecewise-linear record; FFT and Morse CWT (beta 27, gamma 3) peaks refined by parabolas",
         "", run_table2},
        {"fig11", "Figure 11: (p to_k, q) of every definition k against eq. 27; non-conservative points counted",
         "eq. 27 (case 2, 6 + 1 pulses) against the paper's Tables 1-2 and the available records",
         "superposition engine for eq. 27; records as table1 and table2", "", run_fig11},
        {"fig12", "Figure 12: to_5 only, with the code's q = 2 and where eq. 27 falls below it",
         "eq. 27 with to_5 = pi PGV / PGA (eq. 31)", "superposition engine; crossing by TOMS 748", "", run_fig12},
        {"spectrum", "Rocking spectrum of the Norcia records: the overturning intervals in p at Table 1's alphas against Table 1's p; "
                     "beside them the refine method's first overturning and first robust collapse",
         "linearised eq. 3, Housner restitution, overturning at any time (free rocking included)",
         "exact solver on 200 + 199 log-spaced p (0.3-30 rad/s) and Table 1's bracket; the refine search from the 200 "
         "down to 1e-3 in ln p; boundaries bisected to 1e-6, each probed (input x 1 +- 1e-13) and checked by GSL rk8pd "
         "at rtol 1e-13",
         "every confirmed bracket re-simulated at both ends by GSL rk8pd at rtol 1e-13 (records::collapses_at)", run_spectrum},
        {"fragility", "Fragility of four blocks over the shared records and a fixed synthetic set (10 MP2003 pulses, 10 "
                      "RDK2008 records): first collapse q by IDA, lognormal fits, eq. 27's share per to_k; and under "
                      "each capacity (issue 39): first overturning, first robust collapse, stripes",
         "linearised eq. 3, Housner restitution, overturning at any time (free rocking included)",
         "exact solver on 100 + 99 log-spaced q (1-20); first collapse bisected to 1e-6, probed (input x 1 +- 1e-13) "
         "and checked by GSL rk8pd at rtol 1e-13; maximum-likelihood lognormal, bootstrap 500 resamples (mt19937, seed 1); "
         "the capacities by the refine method from the same 100 q down to w = 1e-3 in ln q",
         "both ends of every confirmed first-collapse and first-overturning bracket re-simulated by GSL rk8pd at rtol "
         "1e-13 (records::collapses_at)",
         run_fragility},
        {"imperfection", "Imperfect blocks (issue 41): the closed forms toward each corner of a leaning, out-of-plumb or "
                         "set-back block against the perfect block's q; eq. 27's non-conservative share per to_k with "
                         "them on the shared records",
         "linearised eq. 3 on each corner with its own alpha and p (dynamics/imperfect_block.hpp: lean 0.01-0.02 rad, "
         "out of plumb 0.01-0.02 rad, setback of NTC 2018 eq. 7.8.2's stress block at fc 1, 2, 5 MPa, 1800 kg/m3), "
         "each corner's restitution from the geometry; closed forms without impact, collapse theta(t_fin) = the "
         "corner's alpha; records: overturning at any time",
         "closed forms: qfactor::imperfect_collapse ((S2) per corner, exact up to rounding); records: the fragility "
         "scene's IDA (exact solver on 100 + 99 log-spaced q from where each block lifts, min(1, alpha_sigma/alpha), "
         "to 20, first collapse bisected to 1e-6, probed x 1 +- "
         "1e-13 and checked by GSL rk8pd at rtol 1e-13) on its four blocks",
         "", run_imperfection},
        {"sliding", "Sliding (issue 41): the paper's claims on a base with Coulomb friction mu = 0.8, 0.6, 0.4: "
                    "'sliding can be neglected below alpha = 0.35' on the shared records, eq. 27's non-conservative "
                    "share per to_k, Figure 5's Rd < 1; and the closed forms the engine must meet",
         "rocking-only: full eq. 1, Housner's restitution, overturning at any time; with friction: the "
         "sliding-rocking block (docs/sliding.md: full equations, rest, slide, rock, slide-rock, impacts without "
         "rebound, stuck or slipping); eq. 27's ideal model: linearised eq. 3 (Table 1's)",
         "the sliding engine's event-driven Dormand-Prince 5(4) and the full model's Odeint dopri5, every run at "
         "rtol = atol = 1e-9 and 1e-11 alpha (the rocking model's near-ties told apart from sliding's effects); "
         "eq. 27: the IDA's grid (100 + 99 q from 1 to 20) to the first collapse, bisected to 1e-6, each bracket "
         "run again at 1e-11",
         "", run_sliding},
    };
    return scenes;
}

}  // namespace rocking::scenes
