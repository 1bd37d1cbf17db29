#include "cli/cluster_front.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "batch/cluster.hpp"
#include "batch/results_file.hpp"
#include "cli/options.hpp"

namespace rocking::cli {

bool first_rank() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
        if (const char* v = std::getenv(name)) return std::string(v) == "0";
    return true;
}

std::unique_ptr<batch::Ranks> join_if_launched(const std::string& command) {
    if (!batch::launched_by_mpirun()) return nullptr;
    if (!batch::built_with_mpi()) {
        if (!first_rank()) throw EndQuietly{2};
        throw UsageError("started by mpirun, but this rocking was built without MPI, and each copy would run the whole " +
                         command + ": install libopenmpi-dev and openmpi-bin (make deps) and rebuild, or run it without "
                         "mpirun (--jobs N threads)");
    }
    return batch::join_cluster();
}

namespace {

[[noreturn]] void refuse_on_every_rank(const std::string& why) {
    if (!first_rank()) throw EndQuietly{2};
    throw UsageError(why);
}

// The exit status of a failed setup, as main() gives it without ranks.
int status_of(std::exception_ptr failure) {
    if (!failure) return 0;
    try {
        std::rethrow_exception(failure);
    } catch (const UsageError&) {
        return 2;
    } catch (...) {
        return 1;
    }
}

}  // namespace

void refuse_unshared(const std::string& command, const std::string& sharing) {
    if (!batch::launched_by_mpirun()) return;
    refuse_on_every_rank("does not share its work across the ranks of an MPI run, and each copy would run it whole "
                         "and print its own report: run 'rocking " + command + "' without mpirun (the commands that "
                         "run under mpirun: " + sharing + ")");
}

void refuse_piped_inputs(int argc, char** argv, const std::string& command) {
    if (!batch::launched_by_mpirun()) return;
    // The inputs come before the first option, as file_arguments reads them.
    for (int i = 2; i < argc && std::string(argv[i]).rfind("--", 0) != 0; ++i)
        if (batch::unshareable_by_ranks(argv[i]))
            refuse_on_every_rank(batch::unshareable_text(argv[i]) + " and give that file to mpirun -np K rocking " +
                                 command);
}

void parse_on_every_rank(const std::function<void()>& parse) {
    try {
        parse();
    } catch (const UsageError&) {
        if (batch::launched_by_mpirun() && !first_rank()) throw EndQuietly{2};
        throw;
    }
}

int agree_on_setup(batch::Ranks* ranks, std::exception_ptr failure, const std::string& command) {
    if (!ranks) {
        if (failure) std::rethrow_exception(failure);
        return 0;
    }
    const int status = status_of(failure);
    const bool first_failed = ranks->broadcast(std::to_string(status)) != "0";
    const int all = ranks->agree(status);
    if (all == 0) return 0;
    // Said before any rank ends: mpirun stops the job at the first non-zero exit, and the message with it.
    if (failure && (ranks->rank() == 0 || !first_failed)) {
        try {
            std::rethrow_exception(failure);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: %s%s\n", command.c_str(),
                         ranks->rank() == 0 ? "" : ("rank " + std::to_string(ranks->rank()) + ": ").c_str(), e.what());
        }
    }
    ranks->agree(0);
    return all;
}

void refuse_engine_files_over(const harness::NamedPath& output, const std::vector<harness::NamedPath>& inputs,
                              const std::vector<harness::NamedPath>& others) {
    std::vector<harness::NamedPath> written;
    for (const batch::EngineFile& f : batch::engine_files(output.path))
        written.push_back({f.what.empty() ? output.role : output.role + "'s " + f.what, f.path});
    written.insert(written.end(), others.begin(), others.end());
    try {
        harness::refuse_outputs_over_inputs(written, inputs);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

void refuse_engine_files_over(const Args& a, const std::string& flag, const std::vector<std::string>& other_flags,
                              const std::vector<std::string>& inputs) {
    if (!a.values.count(flag)) return;
    std::vector<harness::NamedPath> files, others;
    for (const std::string& path : inputs) files.push_back({"FILE", path});
    for (const std::string& other : other_flags)
        if (a.values.count(other)) others.push_back({other, a.values.at(other)});
    refuse_engine_files_over({flag, a.values.at(flag)}, files, others);
}

void set_threads_and_flush(batch::EngineOptions& engine, const Args& a, bool mpi) {
    engine.threads = a.values.count("--jobs") || !mpi ? jobs_option(a) : 1;
    if (const char* every = std::getenv("ROCKING_BATCH_FLUSH_SECONDS")) engine.flush_seconds = std::atof(every);
}

}  // namespace rocking::cli
