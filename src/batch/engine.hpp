// The batch engine: a plan of jobs, each giving one row, run on threads on
// one machine or on the ranks of an MPI run, the rows written in the jobs'
// order to a results file that a killed batch resumes (results_file.hpp),
// with progress on stderr.  It knows jobs and rows, no physics: what job i
// computes and what its row says is the plan's (src/jobs/batch_plan.hpp).
//
// Memory is bounded whatever the number of jobs: at most `window` rows wait
// for their turn (by default 64 chunks of at most 32 jobs a thread, or 64 rows
// per rank and thread under MPI), and the rows not yet flushed to the file
// are at most 4 MiB; the plan holds what it needs for its jobs (the
// manifest's text, and the records' cache with its own budget).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "batch/job_row.hpp"
#include "batch/results_file.hpp"
#include "batch/ranks.hpp"

namespace rocking::batch {

struct BatchPlan {
    std::size_t jobs = 0;
    std::string header;  // the results' lines after the digest's, each ending '\n'
    std::string digest;  // the manifest's SHA-256: the results' identity on resume
    // What the jobs read besides (a batch's records), each with its SHA-256:
    // kept in the results' header, and checked by a resume (results_file.hpp).
    std::vector<InputDigest> inputs;
    JobFunction run;     // job i's row; never throws
};

struct EngineOptions {
    std::string output;  // "" for standard output
    bool resume = false;
    bool quiet = false;     // no progress line even on a terminal
    int threads = 1;        // per process
    std::size_t window = 0; // rows held at most (threads: rounded down to chunks of 32, at least one); 0 for the default
    double flush_seconds = 1.0;
    // The command that runs the batch, as its messages name it.
    std::string command = "rocking batch";
    std::string jobs_from = "manifest";  // or "study": what a refused resume says has changed
    // A front end that needs the rows themselves (rocking fragility fits
    // them): on rank 0, every row's text in the jobs' order, once each.  With
    // an output file it is called after the batch has run to its end, from
    // the finished file, so that the rows a resume skipped come too; without
    // one the rows come only here, as they are ready, and none is written.
    std::function<void(std::size_t, const std::string&)> collect;
};

struct BatchOutcome {
    std::size_t jobs = 0;     // in the results (all of them, unless interrupted)
    std::size_t failed = 0;   // rows marked failed, those of a resumed part included
    std::size_t ran = 0;      // jobs run by this call
    bool already_complete = false;  // --resume found the results finished
};

// `ranks` null: threads in this process; throws ResultsError when the results
// cannot be written or resumed.  Otherwise this process's part of an MPI run:
// rank 0 writes and returns the outcome, the other ranks an empty one; when
// the results cannot be written or resumed, or a rank read another manifest,
// the rank that knows why says so on stderr and every rank throws
// OtherRankFailed once it is said.
// SIGINT and SIGTERM flush the rows delivered so far and end the process by
// the signal, after a line on stderr saying how to resume.  No more threads
// start than there are jobs to run; when they cannot start, ThreadsUnavailable
// is thrown (under mpirun every rank tries its threads before the first job,
// and every rank throws OtherRankFailed(2) once the refusal is said).  A run
// that fails (threads, a full disk) removes the results' partial file and
// state when they keep no row, and the state's temporary always, so that the
// next run is not asked for a --resume of nothing.
BatchOutcome run_batch(const BatchPlan& plan, const EngineOptions& options, Ranks* ranks);

}  // namespace rocking::batch
