// The processes of a batch run under mpirun, as the engine sees them: a
// rank and a size, collective agreement, and the jobs shared out with their
// rows coming back to rank 0 in order (cluster.hpp says how).  An interface,
// so that the engine and its tests need no MPI; `rocking` links the one
// implementation its build has.
#pragma once

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
