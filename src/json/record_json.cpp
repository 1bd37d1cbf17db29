#include "json/record_json.hpp"

#include <cmath>
#include <string>

#include "numerics/number_text.hpp"
#include "records/synthetic.hpp"

namespace rocking::json {

Json record_info_json(const std::string& file, const records::Record& r, const records::HalfPeriods& h) {
    Json o;
    o["file"] = file;
    o["format"] = r.format;
    o["name"] = r.name;
    o["samples"] = r.accel.size();
    o["dt"] = r.dt;
    o["pga_ms2"] = h.pga;
    o["pgv_ms"] = h.pgv;
    o["amax_ms"] = h.amax;
    Json& to = o["to"] = Json::array();
    for (int k = 0; k < 11; ++k) to.push_back(h.to[k]);
    Json& at_edge = o["to_at_band_edge"] = Json::array();
    for (int k = 0; k < 4; ++k)
        if (h.cwt_at_band_edge[k]) at_edge.push_back(8 + k);
    o["cwt_band_hz"] = Json::array({h.cwt_band_hz[0], h.cwt_band_hz[1]});
    return o;
}

namespace {

// The header's values are %.17g text or words: numbers stay numbers in JSON,
// written as JSON writes them (".5" or "+1" would not be JSON).
Json header_value(const std::string& text) {
    double v;
    return numerics::sample_number(text, v) ? Json(v) : Json(text);
}

}  // namespace

Json synthetic_record_json(const records::Record& r, const records::PeakMotion& m, const std::string& output) {
    Json o;
    o["name"] = r.name;
    o["format"] = r.format;
    o["samples"] = r.accel.size();
    o["dt"] = r.dt;
    o["pga_ms2"] = m.pga;
    o["pgv_ms"] = m.pgv;
    o["to5_s"] = m.to5;
    Json& parameters = o["parameters"] = Json::object();
    for (const auto& [key, value] : r.header)
        if (key != "warning") parameters[key] = header_value(value);
    o["warnings"] = records::warnings_of(r);
    o["output"] = output.empty() ? Json(nullptr) : Json(output);
    return o;
}

Json floor_record_json(const std::string& file, const records::Record& ground, const records::Record& floor,
                       const records::FloorModel& m, const std::string& output) {
    const double pga_g = ground.pga(), pga_f = floor.pga();
    Json o;
    o["file"] = file;
    o["ground_name"] = ground.name;
    o["ground_format"] = ground.format;
    o["name"] = floor.name;
    o["format"] = floor.format;
    o["samples"] = floor.accel.size();
    o["dt"] = floor.dt;
    o["model"] = {{"T1_s", m.T1}, {"zeta", m.zeta}, {"G", m.G}};
    o["method"] = floor.header.at("method");
    o["ground_pga_ms2"] = pga_g;
    o["floor_pga_ms2"] = pga_f;
    o["pga_ratio"] = pga_g > 0 ? pga_f / pga_g : NAN;  // a ground at rest has no ratio
    o["end_amplitude_ms2"] = std::stod(floor.header.at("end_amplitude_m_s2"));
    o["warnings"] = records::warnings_of(floor);
    o["output"] = output.empty() ? Json(nullptr) : Json(output);
    return o;
}

}  // namespace rocking::json
