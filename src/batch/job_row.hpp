// What a batch's job gives back: its row of the results, as text without the
// newline, and whether it failed.  The engine, the pool and the ranks move
// rows; what a row says is the job's affair (src/jobs/).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "batch/row_digest.hpp"

namespace rocking::batch {

struct JobRow {
    std::string text;
    bool failed = false;
};

// Job i's row.  It must not throw: a job that fails says so in its row.
using JobFunction = std::function<JobRow(std::size_t)>;

// What rank 0 needs of a chunk its rank writes itself: where it is in the
// order, how long, how many failed, and its rows' terms of the results'
// checksum (row_digest.hpp).
struct ChunkSummary {
    std::size_t first = 0, count = 0, failed = 0, bytes = 0;
    std::uint64_t digest = 0;
};

// The rows of consecutive jobs as the results file takes them, each row's
// text and its newline one after the other, with each row's length (its
// newline included) to take them apart, kFailedRow set in it where the row
// failed, the number that failed, and the sum of its rows' row_digest.  The
// batch moves rows a chunk at a time: what rank 0 spends on a chunk (a
// message, a place in the order, an append) is shared by all its rows.
// `first` is set before the first add(): a row's digest is seeded by its job.
struct RowChunk {
    static constexpr std::uint32_t kFailedRow = 0x80000000u;
    std::size_t first = 0;
    std::size_t failed = 0;
    std::uint64_t digest = 0;
    std::vector<std::uint32_t> lengths;
    std::string text;
    std::size_t count() const { return lengths.size(); }
    ChunkSummary summary() const { return {first, count(), failed, text.size(), digest}; }
    static std::size_t length(std::uint32_t entry) { return entry & ~kFailedRow; }
    static bool failed_row(std::uint32_t entry) { return (entry & kFailedRow) != 0; }
    void add(const JobRow& row);
    // Calls row(i, text) for each row, its newline left off, in order.
    void each(const std::function<void(std::size_t, std::string_view)>& row) const;
};

// A chunk of rows, handed over in the jobs' order.
using DeliverChunk = std::function<void(RowChunk&)>;

inline void RowChunk::add(const JobRow& row) {
    // A row of 2 GiB would not fit its length; none is near it (a row is one job's figures).
    if (row.text.size() >= kFailedRow - 1) throw std::length_error("a batch row of 2 GiB or more");
    const std::size_t at = text.size();
    text += row.text;
    text += '\n';
    digest += row_digest(std::string_view(text).substr(at), first + lengths.size());
    lengths.push_back(static_cast<std::uint32_t>(row.text.size() + 1) | (row.failed ? kFailedRow : 0u));
    failed += row.failed;
}

inline void RowChunk::each(const std::function<void(std::size_t, std::string_view)>& row) const {
    std::size_t at = 0;
    for (std::size_t k = 0; k < lengths.size(); at += length(lengths[k]), ++k)
        row(first + k, std::string_view(text).substr(at, length(lengths[k]) - 1));
}

}  // namespace rocking::batch
