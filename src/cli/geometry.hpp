// The block as the command line takes it (issue 40): --thickness B --height H
// (full dimensions, m), or --alpha A with --p, --half-height or --height;
// --block BxH,... for the studies.  The reading is the library's
// (dynamics/block_geometry.hpp); here its flags, its UsageErrors and its JSON.
#pragma once

#include <string>
#include <vector>

#include "cli/json_text.hpp"
#include "cli/options.hpp"
#include "dynamics/block_geometry.hpp"
#include "json/pieces.hpp"
#include "studies/ida.hpp"

namespace rocking::cli {

using dynamics::describe_block;
using dynamics::GivenBlock;

// The flags block_option reads, for a command's parse() list.
const std::vector<std::string>& geometry_flags();

// The block of the command line, or a UsageError saying what is wrong.
GivenBlock block_option(const Args& a);

// --block (or `flag`) as a study's blocks (each alpha in the searches' range,
// each p in (0.01, 1000) rad/s); --block is refused beside --alpha or --p.
std::vector<studies::BlockShape> study_blocks(const Args& a, const std::string& flag = "--block");

// The block's geometry as members of a document (json/pieces.hpp).
using json::add_block;

}  // namespace rocking::cli
