// The fragility scene under each capacity (issue 39, item 4): the same records
// and blocks through the refine method's IDA (docs/overturning_set.md), whose
// first overturning, first robust collapse and overturned shares give the
// three fits of docs/fragility.md ("Three capacities") and eq. 27's share
// under each capacity (docs/eq27_at_scale.md, "Under each capacity"), beside
// the grid method's files, which stay as they were.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "dynamics/ground_input.hpp"
#include "fragility_scene.hpp"
#include "scene.hpp"

namespace rocking::scenes {

// One population of records: the shared records (set "", whose files have no
// set column) or one synthetic set.
struct CapacitySet {
    std::string set;
    std::vector<std::string> names;  // each record's row label
    std::vector<std::string> identities;  // the draw order's keys (fragility_scene.hpp, identity_of)
    std::vector<const dynamics::GroundInput*> inputs;
    std::vector<fragility_scene::HalfPeriodArray> to;
};

// The shared records' files, for the scene to skip without the records folder.
extern const std::array<const char*, 5> kCapacityFiles;

// Runs the refine study on every set and writes <prefix>_capacities.csv,
// <prefix>_capacity_fits.csv, <prefix>_stripe_shares.csv,
// <prefix>_stripe_fits.csv and <prefix>_capacity_eq27.csv.  With more than one set, eq. 27 is also counted
// over their union, named `union_name` (each set is fitted apart).
void write_capacities(SceneContext& ctx, const std::vector<CapacitySet>& sets, const std::string& prefix,
                      const std::string& inputs_text, const std::string& union_name = "");

}  // namespace rocking::scenes
