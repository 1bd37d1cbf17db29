// rocking eq27's document: eq. 27 against each record's first collapse on
// every block of a grid, per half-period to_k (studies/eq27_at_scale.hpp).
#pragma once

#include <string>
#include <vector>

#include "json/document.hpp"
#include "studies/eq27_at_scale.hpp"

namespace rocking::json {

// How many blocks of the map have a non-conservative case at to_(k + 1).
int blocks_with_any(const studies::Eq27Study& s, int k);

// A study's members, into o: "censored", "shares" (per to_k {"k",
// "non_conservative", "cases", "share", "bootstrap" ([lo, hi], or null
// without one), "wilson" ([lo, hi]), "records_with_any", "records",
// "blocks_with_any"}), "by_record" ({"file", "sha256", "non_conservative":
// the 11 counts}, what the bootstrap resamples) and "map" (per block
// {"alpha", "p", "records", "censored", "non_conservative"}).
void add_eq27_study(Json& o, const std::vector<std::string>& files, const studies::Eq27Study& s);

// The whole document: {"model", "ida", "q_max", with the refine method
// "method", "width", "robust_width", "refine_note", then "blocks", "verdict",
// "wilson" ({"level", "note"}), "bootstrap_run", "bootstrap" ({"over",
// "resamples", "seed", "level"}, or null beside "bootstrap_note"), "records",
// "files", "cases", refined "capacity" and "capacity_note", the first
// overturning's study (add_eq27_study), and refined "first_robust_collapse":
// {"capacity_note", its study}}.
Json eq27_document(const std::vector<std::string>& files, const studies::Eq27Options& o,
                   const studies::Eq27ByCapacity& by);

}  // namespace rocking::json
