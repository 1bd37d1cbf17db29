// What the commands that run on the batch engine (rocking batch, fragility,
// spectrum, eq27) share under mpirun: the same binary started K times, each
// copy parsing the same command line, so that each finds the same errors;
// rank 0 alone says them, and every rank ends with the same status
// (docs/batch.md).  The other commands refuse to start under mpirun.
#pragma once

#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "batch/engine.hpp"
#include "batch/ranks.hpp"
#include "cli/options.hpp"
#include "harness/output_paths.hpp"

namespace rocking::cli {

// Under mpirun, before MPI is started: whether this copy is rank 0, from the
// launcher's variables (true when not under mpirun).
bool first_rank();

// The ranks of an MPI run when mpirun started this process, null otherwise.
// Under mpirun with a build without MPI each copy would run the whole study:
// rank 0 throws UsageError saying so, the others end with status 2 silently
// (through EndQuietly).
std::unique_ptr<batch::Ranks> join_if_launched(const std::string& command);

// A copy other than rank 0 ending with `status` after rank 0 said why.
struct EndQuietly {
    int status;
};

// Under mpirun, a command that does not share its work across the ranks:
// each copy would run it whole and print its own report.  Refused, said once:
// rank 0 throws UsageError, the others EndQuietly{2}.  `sharing`: the
// commands that do share, named in the message.
void refuse_unshared(const std::string& command, const std::string& sharing);

// Under mpirun, an input named before the first option (a record, batch's
// manifest) that the ranks cannot share (batch::unshareable_by_ranks: a pipe,
// /dev/stdin).  Refused as refuse_unshared does, the file named.
void refuse_piped_inputs(int argc, char** argv, const std::string& command);

// `parse` run on every copy: a UsageError is rank 0's to say; the others
// throw EndQuietly{2}.
void parse_on_every_rank(const std::function<void()>& parse);

// After each rank's setup (reading its inputs), `failure` null where it went
// well: 0 when every rank is ready.  Otherwise the status to end with (2 for
// a UsageError, 1 for any other failure), the
// failure said once (by rank 0, or by a rank that failed where rank 0 did
// not) before any rank ends.  Without ranks a failure is rethrown.
int agree_on_setup(batch::Ranks* ranks, std::exception_ptr failure, const std::string& command);

// Before any work: none of the files the engine writes for its results at
// `output` (batch::engine_files: the results, their .partial file, its
// .partial.state and the state's .tmp), named after output.role ("--rows's
// partial file"), is one of `inputs` or one of the command's `others`
// outputs: the engine would replace or remove it (spectrum REC.partial.state
// --rows REC removed the record).  Throws UsageError naming both.
void refuse_engine_files_over(const harness::NamedPath& output, const std::vector<harness::NamedPath>& inputs,
                              const std::vector<harness::NamedPath>& others = {});
// The same for a command's --rows (`flag`), the inputs its FILEs, the others
// the outputs `other_flags` name; nothing when `flag` is not given.
void refuse_engine_files_over(const Args& a, const std::string& flag, const std::vector<std::string>& other_flags,
                              const std::vector<std::string>& inputs);

// What every front end of the engine sets alike from its command line: its
// threads (--jobs, by default the cores; under mpirun one a rank unless
// --jobs, each rank a process on a core as MPI runs are laid out), and how
// often the rows reach the disk (results_file.hpp: every second, or as the
// tests ask through ROCKING_BATCH_FLUSH_SECONDS, to be killed between many flushes).
void set_threads_and_flush(batch::EngineOptions& engine, const Args& a, bool mpi);

}  // namespace rocking::cli
