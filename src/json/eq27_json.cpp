#include "json/eq27_json.hpp"

#include <array>

namespace rocking::json {

namespace {

bool bootstrapped(const studies::Eq27Study& s) { return s.bootstrap.resamples > 0; }

}  // namespace

int blocks_with_any(const studies::Eq27Study& s, int k) {
    int n = 0;
    for (const studies::Eq27Cell& c : s.map) n += c.non_conservative[k] > 0;
    return n;
}

void add_eq27_study(Json& o, const std::vector<std::string>& files, const studies::Eq27Study& s) {
    o["censored"] = s.censored;
    Json& shares = o["shares"] = Json::array();
    for (int k = 0; k < studies::kHalfPeriods; ++k) {
        const studies::Eq27Share& sh = s.shares[k];
        // Without a bootstrap, null: the document's bootstrap_run and bootstrap_note say why.
        shares.push_back({{"k", k + 1},
                          {"non_conservative", sh.non_conservative},
                          {"cases", sh.cases},
                          {"share", sh.share},
                          {"bootstrap", bootstrapped(s) ? Json::array({sh.bootstrap.lo, sh.bootstrap.hi}) : Json(nullptr)},
                          {"wilson", Json::array({sh.wilson.lo, sh.wilson.hi})},
                          {"records_with_any", sh.records_with_any},
                          {"records", sh.records},
                          {"blocks_with_any", blocks_with_any(s, k)}});
    }
    std::vector<std::array<int, studies::kHalfPeriods>> by_record(s.records, std::array<int, studies::kHalfPeriods>{});
    for (const studies::Eq27Case& c : s.cases)
        for (int k = 0; k < studies::kHalfPeriods; ++k) by_record[c.record][k] += c.non_conservative[k];
    Json& records = o["by_record"] = Json::array();
    for (std::size_t r = 0; r < by_record.size(); ++r)
        records.push_back({{"file", files[r]}, {"sha256", s.identities[r]}, {"non_conservative", by_record[r]}});
    Json& map = o["map"] = Json::array();
    for (const studies::Eq27Cell& c : s.map)
        map.push_back({{"alpha", c.block.alpha},
                       {"p", c.block.p},
                       {"records", c.records},
                       {"censored", c.censored},
                       {"non_conservative", c.non_conservative}});
}

Json eq27_document(const std::vector<std::string>& files, const studies::Eq27Options& o,
                   const studies::Eq27ByCapacity& by) {
    const studies::Eq27Study& s = by.first_overturning;
    const bool refined = o.ida.method == studies::IdaOptions::Method::refine;
    Json js;
    js["model"] = o.ida.describe_model();
    js["ida"] = o.ida.describe_grid();
    js["q_max"] = o.ida.q_max;
    if (refined) {
        js["method"] = "refine";
        js["width"] = o.ida.width;
        js["robust_width"] = o.ida.robust_width;
        js["refine_note"] = studies::eq27_refine_note(o.ida);
    }
    js["blocks"] = o.grid.describe();
    js["verdict"] = studies::kEq27Verdict;
    js["wilson"] = {{"level", s.level}, {"note", studies::kEq27WilsonNote}};
    js["bootstrap_run"] = bootstrapped(s);
    if (bootstrapped(s)) {
        js["bootstrap"] = {{"over", "records"}, {"resamples", s.bootstrap.resamples}, {"seed", s.bootstrap.seed},
                           {"level", s.bootstrap.level}};
    } else {
        js["bootstrap"] = nullptr;
        js["bootstrap_note"] = studies::kEq27NoBootstrap;
    }
    js["records"] = s.records;
    js["files"] = files;
    js["cases"] = s.cases.size();
    // The refine method: the members as the grid's under the first overturning
    // (the IDA's point, either method), the robust collapse's in an object.
    if (refined) {
        js["capacity"] = "first_overturning";
        js["capacity_note"] = studies::kEq27FirstOverturningNote;
    }
    add_eq27_study(js, files, s);
    if (refined) {
        Json robust = {{"capacity_note", studies::kEq27RobustCollapseNote}};
        add_eq27_study(robust, files, by.first_robust_collapse);
        js["first_robust_collapse"] = robust;
    }
    return js;
}

}  // namespace rocking::json
