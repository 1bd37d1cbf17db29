// The grid method's tables of eq. 27 in the fragility scene
// (fragility_eq27.csv, fragility_synthetic_eq27.csv; reproduce/scenes/fragility.cpp
// writes them): the study over one set of records from the IDA points already
// run, its notes and its rows.
#pragma once

#include <string>
#include <vector>

#include "fragility_scene.hpp"
#include "harness/table.hpp"
#include "studies/eq27_at_scale.hpp"

namespace rocking::scenes::fragility_scene {

// Eq. 27 over one set of records (or the union of sets): each record's point
// and ill-conditioned flag on every block, and its to_k.
struct Eq27Input {
    std::string set;
    std::vector<std::string> names;
    std::vector<std::string> identities;  // the draw order's keys (fragility_scene.hpp, identity_of)
    std::vector<HalfPeriodArray> to;
    std::vector<std::vector<studies::IdaPoint>> points;  // [r][b]
    std::vector<std::vector<bool>> ill;                  // [r][b]
};

// studies::eq27_from_points on the set, with the scene's bootstrap over records.
studies::Eq27Study eq27_of(const Eq27Input& in);

// The notes "margin", "levels" and "zero" of an eq. 27 table, each key
// followed by " <set>" in the synthetic file.
void eq27_notes(harness::Table& et, const Eq27Input& in, const studies::Eq27Study& eq27, const std::string& suffix);

// One row per to_k, led by the set's name where `set` is not empty.
void eq27_rows(harness::Table& et, const studies::Eq27Study& eq27, const std::string& set);

}  // namespace rocking::scenes::fragility_scene
