#include "json/assess_json.hpp"

#include <cmath>
#include <cstdio>

#include "json/pieces.hpp"

namespace rocking::json {

namespace {

Json first_json(const studies::IdaPoint& at, double scale, double to) {
    Json o{{"found", at.collapsed}, {"q", at.q}, {"scale", scale}};
    if (at.collapsed) o["interval_to"] = to;
    return o;
}

// %.17g: the bound read back as the same double.
std::string exact(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

}  // namespace

Json assessed_record_json(const std::string& file, const std::string& name, const studies::RecordAssessment& r) {
    Json o;
    o["file"] = file;
    o["name"] = name;
    o["pga_g"] = r.motion.pga / dynamics::kGravity;
    o["to5"] = r.motion.to5;
    o["x"] = r.x;
    o["q_eq27"] = r.q_eq27;
    o["q_eq27_as_printed"] = r.q_eq27_as_printed;
    o["eq27_side"] = r.eq27_side;
    o["q_record"] = r.q_record;
    o["ratio"] = r.ratio;
    o["margin"] = r.margin;
    o["passes"] = r.passes;
    o["eq27_passes_alpha_before_t_fin"] = r.eq27_passes_alpha;
    o["eq27_impact_before_t_fin"] = r.eq27_strikes;
    o["overturns"] = r.overturns;
    o["fell_during_input"] = r.fell_during_input;
    o["peak_theta_over_alpha"] = r.peak_theta_over_alpha;
    o["first_overturning"] = first_json(r.ida.first_overturning, r.scale_first_overturning, r.first_overturning_to);
    o["first_robust_collapse"] = first_json(r.ida.first_robust_collapse, r.scale_first_robust, r.first_robust_to);
    o["change_below"] = nearest_json(r.mark.below, r.mark.height_below);
    o["change_above"] = nearest_json(r.mark.above, r.mark.height_above);
    o["change_below_far"] = nearest_json(r.mark.below_far, studies::far_height(r.mark, r.mark.below_far));
    o["change_above_far"] = nearest_json(r.mark.above_far, studies::far_height(r.mark, r.mark.above_far));
    o["in_spectrum_set"] = r.mark.in_set;
    o["guaranteed"] = std::isfinite(r.ida.unguaranteed_from) ? "below q = " + exact(r.ida.unguaranteed_from)
                                                             : std::string("over the whole search");
    o["survivors_below"] = nearest_json(r.mark.survivors_below, r.mark.height_survivors_below);
    o["survivors_above"] = nearest_json(r.mark.survivors_above, r.mark.height_survivors_above);
    if (r.has_probability) o["probability"] = r.probability;
    return o;
}

Json assess_json(const std::vector<std::string>& files, const std::vector<std::string>& names,
                 const dynamics::GivenBlock& given, const studies::Assessment& s, const studies::AssessOptions& o,
                 const std::string& input) {
    Json js;
    js["alpha"] = given.alpha;
    js["p"] = given.block.p;
    add_block(js, given);
    js["model"] = o.describe();
    js["width"] = o.width;
    js["input"] = input.empty() ? std::string("each record as recorded: the ground's motion") : input;
    js["check"] = o.describe_check();
    if (o.model.imperfection.any())
        js["imperfection"] =
            imperfection_json(o.model.imperfection, given.block, o.model.housner_restitution ? NAN : o.model.restitution);
    Json& records = js["records"] = Json::array();
    for (std::size_t k = 0; k < files.size(); ++k) records.push_back(assessed_record_json(files[k], names[k], s.records[k]));
    Json& fragility = js["fragility"] = {{"fitted", s.fitted}};
    if (s.fitted) {
        fragility["median"] = s.fit.median;
        fragility["beta"] = s.fit.beta;
    } else {
        fragility["no_fit"] = s.no_fit;
    }
    return js;
}

}  // namespace rocking::json
