#include "jobs/batch_plan.hpp"

#include <memory>
#include <stdexcept>

#include "jobs/job.hpp"
#include "jobs/result_row.hpp"
#include "jobs/run_job.hpp"

namespace rocking::jobs {

batch::BatchPlan make_plan(const batch::Manifest& manifest, RecordStore& records) {
    std::shared_ptr<const Columns> columns;
    try {
        columns = std::make_shared<const Columns>(manifest.header());
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(manifest.path() + ": the header: " + e.what());
    }
    batch::BatchPlan plan;
    plan.jobs = manifest.size();
    plan.digest = manifest.digest();
    plan.header = results_header(manifest.path(), manifest.size(), manifest.header());
    plan.run = [&manifest, &records, columns](std::size_t i) {
        const int line = manifest.line(i);
        std::vector<std::string> echo(columns->size());
        std::unique_ptr<Job> job;
        try {
            const std::vector<std::string> cells = batch::split_csv_line(manifest.text(i));
            for (std::size_t c = 0; c < echo.size() && c < cells.size(); ++c) echo[c] = cells[c];
            job = std::make_unique<Job>(parse_job(*columns, cells, manifest.folder()));
            const Figures figures = run_job(*job, records);
            return batch::JobRow{result_row(line, echo, job.get(), &figures, ""), false};
        } catch (const std::exception& e) {
            const std::string error = "manifest line " + std::to_string(line) + ": " + e.what();
            return batch::JobRow{result_row(line, echo, job.get(), nullptr, error), true};
        }
    };
    return plan;
}

}  // namespace rocking::jobs
