// The batch across processes: the same binary started K times by mpirun
// (OpenMPI; MPICH and Slurm's srun set the same kind of variables), one
// process a rank.  Rank 0 hands out the jobs in chunks to the ranks that ask
// for work, runs some itself, and receives every row; it alone delivers them,
// in the jobs' order, to the results file.  A chunk is handed out only when a
// rank asks, so a rank that drew cheap jobs asks again sooner: the jobs'
// costs vary by 1000x, and a fixed split would leave ranks idle.  Each rank
// reads only the records of the jobs it runs.  The rows do not depend on
// which rank ran them, so the results are those of one rank, or of threads.
//
// Built without MPI (no libopenmpi-dev at cmake time: cluster_none.cpp),
// built_with_mpi() is false and join_cluster() throws: `rocking batch` runs
// on threads, and refuses to run under mpirun, where each copy would run the
// whole batch.
#pragma once

#include <memory>

#include "batch/ranks.hpp"

namespace rocking::batch {

bool built_with_mpi();
// MPI_Init (only the calling thread talks to MPI); MPI_Finalize when the
// object goes.  Throws std::runtime_error when built without MPI.
std::unique_ptr<Ranks> join_cluster();

}  // namespace rocking::batch
