// The slenderness the searches take (collapse, spectrum, ida, and so
// fragility and eq27): one range for every command, batch row and function of
// the Python module, where each had its own copy (and the library's (0, 1)).
// The dynamics alone (simulate) take the block's (0, pi/4).
#pragma once

namespace rocking::studies {

constexpr double kSearchAlphaMax = 0.7;
constexpr const char* kSearchAlphaRange = "(0, 0.7)";  // as the messages print it

inline bool in_search_alpha_range(double alpha) { return alpha > 0 && alpha < kSearchAlphaMax; }

}  // namespace rocking::studies
