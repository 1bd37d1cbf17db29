// The cluster in a build without MPI (cluster.hpp): none.
#include <stdexcept>

#include "batch/cluster.hpp"

namespace rocking::batch {

bool built_with_mpi() { return false; }

std::unique_ptr<Ranks> join_cluster() {
    throw std::runtime_error("this rocking was built without MPI (cmake found no libopenmpi-dev)");
}

}  // namespace rocking::batch
