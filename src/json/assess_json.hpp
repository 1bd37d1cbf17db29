// rocking assess's document: the paper's eq. 27 check of a block against
// each record, what the model says of it, and the fragility over the records
// (studies/assessment.hpp).
#pragma once

#include <string>
#include <vector>

#include "dynamics/block_geometry.hpp"
#include "json/document.hpp"
#include "studies/assessment.hpp"

namespace rocking::json {

// One record's member of "records": {"file", "name", "pga_g", "to5", "x",
// "q_eq27", "q_eq27_as_printed", "eq27_side" (an integer), "q_record",
// "ratio", "margin", "passes", "eq27_passes_alpha_before_t_fin",
// "eq27_impact_before_t_fin", "overturns", "fell_during_input",
// "peak_theta_over_alpha", "first_overturning" and "first_robust_collapse"
// ({"found", "q", "scale"}, and "interval_to" where found), the marked
// block's "change_below", "change_above", "change_below_far",
// "change_above_far" (nearest_json), "in_spectrum_set", "guaranteed" (in
// words), "survivors_below", "survivors_above", and "probability" where the
// fragility was fitted}.
Json assessed_record_json(const std::string& file, const std::string& name, const studies::RecordAssessment& r);

// {"alpha", "p", the block's members (add_block), "model", "width", "input"
// (input, or the ground's motion where it is empty), "check", "imperfection"
// where the block has any, "records" (files[k], names[k] and s.records[k] as
// assessed_record_json), "fragility": {"fitted", then "median" and "beta", or
// "no_fit"}}.
Json assess_json(const std::vector<std::string>& files, const std::vector<std::string>& names,
                 const dynamics::GivenBlock& given, const studies::Assessment& s, const studies::AssessOptions& o,
                 const std::string& input);

}  // namespace rocking::json
