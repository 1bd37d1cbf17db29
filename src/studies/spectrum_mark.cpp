#include "studies/spectrum_mark.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "dynamics/model.hpp"
#include "records/collapse.hpp"

namespace rocking::studies {

double height_at_p(double alpha, double p) {
    const double R = 3 * dynamics::kGravity / (4 * p * p);
    return 2 * R * std::cos(alpha);
}

SpectrumMark mark_block(const dynamics::GroundInput& input, const Spectrum& s, const BlockShape& block,
                        const SpectrumOptions& o) {
    if (s.alpha != block.alpha) throw std::invalid_argument("mark_block: the spectrum is of another alpha");
    SpectrumMark m;
    m.block = block;
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
        if (in.to < block.p) m.below = SpectrumFirst{in.to, true};
        if (in.from > block.p && !m.above.found) m.above = SpectrumFirst{in.from, true};
    }
    if (m.below.found) m.height_below = height_at_p(block.alpha, m.below.p);
    if (m.above.found) m.height_above = height_at_p(block.alpha, m.above.p);
    if (m.survivors_below.found) m.height_survivors_below = height_at_p(block.alpha, m.survivors_below.p);
    if (m.survivors_above.found) m.height_survivors_above = height_at_p(block.alpha, m.survivors_above.p);
    return m;
}

std::string describe_mark(const SpectrumMark& m) {
    const std::string name = m.block.built.empty() ? "the block" : "block " + m.block.built + " m";
    char text[600];
    std::snprintf(text, sizeof text, "%s (alpha %.6g, p %.6g rad/s, H %.4g m): %s at its own p (a run)", name.c_str(),
                  m.block.alpha, m.block.p, height_at_p(m.block.alpha, m.block.p),
                  m.overturns ? "OVERTURNS" : "does not overturn");
    std::string out = text;
    auto side = [&](const SpectrumFirst& f, double h, const char* which, const char* what, const char* none) {
        if (!f.found) return std::string("; ") + none;
        std::snprintf(text, sizeof text, "; %s p %s it %.6g rad/s (%+.3g %%: H = %.4g m)", what, which, f.p,
                      100 * (f.p / m.block.p - 1), h);
        return std::string(text);
    };
    if (m.in_set) {
        out += "; inside an overturning interval of the spectrum, the blocks between its ends overturn too: "
               "the nearest surviving blocks lie beyond them";
        out += side(m.below, m.height_below, "below", "its interval ends, for taller blocks, at",
                    "for taller blocks its interval reaches the spectrum's lowest p");
        auto band = [&](const SpectrumFirst& edge, const SpectrumFirst& next, const char* which) {
            if (!edge.found) return std::string();
            if (!next.found) return std::string("; the ") + which + " blocks survive on the rest of the spectrum's range";
            std::snprintf(text, sizeof text, "; the %s survivors reach only to p %.6g rad/s (H %.4g m: a band %.3g in ln p)",
                          which, next.p, height_at_p(m.block.alpha, next.p), std::fabs(std::log(next.p / edge.p)));
            return std::string(text);
        };
        out += band(m.below, m.survivors_below, "taller");
        out += side(m.above, m.height_above, "above", "its interval ends, for shorter blocks, at",
                    "for shorter blocks its interval reaches the spectrum's highest p");
        out += band(m.above, m.survivors_above, "shorter");
    } else {
        if (m.overturns) out += ", on an island the spectrum's method did not resolve";
        out += side(m.below, m.height_below, "below", "nearest overturning",
                    "no overturning p below it on the spectrum's range");
        out += side(m.above, m.height_above, "above", "nearest overturning",
                    "no overturning p above it on the spectrum's range");
    }
    return out;
}

}  // namespace rocking::studies
