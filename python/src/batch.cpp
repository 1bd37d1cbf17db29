// rocking_q.batch: `rocking batch MANIFEST --output FILE` from Python, the same
// engine (src/batch/) and job meanings (src/jobs/) on this process's threads.
// The results go to a file, as a batch of 10^6 jobs must not be held in memory;
// the call returns what the command line reports on stderr.  Ctrl-C behaves as
// it does for the command: the rows so far are made durable and the process
// ends by the signal, so that resume=True completes them (docs/batch.md).
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/engine.hpp"
#include "batch/manifest.hpp"
#include "batch/results_file.hpp"
#include "common.hpp"
#include "jobs/batch_plan.hpp"
#include "jobs/record_store.hpp"

namespace rocking::python {

namespace {

py::dict run(const Text& manifest_arg, const Text& output_arg, const std::optional<Whole>& jobs, const Flag& resume) {
    const std::string manifest_path = string_argument(manifest_arg, "manifest");
    const std::string output = string_argument(output_arg, "output");
    if (output.empty()) refuse("output: an empty file name (the results of a batch go to a file)");
    batch::EngineOptions o;
    o.output = output;
    o.resume = flag(resume, "resume");
    o.quiet = true;
    o.threads = jobs_argument(jobs);
    batch::BatchOutcome outcome;
    {
        py::gil_scoped_release free;
        // A manifest that cannot be read is a bad argument, as a bad record file is.
        std::optional<batch::Manifest> manifest;
        try {
            manifest.emplace(batch::Manifest::read(manifest_path));
        } catch (const batch::ManifestError& e) {
            throw std::invalid_argument(e.what());
        }
        // Before any job, as rocking batch: an output that is an input (the manifest,
        // a record) is a ValueError, one that cannot be written a RuntimeError.
        const std::vector<jobs::NamedRecord> named = jobs::named_records(*manifest);
        jobs::check_output("output", output, *manifest, named);
        jobs::RecordStore records;
        const batch::BatchPlan plan = jobs::make_plan(*manifest, records, named);
        outcome = batch::run_batch(plan, o, nullptr);
    }
    py::dict r = result();
    r["manifest"] = text(manifest_path);
    r["output"] = text(output);
    r["jobs"] = outcome.jobs;
    r["failed"] = outcome.failed;
    r["ran"] = outcome.ran;
    r["already_complete"] = outcome.already_complete;
    r["threads"] = o.threads;
    return r;
}

}  // namespace

void init_batch(py::module_& m) {
    using namespace pybind11::literals;
    m.def("batch", gsl_checked(&run), "manifest"_a, py::kw_only(), "output"_a, "jobs"_a = py::none(), "resume"_a = false,
          R"(`rocking batch MANIFEST --output FILE [--jobs N] [--resume]`: every job of the CSV manifest run
on this process's threads, one results row per job in the manifest's order in `output` (CSV,
docs/batch.md); a job that fails has its error in its row and the rest run.  Returns jobs,
failed, ran and already_complete.  A manifest that cannot be read raises ValueError naming it, as
does an output that is the manifest or one of its records (before any job); results that cannot
be written or resumed, RuntimeError.  Releases the GIL.)");
}

}  // namespace rocking::python
