// The results of a batch on disk: rows streamed out in the jobs' order,
// made durable piece by piece so that a batch killed at any moment can be
// resumed, and the finished file appearing at its name whole or not at all.
// It knows rows of text and whether each failed, not what they hold.
//
// While the batch runs, the rows go to OUT.partial and a state file beside
// it, OUT.partial.state, records how far that file is good: the jobs
// written, the failed ones among them, its length in bytes, the header's
// length, and a checksum of those bytes that sums one term a row
// (row_digest.hpp), so that rows written by other processes count without
// passing through this one.  A flush appends the rows held, syncs them to the disk, then
// replaces the state file atomically (a temporary file, synced, renamed): a
// kill between the two leaves rows beyond the recorded length, which a resume
// cuts off, and a kill inside the rename leaves the old state, still true.
// The state moves only after the rows it counts are on the disk, so a
// half-written piece is never taken for a finished one.  When every job is
// written, a last line '# end: N jobs, K failed' closes the file and it is
// renamed to OUT.
//
// The file's first line is '# manifest sha256: HEX': a resume on a manifest
// whose digest differs is refused, since its jobs are not the ones counted.
// Then one line '# record sha256: HEX NAME' for each input the jobs read
// besides (a batch's records): a resume, or a --resume that finds the file
// complete, is refused naming the first whose digest differs now, and any
// that is not a regular file (its digest is "unverifiable": a pipe cannot
// be read again to prove what the first part read).
// Resuming keeps the header already written and appends the rows after it,
// so that a resumed batch ends with the same bytes as one never interrupted.
// Without a path the rows go to standard output, and nothing can be resumed.
//
// Under MPI the ranks write their own rows (cluster_mpi.cpp): rank 0 places
// each chunk at the end of those before it, the rank that ran it writes it
// there and syncs it when asked, and the state counts the chunks in order up
// to the first not yet synced.  The file is the same, byte for byte.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/job_row.hpp"

namespace rocking::batch {

// A results file that cannot be written, or a resume refused: the message
// says which file and why, and what to do.
struct ResultsError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// An input of the jobs besides the manifest, as the results' header keeps it:
// its name as the manifest gives it, and the SHA-256 of its bytes (64 hex
// digits, or a word and a reason for a file that could not be read, whose
// absence is then what a resume checks); "" when it is not a regular file.
struct InputDigest {
    std::string name;
    std::string digest;
};
constexpr char kUnverifiable[] = "unverifiable";

// Every file the engine writes for results at `output`, and what each is,
// for the messages: the results themselves, OUT.partial, its state
// OUT.partial.state, and the state's temporary OUT.partial.state.tmp.  A
// front end refuses any of them that is an input (issue 38: a record named
// X.partial.state was removed by spectrum --rows X, one named X.partial
// taken for the rows of a resume).
struct EngineFile {
    std::string what;  // "" for the results, else "partial file", "state file", "state file's temporary"
    std::string path;
};
std::vector<EngineFile> engine_files(const std::string& output);

struct ResultsOptions {
    std::string path;       // "" for standard output
    bool resume = false;
    // A flush at the first row after this many seconds since the last one,
    // or once this many bytes are held: what a kill can lose, and the
    // memory the rows not yet written take.
    double flush_seconds = 1.0;
    std::size_t flush_bytes = std::size_t{4} << 20;
    // What the jobs come from, as a refused resume names it: "manifest", "study".
    std::string jobs_from = "manifest";
};

class ResultsFile {
public:
    // `header`: the lines after the digest's, each ending with '\n'.
    // Throws ResultsError when the files cannot be made, when a partial file
    // exists and resume is off, and when a resume is refused.
    ResultsFile(const ResultsOptions& options, const std::string& header, const std::string& digest, std::size_t jobs,
                const std::vector<InputDigest>& inputs = {});
    ~ResultsFile();
    ResultsFile(const ResultsFile&) = delete;
    ResultsFile& operator=(const ResultsFile&) = delete;

    std::size_t done() const;    // the jobs written or placed, those a resume skips included
    std::size_t failed() const;  // among them, the rows marked failed
    std::size_t kept() const;    // the jobs the state on the disk counts (all of done() after a flush on threads)
    // A resume found the results already complete at the path (nothing to run).
    bool complete() const { return complete_; }
    // Job done()'s row (its text without the newline), and whether it failed.
    void append(const std::string& row, bool failed);
    // The rows of jobs done() .. done() + chunk.count() - 1, at once.
    void append(const RowChunk& chunk);
    // The rows held reach the file, synced, and the state counts them (the
    // chunks placed: those synced by their writers, in order).
    void flush();

