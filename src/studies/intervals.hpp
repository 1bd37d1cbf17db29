// The parameter-agnostic machinery of a search for the set where an input
// collapses a block: a log grid (with a second grid offset by half a step and
// extra points), the bisection of a change of outcome to a relative
// tolerance, and the assembly of intervals from the grid's outcomes and the
// refined boundaries.  The rocking spectrum runs it over p, the incremental
// dynamic analysis over q; neither the parameter nor the model is known here.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace rocking::studies {

enum class GridKind { main, offset, extra };
std::string grid_kind_name(GridKind g);  // "main", "offset", "extra"

struct GridPoint {
    double x;
    GridKind kind;
};

// `points` values log-spaced from lo to hi, both included (hi exactly), with,
// when `offset`, the points - 1 values half a step in log between them, and
// the `extra` values within [lo, hi]; in increasing order, an extra value
// equal to a grid value being that value.  Expects 0 < lo < hi, points >= 2.
std::vector<GridPoint> log_grid(double lo, double hi, int points, bool offset, const std::vector<double>& extra);

// The main grid's ratio between neighbours.
double log_step(double lo, double hi, int points);

// A refined change of outcome: safe at `safe`, collapse at `collapse`.
struct Bracket {
    double safe = 0, collapse = 0;
    bool lower() const { return collapse > safe; }  // the start of an interval
};

// Bisects [a, b], whose outcomes differ (collapse_a at a), until
// |collapse - safe| <= rel_tol max(safe, collapse); each call of `collapses`
// is counted in `runs`.
Bracket bisect_boundary(const std::function<bool(double)>& collapses, double a, bool collapse_a, double b,
                        double rel_tol, long& runs);

enum class Confirmation {
    not_checked,      // confirm off
    confirmed,        // well conditioned, and the second solver sees the same bracket
    disagrees,        // well conditioned, but the second solver does not see the bracket
    ill_conditioned,  // the probe flips an outcome at an end: no solver's answer is the truth there
};
std::string confirmation_name(Confirmation c);

// What the checks of a bracket found.
struct Checked {
    Confirmation confirmation = Confirmation::not_checked;
    std::string detail;  // what the probe or the second solver saw, "... at <name> = <value>"
};

// The outcomes a bracket is checked with, at a value of the parameter: the
// input scaled by 1 + probe and 1 - probe (the same model), and a second
// solver on the unscaled input.
struct BracketChecks {
    std::function<bool(double)> up, down, second;
};

// The probe first: where scaling the input by 1 +- probe flips an outcome at
// either end, the boundary's place is set by rounding, and a second solver's
// agreement or not would prove nothing.  Elsewhere both ends must come out the
// same under the second solver.  `name` is the parameter's ("p", "q"); the
// probe's runs are counted in `runs`, the second solver's in `second_runs`.
Checked check_bracket(const Bracket& b, const std::string& name, const BracketChecks& checks, long& runs,
                      long& second_runs);

// Collapse from `from` to `to`.  lower and upper index the brackets; -1 where
// the end is the grid's own (the set may go on beyond it).
struct Span {
    double from = 0, to = 0;
    int lower = -1, upper = -1;
};

// The spans of collapse from the outcomes at increasing xs and the brackets
// of their changes, in order (one per change of outcome between neighbours).
std::vector<Span> spans_of(const std::vector<double>& xs, const std::vector<bool>& collapse,
                           const std::vector<Bracket>& brackets);

}  // namespace rocking::studies
