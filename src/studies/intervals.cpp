#include "studies/intervals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rocking::studies {

std::string grid_kind_name(GridKind g) {
    switch (g) {
        case GridKind::main: return "main";
        case GridKind::offset: return "offset";
        case GridKind::extra: return "extra";
    }
    return "?";
}

double log_step(double lo, double hi, int points) { return std::pow(hi / lo, 1.0 / (points - 1)); }

std::vector<GridPoint> log_grid(double lo, double hi, int points, bool offset, const std::vector<double>& extra) {
    const double span = std::log(hi / lo);
    std::vector<GridPoint> xs;
    for (int k = 0; k < points; ++k) {
        // hi itself, not lo e^span: a search's end must be the one asked for.
        xs.push_back({k == points - 1 ? hi : lo * std::exp(span * k / (points - 1)), GridKind::main});
        if (offset && k < points - 1) xs.push_back({lo * std::exp(span * (k + 0.5) / (points - 1)), GridKind::offset});
    }
    for (double x : extra)
        if (x >= lo && x <= hi) xs.push_back({x, GridKind::extra});
    std::stable_sort(xs.begin(), xs.end(), [](const GridPoint& a, const GridPoint& b) { return a.x < b.x; });
    xs.erase(std::unique(xs.begin(), xs.end(), [](const GridPoint& a, const GridPoint& b) { return a.x == b.x; }),
             xs.end());
    return xs;
}

Bracket bisect_boundary(const std::function<bool(double)>& collapses, double a, bool collapse_a, double b,
                        double rel_tol, long& runs) {
    Bracket br;
    br.safe = collapse_a ? b : a;
    br.collapse = collapse_a ? a : b;
    while (std::fabs(br.collapse - br.safe) > rel_tol * std::max(br.safe, br.collapse)) {
        const double mid = 0.5 * (br.safe + br.collapse);
        ++runs;
        (collapses(mid) ? br.collapse : br.safe) = mid;
    }
    return br;
}

std::vector<Span> spans_of(const std::vector<double>& xs, const std::vector<bool>& collapse,
                           const std::vector<Bracket>& brackets) {
    std::vector<Span> out;
    std::size_t next = 0;
    if (collapse.front()) out.push_back(Span{xs.front(), 0, -1, -1});
    for (std::size_t k = 1; k < xs.size(); ++k) {
        if (collapse[k] == collapse[k - 1]) continue;
        const int index = static_cast<int>(next++);
        const Bracket& b = brackets.at(index);
        if (b.lower()) {
            out.push_back(Span{b.collapse, 0, index, -1});
        } else {
            out.back().to = b.collapse;
            out.back().upper = index;
        }
    }
    if (!out.empty() && out.back().upper < 0) out.back().to = xs.back();
    return out;
}

std::string confirmation_name(Confirmation c) {
    switch (c) {
        case Confirmation::not_checked: return "not checked";
        case Confirmation::confirmed: return "confirmed";
        case Confirmation::disagrees: return "second solver disagrees";
        case Confirmation::ill_conditioned: return "ill-conditioned";
    }
    return "?";
}

namespace {

std::string at(const char* what, const std::string& name, double x) {
    char text[160];
    std::snprintf(text, sizeof text, "%s at %s = %.9g", what, name.c_str(), x);
    return text;
}

}  // namespace

Checked check_bracket(const Bracket& b, const std::string& name, const BracketChecks& checks, long& runs,
                      long& second_runs) {
    Checked out;
    for (const double x : {b.safe, b.collapse}) {
        const bool expected = x == b.collapse;
        for (const bool up : {true, false}) {
            ++runs;
            if ((up ? checks.up : checks.down)(x) != expected) {
                out.confirmation = Confirmation::ill_conditioned;
                out.detail = at(up ? "the input times 1 + probe flips the outcome"
                                   : "the input times 1 - probe flips the outcome",
                                name, x);
                return out;
            }
        }
    }
    second_runs += 2;
    const bool hit = checks.second(b.collapse);
    const bool safe = !checks.second(b.safe);
    out.confirmation = hit && safe ? Confirmation::confirmed : Confirmation::disagrees;
    if (!hit) out.detail = at("the second solver sees no collapse", name, b.collapse);
    else if (!safe) out.detail = at("the second solver sees a collapse", name, b.safe);
    return out;
}

}  // namespace rocking::studies
