// The rocking spectrum (Makris & Konstantinidis 2003): for one input and one
// slenderness alpha, the block's response over a log grid of pulsations p,
// and the set of p at which the input collapses the block, as intervals whose
// ends are refined by bisection and checked by a second solver.
//
// The grid sees an island of collapse (or of safety) only where a grid point
// falls inside it.  A second grid, offset by half a step in log p, halves that
// limit: a change of outcome between any two neighbours of the merged grids is
// a boundary.  Islands narrower than half a step may still be missed
// (docs/spectrum.md).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "records/collapse.hpp"
#include "studies/intervals.hpp"
#include "studies/overturning_set.hpp"

namespace rocking::studies {

struct SpectrumOptions {
    // Model, restitution, criterion and solver: by default those of Table 1's
    // search (linearised, exact solver, Housner's restitution, overturning,
    // free rocking followed).  Its scan fields (p_min, growth, ...) are unused.
    records::CollapseOptions model{};
    double p_min = 0.3, p_max = 30.0;  // rad/s
    int points = 200;                  // log-spaced from p_min to p_max, both included
    bool offset_grid = true;           // the second grid, half a step in log p from the first
    // More points to take as grid points (those within [p_min, p_max]): where
    // another search saw a change of outcome, e.g. Table 1's bracket, so that
    // an island it met and the grid stepped over is refined too.
    std::vector<double> extra_points;
    double rel_tol = 1e-6;             // boundaries bisected until (p_hi - p_lo) / p_hi <= rel_tol
    bool confirm = true;               // the conditioning probe and the second solver at every boundary
    double probe = 1e-13;              // the probe: the input scaled by 1 + probe and 1 - probe
    // The method (issue 39).  grid: the grids above.  refine: the overturning
    // set to a width w in ln p (studies/overturning_set.hpp, docs/
    // overturning_set.md section 3) from the main grid (`points`, no offset
    // grid, no extra points), each sample a run with each flight's escape
    // margin Xi_j plus a second run at p (1 + slope_step) for dXi_j / d ln p
    // (flights matched by index; a sample whose two runs differ in outcome or
    // in number of flights carries its outcome only).  Without the record
    // kernel (another input, solver, equation or criterion) every interval is
    // split to w.
    enum class Method { grid, refine };
    Method method = Method::grid;
    double width = 1e-5;         // w, in ln p (refine)
    double slope_step = 1e-9;    // the second run's relative step in p (refine)
    double robust_width = 5e-3;  // an interval wider than this in ln p is a robust collapse
    // refine: stop at the first sample that overturns (RefineOptions::
    // first_only): the first overturning only, as Table 1's search wants it.
    // The spectrum then ends there: its last interval is cut at that sample,
    // its points stop there, no bands and no first robust collapse.
    bool first_only = false;
    // The second solver, on the model of `model`: GSL rk8pd at rtol = atol =
    // 1e-13 alpha, as Table 1's bracket check (reproduce/scenes/records_analysis.cpp).
    dynamics::SolverOptions check_solver = rk8pd_check();
    static dynamics::SolverOptions rk8pd_check();
    // The grid in words: its points, step and the islands it may miss.
    std::string describe_grid() const;
    // The model, restitution, criterion and solver; the refinement and its checks.
    std::string describe_model() const;
    std::string describe_refinement() const;
    // The refine method's width, guarantee and robust width, in words.
    std::string describe_guarantee() const;
    double step() const;  // the main grid's ratio between neighbours
};

struct SpectrumPoint {
    double p = 0;
    GridKind grid = GridKind::main;
    double max_theta = 0;       // max |theta| / alpha during the input
    bool final_rotation = false, peak_rotation = false, overturning = false;  // collapse under each criterion
    double t_overturn = 0;      // s; NaN when the block does not overturn, or is taken to by its energy
    bool collapse = false;      // under the options' criterion
};


// One boundary of the collapse set: safe at p_safe, collapse at p_collapse,
// |p_collapse - p_safe| <= rel_tol max(p_safe, p_collapse).
struct Boundary {
    double p_safe = 0, p_collapse = 0;
    Confirmation confirmation = Confirmation::not_checked;
    std::string detail;  // what the probe or the second solver saw
    bool lower() const { return p_collapse > p_safe; }  // the start of an interval
};

// Collapse for p from `from` to `to`.  An end without a boundary is the
// grid's own (p_min or p_max): the set may go on beyond it.
struct Interval {
    double from = 0, to = 0;
    bool has_lower = false, has_upper = false;
    Boundary lower, upper;
};

// The start of the first interval of collapse of some kind, or p_max and
// found false (censored) without one.
struct SpectrumFirst {
    double p = 0;
    bool found = false;
};

struct Spectrum {
    double alpha = 0;
    bool lifts = false;                 // the input exceeds the uplift threshold at all
    std::vector<SpectrumPoint> points;  // both grids and the extra points, in increasing p
    std::vector<Interval> intervals;    // in increasing p
    int boundaries = 0;
    long simulations = 0;        // the first solver's: grid, bisection and probe
    long check_simulations = 0;  // the second solver's
    // Issue 39, both methods: the first overturning (the start of the first
    // interval), the first robust collapse (of the first interval wider than
    // robust_width in ln p) and the overturned share of each main-grid step in
    // ln p.  With the grid method they hold only what its grids saw.
    SpectrumFirst first_overturning, first_robust_collapse;
    std::vector<Band> bands;
    // The refine method's: `points` are then its coarse grid's, each run in full.
    bool refined = false;
    long samples = 0;           // samples with margins (each two runs, of `simulations`)
    long accepted = 0;          // intervals accepted by the margins
    long at_width = 0;          // intervals split down to w with one outcome at both ends
    bool with_margins = false;  // false: the record kernel does not run this model (every interval split to w)
    // The input's q = PGA / (alpha g) above (pi/2 - alpha)/alpha: an
    // overturning run need not have a flight with Xi > 0 (the guarantee stops
    // at p_min), else +inf.
    double unguaranteed_from = std::numeric_limits<double>::infinity();
};

// Throws std::invalid_argument for options out of range (points < 2,
// p_min not > 0, p_max not > p_min, rel_tol not in [1e-15, 0.1], probe not
// in (0, 1e-3], width not in (0, 0.1], slope_step not in [1e-12, 1e-6],
// robust_width not > 0) and whatever simulate() throws.
Spectrum rocking_spectrum(const dynamics::GroundInput& input, double alpha, const SpectrumOptions& options);

// One sample of the refine method at p (docs/overturning_set.md section 5):
// the run's outcome and, as records::collapses_at runs the model, each
// flight's escape margin Xi_j with dXi_j / d ln p from a second run at
// p (1 + slope_step), flights matched by index; the outcome only
// (has_margins false) where the two runs differ in outcome or number of
// flights.  Throws std::invalid_argument where the record kernel does not run
// the model (not a record, another solver, equation or criterion).
MarginSample margins_in_p(const dynamics::GroundInput& input, double alpha, double p, const SpectrumOptions& options);

}  // namespace rocking::studies
