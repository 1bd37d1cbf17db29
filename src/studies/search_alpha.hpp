// The slenderness the searches take (collapse, spectrum, ida, and so
// fragility and eq27): one range for every command, batch row and function of
// the Python module, where each had its own copy (and the library's (0, 1)).
// It is the block's own (0, pi/4), as simulate takes it: 0.7 had no reason
// but a round number, and a wall with B/H in (0.84, 1) ran in simulate and
// was refused by every search.
#pragma once

namespace rocking::studies {

constexpr double kSearchAlphaMax = 0.78539816339744830962;  // pi/4
constexpr const char* kSearchAlphaRange = "(0, pi/4)";      // as the messages print it

inline bool in_search_alpha_range(double alpha) { return alpha > 0 && alpha < kSearchAlphaMax; }

// The block's p a search reads it at: the spectrum's own p range's bounds.
// A block outside it (H below 0.02 mm or above 150 km at small alpha) is no
// wall; beyond 1000 rad/s assess failed deep inside the record kernel.
constexpr double kSearchPMin = 0.01, kSearchPMax = 1000;
constexpr const char* kSearchPRange = "(0.01, 1000) rad/s";
inline bool in_search_p_range(double p) { return p > kSearchPMin && p < kSearchPMax; }

}  // namespace rocking::studies
