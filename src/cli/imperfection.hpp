// The imperfect block on the command line (issue 41): --lean RAD and
// --out-of-plumb RAD (toward theta > 0), --fc MPA (the masonry's
// compressive strength: pivots set back) with --density KG/M3.  The same
// flags on simulate and every study; the library's reading is
// dynamics/imperfect_block.hpp.
#pragma once

#include <string>
#include <vector>

#include "cli/json_text.hpp"
#include "cli/options.hpp"
#include "dynamics/block_geometry.hpp"
#include "dynamics/imperfect_block.hpp"
#include "json/pieces.hpp"
#include "records/collapse.hpp"

namespace rocking::cli {

// The flags imperfection_option reads, for a command's parse() list.
const std::vector<std::string>& imperfection_flags();

// The imperfections given (none: Imperfection{} with any() false), or a
// UsageError naming the flag: angles in (-pi/4, pi/4) rad, fc > 0 MPa,
// --density > 0 kg/m3 and only with --fc; not with --friction.
dynamics::Imperfection imperfection_option(const Args& a);

// The imperfection flags as given (" --lean 0.01 --fc 2"), or "", for a
// command line the output suggests.
std::string imperfection_flags_text(const Args& a);

// Into a search's model (every block of the search takes them).
void imperfection_into(const Args& a, records::CollapseOptions& model);

// The block's model with the imperfections (restitution: a factor, or NaN
// for each corner's own), or a UsageError naming the flags where the block
// cannot stand or crushes.
dynamics::Model imperfect_model_option(const Args& a, dynamics::Equation equation, const dynamics::GivenBlock& given,
                                       double restitution);

// The JSON member "imperfection" (json/pieces.hpp).
using json::imperfection_json;
using json::imperfection_inputs_json;

}  // namespace rocking::cli
