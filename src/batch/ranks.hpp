// The processes of a batch run under mpirun, as the engine sees them: a
// rank and a size, collective agreement, and the jobs shared out with their
// rows coming back to rank 0 in order (cluster.hpp says how).  An interface,
// so that the engine and its tests need no MPI; `rocking` links the one
// implementation its build has.
#pragma once

#include <sys/stat.h>

#include <cstddef>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "batch/job_row.hpp"
#include "batch/results_file.hpp"

namespace rocking::batch {

// Whether mpirun (or mpiexec, srun) started this process: the variables
// they set, OMPI_COMM_WORLD_SIZE (OpenMPI), PMI_SIZE (MPICH, Slurm) or PMIX_RANK.
inline bool launched_by_mpirun() {
    return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
}

// Whether `path` names a descriptor of the process that opens it:
// /dev/stdin, /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N,
// /proc/thread-self/fd/N or /proc/PID/fd/N (bash's <(...) gives /dev/fd/63).
// The ranks are processes mpirun starts, not the shell's children: the
// descriptor is not theirs, whatever file is behind it (rank 1 found no
// /dev/fd/63 and said "cannot open the file").
inline bool descriptor_path(const std::string& path) {
    auto number = [](const std::string& text) {
        return !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
    };
    if (path == "/dev/stdin" || path == "/dev/stdout" || path == "/dev/stderr") return true;
    if (path.rfind("/dev/fd/", 0) == 0) return number(path.substr(8));
    if (path.rfind("/proc/", 0) != 0) return false;
    const std::string rest = path.substr(6);
    const auto fd = rest.find("/fd/");
    if (fd == std::string::npos) return false;
    const std::string process = rest.substr(0, fd);
    return (process == "self" || process == "thread-self" || number(process)) && number(rest.substr(fd + 4));
}

// Whether the ranks of an MPI run cannot each read `path` whole: a
// descriptor's path (descriptor_path), or a pipe, FIFO, socket or device:
// mpirun hands standard input to rank 0 alone (the others read /dev/null),
// and a pipe or FIFO is drained by the first rank that reads it.  A missing
// file or a folder is not one: its reader names it.
inline bool unshareable_by_ranks(const std::string& path) {
    if (descriptor_path(path)) return true;
    struct stat st;
    if (stat(path.c_str(), &st) != 0) return false;
    return !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

// What is said of such a file, before the remedy's last words.
inline std::string unshareable_text(const std::string& path) {
    if (descriptor_path(path))
        return path + ": a descriptor of the process that names it (standard input, or a <(...) of the shell), which "
                      "the ranks of an MPI run cannot share (they are processes of mpirun's, which hands standard "
                      "input to rank 0 alone and no other descriptor to any): save it to a file";
    return path + ": not a regular file (standard input, a pipe, a FIFO or a device), which the ranks of an MPI run "
                  "cannot share (mpirun gives standard input to rank 0 alone, and each rank reads its inputs itself): "
                  "save it to a file";
}

// A rank failed and said why on stderr; this one ends with `status`, silently.
struct OtherRankFailed : std::runtime_error {
    int status;
    explicit OtherRankFailed(int s) : std::runtime_error("another rank failed"), status(s) {}
};

// Where rank 0 puts the rows of a run.  When every rank can open `file`'s
// partial file (the same file, proved by a probe), the ranks write their own
// rows into it at the offsets rank 0 places them at, and only a summary of
// each chunk reaches rank 0, given to `placed` in the jobs' order; otherwise
// (no file: standard output or rows for the front end; a rank that sees
// another file or none) every chunk's rows come to rank 0 and go to `rows`.
struct Delivery {
    DeliverChunk rows;
    ResultsFile* file = nullptr;
    std::function<void(const ChunkSummary&)> placed;
    // How often the ranks sync what they wrote, and the state moves.
    double flush_seconds = 1.0;
    // When set, rank 0's main thread adds the CPU of its busy turns (something
    // received, handed out, placed or synced; not its waits): what it spends
    // on the rows, the bound on how many a second it can take (bench/batch.sh).
    double* busy_cpu = nullptr;
};

class Ranks {
public:
    virtual ~Ranks() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    // Collective: every rank's status (0 for ready), and the largest back.
    virtual int agree(int status) = 0;
    // Collective: rank 0's text on every rank.
    virtual std::string broadcast(const std::string& text) = 0;
    // Collective.  Rank 0: jobs first .. n - 1 handed out in chunks to the
    // ranks that ask, `threads` of its own taking chunks too, and every
    // chunk delivered in the jobs' order (Delivery), at most `window` rows
    // placed ahead of the first not yet run.  The other ranks: the chunks
    // they are given, on `threads` threads, until told to stop (their
    // Delivery is empty).  With a file, every row placed is on the disk
    // (synced by its writer) when run() returns on rank 0.  A failure on any
    // rank (a row that cannot be written, a thread that cannot start) aborts
    // every rank, its message printed after `command` ("rocking fragility"),
    // rank 0's files removed first when they keep no row.
    virtual void run(std::size_t first, std::size_t n, int threads, std::size_t window, const JobFunction& job,
                     const Delivery& delivery, const std::string& command) = 0;
};

}  // namespace rocking::batch
