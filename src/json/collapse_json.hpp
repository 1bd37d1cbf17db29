// rocking collapse's document: the smallest p of the search at which a
// record overturns a block of slenderness alpha (records/collapse.hpp).
#pragma once

#include <string>

#include "dynamics/block_geometry.hpp"
#include "json/document.hpp"
#include "records/collapse.hpp"

namespace rocking::json {

// {"file", "alpha", "found", "p" and "p_safe" (null where nothing was found;
// p_safe null too where the search's lowest p overturns, below_range),
// "below_range", "simulations" (an integer), "search" (the options in words)},
// then, for a block given by its size (given not null), "block_p" and the
// block's members (add_block), and, with imperfections, "imperfection": each
// corner at the p found, or the imperfections alone where none was found.
Json collapse_json(const std::string& file, double alpha, const records::CollapseResult& c,
                   const records::CollapseOptions& o, const dynamics::GivenBlock* given);

}  // namespace rocking::json
