// Incremental dynamic analysis (IDA) of one block under one input: the input
// scaled so that its intensity q = PGA/(alpha g) runs over a log grid, the
// outcome under the model's criterion at each q, every change of outcome
// bisected, and the set of q that overturn the block as intervals.  Collapse
// need not be monotone in q: a stronger input can throw the block back before
// it tips ("resurrection"), so every interval is kept, and the first
// collapse q (the record's collapse intensity, the point the fragility fit
// takes) is the lowest interval's start.
//
// The grid's limit is the spectrum's (studies/intervals.hpp): an island of
// collapse or of safety narrower than half a step in log q may be missed.
// The refine method (issue 39, studies/overturning_set.hpp) finds every
// island and gap wider than a width w in ln q instead, from each flight's
// escape margin, where the record kernel runs the model (a record, eq. 3, the
// exact solver, overturning); elsewhere it splits every interval down to w.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "records/collapse.hpp"
#include "studies/fragility.hpp"
#include "studies/intervals.hpp"
#include "studies/overturning_set.hpp"
#include "studies/stripe_fit.hpp"

namespace rocking::studies {

struct IdaOptions {
    // Table 1's model by default (linearised, exact solver, Housner's
    // restitution, overturning); its scan fields (p_min, growth, ...) are unused.
    records::CollapseOptions model{};
    // q = 1 is where the input just reaches alpha g, the linearised uplift
    // threshold: below it the block does not lift on the linearised equation.
    double q_min = 1.0, q_max = 20.0;
    // Where the grid of the block (alpha, p) starts: q_min, or lower where an
    // imperfect block lifts below it (lowest_lift_q), so that no first
    // collapse below q = 1 passes unseen.  Per block: a shared start would
    // take every block's grid down to the weakest's (a setback near
    // crushing lifts at q ~ 1e-13).
    double q_start(double alpha, double p) const;
    int points = 100;          // log-spaced from q_min to q_max, both included
    bool offset_grid = true;   // a second grid, half a step in log q from the first
    double rel_tol = 1e-6;     // boundaries bisected until (q_hi - q_lo) / q_hi <= rel_tol
    // The checks of a bracket (intervals.hpp, check_bracket), as the spectrum's:
    // the input scaled by 1 +- probe at both ends, then GSL rk8pd at 1e-13.
    // By default only the first collapse's bracket, the point a fragility fit
    // takes (all of them cost about 6 runs each, 2 of them rk8pd's).
    enum class Checks { none, first_collapse, every_bracket };
    Checks checks = Checks::first_collapse;
    double probe = 1e-13;
    // grid: the log grid above (and its offset grid); refine: the search of
    // docs/overturning_set.md, section 3, from the main grid (points) down to
    // a spacing of `width` in ln q where the escape margins do not accept an
    // interval.  The grid is the default until the refine method's cost is
    // decided (docs/overturning_set.md, section 4).
    enum class Method { grid, refine };
    Method method = Method::grid;
    double width = 1e-5;         // w, in ln q (refine)
    double robust_width = 5e-3;  // an interval wider than this in ln q is a robust collapse
    // What the inputs are where they are not the records as read (a floor's
    // motion in place of the ground's): stated by describe_model, so that every
    // output and a rows file's resume check carry it.  Empty: the records.
    std::string input_note;
    std::string describe_grid() const;
    // What q is and where the grid starts, in words.
    std::string describe_q() const;
    std::string describe_model() const;
    std::string describe_checks() const;
    // The refine method's width, guarantee and robust width, in words.
    std::string describe_guarantee() const;
};

struct IdaInterval {
    double from = 0, to = 0;          // q
    bool has_lower = false, has_upper = false;  // false: the grid's own end
    Bracket lower, upper;             // in q
    Checked lower_check, upper_check; // not_checked unless the options ask for it
};

struct IdaGridPoint {
    double q = 0;
    GridKind grid = GridKind::main;
    bool collapse = false;
};

// A band of q (a step of the main grid) and the share of it, in ln q, that
// the intervals cover.
using IdaBand = Band;

struct Ida {
    double alpha = 0, p = 0;
    double q_input = 0;                   // the input's own q, unscaled
    double q_start = 1;                   // where the grid started (IdaOptions::q_start)
    std::vector<IdaGridPoint> points;     // both grids, increasing q
    std::vector<IdaInterval> intervals;   // increasing q
    // The first collapse q (the lowest interval's start), or q_max censored.
    IdaPoint point{0, false};
    long simulations = 0;        // the model's solver: grid, bisection and probe
    long check_simulations = 0;  // the second solver's
    // Both methods, from the intervals: the first overturning (the lowest
    // interval's start: `point`), the first robust collapse (the start of the
    // first interval wider than robust_width in ln q, or q_max censored), and
    // the overturned share of each main-grid step.  With the grid method they
    // hold only what its grid saw.
    IdaPoint first_overturning{0, false}, first_robust_collapse{0, false};
    std::vector<IdaBand> bands;
    // The refine method's: `points` are then its coarse grid's samples only.
    bool refined = false;
    long samples = 0;        // runs with margins (of `simulations`)
    long accepted = 0;       // intervals accepted by the margins
    long at_width = 0;       // intervals split down to w with one outcome at both ends
    bool with_margins = false;  // false: the record kernel does not run this model (every interval split to w)
    // Above the turn-back bound q = (pi/2 - alpha)/alpha an overturning run
    // need not have a flight with Xi > 0: the search's guarantee stops there
    // (+inf when q_max is below it).
    double unguaranteed_from = std::numeric_limits<double>::infinity();
};

// Throws std::invalid_argument for alpha not in (0, pi/4), p not finite and > 0,
// an input that never moves (peak 0), points < 2, q_min not > 0, q_max not
// > q_min, rel_tol not in [1e-15, 0.1], width not in (0, 0.1],
// robust_width not > 0, and whatever simulate() throws.  The grid runs from
// options.q_start(alpha, p): an imperfect block's from where it lifts.
Ida incremental_dynamic_analysis(const dynamics::GroundInput& input, double alpha, double p, const IdaOptions& options);

struct BlockShape {
    double alpha = 0, p = 0;
    std::string built;  // "0.6x4" where given as thickness x height (m), for the outputs; else empty
    // {alpha, p} as before the name: most blocks have none.
    BlockShape(double alpha_ = 0, double p_ = 0, std::string built_ = {})
        : alpha(alpha_), p(p_), built(std::move(built_)) {}
};

// The lowest q = PGA/(alpha g) at which the block (alpha, p) lifts, alpha
// the nominal: 1 for the paper's block (eq. 3's threshold alpha g); an
// imperfect block's lowest corner, min over sigma of alpha_sigma/alpha (a
// lean psi: (alpha - psi)/alpha; a setback lowers both corners).  The full
// equations lift at tan alpha_sigma g, above it: nothing below lifts.
double lowest_lift_q(double alpha, double p, const records::CollapseOptions& model);


struct FragilityStudyOptions {
    IdaOptions ida{};
    int resamples = 1000;        // 0: no bootstrap
    std::uint64_t seed = 1;
    double level = 0.9;
    // Threads of the batch engine (batch/pool.hpp); the result does not depend on it.
    int threads = 1;
    // The refine method's guarantee and its three fits, each named by its capacity, in words.
    std::string describe_fits() const;
};

// A lognormal fit of one capacity's points (fit_lognormal, bootstrap), or why
// ln L has none.
struct CapacityFit {
    std::vector<IdaPoint> points;
    bool fitted = false;
    std::string no_fit;  // why not fitted (why_no_maximum)
    LognormalFragility fit;
    bool bootstrapped = false;
    BootstrapInterval interval;
};

// The multiple-stripe fit (stripe_fit.hpp) of the IDAs' overturning sets, or why not.
struct StripeFit {
    StripeShares shares;
    std::vector<Stripe> stripes;
    bool fitted = false;
    std::string no_fit;  // why not fitted (why_no_stripe_maximum)
    StripeFragility fit;
    bool bootstrapped = false;
    BootstrapInterval interval;
};

struct BlockFragility {
    BlockShape block;
    std::vector<Ida> idas;            // one per input, in the inputs' order
    std::vector<IdaPoint> points;     // each IDA's point, in the inputs' order
    // Each record's identity (record_order.hpp), in the inputs' order, and
    // the draw order they set: every fit and bootstrap below takes the
    // records in it, so that none depends on the order the records were
    // given in.
    std::vector<std::string> identities;
    std::vector<std::size_t> draw_order;
    bool fitted = false;              // false where ln L has no maximum (why_no_maximum)
    std::string no_fit;               // why not fitted
    LognormalFragility fit;
    bool bootstrapped = false;
    BootstrapInterval interval;
    std::vector<EmpiricalPoint> empirical;
    // With the refine method (issue 39) the capacity three ways: the fit
    // above takes the first overturning (its points are the first
    // overturnings); `robust` the first robust collapses; `stripes` the
    // multiple-stripe fit of the overturned shares (docs/fragility.md,
    // "Three capacities").  Empty with the grid method.
    bool three_ways = false;
    CapacityFit robust;
    StripeFit stripes;
};

// One block's fragility from its IDAs (one per input, in the inputs' order):
// their points, the empirical curve and, where ln L has a maximum
// (why_no_maximum), the lognormal fit with its bootstrap interval; with the
// refine method (options.ida.method) also the fit on the first robust
// collapses and the multiple-stripe fit on the main grid's stripes
// (stripe_shares of options.ida's q_min, q_max and points), each with its
// bootstrap at the same resamples, seed and level.  `identities` (one per
// IDA: record_order.hpp, sample_digest for a record) set the draw order in
// which every fit and bootstrap takes the records, so that the three
// bootstraps draw the same records and none depends on the order given.
// fragility_study's second half, for a front end that ran the IDAs elsewhere
// (rocking fragility on the batch engine's ranks).  Throws what fit_lognormal,
// bootstrap, fit_stripes and bootstrap_stripes throw on data that have a
// maximum, and std::invalid_argument for an identity count other than the IDAs'.
BlockFragility block_fragility(const BlockShape& block, std::vector<Ida> idas, const std::vector<std::string>& identities,
                               const FragilityStudyOptions& options);

// For each block, the IDA of every input, the lognormal fit of their points
// with its bootstrap interval, and the empirical curve; the draw order from
// `identities` (one per input), or from input_digests(inputs) without them.
// Throws what incremental_dynamic_analysis, bootstrap and block_fragility throw.
std::vector<BlockFragility> fragility_study(const std::vector<const dynamics::GroundInput*>& inputs,
                                            const std::vector<std::string>& identities,
                                            const std::vector<BlockShape>& blocks, const FragilityStudyOptions& options);
std::vector<BlockFragility> fragility_study(const std::vector<const dynamics::GroundInput*>& inputs,
                                            const std::vector<BlockShape>& blocks, const FragilityStudyOptions& options);

}  // namespace rocking::studies
