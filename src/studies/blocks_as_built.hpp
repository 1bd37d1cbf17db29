// A study's blocks given as built (issue 40): "0.6x4,0.45x3", thickness x
// height in m, each alpha = atan(B/H) and p = sqrt(3 g/(4 R)) (eqs. 2, 4)
// within what the studies search (alpha in (0, pi/4), p in (0.01, 1000)
// rad/s).  One reading for `--block`/`--mark` and Python's block lists.
#pragma once

#include <string>
#include <vector>

#include "studies/ida.hpp"

namespace rocking::studies {

// std::invalid_argument prefixed by `what` (the option or keyword) for a
// block the grammar, the geometry or the studies' ranges refuse.
std::vector<BlockShape> blocks_as_built(const std::string& text, const std::string& what);

}  // namespace rocking::studies
