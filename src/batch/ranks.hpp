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

namespace rocking::batch {

// Whether mpirun (or mpiexec, srun) started this process: the variables
// they set, OMPI_COMM_WORLD_SIZE (OpenMPI), PMI_SIZE (MPICH, Slurm) or PMIX_RANK.
inline bool launched_by_mpirun() {
    return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
}

// Whether `path` is a pipe, FIFO, socket or device (/dev/stdin among them),
// which the ranks of an MPI run cannot each read whole: mpirun hands standard
// input to rank 0 alone (the others read /dev/null), and a pipe or FIFO is
// drained by the first rank that reads it.  A missing file or a folder is
// not one: its reader names it.
inline bool unshareable_by_ranks(const std::string& path) {
    struct stat st;
    if (stat(path.c_str(), &st) != 0) return false;
    return !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

// What is said of such a file, before the remedy's last words.
inline std::string unshareable_text(const std::string& path) {
    return path + ": not a regular file (standard input, a pipe, a FIFO or a device), which the ranks of an MPI run "
                  "cannot share (mpirun gives standard input to rank 0 alone, and each rank reads its inputs itself): "
                  "save it to a file";
}

// A rank failed and said why on stderr; this one ends with `status`, silently.
struct OtherRankFailed : std::runtime_error {
    int status;
    explicit OtherRankFailed(int s) : std::runtime_error("another rank failed"), status(s) {}
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
    // ranks that ask, `threads` of its own taking them one by one too, and
    // every row to deliver() in the jobs' order, at most `window` rows held.
    // The other ranks: the chunks they are given, on `threads` threads, until
    // told to stop (deliver is not called there).  A failure on rank 0
    // (deliver throwing) aborts every rank, its message printed.
    virtual void run(std::size_t first, std::size_t n, int threads, std::size_t window, const JobFunction& job,
                     const DeliverRow& deliver) = 0;
};

}  // namespace rocking::batch
