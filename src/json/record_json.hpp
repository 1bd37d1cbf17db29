// rocking record info's document: a record's peaks and its eleven
// half-periods (records/measures.hpp).
#pragma once

#include <string>

#include "json/document.hpp"
#include "records/floor_motion.hpp"
#include "records/measures.hpp"
#include "records/record.hpp"

namespace rocking::json {

// {"file", "format", "name", "samples" (an integer), "dt", "pga_ms2",
// "pgv_ms", "amax_ms", "to" (to_1..to_11, s), "to_at_band_edge" (which of
// to_8..to_11, as integers, are the CWT band's edge rather than a peak),
// "cwt_band_hz" ([low, high])}.
Json record_info_json(const std::string& file, const records::Record& r, const records::HalfPeriods& h);

// rocking record synth's document: {"name", "format", "samples", "dt",
// "pga_ms2", "pgv_ms", "to5_s", "parameters" (the header's generator and
// parameters, numbers as numbers), "warnings", "output" (the file written,
// or null)}.
Json synthetic_record_json(const records::Record& r, const records::PeakMotion& m, const std::string& output);

// rocking record floor's document: {"file", "ground_name", "ground_format",
// "name", "format", "samples", "dt", "model": {"T1_s", "zeta", "G"},
// "method", "ground_pga_ms2", "floor_pga_ms2", "pga_ratio" (NaN for a ground
// at rest), "end_amplitude_ms2" (the building's free vibration left out),
// "warnings", "output"}.
Json floor_record_json(const std::string& file, const records::Record& ground, const records::Record& floor,
                       const records::FloorModel& m, const std::string& output);

}  // namespace rocking::json
