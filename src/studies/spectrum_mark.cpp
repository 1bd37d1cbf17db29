#include "studies/spectrum_mark.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "dynamics/model.hpp"
#include "records/collapse.hpp"

namespace rocking::studies {

double height_at_p(double alpha, double p) {
    const double R = 3 * dynamics::kGravity / (4 * p * p);
    return 2 * R * std::cos(alpha);
}

double far_height(const SpectrumMark& m, const SpectrumFirst& far) {
    return far.found ? height_at_p(m.block.alpha, far.p) : 0;
}

std::string why_not_markable(const BlockShape& block, const SpectrumOptions& o) {
    if (block.p >= o.p_min && block.p <= o.p_max) return "";
    char text[300];
    std::snprintf(text, sizeof text, "its p, %.6g rad/s (H %.4g m), lies outside the spectrum's p range [%g, %g] rad/s",
                  block.p, height_at_p(block.alpha, block.p), o.p_min, o.p_max);
    return text;
}

namespace {

std::string resolution_of(const SpectrumOptions& o) {
    char text[300];
    if (o.method == SpectrumOptions::Method::refine)
        std::snprintf(text, sizeof text, "the set to w = %g in ln p: islands and gaps narrower than w may be missed", o.width);
    else
        std::snprintf(text, sizeof text, "the set read on a grid (steps x%.5g): it may hold survivors and miss islands "
                      "between its points (--method refine finds every one wider than w)",
                      o.offset_grid ? std::sqrt(o.step()) : o.step());
    return text;
}

}  // namespace

SpectrumMark mark_block(const dynamics::GroundInput& input, const Spectrum& s, const BlockShape& block,
                        const SpectrumOptions& o) {
    if (s.alpha != block.alpha) throw std::invalid_argument("mark_block: the spectrum is of another alpha");
    const std::string why = why_not_markable(block, o);
    if (!why.empty()) throw std::invalid_argument("mark_block: " + why);
    SpectrumMark m;
    m.block = block;
    m.resolution = resolution_of(o);
    m.refined = o.method == SpectrumOptions::Method::refine;
    m.overturns = records::collapses_at(input, block.alpha, block.p, o.model);
    for (std::size_t k = 0; k < s.intervals.size(); ++k) {
        const Interval& in = s.intervals[k];
        if (in.from <= block.p && block.p <= in.to) {
            m.in_set = true;
            // Its ends where they are boundaries, not the grid's own ends.
            m.below = SpectrumFirst{in.from, in.has_lower};
            m.above = SpectrumFirst{in.to, in.has_upper};
            if (k > 0) m.survivors_below = SpectrumFirst{s.intervals[k - 1].to, true};
            if (k + 1 < s.intervals.size()) m.survivors_above = SpectrumFirst{s.intervals[k + 1].from, true};
            break;
        }
        if (in.to < block.p) m.below = SpectrumFirst{in.to, true}, m.below_far = SpectrumFirst{in.from, in.has_lower};
        if (in.from > block.p && !m.above.found)
            m.above = SpectrumFirst{in.from, true}, m.above_far = SpectrumFirst{in.to, in.has_upper};
    }
    if (m.below.found) m.height_below = height_at_p(block.alpha, m.below.p);
    if (m.above.found) m.height_above = height_at_p(block.alpha, m.above.p);
    if (m.survivors_below.found) m.height_survivors_below = height_at_p(block.alpha, m.survivors_below.p);
    if (m.survivors_above.found) m.height_survivors_above = height_at_p(block.alpha, m.survivors_above.p);
    return m;
}

std::vector<std::string> describe_mark_lines(const SpectrumMark& m) {
    const std::string name = m.block.built.empty() ? "the block" : "block " + m.block.built + " m";
    const double alpha = m.block.alpha;
    char text[600];
    std::vector<std::string> out;
    std::snprintf(text, sizeof text, "%s (alpha %.6g, p %.6g rad/s, H %.4g m): %s (a run at its p)%s", name.c_str(),
                  alpha, m.block.p, height_at_p(alpha, m.block.p), m.overturns ? "OVERTURNS" : "does not overturn",
                  !m.in_set && m.overturns ? ", on an island the spectrum's method did not resolve" : "");
    out.push_back(text);
    // A grid's intervals join its sampled points: what they say of the blocks
    // between is the grid's reading, said as such (a newcomer read "taller
    // blocks survive" as fact; simulate overturned two of them).
    const std::string seen = m.refined ? "" : "on the grid: ";
    // H and p of a side's change, with its distance from the block in p.
    auto at = [&](const SpectrumFirst& f) {
        std::snprintf(text, sizeof text, "H %.6g m (p %.7g rad/s, %+.3g %%)", height_at_p(alpha, f.p), f.p,
                      100 * (f.p / m.block.p - 1));
        return std::string(text);
    };
    // The nearest overturning blocks on one side: the whole interval, near end first.
    auto span = [&](const SpectrumFirst& near, const SpectrumFirst& far) {
        if (!far.found) return at(near) + " and beyond, to the spectrum's range";
        std::snprintf(text, sizeof text, "H %.6g to %.6g m (p %.7g to %.7g rad/s, %+.3g %%)", height_at_p(alpha, near.p),
                      height_at_p(alpha, far.p), near.p, far.p, 100 * (near.p / m.block.p - 1));
        return std::string(text);
    };
    if (m.in_set) {
        std::string line = seen + "inside an overturning interval, whose blocks all overturn: from ";
        line += m.below.found ? at(m.below) : std::string("the spectrum's lowest p");
        line += " to ";
        line += m.above.found ? at(m.above) : std::string("the spectrum's highest p");
        out.push_back(line);
        auto band = [&](const SpectrumFirst& edge, const SpectrumFirst& next, const char* which) {
            if (!edge.found) return;
            if (!next.found) {
                out.push_back(seen + which + " blocks survive from there to the end of the spectrum's range");
                return;
            }
            std::snprintf(text, sizeof text, "%s blocks survive only to H %.6g m (p %.7g rad/s: a band %.3g in ln p)",
                          which, height_at_p(alpha, next.p), next.p, std::fabs(std::log(next.p / edge.p)));
            out.push_back(seen + text);
        };
        band(m.below, m.survivors_below, "taller");
        band(m.above, m.survivors_above, "shorter");
    } else {
        out.push_back(seen + "the nearest taller blocks that overturn: " +
                      (m.below.found ? span(m.below, m.below_far) : std::string("none on the spectrum's range")));
        out.push_back(seen + "the nearest shorter blocks that overturn: " +
                      (m.above.found ? span(m.above, m.above_far) : std::string("none on the spectrum's range")));
    }
    if (!m.resolution.empty()) out.push_back(m.resolution);
    return out;
}

std::string describe_mark(const SpectrumMark& m) {
    std::string out;
    for (const std::string& line : describe_mark_lines(m)) out += (out.empty() ? "" : "; ") + line;
    return out;
}

}  // namespace rocking::studies
