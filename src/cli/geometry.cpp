#include "cli/geometry.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace rocking::cli {

namespace {

std::string g6(double v) { return significant(v, 6); }

// B x H (full dimensions, m) as a block, or a UsageError saying why not, in
// the terms of `what` ("--thickness 0.6 --height 4", "--block 0.6x4").
dynamics::Block from_dimensions(double B, double H, const std::string& what) {
    if (!(std::isfinite(B) && B > 0 && std::isfinite(H) && H > 0))
        throw UsageError(what + ": the thickness and the height must be finite and > 0");
    // atan(B/H) >= pi/4 is a block wider than tall: it does not rock about a corner
    // before it slides or tips as a squat body, and eq. 3's small-angle forms fail.
    if (!(B < H))
        throw UsageError(what + ": alpha = atan(B/H) = " + g6(std::atan(B / H)) +
                         " rad is not below pi/4: a rocking block is thinner than it is tall (B < H)");
    dynamics::Block b{};
    try {
        b = dynamics::Block::from_half_dimensions(B / 2, H / 2);
    } catch (const std::invalid_argument& e) {
        throw UsageError(what + ": " + e.what());
    }
    // A subnormal B/H loses the digits of alpha; an underflowing R gives p = inf.
    if (!(b.alpha >= DBL_MIN && std::isfinite(b.p) && b.p > 0))
        throw UsageError(what + ": B/H = " + g6(B / H) + " gives no usable alpha and p (alpha " + g6(b.alpha) +
                         ", p " + g6(b.p) + " rad/s)");
    return b;
}

bool agrees(double given, double derived) { return std::fabs(given - derived) <= kGeometryAgreement * std::fabs(derived); }

}  // namespace

const std::vector<std::string>& geometry_flags() {
    static const std::vector<std::string> flags = {"--thickness", "--height", "--half-height", "--alpha", "--p"};
    return flags;
}

bool dimensions_given(const Args& a) { return a.values.count("--thickness") > 0; }

GivenBlock block_option(const Args& a) {
    auto has = [&](const char* f) { return a.values.count(f) > 0; };
    auto num = [&](const char* f) { return number(f, a.values.at(f)); };
    GivenBlock g;
    if (has("--thickness")) {
        if (has("--height") + has("--half-height") != 1)
            throw UsageError("--thickness B goes with exactly one of --height H and --half-height h (m)");
        const double B = num("--thickness");
        const double H = has("--height") ? num("--height") : 2 * num("--half-height");
        const std::string what = "--thickness " + a.values.at("--thickness") +
                                 (has("--height") ? " --height " + a.values.at("--height")
                                                  : " --half-height " + a.values.at("--half-height"));
        g.block = from_dimensions(B, H, what);
        g.given = GivenBlock::Given::dimensions;
        g.thickness = B;
        g.height = H;
        if (has("--alpha") && !agrees(num("--alpha"), g.block.alpha))
            throw UsageError(what + " give alpha = atan(B/H) = " + g6(g.block.alpha) + " rad, but --alpha is " +
                             a.values.at("--alpha") + ": give the block one way, or both ways agreeing to 0.1 %");
        if (has("--p") && !agrees(num("--p"), g.block.p))
            throw UsageError(what + " give p = sqrt(3 g / (4 R)) = " + g6(g.block.p) + " rad/s, but --p is " +
                             a.values.at("--p") + ": give the block one way, or both ways agreeing to 0.1 %");
        return g;
    }
    if (!has("--alpha")) throw UsageError("give the block as --thickness B --height H (m), or as --alpha A with --p, --half-height or --height");
    const double alpha = num("--alpha");
    if (has("--p") + has("--half-height") + has("--height") != 1)
        throw UsageError("--alpha A goes with exactly one of --p, --half-height and --height");
    try {
        if (has("--p")) {
            g.block = dynamics::Block::from_p(num("--p"), alpha);
        } else {
            g.block = has("--half-height") ? dynamics::Block::from_half_height(num("--half-height"), alpha)
                                           : dynamics::Block::from_full_height(num("--height"), alpha);
            g.given = GivenBlock::Given::alpha_and_size;
            g.height = 2 * g.block.R * std::cos(alpha);
            g.thickness = 2 * g.block.R * std::sin(alpha);
        }
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    return g;
}

std::vector<GivenBlock> block_list(const std::string& flag, const std::string& text) {
    std::vector<GivenBlock> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = text.find(',', start);
        const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const std::size_t x = item.find('x');
        if (item.empty() || x == std::string::npos || item.find('x', x + 1) != std::string::npos)
            throw UsageError(flag + ": each block is THICKNESSxHEIGHT in m, e.g. 0.6x4 (got '" + item + "')");
        const double B = number(flag + " (thickness of " + item + ")", item.substr(0, x));
        const double H = number(flag + " (height of " + item + ")", item.substr(x + 1));
        GivenBlock g;
        g.block = from_dimensions(B, H, flag + " " + item);
        g.given = GivenBlock::Given::dimensions;
        g.thickness = B;
        g.height = H;
        g.label = item;
        for (const GivenBlock& seen : out)
            if (seen.thickness == B && seen.height == H) throw UsageError(flag + ": " + item + " is given twice");
        out.push_back(g);
        if (out.size() > 50) throw UsageError(flag + ": at most 50 blocks");
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
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

std::string block_json(const GivenBlock& b) {
    const bool sized = b.sized();
    const char* given = b.given == GivenBlock::Given::dimensions       ? "dimensions"
                        : b.given == GivenBlock::Given::alpha_and_size ? "alpha and height"
                                                                       : "alpha and p";
    return std::string("\"given\": \"") + given + "\", \"thickness\": " + (sized ? json_number(b.thickness) : std::string("null")) +
           ", \"height\": " + (sized ? json_number(b.height) : std::string("null")) +
           ", \"R\": " + (sized ? json_number(b.block.R) : std::string("null"));
}

}  // namespace rocking::cli
