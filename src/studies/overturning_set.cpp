#include "studies/overturning_set.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rocking::studies {

bool accept_interval(const MarginSample& A, const MarginSample& B, double d, const RefineOptions& o) {
    if (A.collapse != B.collapse || !A.has_margins || !B.has_margins) return false;
    const std::size_t n = A.xi.size();
    if (B.xi.size() != n) return false;
    if (n == 0) return !A.collapse;  // never lifted at either end
    // Safe: every flight stays below 0; overturning: the falling flight above.
    const std::size_t j0 = A.collapse ? n - 1 : 0;
    double reach_a = INFINITY, reach_b = INFINITY;
    for (std::size_t j = j0; j < n; ++j) {
        const double xa = A.xi[j], xb = B.xi[j];
        if (A.collapse ? !(xa > 0 && xb > 0) : !(xa < 0 && xb < 0)) return false;
        if (A.slope[j] != 0) reach_a = std::min(reach_a, std::fabs(xa) / std::fabs(A.slope[j]));
        if (B.slope[j] != 0) reach_b = std::min(reach_b, std::fabs(xb) / std::fabs(B.slope[j]));
    }
    if (!(o.reach * d <= reach_a + reach_b)) return false;
    // Borne out: a Xi_j that turns inside shows as tangents the secant denies.
    for (std::size_t j = j0; j < n; ++j) {
        const double tol = o.consistency * std::min(std::fabs(A.xi[j]), std::fabs(B.xi[j]));
        if (!(std::fabs(A.xi[j] + A.slope[j] * d - B.xi[j]) <= tol)) return false;
        if (!(std::fabs(B.xi[j] - B.slope[j] * d - A.xi[j]) <= tol)) return false;
    }
    return true;
}

namespace {

struct Search {
    const std::function<MarginSample(double)>& sample;
    const RefineOptions& o;
    RefinedSet& out;

    MarginSample at(double x) {
        ++out.samples;
        MarginSample s = sample(x);
        if (s.has_margins && (s.xi.size() != s.slope.size()))
            throw std::logic_error("refine_set: a sample's margins and slopes differ in number");
        return s;
    }

    // [a, b] with its ends sampled; appends the samples strictly inside and b.
    void refine(double a, const MarginSample& A, double b, const MarginSample& B) {
        if (out.stopped) return;
        const double d = std::log(b / a);
        if (accept_interval(A, B, d, o)) {
            ++out.accepted;
        } else if (d > o.width) {
            const double m = std::sqrt(a * b);
            const MarginSample M = at(m);
            refine(a, A, m, M);
            refine(m, M, b, B);
            return;
        } else if (A.collapse == B.collapse) {
            ++out.at_width;
        }
        out.xs.push_back(b);
        out.collapse.push_back(B.collapse);
        out.stopped = o.first_only && B.collapse;
    }
};

}  // namespace

RefinedSet refine_set(const std::function<MarginSample(double)>& sample, const std::function<bool(double)>& collapses,
                      double lo, double hi, const RefineOptions& o) {
    if (!(lo > 0 && std::isfinite(hi) && hi > lo)) throw std::invalid_argument("refine_set: needs 0 < lo < hi, finite");
    if (!(o.width > 0 && o.width < 1)) throw std::invalid_argument("refine_set: the width must be in (0, 1)");
    if (o.coarse < 2) throw std::invalid_argument("refine_set: the coarse grid needs at least 2 points");
    if (!(o.reach > 0)) throw std::invalid_argument("refine_set: the reach must be > 0");
    if (!(o.consistency > 0 && o.consistency <= 1)) throw std::invalid_argument("refine_set: consistency must be in (0, 1]");
    if (!(o.rel_tol >= 1e-15 && o.rel_tol <= 0.1)) throw std::invalid_argument("refine_set: rel_tol must be in [1e-15, 0.1]");
    RefinedSet out;
    Search search{sample, o, out};
    const std::vector<GridPoint> grid = log_grid(lo, hi, o.coarse, false, {});
    MarginSample prev = search.at(grid.front().x);
    out.xs.push_back(grid.front().x);
    out.collapse.push_back(prev.collapse);
    out.stopped = o.first_only && prev.collapse;
    for (std::size_t k = 1; k < grid.size() && !out.stopped; ++k) {
        MarginSample next = search.at(grid[k].x);
        search.refine(grid[k - 1].x, prev, grid[k].x, next);
        prev = std::move(next);
    }
    for (std::size_t k = 1; k < out.xs.size(); ++k)
        if (out.collapse[k] != out.collapse[k - 1])
            out.brackets.push_back(
                bisect_boundary(collapses, out.xs[k - 1], out.collapse[k - 1], out.xs[k], o.rel_tol, out.bisection_runs));
    out.spans = spans_of(out.xs, out.collapse, out.brackets);
    if (o.guarantee_below < hi) out.unguaranteed_from = std::max(lo, o.guarantee_below);
    return out;
}

double covered_share(const std::vector<Span>& spans, double from, double to) {
    double covered = 0;
    for (const Span& s : spans) {
        const double a = std::max(from, s.from), b = std::min(to, s.to);
        if (b > a) covered += std::log(b / a);
    }
    return covered / std::log(to / from);
}

SetSummary summarise_set(const std::vector<Span>& spans, double lo, double hi, int points, double robust_width) {
    SetSummary out;
    out.first_overturning = out.first_robust_collapse = hi;
    if (!spans.empty()) {
        out.first_overturning = spans.front().from;
        out.overturns = true;
    }
    for (const Span& s : spans)
        if (std::log(s.to / s.from) > robust_width) {
            out.first_robust_collapse = s.from;
            out.robustly = true;
            break;
        }
    const std::vector<GridPoint> steps = log_grid(lo, hi, points, false, {});
    for (std::size_t k = 1; k < steps.size(); ++k)
        out.bands.push_back({steps[k - 1].x, steps[k].x, covered_share(spans, steps[k - 1].x, steps[k].x)});
    return out;
}

}  // namespace rocking::studies
