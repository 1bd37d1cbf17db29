// The block as an engineer gives it (issue 40): as built, by its full
// thickness B and height H in metres,
//   alpha = atan(B/H),  R = sqrt(B^2 + H^2) / 2,  p = sqrt(3 g / (4 R))   (eqs. 2, 4),
// or by its slenderness alpha (rad) with p (rad/s), the half-height h (the H
// of eq. 2) or the height 2h.  Given both ways (B and H with alpha or p),
// the two must agree.  One reading for the command line and Python, each
// naming the arguments its own way.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/model.hpp"

namespace rocking::dynamics {

// Given both ways, alpha and p must agree with the dimensions' to this share:
// the digits an engineer types (0.149 for atan(0.15) = 0.14889) pass, another
// block does not.
constexpr double kGeometryAgreement = 1e-3;

struct BlockSpec {
    std::optional<double> thickness, height, half_height, alpha, p;
};

struct GivenBlock {
    enum class Given { dimensions, alpha_and_size, alpha_and_p };
    Block block{};
    // The slenderness the outputs divide by and the thresholds use: the alpha
    // typed where it was given (block.alpha, recomputed from the half-width
    // and half-height, may differ from it in the last bit), else block.alpha.
    double alpha = 0;
    Given given = Given::alpha_and_p;
    double thickness = 0, height = 0;  // m, where known (not with alpha and p)
    std::string label;                 // "0.6x4" for a block of a list, else empty
    bool sized() const { return given != Given::alpha_and_p; }
};

// How the caller spells an argument: "thickness" -> "--thickness" or "thickness".
using ArgumentName = std::function<std::string(const std::string&)>;

// The block of spec, or std::invalid_argument saying what is wrong in the
// caller's names: thickness with exactly one of height and half_height
// (alpha, p beside them are checks), or alpha with exactly one of p,
// half_height and height.
GivenBlock given_block(const BlockSpec& spec, const ArgumentName& name);

// B x H (full dimensions, m), refused (std::invalid_argument, prefixed by
// `what`) where B/H gives no rocking block: B >= H, or no usable alpha and p.
GivenBlock block_of_dimensions(double B, double H, const std::string& what);

// "0.6x4,0.45x3": blocks THICKNESSxHEIGHT in m, at most 50, none twice;
// std::invalid_argument prefixed by `what`.
std::vector<GivenBlock> block_list(const std::string& text, const std::string& what);

// One line: what was given and what follows from it, with the equations.
std::string describe_block(const GivenBlock& b);

// "dimensions", "alpha and height" or "alpha and p".
const char* given_name(const GivenBlock& b);

}  // namespace rocking::dynamics
