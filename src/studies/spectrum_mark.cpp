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
    for (const Interval& in : s.intervals) {
        if (in.from <= block.p && block.p <= in.to) {
            m.in_set = true;
            m.below = m.above = SpectrumFirst{block.p, true};
            break;
        }
        if (in.to < block.p) m.below = SpectrumFirst{in.to, true};
        if (in.from > block.p && !m.above.found) m.above = SpectrumFirst{in.from, true};
    }
    if (m.below.found) m.height_below = height_at_p(block.alpha, m.below.p);
    if (m.above.found) m.height_above = height_at_p(block.alpha, m.above.p);
    return m;
}

std::string describe_mark(const SpectrumMark& m) {
    const std::string name = m.block.built.empty() ? "the block" : "block " + m.block.built + " m";
    char text[600];
    std::snprintf(text, sizeof text, "%s (alpha %.6g, p %.6g rad/s, H %.4g m): %s at its own p (a run)", name.c_str(),
                  m.block.alpha, m.block.p, height_at_p(m.block.alpha, m.block.p),
                  m.overturns ? "OVERTURNS" : "does not overturn");
    std::string out = text;
    if (m.in_set) {
        out += "; inside an overturning interval of the spectrum";
    } else {
        if (m.overturns) out += ", on an island the spectrum's method did not resolve";
        auto side = [&](const SpectrumFirst& f, double h, const char* which) {
            if (!f.found) return std::string("; no overturning p ") + which + " it on the spectrum's range";
            std::snprintf(text, sizeof text, "; nearest overturning p %s it %.6g rad/s (%+.3g %%: the block with H = %.4g m)",
                          which, f.p, 100 * (f.p / m.block.p - 1), h);
            return std::string(text);
        };
        out += side(m.below, m.height_below, "below");
        out += side(m.above, m.height_above, "above");
    }
    return out;
}

}  // namespace rocking::studies
