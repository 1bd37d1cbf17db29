// The results of a batch: one row per manifest row, in the manifest's order.
// A row echoes the manifest's line number and every cell as written, then
// says how the job ran (status, and the model, solver, restitution and
// criterion applied, defaults filled in) and what it found (the figures of
// its kind; run_job.hpp), and ends with the error of a job that failed.
// Numbers are written with %.17g, so that they read back exactly and two runs
// give the same bytes.  Columns: docs/batch.md.
#pragma once

#include <string>
#include <vector>

#include "jobs/job.hpp"
#include "jobs/run_job.hpp"

namespace rocking::jobs {

// Whether the results carry issue 39's columns (robust_collapse, q_robust,
// p_robust, bands): for a manifest that names method, width or
// robust_width.  Without them the results are those written before the
// refine method, byte for byte.
bool capacity_columns(const std::vector<std::string>& manifest_header);

// The columns after the manifest's own.
const std::vector<std::string>& result_columns(bool capacities = false);

// The header's '#' lines and the column row, each ending with '\n'.
std::string results_header(const std::string& manifest_path, std::size_t jobs, const std::vector<std::string>& manifest_header);

// A row (without the newline).  `echo` holds the manifest's cells, padded or
// cut to the header's count; `job` and `figures` are null where the job
// failed before them; `capacities` as capacity_columns of the header.
std::string result_row(int line, const std::vector<std::string>& echo, const Job* job, const Figures* figures,
                       const std::string& error, bool capacities = false);

}  // namespace rocking::jobs
