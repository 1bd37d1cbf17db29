// rocking spectrum's document: a record's overturning intervals in p for
// each alpha, beside Table 1's first collapse, and the marked blocks
// (studies/spectrum.hpp, studies/spectrum_mark.hpp).
#pragma once

#include <string>
#include <vector>

#include "jobs/spectrum_plan.hpp"
#include "json/document.hpp"
#include "records/record.hpp"
#include "studies/overturning_set.hpp"
#include "studies/spectrum.hpp"
#include "studies/spectrum_mark.hpp"

namespace rocking::json {

// [{"from", "to", "share"}, ...]: every band of a refined study, zeros included.
Json bands_json(const std::vector<studies::Band>& bands);

// The grid in words, as the text output and "grid"'s "note" say it.
std::string spectrum_grid_note(const studies::SpectrumOptions& o);

// One alpha's member of "spectra": {"alpha", "lifts", "intervals" (each
// {"from", "to", "height_from", "height_to", "lower", "upper"}, a boundary
// {"p_safe", "p_collapse", "confirmation", "detail"} or null), with the
// refine method "first_overturning", "first_robust_collapse", "bands",
// "samples", "accepted", "at_width", "with_margins", "unguaranteed_from" (a
// double, NaN where the guarantee holds throughout), then "table1" ({"found",
// "p", "p_safe", "below_range"}, as rocking collapse), "simulations",
// "check_simulations" and "points" (each {"p", "grid", "max_theta",
// "final_rotation", "peak_rotation", "overturning", "t_overturn"}, t_overturn
// NaN where the block does not overturn or falls by its energy)}.
Json spectrum_json(const jobs::SpectrumStudy& study);

// A marked block's member of "marks": {"built", "alpha", "p", "height",
// "overturns", "in_set", the nearest p of the set on each side (nearest_json:
// "change_below", "change_above", "change_below_far", "change_above_far",
// "survivors_below", "survivors_above"), "text"}.
Json mark_json(const studies::SpectrumMark& m);

// The whole document: {"file", "name", "samples", "dt", "pga_g", "model",
// "grid": {"p_min", "p_max", "points", "step", "offset_grid",
// "islands_missed_below_ratio", "note"}, "rel_tol", "refinement", with the
// refine method "method", "width", "robust_width", "refine_note", then
// "t_overturn_null" (why a t_overturn is null), "spectra", "marks"}.
Json spectrum_document(const std::string& file, const records::Record& r, const studies::SpectrumOptions& o,
                       const std::vector<jobs::SpectrumStudy>& studies, const std::vector<studies::SpectrumMark>& marks);

}  // namespace rocking::json
