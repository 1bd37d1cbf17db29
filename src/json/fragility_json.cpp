#include "json/fragility_json.hpp"

#include "json/spectrum_json.hpp"
#include "studies/stripe_fit.hpp"

namespace rocking::json {

namespace {

bool refined(const studies::FragilityStudyOptions& o) { return o.ida.method == studies::IdaOptions::Method::refine; }

Json bracket_json(bool has, const studies::Bracket& b) {
    if (!has) return nullptr;
    return {{"q_safe", b.safe}, {"q_collapse", b.collapse}};
}

Json range_json(const studies::Range& r) { return Json::array({r.lo, r.hi}); }

// A capacity's fit, or null beside its no_fit (the reason).
Json fit_json(const studies::BlockFragility& f) { return f.fitted ? lognormal_json(f.fit, f.bootstrapped, f.interval) : nullptr; }

Json no_fit_json(bool fitted, const std::string& why) { return fitted ? Json(nullptr) : Json(why); }

// The refine method's three fits, each named by its capacity, and the stripes (issue 39, item 3).
void add_three_ways(Json& o, const studies::BlockFragility& f) {
    const studies::CapacityFit& r = f.robust;
    const studies::StripeFit& s = f.stripes;
    Json stripe_fit = nullptr;
    if (s.fitted)
        stripe_fit = {{"median", s.fit.median}, {"beta", s.fit.beta}, {"stripes", s.stripes.size()},
                      {"records", s.shares.share.size()}, {"bootstrap", bootstrap_json(s.bootstrapped, s.interval)}};
    o["fits"] = {
        {"first_overturning", {{"fit", fit_json(f)}, {"no_fit", no_fit_json(f.fitted, f.no_fit)}}},
        {"first_robust_collapse",
         {{"fit", r.fitted ? lognormal_json(r.fit, r.bootstrapped, r.interval) : Json(nullptr)},
          {"no_fit", no_fit_json(r.fitted, r.no_fit)}}},
        {"stripes", {{"fit", stripe_fit}, {"no_fit", no_fit_json(s.fitted, s.no_fit)}}}};
    Json& stripes = o["stripes"] = Json::array();
    for (std::size_t j = 0; j < s.stripes.size(); ++j)
        stripes.push_back({{"q", s.stripes[j].q}, {"from", s.shares.from[j]}, {"to", s.shares.to[j]},
                           {"share", s.stripes[j].overturned / s.stripes[j].records}});
}

// A point's members; its object may take more (refine's bracket and check).
Json point_json(const studies::IdaPoint& p) { return {{"q", p.q}, {"collapsed", p.collapsed}}; }

Json check_json(const studies::IdaInterval& in) {
    return {{"confirmation", studies::confirmation_name(in.lower_check.confirmation)}, {"detail", in.lower_check.detail}};
}

// The refine method's members of a record (issue 39): first_overturning with
// its bracket and check, first_robust_collapse, every band's overturned share.
void add_refined(Json& o, const studies::Ida& ida) {
    const bool bracketed = ida.first_overturning.collapsed && ida.intervals.front().has_lower;
    Json first = point_json(ida.first_overturning);
    first["bracket"] = bracket_json(bracketed, bracketed ? ida.intervals.front().lower : studies::Bracket{});
    first["check"] = bracketed ? check_json(ida.intervals.front()) : Json(nullptr);
    o["first_overturning"] = first;
    o["first_robust_collapse"] = point_json(ida.first_robust_collapse);
    o["bands"] = bands_json(ida.bands);
    o["method"] = "refine";
    o["samples"] = ida.samples;
    o["accepted"] = ida.accepted;
    o["at_width"] = ida.at_width;
    o["with_margins"] = ida.with_margins;
    o["unguaranteed_from"] = ida.unguaranteed_from;
}

}  // namespace

Json bootstrap_json(bool bootstrapped, const studies::BootstrapInterval& b) {
    if (!bootstrapped) return nullptr;
    return {{"resamples", b.resamples}, {"seed", b.seed}, {"level", b.level},
            {"median", range_json(b.median)}, {"beta", range_json(b.beta)}};
}

Json lognormal_json(const studies::LognormalFragility& fit, bool bootstrapped, const studies::BootstrapInterval& interval) {
    return {{"median", fit.median}, {"beta", fit.beta}, {"collapsed", fit.collapsed}, {"censored", fit.censored},
            {"bootstrap", bootstrap_json(bootstrapped, interval)}};
}

Json ida_record_json(const std::string& file, const std::string& identity, const studies::Ida& ida, bool refine) {
    Json o;
    o["file"] = file;
    o["sha256"] = identity;
    o["q_input"] = ida.q_input;
    o["q"] = ida.point.q;
    o["collapsed"] = ida.point.collapsed;
    o["point_check"] = ida.point.collapsed && ida.intervals.front().has_lower ? check_json(ida.intervals.front()) : Json(nullptr);
    o["simulations"] = ida.simulations;
    o["check_simulations"] = ida.check_simulations;
    Json& intervals = o["intervals"] = Json::array();
    for (const studies::IdaInterval& in : ida.intervals)
        intervals.push_back({{"from", in.from}, {"to", in.to}, {"lower", bracket_json(in.has_lower, in.lower)},
                             {"upper", bracket_json(in.has_upper, in.upper)}});
    if (refine) add_refined(o, ida);
    return o;
}

Json fragility_block_json(const std::vector<std::string>& files, const studies::FragilityStudyOptions& o,
                          const studies::BlockFragility& f) {
    Json js;
    js["alpha"] = f.block.alpha;
    js["p"] = f.block.p;
    if (!f.block.built.empty()) js["built"] = f.block.built;
    // An imperfect block's grid may start below q_min, where it lifts.
    if (o.ida.model.imperfection.any()) {
        const double start = o.ida.q_start(f.block.alpha, f.block.p);
        js["q_start"] = start;
        if (refined(o)) js["stripe_half_width"] = studies::stripe_half_width(start, o.ida.q_max, o.ida.points);
    }
    Json& records = js["records"] = Json::array();
    for (std::size_t k = 0; k < files.size(); ++k)
        records.push_back(ida_record_json(files[k], f.identities[k], f.idas[k], refined(o)));
    js["fit"] = fit_json(f);
    js["no_fit"] = no_fit_json(f.fitted, f.no_fit);
    Json& empirical = js["empirical"] = Json::array();
    for (const auto& point : f.empirical) empirical.push_back({{"q", point.q}, {"share", point.share}});
    if (f.three_ways) add_three_ways(js, f);
    return js;
}

std::string fragility_grid_note(const studies::FragilityStudyOptions& o) {
    return o.ida.describe_grid() + "; " + o.ida.describe_q() + "; " + o.ida.describe_checks();
}

Json fragility_document(const std::vector<std::string>& files, const studies::FragilityStudyOptions& o,
                        const std::vector<studies::BlockFragility>& study) {
    Json js;
    js["model"] = o.ida.describe_model();
    Json& grid = js["grid"] = {{"q_min", o.ida.q_min}, {"q_max", o.ida.q_max}, {"points", o.ida.points},
                               {"rel_tol", o.ida.rel_tol}, {"note", fragility_grid_note(o)}};
    if (refined(o)) {
        grid["method"] = "refine";
        grid["width"] = o.ida.width;
        grid["robust_width"] = o.ida.robust_width;
        grid["fit_capacity"] = "first_overturning";
        grid["stripe_half_width"] = studies::stripe_half_width(o.ida.q_min, o.ida.q_max, o.ida.points);
        grid["refine_note"] = o.describe_fits();
    }
    Json& blocks = js["blocks"] = Json::array();
    for (const studies::BlockFragility& f : study) blocks.push_back(fragility_block_json(files, o, f));
    return js;
}

}  // namespace rocking::json
