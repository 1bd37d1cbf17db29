// rocking record info's document: a record's peaks and its eleven
// half-periods (records/measures.hpp).
#pragma once

#include <string>

#include "json/document.hpp"
#include "records/measures.hpp"
#include "records/record.hpp"

namespace rocking::json {

// {"file", "format", "name", "samples" (an integer), "dt", "pga_ms2",
// "pgv_ms", "amax_ms", "to" (to_1..to_11, s), "to_at_band_edge" (which of
// to_8..to_11, as integers, are the CWT band's edge rather than a peak),
// "cwt_band_hz" ([low, high])}.
Json record_info_json(const std::string& file, const records::Record& r, const records::HalfPeriods& h);

}  // namespace rocking::json
