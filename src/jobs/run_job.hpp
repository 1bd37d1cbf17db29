// Running a typed job (job.hpp) through the library, as the command that
// runs the same study alone does: simulate as `rocking simulate --record`,
// collapse as `rocking collapse` (Table 1's search), ida as one record and
// block of `rocking fragility`, spectrum as one alpha of `rocking spectrum`
// (Table 1's bracket joining the grid).  The figures each gives back are the
// results' columns (result_row.hpp); a figure that does not apply stays empty.
#pragma once

#include <optional>
#include <vector>

#include "jobs/job.hpp"
#include "jobs/record_store.hpp"
#include "studies/overturning_set.hpp"

namespace rocking::jobs {

struct Figures {
    bool collapse = false;
    std::optional<double> max_theta, theta_tfin, t_overturn;  // simulate, in alpha and s
    std::optional<long> impacts;                              // simulate
    // collapse: Table 1's p; spectrum: the first overturning p (rad/s)
    std::optional<double> p_collapse, p_safe;
    std::optional<double> q_collapse, q_safe;                 // ida: the first overturning q
    // ida and spectrum (issue 39): whether there is a first robust collapse,
    // its q (ida) or p (spectrum), and the overturned share of each step of
    // the main grid, in ln q or ln p.
    std::optional<bool> robust;
    std::optional<double> q_robust, p_robust;
    std::vector<studies::Band> bands;
    std::optional<long> intervals;                            // ida, spectrum
    std::optional<long> simulations;                          // collapse, ida, spectrum
};

// Throws what reading the record and the study throw (std::exception).
Figures run_job(const Job& job, RecordStore& records);

}  // namespace rocking::jobs
