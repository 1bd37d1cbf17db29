// Eq. 27 at scale (issue 28, item 3; the paper's Figure 11 generalised): for
// every record and every block (alpha, p) of a grid, the record's first
// collapse q from its incremental dynamic analysis (studies/ida.hpp) against
// eq. 27's q at x = p to_k, for each of the eleven half-periods to_k
// (records/measures.hpp).
//
// A case (record, block, k) is non-conservative when the record, scaled to
// its collapse q, overturns a block that eq. 27 calls safe at that q:
//     collapse_q < q2_n6(p to_k).
// A record that never overturns the block up to the IDA's q_max is censored:
// its collapse q is above q_max, unknown, so it cannot show eq. 27 unsafe and
// is counted as conservative (with q_max above eq. 27's q that is exact;
// below it, a lower bound on the share).  The censored are counted apart.
//
// The share of non-conservative cases per k comes with two intervals.  The
// one to quote is the bootstrap over records (a cluster bootstrap: the
// records drawn with replacement, each drawn record bringing all its blocks,
// the share recomputed per k; the percentile interval at 90 % as the
// fragility fit's, GSL's mt19937 seeded, studies/resampling.hpp): the cases of
// one record on neighbouring blocks are strongly correlated, and the records
// are the independent draws.  Beside it the Wilson score interval (Wilson
// 1927), which stays inside [0, 1] and is not empty at 0 or n successes, but
// treats every case as an independent draw and so is too narrow here.  And
// per k the number of records non-conservative on at least one block.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "studies/ida.hpp"
#include "studies/resampling.hpp"

