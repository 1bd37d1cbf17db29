// Members that several documents share: the block as given, its
// imperfections, and a marked block's nearest p of a set.
#pragma once

#include "dynamics/block_geometry.hpp"
#include "dynamics/imperfect_block.hpp"
#include "json/document.hpp"
#include "studies/spectrum_mark.hpp"

namespace rocking::json {

// The block's geometry as members of o: "given": "dimensions", "alpha and
// height" or "alpha and p", then "thickness", "height" and "R" in m (null
// where it is "alpha and p": the size is not known).
void add_block(Json& o, const dynamics::GivenBlock& b);

// The member "imperfection"'s value for these imperfections on the block
// (alpha, p): "lean", "out_of_plumb" (rad), "fc" (MPa), "density" (kg/m3),
// "sigma0_kpa", "setback_m", then "corner_plus" and "corner_minus", each
// {"alpha", "p", "R", "restitution_onto"}.  restitution: NaN (each corner's
// own) or the factor given on both.
Json imperfection_json(const dynamics::Imperfection& imp, const dynamics::Block& base, double restitution);

// The same member with the imperfections alone (its first four members), for
// a search over blocks of many sizes (the corners of a setback change with the size).
Json imperfection_inputs_json(const dynamics::Imperfection& imp);

// A p of the set beside a marked block, with the height of the block of its
// alpha there: {"found": true, "p": p, "height": h}, or {"found": false}.
Json nearest_json(const studies::SpectrumFirst& f, double height);

}  // namespace rocking::json
