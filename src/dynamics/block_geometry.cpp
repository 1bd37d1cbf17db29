#include "dynamics/block_geometry.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace rocking::dynamics {

namespace {

std::string g6(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

bool agrees(double given, double derived) { return std::fabs(given - derived) <= kGeometryAgreement * std::fabs(derived); }

}  // namespace

GivenBlock block_of_dimensions(double B, double H, const std::string& what) {
    if (!(std::isfinite(B) && B > 0 && std::isfinite(H) && H > 0))
        throw std::invalid_argument(what + ": the thickness and the height must be finite and > 0");
    // atan(B/H) >= pi/4 is a block at least as wide as tall: eq. 3's small-angle
    // forms and the rocking about a corner (before sliding) no longer hold.
    if (!(B < H))
        throw std::invalid_argument(what + ": alpha = atan(B/H) = " + g6(std::atan(B / H)) +
                                    " rad is not below pi/4: a rocking block is thinner than it is tall (B < H)");
    GivenBlock g;
    try {
        g.block = Block::from_half_dimensions(B / 2, H / 2);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(what + ": " + e.what());
    }
    // A subnormal B/H loses the digits of alpha; an underflowing R gives p = inf.
    if (!(g.block.alpha >= DBL_MIN && std::isfinite(g.block.p) && g.block.p > 0))
        throw std::invalid_argument(what + ": B/H = " + g6(B / H) + " gives no usable alpha and p (alpha " +
                                    g6(g.block.alpha) + ", p " + g6(g.block.p) + " rad/s)");
    g.given = GivenBlock::Given::dimensions;
    g.alpha = g.block.alpha;
    g.thickness = B;
    g.height = H;
    return g;
}

GivenBlock given_block(const BlockSpec& s, const ArgumentName& name) {
    if (s.thickness) {
        if (s.height.has_value() + s.half_height.has_value() != 1)
            throw std::invalid_argument(name("thickness") + " B goes with exactly one of " + name("height") + " H and " +
                                        name("half_height") + " h (m)");
        const double H = s.height ? *s.height : 2 * *s.half_height;
        const std::string what = name("thickness") + " " + g6(*s.thickness) + " " +
                                 (s.height ? name("height") + " " + g6(*s.height)
                                           : name("half_height") + " " + g6(*s.half_height));
        GivenBlock g = block_of_dimensions(*s.thickness, H, what);
        if (s.alpha && !agrees(*s.alpha, g.block.alpha))
            throw std::invalid_argument(what + " give alpha = atan(B/H) = " + g6(g.block.alpha) + " rad, but " +
                                        name("alpha") + " is " + g6(*s.alpha) +
                                        ": give the block one way, or both ways agreeing to 0.1 %");
        if (s.p && !agrees(*s.p, g.block.p))
            throw std::invalid_argument(what + " give p = sqrt(3 g / (4 R)) = " + g6(g.block.p) + " rad/s, but " +
                                        name("p") + " is " + g6(*s.p) +
                                        ": give the block one way, or both ways agreeing to 0.1 %");
        return g;
    }
    if (!s.alpha)
        throw std::invalid_argument("give the block as " + name("thickness") + " B " + name("height") + " H (m), or as " +
                                    name("alpha") + " A with " + name("p") + ", " + name("half_height") + " or " +
                                    name("height"));
    if (s.p.has_value() + s.half_height.has_value() + s.height.has_value() != 1)
        throw std::invalid_argument(name("alpha") + " A goes with exactly one of " + name("p") + ", " +
                                    name("half_height") + " and " + name("height"));
    // Named by its option here: Block's own "block: alpha must be ..." named none.
    if (!(std::isfinite(*s.alpha) && *s.alpha > 0 && *s.alpha < M_PI / 4))
        throw std::invalid_argument(name("alpha") + ": the slenderness must be in (0, pi/4) rad (got " + g6(*s.alpha) + ")");
    if (s.p && !(std::isfinite(*s.p) && *s.p > 0))
        throw std::invalid_argument(name("p") + ": must be > 0 rad/s (got " + g6(*s.p) + ")");
    GivenBlock g;
    g.alpha = *s.alpha;
    if (s.p) {
        g.block = Block::from_p(*s.p, *s.alpha);
        return g;
    }
    g.block = s.half_height ? Block::from_half_height(*s.half_height, *s.alpha) : Block::from_full_height(*s.height, *s.alpha);
    g.given = GivenBlock::Given::alpha_and_size;
    g.height = 2 * g.block.R * std::cos(*s.alpha);
    g.thickness = 2 * g.block.R * std::sin(*s.alpha);
    return g;
}

std::vector<GivenBlock> block_list(const std::string& text, const std::string& what) {
    std::vector<GivenBlock> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const std::size_t x = item.find('x');
        double B = NAN, H = NAN;
        std::size_t used_b = 0, used_h = 0;
        if (x != std::string::npos && item.find('x', x + 1) == std::string::npos) {
            try {
                B = std::stod(item.substr(0, x), &used_b);
                H = std::stod(item.substr(x + 1), &used_h);
            } catch (const std::exception&) {
                used_b = used_h = 0;
            }
        }
        if (x == std::string::npos || used_b != x || used_h != item.size() - x - 1 || used_b == 0 || used_h == 0)
            throw std::invalid_argument(what + ": each block is THICKNESSxHEIGHT in m, e.g. 0.6x4 (got '" + item + "')");
        GivenBlock g = block_of_dimensions(B, H, what + " " + item);
        g.label = item;
        for (const GivenBlock& seen : out)
            if (seen.thickness == B && seen.height == H) throw std::invalid_argument(what + ": " + item + " is given twice");
        out.push_back(g);
        if (out.size() > 50) throw std::invalid_argument(what + ": at most 50 blocks");
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

const char* given_name(const GivenBlock& b) {
    switch (b.given) {
    case GivenBlock::Given::dimensions: return "dimensions";
    case GivenBlock::Given::alpha_and_size: return "alpha and height";
    case GivenBlock::Given::alpha_and_p: break;
    }
    return "alpha and p";
}

std::string describe_block(const GivenBlock& b) {
    char text[400];
    const double alpha = b.block.alpha, deg = alpha * 180 / M_PI;
    switch (b.given) {
    case GivenBlock::Given::dimensions:
        std::snprintf(text, sizeof text,
                      "%s%sB = %.6g m, H = %.6g m: alpha = atan(B/H) = %.6g rad (%.4g deg), R = sqrt(B^2 + H^2)/2 = "
                      "%.6g m, p = sqrt(3 g/(4 R)) = %.6g rad/s (eqs. 2, 4; g = 9.81 m/s^2)",
                      b.label.empty() ? "" : "block ", b.label.empty() ? "" : (b.label + ": ").c_str(), b.thickness,
                      b.height, alpha, deg, b.block.R, b.block.p);
        break;
    case GivenBlock::Given::alpha_and_size:
        std::snprintf(text, sizeof text,
                      "alpha = %.6g rad (%.4g deg) and H = %.6g m given: B = H tan(alpha) = %.6g m, R = %.6g m, "
                      "p = sqrt(3 g/(4 R)) = %.6g rad/s (eqs. 2, 4; g = 9.81 m/s^2)",
                      alpha, deg, b.height, b.thickness, b.block.R, b.block.p);
        break;
    case GivenBlock::Given::alpha_and_p:
        std::snprintf(text, sizeof text, "alpha = %.6g rad (%.4g deg) and p = %.6g rad/s given (the block's size is not)",
                      alpha, deg, b.block.p);
        break;
    }
    return text;
}

}  // namespace rocking::dynamics
