#include "records_analysis.hpp"

#include "harness/compare.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>

#include "batch/pool.hpp"
#include "dynamics/ground_input.hpp"
#include "records/record.hpp"

#ifndef ROCKING_SOURCE_DIR
#define ROCKING_SOURCE_DIR "."
#endif

namespace rocking::scenes {

namespace fs = std::filesystem;

std::string records_dir() {
    if (const char* env = std::getenv("ROCKING_RECORDS")) return env;
    return std::string(ROCKING_SOURCE_DIR) + "/../shared/records";
}

std::string alpha_label(double alpha) {
    char text[16];
    std::snprintf(text, sizeof text, "%.2f", alpha);
    return text;
}

std::string g_text(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

records::CollapseOptions table1_search() {
    records::CollapseOptions o;  // linearised, exact, Housner restitution, overturning
    // The record kernel, the most precise of the solvers on a record: near
    // the collapse boundary the outcome is chaotic (impact-time differences
    // grow ~5 times per impact in the long free-rocking cycles), and the
    // kernel follows its long-double twin there orders of magnitude more
    // closely than the general path (eps alpha rounding at every event) or
    // rk8pd at rtol 1e-13.  Its 80 final brackets pass the rk8pd check; the
    // one row where it differs from the general path's search (IT.AQK HNE
    // 20090406, alpha 0.05) is in PROVENANCE.md (table1), with the evidence.
    o.solver.record_kernel = true;
    return o;
}

records::CollapseOptions table1_check() {
    // rtol 1e-13: at 1e-11 rk8pd itself flips borderline outcomes (rocking
    // on a record is that sensitive near the boundary; measured, see
    // PROVENANCE.md).
    records::CollapseOptions check = table1_search();
    check.solver.kind = dynamics::SolverKind::gsl_rk8pd;
    check.solver.rtol = 1e-13;
    check.solver.atol_alpha = 1e-13;
    return check;
}

namespace {

RecordRow analyse(const std::string& root, const std::string& path, bool reference) {
    RecordRow row;
    const records::Record r = records::read_any(path);
    row.file = fs::relative(path, root).string();
    row.name = r.name;
    row.h = records::half_periods(r);
    row.pga_cms2 = 100.0 * row.h.pga;
    row.pgv_cms = 100.0 * row.h.pgv;
    const dynamics::SampledInput input(r.in_g(9.81), r.dt, r.name);
    const records::CollapseOptions o = table1_search();
    for (std::size_t k = 0; k < kTableAlphas.size(); ++k) {
        row.collapse[k] = records::smallest_collapse_p(input, kTableAlphas[k], o);
        const bool bracket = row.collapse[k].found && !row.collapse[k].below_range();
        if (!reference) {
            row.confirmed[k] = harness::kNotChecked;
        } else if (!bracket) {
            row.confirmed[k] = "-";
        } else {
            // A second solver at a much tighter tolerance must see the same
            // boundary: collapse at p, none at p_safe.
            const records::CollapseOptions check = table1_check();
            const bool at_p = records::collapses_at(input, kTableAlphas[k], row.collapse[k].p, check);
            const bool below = records::collapses_at(input, kTableAlphas[k], row.collapse[k].p_safe, check);
            row.confirmed[k] = at_p && !below ? "yes" : "no";
        }
    }
    return row;
}

}  // namespace

std::vector<std::string> record_files(const std::string& root) {
    std::vector<std::string> files;
    for (const char* sub : {"esm", "peer"}) {
        const fs::path dir = fs::path(root) / sub;
        if (!fs::is_directory(dir)) continue;
        for (const auto& e : fs::directory_iterator(dir))
            if (e.is_regular_file()) files.push_back(e.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

const std::vector<RecordRow>& shared_records(bool reference) {
    static std::map<bool, std::vector<RecordRow>> cache;
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    auto found = cache.find(reference);
    if (found != cache.end()) return found->second;
    std::vector<RecordRow>& rows = cache[reference];
    const std::string root = records_dir();
    const std::vector<std::string> files = record_files(root);
    // One job a record on the batch engine, taken on demand (a record's cost
    // varies with how long blocks rock on it), delivered in the files' order.
    // The first failing record (in that order) is the error, as in one thread.
    rows.resize(files.size());
    batch::run_ordered<RecordRow>(
        files.size(), batch::PoolOptions{batch::default_threads()},
        [&](std::size_t i) {
            try {
                return analyse(root, files[i], reference);
            } catch (const std::exception& e) {
                throw std::runtime_error(std::string("record analysis: ") + e.what());
            }
        },
        [&](std::size_t i, RecordRow& row) { rows[i] = std::move(row); });
    return rows;
}

}  // namespace rocking::scenes
