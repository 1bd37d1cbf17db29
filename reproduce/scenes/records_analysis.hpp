// The real records of ../shared/records/ (or $ROCKING_RECORDS) analysed once
// per process: the eleven half-periods and the collapse search for the five
// slendernesses of Table 1, in parallel across records.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "records/collapse.hpp"
#include "records/measures.hpp"

namespace rocking::scenes {

inline constexpr std::array<double, 5> kTableAlphas = {0.05, 0.1, 0.15, 0.2, 0.25};
inline constexpr double kTableG = 981.0;  // cm/s^2, as the paper's Table 1

struct RecordRow {
    std::string file;  // path relative to the records folder
    std::string name;
    double pga_cms2 = 0, pgv_cms = 0;
    records::HalfPeriods h;
    std::array<records::CollapseResult, 5> collapse;
    // The second solver's verdict on the bracket: "yes" or "no" in reference
    // mode, "-" where there is no bracket, harness::kNotChecked otherwise.
    std::array<std::string, 5> confirmed{};
};

// Table 1's alpha as the record scenes name it in their rows ("0.05", %.2f).
std::string alpha_label(double alpha);
// A width, a tolerance or a step as a note states it (%g: 1e-04 as 0.0001).
std::string g_text(double v);

// The records folder: $ROCKING_RECORDS, else <source>/../shared/records.
std::string records_dir();
// Why a record scene skips its files: the folder is absent.
inline const char* kNoRecords = "the records folder is absent (../shared/records or $ROCKING_RECORDS)";
// The files of root's esm/ and peer/ (the records the scenes read), sorted by
// path; empty where neither folder exists.
std::vector<std::string> record_files(const std::string& root);
// Every readable record in it, analysed (cached); empty when the folder is absent.
const std::vector<RecordRow>& shared_records(bool reference);
// The options of Table 1's collapse search (stated in every output).
records::CollapseOptions table1_search();
// The same search's second solver, which must see each bracket the same
// (reference mode): GSL rk8pd at rtol 1e-13.
records::CollapseOptions table1_check();

}  // namespace rocking::scenes
