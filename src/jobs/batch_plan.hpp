// A manifest's meaning, for the batch engine: its header checked (every
// column known), and job i's row made by reading manifest row i into a job,
// running it and writing its result row; a row that cannot be read or a job
// that fails gives a row marked failed, its error naming the manifest's line
// and the problem, and the batch goes on.
#pragma once

#include "batch/engine.hpp"
#include "batch/manifest.hpp"
#include "jobs/record_store.hpp"

namespace rocking::jobs {

// Throws std::invalid_argument (naming the manifest and the column) for a
// header the jobs cannot be read under.  The plan refers to `manifest` and
// `records`, which must outlive it.
batch::BatchPlan make_plan(const batch::Manifest& manifest, RecordStore& records);

}  // namespace rocking::jobs
