// A manifest's meaning, for the batch engine: its header checked (every
// column known), and job i's row made by reading manifest row i into a job,
// running it and writing its result row; a row that cannot be read or a job
// that fails gives a row marked failed, its error naming the manifest's line
// and the problem, and the batch goes on.
#pragma once

#include <string>
#include <vector>

#include "batch/engine.hpp"
#include "batch/manifest.hpp"
#include "jobs/record_store.hpp"

namespace rocking::jobs {

// A record file the manifest names: its cell as written, its path (resolved
// against the manifest's folder) and the line of the first row naming it.
struct NamedRecord {
    std::string cell, path;
    int line = 0;
};

// Every record cell of the manifest's rows once, in the order first named
// (rows that cannot be read, or name none, are skipped: their jobs fail).
std::vector<NamedRecord> named_records(const batch::Manifest& manifest);

// Before any job (issue 38): the results at `output`, and the partial file
// and state they are written through, are none of the inputs (the manifest,
// the records it names: batch study.csv --output study.csv replaced the
// manifest at the end), and their folder is writable.  `role` names the
// output as the front end's user gave it ("--output", "output").  Throws
// std::invalid_argument for an output that is an input (or a partial file
// that is one), std::runtime_error for an output that cannot be written.
void check_output(const std::string& role, const std::string& output, const batch::Manifest& manifest,
                  const std::vector<NamedRecord>& records);

// Throws std::invalid_argument (naming the manifest and the column) for a
// header the jobs cannot be read under.  Each named record is read once
// here for its SHA-256 (plan.inputs, in the results' header; the store then
// refuses a job on bytes that differ).  The plan refers to `manifest` and
// `records`, which must outlive it.
batch::BatchPlan make_plan(const batch::Manifest& manifest, RecordStore& records);
batch::BatchPlan make_plan(const batch::Manifest& manifest, RecordStore& records, const std::vector<NamedRecord>& named);

}  // namespace rocking::jobs
