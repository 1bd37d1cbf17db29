#include "json/spectrum_json.hpp"

#include <cmath>

#include "dynamics/model.hpp"
#include "json/pieces.hpp"

namespace rocking::json {

namespace {

bool refined(const studies::SpectrumOptions& o) { return o.method == studies::SpectrumOptions::Method::refine; }

Json boundary_json(const studies::Interval& in, bool lower) {
    const bool has = lower ? in.has_lower : in.has_upper;
    if (!has) return nullptr;
    const studies::Boundary& b = lower ? in.lower : in.upper;
    return {{"p_safe", b.p_safe}, {"p_collapse", b.p_collapse},
            {"confirmation", studies::confirmation_name(b.confirmation)}, {"detail", b.detail}};
}

// As rocking collapse's document: null where nothing was found, or (p_safe) found at the lowest p.
Json table1_json(const records::CollapseResult& c) {
    return {{"found", c.found},
            {"p", c.found ? Json(c.p) : Json(nullptr)},
            {"p_safe", c.found && !c.below_range() ? Json(c.p_safe) : Json(nullptr)},
            {"below_range", c.below_range()}};
}

// The refine method's members of one alpha (issue 39), into its object o.
void add_refined(Json& o, const studies::Spectrum& sp) {
    const bool bracketed = sp.first_overturning.found && sp.intervals.front().has_lower;
    o["first_overturning"] = {{"p", sp.first_overturning.p},
                              {"found", sp.first_overturning.found},
                              {"boundary", bracketed ? boundary_json(sp.intervals.front(), true) : Json(nullptr)}};
    o["first_robust_collapse"] = {{"p", sp.first_robust_collapse.p}, {"found", sp.first_robust_collapse.found}};
    o["bands"] = bands_json(sp.bands);
    o["samples"] = sp.samples;
    o["accepted"] = sp.accepted;
    o["at_width"] = sp.at_width;
    o["with_margins"] = sp.with_margins;
    o["unguaranteed_from"] = sp.unguaranteed_from;
}

}  // namespace

Json bands_json(const std::vector<studies::Band>& bands) {
    Json list = Json::array();
    for (const studies::Band& b : bands) list.push_back({{"from", b.from}, {"to", b.to}, {"share", b.share}});
    return list;
}

std::string spectrum_grid_note(const studies::SpectrumOptions& o) {
    if (refined(o))
        return o.describe_grid() + "; Table 1's search beside it (its bracket is not added: an island of it narrower "
                                   "than w may be missing from the set)";
    return o.describe_grid() + "; Table 1's bracket of each alpha added as extra points";
}

Json spectrum_json(const jobs::SpectrumStudy& study) {
    const studies::Spectrum& sp = study.spectrum;
    Json o;
    o["alpha"] = sp.alpha;
    o["lifts"] = sp.lifts;
    Json& intervals = o["intervals"] = Json::array();
    for (const studies::Interval& in : sp.intervals)
        intervals.push_back({{"from", in.from},
                             {"to", in.to},
                             {"height_from", studies::height_at_p(sp.alpha, in.from)},
                             {"height_to", studies::height_at_p(sp.alpha, in.to)},
                             {"lower", boundary_json(in, true)},
                             {"upper", boundary_json(in, false)}});
    if (sp.refined) add_refined(o, sp);
    o["table1"] = table1_json(study.table1);
    o["simulations"] = sp.simulations;
    o["check_simulations"] = sp.check_simulations;
    Json& points = o["points"] = Json::array();
    for (const studies::SpectrumPoint& pt : sp.points)
        points.push_back({{"p", pt.p},
                          {"grid", studies::grid_kind_name(pt.grid)},
                          {"max_theta", pt.max_theta},
                          {"final_rotation", pt.final_rotation},
                          {"peak_rotation", pt.peak_rotation},
                          {"overturning", pt.overturning},
                          {"t_overturn", pt.t_overturn}});
    return o;
}

Json mark_json(const studies::SpectrumMark& m) {
    Json o;
    o["built"] = m.block.built;
    o["alpha"] = m.block.alpha;
    o["p"] = m.block.p;
    o["height"] = studies::height_at_p(m.block.alpha, m.block.p);
    o["overturns"] = m.overturns;
    o["in_set"] = m.in_set;
    o["change_below"] = nearest_json(m.below, m.height_below);
    o["change_above"] = nearest_json(m.above, m.height_above);
    o["change_below_far"] = nearest_json(m.below_far, studies::far_height(m, m.below_far));
    o["change_above_far"] = nearest_json(m.above_far, studies::far_height(m, m.above_far));
    o["survivors_below"] = nearest_json(m.survivors_below, m.height_survivors_below);
    o["survivors_above"] = nearest_json(m.survivors_above, m.height_survivors_above);
    o["text"] = studies::describe_mark(m);
    return o;
}

Json spectrum_document(const std::string& file, const records::Record& r, const studies::SpectrumOptions& o,
                       const std::vector<jobs::SpectrumStudy>& studies, const std::vector<studies::SpectrumMark>& marks) {
    Json js;
    js["file"] = file;
    js["name"] = r.name;
    js["samples"] = r.accel.size();
    js["dt"] = r.dt;
    js["pga_g"] = r.pga() / dynamics::kGravity;
    js["model"] = o.describe_model();
    js["grid"] = {{"p_min", o.p_min},
                  {"p_max", o.p_max},
                  {"points", o.points},
                  {"step", o.step()},
                  {"offset_grid", !refined(o)},
                  {"islands_missed_below_ratio", refined(o) ? std::exp(o.width) : std::sqrt(o.step())},
                  {"note", spectrum_grid_note(o)}};
    js["rel_tol"] = o.rel_tol;
    js["refinement"] = o.describe_refinement();
    if (refined(o)) {
        js["method"] = "refine";
        js["width"] = o.width;
        js["robust_width"] = o.robust_width;
        js["refine_note"] = o.describe_guarantee();
    }
    js["t_overturn_null"] = "the block does not overturn, or is taken to overturn by its energy after 200/p of free rocking";
    Json& spectra = js["spectra"] = Json::array();
    for (const jobs::SpectrumStudy& study : studies) spectra.push_back(spectrum_json(study));
    Json& marked = js["marks"] = Json::array();
    for (const studies::SpectrumMark& m : marks) marked.push_back(mark_json(m));
    return js;
}

}  // namespace rocking::json
