// What a batch's job gives back: its row of the results, as text without the
// newline, and whether it failed.  The engine, the pool and the ranks move
// rows; what a row says is the job's affair (src/jobs/).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace rocking::batch {

struct JobRow {
    std::string text;
    bool failed = false;
};

// Job i's row.  It must not throw: a job that fails says so in its row.
using JobFunction = std::function<JobRow(std::size_t)>;
// Row i, handed over in the jobs' order.
using DeliverRow = std::function<void(std::size_t, JobRow&)>;

}  // namespace rocking::batch