namespace rocking::studies {

constexpr int kHalfPeriods = 11;  // to_1..to_11

struct WilsonInterval {
    double lo = 0, hi = 1;
};

// The Wilson score interval for `successes` of `trials` at the two-sided
// level (e.g. 0.95):
//     (phat + z^2/(2n) -+ z sqrt(phat(1 - phat)/n + z^2/(4n^2))) / (1 + z^2/n),
// z = Phi^-1((1 + level)/2).  Throws std::invalid_argument for trials < 1,
// successes outside [0, trials], or level not in (0, 1).
WilsonInterval wilson_interval(int successes, int trials, double level);

// How a front end names the grid's parameters in its messages: the command
// line's flags ("--p-points 1"), or the Python module's keywords
// ("p_points=1", the default).
struct Eq27GridNames {
    std::string alpha = "alpha", p_min = "p_min", p_max = "p_max", p_points = "p_points";
    std::string equals = "=";  // between a name and its value
};

struct Eq27Grid {
    std::vector<double> alphas{0.05, 0.10, 0.15, 0.20, 0.25};
    double p_min = 0.5, p_max = 10.0;  // rad/s
    int p_points = 10;                 // log-spaced, both ends included
    std::vector<double> ps() const;
    // Every alpha with every p, alpha outermost; check() first.
    std::vector<BlockShape> blocks() const;
    std::string describe() const;
    // Throws std::invalid_argument, in `names`, for a grid that says other
    // than it counts: p_max below p_min; one p with a range (the p is p_min,
    // the range unused); more than one p on no range; a range too narrow for
    // its points (a p repeated); an alpha given twice (its cases counted
    // twice, distinct_inputs.hpp).  The bounds of each value are the front
    // ends' (their ranges differ in words only).
    void check(const Eq27GridNames& names = {}) const;
};

struct Eq27Record {
    const dynamics::GroundInput* input = nullptr;  // in g
    std::array<double, kHalfPeriods> to{};         // s; records::half_periods(r).to
};

// The bootstrap over records; resamples 0: none.
struct Eq27Bootstrap {
    int resamples = 1000;
    std::uint64_t seed = 1;
    double level = 0.9;  // as the fragility fit's (FragilityStudyOptions)
};

struct Eq27Options {
    Eq27Grid grid{};
    IdaOptions ida{};
    double level = 0.95;  // Wilson's
    Eq27Bootstrap bootstrap{};
    // Threads of the batch engine (batch/pool.hpp); the result does not depend on it.
    int threads = 1;
};

// One record against one block: its IDA point and eq. 27's q per k.
struct Eq27Case {
    int record = 0, block = 0;
    IdaPoint point{0, false};
    std::array<double, kHalfPeriods> q_eq27{};
    std::array<bool, kHalfPeriods> non_conservative{};
};

struct Eq27Share {
    int non_conservative = 0, cases = 0;
    double share = 0;
    WilsonInterval wilson;     // at the study's level, the cases taken as independent
    Range bootstrap;           // over records, at the bootstrap's level; {0, 0} without a bootstrap
    int records_with_any = 0;  // records non-conservative on at least one block
    int records = 0;
};

// One block of the map: of its records, how many are non-conservative per k.
struct Eq27Cell {
    BlockShape block;
    int records = 0, censored = 0;
    std::array<int, kHalfPeriods> non_conservative{};
};

// What a front end states beside the study's shares (the command line and
// the Python module say the same words).
extern const char* const kEq27Verdict;        // the verdict's rule, censoring included
extern const char* const kEq27WilsonNote;     // why the Wilson interval is not the one to quote
extern const char* const kEq27NoBootstrap;    // the bootstrap was not asked for

struct Eq27Study {
    std::vector<BlockShape> blocks;
    std::vector<Eq27Case> cases;  // record-major: cases[r * blocks + b]
    std::array<Eq27Share, kHalfPeriods> shares{};
    std::vector<Eq27Cell> map;    // one per block, in blocks' order
    std::vector<std::string> identities;  // each record's, in the records' order (the bootstrap's draw order)
    int records = 0;
    int censored = 0;             // cases whose record never overturned the block up to q_max
    double level = 0.95;          // Wilson's
    Eq27Bootstrap bootstrap{0, 0, 0};  // as run; resamples 0: none
};

// The verdict of one case for one k: the record overturned the block at a q
// below eq. 27's.  A censored point is never non-conservative.
bool non_conservative(const IdaPoint& point, double q_eq27);

// The bootstrap of the shares over records: counts[r][k] the cases of record
// r non-conservative for k, of `blocks` cases per record, the records in the
// order to draw them (record_order.hpp).  Each of the resamples draws
// counts.size() records with replacement (SeededRng::index, in order), the
// share for k is the sum of the drawn records' counts over
// counts.size() * blocks, and the result per k is the percentile interval of
// the resamples' shares at the level.  The same draws serve every k.
// Throws std::invalid_argument with no record, blocks < 1, a count outside
// [0, blocks], resamples < 2, or the level not in (0, 1).
std::array<Range, kHalfPeriods> record_bootstrap(const std::vector<std::array<int, kHalfPeriods>>& counts, int blocks,
                                                 const Eq27Bootstrap& bootstrap);

// The study from the points already known: points[r][b] for record r and
// block b, to[r] the record's half-periods, identities[r] its identity
// (record_order.hpp: sample_digest for a record), whose order the bootstrap
// draws the records in; Wilson at `level`, and the bootstrap over records
// unless its resamples are 0.  The cases and counts stay in the records'
// given order.  Throws std::invalid_argument when the sizes disagree, there
// is no record or block, a p * to_k is not finite and > 0, or the
// bootstrap's arguments are refused.
Eq27Study eq27_from_points(const std::vector<std::vector<IdaPoint>>& points,
                           const std::vector<std::array<double, kHalfPeriods>>& to,
                           const std::vector<std::string>& identities, const std::vector<BlockShape>& blocks,
                           double level, const Eq27Bootstrap& bootstrap = Eq27Bootstrap{});

// The IDA of every record on every block of the grid, then eq27_from_points
// on each IDA's point (its first overturning, either method), the records'
// identities their inputs' (input_digest).  Throws what
// incremental_dynamic_analysis and eq27_from_points throw.
Eq27Study eq27_at_scale(const std::vector<Eq27Record>& records, const Eq27Options& options);

// ---- Under each capacity (issue 39, item 3; docs/eq27_at_scale.md) ----
//
// A record's capacity on a block, the q a case compares with eq. 27's, is
// one of two numbers of its IDA:
//   first overturning: the lowest q at which the record overturns the block
//     (with the refine method, every island wider than its width w found);
//   first robust collapse: the start of the first interval of overturning
//     wider than the IDA's robust width in ln q, about what the grid method
//     reports as its first collapse (islands below it are left out).
// The first overturning is never above the first robust collapse, so a case
// non-conservative under the robust collapse is non-conservative under the
// first overturning too, and the share under the first overturning is the
// larger: the one that says how often the record, at some q eq. 27 calls
// safe, overturns the block.
struct Eq27Capacities {
    IdaPoint first_overturning{0, false}, first_robust_collapse{0, false};
};
Eq27Capacities capacities_of(const Ida& ida);

// What a front end says of each capacity (the command line and the Python module alike).
extern const char* const kEq27FirstOverturningNote;
extern const char* const kEq27RobustCollapseNote;
// The refine method's width and guarantee, the robust width, and the
// pairing of the two bootstraps, in one sentence.
std::string eq27_refine_note(const IdaOptions& ida);

struct Eq27ByCapacity {
    Eq27Study first_overturning, first_robust_collapse;
};

// eq27_from_points under each capacity: capacities[r][b] for record r and
// block b, identities[r] its identity.  Both bootstraps take the same seed
// and draw order, so that they draw the same records in the same order (paired resamples: a difference between the
// two intervals is the verdicts', not the draws').  Throws what
// eq27_from_points throws, and std::invalid_argument for a case whose first
// robust collapse lies below its first overturning, or is found where the
// first overturning is not (no IDA gives that).
Eq27ByCapacity eq27_by_capacity(const std::vector<std::vector<Eq27Capacities>>& capacities,
                                const std::vector<std::array<double, kHalfPeriods>>& to,
                                const std::vector<std::string>& identities, const std::vector<BlockShape>& blocks,
                                double level, const Eq27Bootstrap& bootstrap = Eq27Bootstrap{});

// The IDA of every record on every block of the grid (options.ida: either
// method), then eq27_by_capacity, the identities the inputs' (input_digest).
// Throws what eq27_at_scale throws.
Eq27ByCapacity eq27_at_scale_by_capacity(const std::vector<Eq27Record>& records, const Eq27Options& options);

}  // namespace rocking::studies
