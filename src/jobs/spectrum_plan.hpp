// rocking spectrum on the batch engine: each alpha a job, its row the whole
// study of that alpha as the command prints it (text, JSON, the grid's CSV
// and the PNG), so that the spectra run on threads, on the ranks of an MPI
// run and from a resumed rows file alike, and rank 0 prints from the rows.
//
// A row, 24 cells: job, alpha, lifts (yes|no), simulations,
// check_simulations, boundaries, table1_found (yes|no), table1_p,
// table1_p_safe, table1_simulations (Table 1's search as it came, p_safe 0
// included: CollapseResult::below_range() is read from found and p_safe),
// intervals, points, then issue 39's: first_overturning_p, overturns
// (yes|no), first_robust_p, robustly (yes|no), bands, refined (yes|no),
// samples, accepted, at_width, with_margins (yes|no), unguaranteed_from
// ("inf" where the guarantee holds throughout), and error.
//   intervals: ';' between intervals, each 10 fields split by '|':
//     from|to|lower_p_safe|lower_p_collapse|lower_confirmation|lower_detail|
//     upper_p_safe|upper_p_collapse|upper_confirmation|upper_detail
//     a boundary's four fields empty where the interval ends at the grid's
//     own end (has_lower/has_upper false); a detail with '%' as %25, '|' as
//     %7C, ';' as %3B, LF as %0A and CR as %0D, so that any text comes back.
//   points: ';' between points, in increasing p, each 8 fields split by '|':
//     p|grid (main, offset or extra)|max_theta|final_rotation|peak_rotation|
//     overturning|collapse|t_overturn, the criteria as 1 or 0, t_overturn
//     "nan" where the block does not overturn or is taken to by its energy.
//   bands: ';' between the main grid's steps, each from|to|share.
//   error: empty, or the failed job's message on one line, every cell from
//     lifts to unguaranteed_from then empty.
// Numbers in %.17g (harness::format_number), which read back to the same
// double, so that the output is the same bit for bit whether the spectra
// came from memory, from a file or from another rank.  The intervals and
// points cells are CSV cells (batch::csv_cell): quoted where a detail holds a
// comma or a quote.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "batch/engine.hpp"
#include "dynamics/ground_input.hpp"
#include "records/collapse.hpp"
#include "studies/spectrum.hpp"

namespace rocking::jobs {

// One alpha's study: its spectrum, and Table 1's first collapse beside it.
struct SpectrumStudy {
    studies::Spectrum spectrum;
    records::CollapseResult table1;
};

// Table 1's search (records::smallest_collapse_p, on the grid's model: Table
// 1's own by default), its bracket added to the grid as extra points (an island its 1 % scan met and the grid stepped over
// is then refined too: docs/spectrum.md), then the spectrum on that grid.
// Throws what the two throw.
SpectrumStudy spectrum_study(const dynamics::GroundInput& input, double alpha, const studies::SpectrumOptions& grid);

struct SpectrumJobs {
    const dynamics::SampledInput* input = nullptr;  // outliving the plan
    std::vector<double> alphas;
    studies::SpectrumOptions grid;  // without Table 1's points: each job adds its own
    // '#' lines stating the study (command, model, grid, record), each ending '\n'.
    std::string description;
    // The record's file as the command line gave it: a refused resume names it.
    std::string name = "the record";
};

// Job k: alphas[k]; the plan's jobs read `jobs`, which must outlive it.  The
// digest covers the description, the alphas and the grid's options; the
// record is the plan's one input, its digest that of its step and samples
// (studies/record_order.hpp's sample_digest), so that a resume on another study is refused, and one on
// an edited record refused naming it.
batch::BatchPlan spectrum_plan(const SpectrumJobs& jobs);

// The row of job `job`, and back.  study_from_row throws std::runtime_error
// naming the alpha and the job's error for a failed row, and for a row that
// is not spectrum_plan's for that job.
std::string study_row(std::size_t job, const SpectrumStudy& study);
SpectrumStudy study_from_row(const std::string& row, std::size_t job, const SpectrumJobs& jobs);

}  // namespace rocking::jobs
