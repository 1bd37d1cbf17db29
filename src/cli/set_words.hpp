// The overturning set of a refined study in words and in JSON (issue 39):
// the bands of the main grid that overturn at all, and each band's share.
// One wording for `rocking spectrum` (ln p) and `rocking fragility` (ln q).
#pragma once

#include <string>
#include <vector>

#include "cli/json_text.hpp"
#include "json/pieces.hpp"
#include "json/spectrum_json.hpp"
#include "studies/overturning_set.hpp"
#include "studies/spectrum.hpp"

namespace rocking::cli {

// "[from, to]:share ..." for every band whose share is above 0, or "none".
std::string bands_text(const std::vector<studies::Band>& bands);
// For the screen: how many bands overturn wholly and in part, and where the
// partial ones lie; the shares themselves (a hundred bands) go to files.
std::string bands_summary(const std::vector<studies::Band>& bands, const char* variable);

// [{"from": f, "to": t, "share": s}, ...] for every band (json/spectrum_json.hpp).
using json::bands_json;

// A p of the set beside a marked block (json/pieces.hpp).
using json::nearest_json;

}  // namespace rocking::cli
