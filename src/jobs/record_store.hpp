// The records of a batch, each read once and shared by every job over it
// (batch::SharedCache): a record read fails the same way for each of its
// jobs, and is read by the first of them only.  Records are keyed by their
// canonical path (with the unit and step of a plain-text one), so that
// ../r.txt and ./r.txt are one record.  A record in the jobs' unit, g, takes
// about 8.5 bytes a sample; past the budget (by default 512 MiB, some 6000
// records of 10^4 samples) the least recently used are dropped and read
// again when a job needs them.
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include "batch/cache.hpp"
#include "dynamics/ground_input.hpp"
#include "jobs/job.hpp"

namespace rocking::jobs {

class RecordStore {
public:
    static constexpr std::size_t kDefaultBudget = std::size_t{512} << 20;
    explicit RecordStore(std::size_t budget_bytes = kDefaultBudget);
    // The record, in g.  Throws std::runtime_error with the reader's message,
    // the file named as the manifest names it, and when its bytes are not
    // those pin() found.
    std::shared_ptr<const dynamics::SampledInput> get(const RecordSource& source);
    // The SHA-256 of the file's bytes (64 hex digits), which every read of it
    // for a job must then find: the rows are computed from the bytes the
    // results' header names.  "unreadable" for a file that cannot be read
    // (its jobs fail; its absence is its identity), "" for one that is not a
    // regular file (a pipe: reading it now would leave nothing for its jobs).
    std::string pin(const std::string& path);
    std::size_t reads() const { return cache_.loads(); }
    // Under mpirun: every rank refuses a record the ranks cannot share
    // (batch::unshareable_by_ranks, /dev/stdin), so that its jobs' rows do not
    // depend on the rank that ran them.
    void refuse_unshareable() { refuse_unshareable_ = true; }

private:
    std::string canonical(const std::string& path);
    bool refuse_unshareable_ = false;
    batch::SharedCache<dynamics::SampledInput> cache_;
    // Each path's canonical form, found once: a search walks the path's
    // folders (a readlink each), a cost per job beside a 20 us simulation.
    std::mutex canonical_mutex_;
    std::unordered_map<std::string, std::string> canonical_;
    std::mutex pinned_mutex_;
    std::unordered_map<std::string, std::string> pinned_;  // canonical path: its SHA-256
};

}  // namespace rocking::jobs