    // The ranks' way.  A chunk another process ran and writes itself: its
    // number (the chunks are placed in the jobs' order, numbered from 0 in
    // this run) and its offset in partial_path(), after every chunk placed
    // before it.
    struct Placement {
        std::size_t number = 0;
        std::uint64_t offset = 0;
    };
    Placement place(const ChunkSummary& chunk);
    // A chunk this process ran and placed: written there, by any thread, and
    // synced by the next flush.
    void write_own(const Placement& at, const std::string& text);
    // Both at once.
    void place_own(const RowChunk& chunk);
    // Placed chunk `number`'s writer has synced it: the next flush may count it.
    void synced(std::size_t number);
    // Before the ranks open partial_path(): `text` written after the rows
    // kept (where a resume would cut it off) and synced, for the others to
    // read and so prove they see this file; its offset.  clear_probe() cuts
    // it off again.
    std::uint64_t write_probe(const std::string& text);
    void clear_probe();
    // Every job written: the end line, and the file moves to its path.
    void finish();
    // A run that failed (its threads could not start, a full disk): the
    // state's temporary goes, and unless a row is kept on the disk (counted
    // by the state: resumable), OUT.partial and its state go too, so that
    // they do not ask the next run for a --resume of nothing.  Files a
    // refused resume found, or another run holds, are never touched.
    void discard_unless_rows_kept();
    // A finished results file's rows, in order, to `row`: the lines after
    // the digest's and `header_lines` more, up to the end line.  Throws
    // ResultsError when it cannot be read or does not end as a finished one.
    static void read_rows(const std::string& path, std::size_t header_lines,
                          const std::function<void(std::size_t, const std::string&)>& row);
    bool on_disk() const { return !options_.path.empty(); }
    std::string partial_path() const { return engine_files(options_.path)[1].path; }
    std::string state_path() const { return engine_files(options_.path)[2].path; }
    std::string state_temporary() const { return engine_files(options_.path)[3].path; }

private:
    void open(const std::string& preamble, const std::string& digest);
    void flush_locked();
    void write_all(const std::string& text);
    void write_at_locked(std::uint64_t offset, const std::string& text);
    void write_state(std::size_t jobs, std::size_t failed);
    // Checks the first `bytes` of the partial file against the state's
    // checksum (`sha256` from a rocking before the sum of row terms, with no
    // header length), and returns its header.
    std::string verify_kept(unsigned long long jobs, unsigned long long bytes, unsigned long long header,
                            std::uint64_t digest, const std::string& sha256);
    void start_fresh(const std::string& preamble);
    bool resume_partial(const std::string& digest);
    void check_complete(const std::string& digest);
    // The inputs' lines of a results file begun (`text` from its first line)
    // against this run's; throws naming the first that differs, when and
    // since what ("r.csv.partial was begun"), and the remedy.
    void check_inputs(const std::string& text, const std::string& since, const std::string& remedy) const;

    ResultsOptions options_;
    std::size_t jobs_ = 0;
    std::vector<InputDigest> inputs_;
    mutable std::mutex mutex_;
    int fd_ = -1;
    std::string held_;
    std::size_t done_ = 0, failed_ = 0, written_done_ = 0, written_failed_ = 0;
    std::size_t preamble_lines_ = 0;
    unsigned long long bytes_ = 0, header_bytes_ = 0;
    std::uint64_t digest_ = 0, held_digest_ = 0;  // row_digest.hpp's sum of the bytes written, and of those held
    // Chunks placed and not yet counted by the state, in order: own (written by
    // this process, synced by its flush) or synced by their writer.
    struct Placed {
        ChunkSummary chunk;
        bool own = false, synced = false;
    };
    std::deque<Placed> placed_;
    std::size_t placed_before_ = 0;      // chunks placed and counted before placed_.front()
    bool placing_ = false, own_unsynced_ = false;
    unsigned long long placed_end_ = 0;  // where the next chunk goes
    bool complete_ = false, finished_ = false;
    bool began_ = false;  // this run made OUT.partial (or begun it again): its to remove
    std::chrono::steady_clock::time_point last_flush_;
};

}  // namespace rocking::batch
