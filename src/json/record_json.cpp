#include "json/record_json.hpp"

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

}  // namespace rocking::json
