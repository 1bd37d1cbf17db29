// rocking fragility on the batch engine: each (block, record) IDA a job, its
// row the IDA as the command prints and fits it, so that the study runs on
// threads, on the ranks of an MPI run and from a resumed rows file alike, and
// rank 0 fits the blocks from the rows (studies::block_fragility).
//
// A row: job, alpha, p, record (its index among the inputs), q_input, q,
// collapsed, simulations, check_simulations, point_confirmation, point_detail
// (the first collapse's bracket check), intervals ("from|to|lower_safe|
// lower_collapse|upper_safe|upper_collapse" each, ';' between; a bracket's
// cells empty where the interval meets the grid's end), robust_q and
// robust_collapsed (the first robust collapse), bands ("from|to|share" each,
// ';' between), refined, samples, accepted, at_width, with_margins,
// unguaranteed_from (issue 39's fields of studies::Ida; the first overturning
// is q, the first collapse, for both methods), error.  Numbers in
// %.17g, which read back to the same double, so that the study is the same
// bit for bit whether its IDAs came from memory or from a file.  The grid's
// points of each IDA are not kept: the command prints none of them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "batch/engine.hpp"
#include "dynamics/ground_input.hpp"
#include "studies/ida.hpp"

namespace rocking::jobs {

struct FragilityJobs {
    std::vector<const dynamics::SampledInput*> inputs;  // one per record, outliving the plan
    std::vector<studies::BlockShape> blocks;
    studies::IdaOptions ida;
    // '#' lines stating the study (command, model, grid, inputs), each ending '\n'.
    std::string description;
    // Each input's file as the command line gave it, for a refused resume to
    // name the one that changed; "record K" (from 0) where none is given.
    std::vector<std::string> names;
};

// Job j: block j / inputs, input j % inputs.  The digest covers the
// description, the blocks and the grid; each record is one of the plan's
// inputs, its digest that of its step and samples as read (studies/record_order.hpp's sample_digest),
// so that a resume on another study is refused, and one on an edited record
// refused naming it.
batch::BatchPlan fragility_plan(const FragilityJobs& jobs);

// A row back into its IDA (grid points left empty).  Throws
// std::runtime_error with the job's error for a failed row, and for a row
// that is not one of fragility_plan's.
studies::Ida ida_from_row(const std::string& row, std::size_t job, const FragilityJobs& jobs);

}  // namespace rocking::jobs
