// A batch cut into shards for clusters without MPI (a scheduler's job
// arrays, cloud batch): `rocking batch MANIFEST --shard I/N` runs the I-th of
// N consecutive parts of the jobs into its own results file, resumable as any
// (results_file.hpp), and `rocking batch join` assembles the N files into
// the bytes one run writes.  Consecutive parts, not interleaved ones, so that
// the join is a concatenation; a manifest sorted by cost balances badly, and
// more shards than nodes (N a few times the nodes) evens it out.
//
// A shard's results file is the whole run's with two differences: its first
// line names the shard ('# manifest sha256: HEX shard I/N', so that a resume
// on another shard's file is refused as another manifest's), and it holds
// only its rows, closed by its own '# end: n jobs, k failed'.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "batch/engine.hpp"

namespace rocking::batch {

struct Shard {
    std::size_t index = 1, count = 1;  // I of N, 1 <= I <= N
};

// "I/N" with 1 <= I <= N <= 100000, or std::invalid_argument saying why.
Shard parse_shard(const std::string& text);

// The jobs of shard I of N of `jobs`: [first, end), floor((I - 1) jobs / N) to floor(I jobs / N).
struct JobRange {
    std::size_t first = 0, end = 0;
};
JobRange shard_jobs(std::size_t jobs, Shard s);

// The plan of shard s of `plan`: its jobs run plan's, its digest names it.
BatchPlan shard_plan(const BatchPlan& plan, Shard s);

struct JoinOutcome {
    std::size_t shards = 0, jobs = 0, failed = 0;
};

// Writes the results of one run from the complete results files of shards
// 1..N of one manifest (given in any order) to `output`, whole or not at all
// (a temporary file, synced, renamed).  Throws ResultsError naming the file
// and what is wrong: a shard missing, given twice or of another N; another
// manifest, other records or another header; a file not complete (its
// '# end' line missing: resume that shard first); `output` among the shards.
JoinOutcome join_shards(const std::vector<std::string>& paths, const std::string& output);

}  // namespace rocking::batch
