#include "jobs/batch_plan.hpp"

#include <unistd.h>

#include <memory>
#include <stdexcept>
#include <string_view>
#include <unordered_set>

#include "batch/results_file.hpp"
#include "harness/output_paths.hpp"
#include "jobs/job.hpp"
#include "jobs/result_row.hpp"
#include "jobs/run_job.hpp"

namespace rocking::jobs {

namespace {

// A relative record that is not there: where it was looked for, since the
// folder is not always the one the user thinks of (a manifest read from
// /dev/stdin or through a link).
std::string where_looked(const Job* job, const batch::Manifest& manifest) {
    if (!job || job->record.cell.front() == '/' || ::access(job->record.path.c_str(), F_OK) == 0) return "";
    return "; " + job->record.cell + " is resolved from " + manifest.folder_said();
}

// The row's cell in `column`, as split_csv_line reads it; false for a row it
// refuses or one too short.  Read once a row before any job, so that a row
// without a quote (nearly all) is cut at its commas in place rather than
// split into a string a cell: that split was 4 % of a batch of idle jobs.
bool record_cell(std::string_view row, std::size_t column, std::string& cell) {
    if (row.find('"') != std::string_view::npos) {
        std::vector<std::string> cells;
        try {
            cells = batch::split_csv_line(row);
        } catch (const std::invalid_argument&) {
            return false;
        }
        if (column >= cells.size()) return false;
        cell = std::move(cells[column]);
        return true;
    }
    std::size_t from = 0;
    for (std::size_t c = 0; c < column; ++c) {
        from = row.find(',', from);
        if (from == std::string_view::npos) return false;
        ++from;
    }
    std::string_view text = row.substr(from, row.find(',', from) - from);
    const std::size_t first = text.find_first_not_of(" \t");
    text = first == std::string_view::npos ? std::string_view() : text.substr(first, text.find_last_not_of(" \t") - first + 1);
    cell.assign(text);
    return true;
}

}  // namespace

std::vector<NamedRecord> named_records(const batch::Manifest& manifest) {
    std::size_t column = manifest.header().size();
    for (std::size_t c = 0; c < manifest.header().size(); ++c)
        if (manifest.header()[c] == "record") column = c;
    std::vector<NamedRecord> named;
    if (column == manifest.header().size()) return named;
    std::unordered_set<std::string> seen;
    std::string cell, last;  // rows come in runs on one record: most need no look-up
    for (std::size_t i = 0; i < manifest.size(); ++i) {
        if (!record_cell(manifest.text(i), column, cell) || cell.empty() || cell == last) continue;
        last = cell;
        if (!seen.insert(cell).second) continue;
        named.push_back({cell, record_path(cell, manifest.folder()), manifest.line(i)});
    }
    return named;
}

void check_output(const std::string& role, const std::string& output, const batch::Manifest& manifest,
                  const std::vector<NamedRecord>& records) {
    std::vector<harness::NamedPath> inputs = {{"the manifest", manifest.path()}};
    for (const NamedRecord& r : records)
        inputs.push_back({"the record of manifest line " + std::to_string(r.line), r.path});
    std::vector<harness::NamedPath> outputs;  // the results and the files they are written through
    for (const batch::EngineFile& f : batch::engine_files(output))
        outputs.push_back({f.what.empty() ? role : role + "'s " + f.what, f.path});
    harness::refuse_outputs_over_inputs(outputs, inputs);
    harness::check_writable({role, output});
}

batch::BatchPlan make_plan(const batch::Manifest& manifest, RecordStore& records) {
    return make_plan(manifest, records, named_records(manifest));
}

batch::BatchPlan make_plan(const batch::Manifest& manifest, RecordStore& records, const std::vector<NamedRecord>& named) {
    std::shared_ptr<const Columns> columns;
    try {
        columns = std::make_shared<const Columns>(manifest.header());
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(manifest.path() + ": the header: " + e.what());
    }
    batch::BatchPlan plan;
    plan.jobs = manifest.size();
    plan.digest = manifest.digest();
    for (const NamedRecord& r : named) plan.inputs.push_back({r.cell, records.pin(r.path)});
    plan.header = results_header(manifest.path(), manifest.size(), manifest.header());
    const bool capacities = capacity_columns(manifest.header());
    plan.run = [&manifest, &records, columns, capacities](std::size_t i) {
        const int line = manifest.line(i);
        std::vector<std::string> echo(columns->size());
        std::unique_ptr<Job> job;
        try {
            const std::vector<std::string> cells = batch::split_csv_line(manifest.text(i));
            for (std::size_t c = 0; c < echo.size() && c < cells.size(); ++c) echo[c] = cells[c];
            job = std::make_unique<Job>(parse_job(*columns, cells, manifest.folder()));
            const Figures figures = run_job(*job, records);
            return batch::JobRow{result_row(line, echo, job.get(), &figures, "", capacities), false};
        } catch (const std::exception& e) {
            const std::string error = "manifest line " + std::to_string(line) + ": " + e.what() + where_looked(job.get(), manifest);
            return batch::JobRow{result_row(line, echo, job.get(), nullptr, error, capacities), true};
        }
    };
    return plan;
}

}  // namespace rocking::jobs
