#include "json/qfactor_json.hpp"

namespace rocking::json {

const char* const kClosedFormModel = "linearised eq. 3, one corner, no impact, collapse theta(t_fin) = alpha";
const char* const kRowsEndReason = "theta/alpha leaves the double range (beyond 1.8e308) on the linearised equation";

void add_validity(Json& o, const Excursion& e) {
    o["rocking_starts"] = e.onset;
    o["impact_free"] = e.stays_positive();
    o["motion_reverses"] = e.min_dphi < 0;
    o["passes_alpha_before_t_fin"] = e.onset && e.passes_alpha();
}

Json q_json(const PulseTrain& train, double x, const QFactor& q, const std::string& equation, const Excursion& e) {
    Json o;
    o["input"] = train.name();
    o["pulses"] = train.size();
    o["x"] = x;
    o["q"] = q.q;
    o["condition"] = q.condition;
    o["equation"] = equation;
    o["model"] = kClosedFormModel;
    add_validity(o, e);
    return o;
}

Json response_json(const PulseTrain& train, double x, double q, bool at_collapse_q, const Excursion& e,
                   const std::vector<ResponseState>& rows, int steps) {
    const int last = static_cast<int>(rows.size()) - 1;
    Json o;
    o["input"] = train.name();
    o["x"] = x;
    o["q"] = q;
    o["at_collapse_q"] = at_collapse_q;
    o["model"] = kClosedFormModel;
    add_validity(o, e);
    o["rows_complete"] = last == steps;
    o["rows_end_at"] = last < steps ? Json(train.t_fin() * (last + 1) / steps) : Json(nullptr);
    o["rows_end_reason"] = last < steps ? Json(kRowsEndReason) : Json(nullptr);
    Json& samples = o["samples"] = Json::array();
    for (int k = 0; k <= last; ++k) samples.push_back(Json::array({train.t_fin() * k / steps, rows[k].phi, rows[k].dphi}));
    return o;
}

}  // namespace rocking::json
