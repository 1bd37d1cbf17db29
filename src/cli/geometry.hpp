// The block as the command line takes it (issue 40): as built, by its full
// thickness B and height H in metres,
//   alpha = atan(B/H),  R = sqrt(B^2 + H^2) / 2,  p = sqrt(3 g / (4 R))   (eqs. 2, 4),
// or by its slenderness alpha (rad) with p (rad/s), the half-height h (the H
// of eq. 2) or the height 2h.  Given both ways, the two must agree.
#pragma once

#include <string>
#include <vector>

#include "cli/options.hpp"
#include "dynamics/model.hpp"

namespace rocking::cli {

// Given both ways (--thickness and --height with --alpha or --p), alpha and p
// must agree with the dimensions' to this share: the digits an engineer types
// (0.149 for atan(0.15) = 0.14889) pass, another block does not.
constexpr double kGeometryAgreement = 1e-3;

struct GivenBlock {
    enum class Given { dimensions, alpha_and_size, alpha_and_p };
    dynamics::Block block{};
    Given given = Given::alpha_and_p;
    double thickness = 0, height = 0; // m, where known (not with alpha and p)
    std::string label;                // "0.6x4" for a block of a list, else empty
    bool sized() const { return given != Given::alpha_and_p; }
};

// The flags block_option reads, for a command's parse() list.
const std::vector<std::string>& geometry_flags();

// --thickness B --height H, or --alpha A with one of --p, --half-height, --height;
// --alpha or --p beside --thickness are checks.  A UsageError names what is wrong.
GivenBlock block_option(const Args& a);

// Whether the command line gives the block by its dimensions.
bool dimensions_given(const Args& a);

// --block BxH[,BxH...] (thickness x height in m, e.g. 0.6x4,0.45x3), at most 50.
std::vector<GivenBlock> block_list(const std::string& flag, const std::string& text);

// One line: "alpha = atan(B/H) = 0.1489 rad (8.53 deg), R = 2.0224 m, p = 1.9046 rad/s
// (eqs. 2, 4) from B = 0.6 m, H = 4 m", or, given by alpha, what was given and what follows.
std::string describe_block(const GivenBlock& b);

// The JSON members of the block's geometry: "given": "dimensions", "alpha and height"
// or "alpha and p", then "thickness", "height" and "R" in m (null where it is "alpha and
// p": the size is not known), without braces.
std::string block_json(const GivenBlock& b);

}  // namespace rocking::cli
