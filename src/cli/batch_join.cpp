// rocking batch join SHARD... --output FILE: the results of one run from the
// complete files of a batch's N shards (batch/shard.hpp, docs/batch.md).
#include <cstdio>
#include <string>
#include <vector>

#include "batch/cluster.hpp"
#include "batch/shard.hpp"
#include "cli/help.hpp"
#include "cli/options.hpp"

namespace rocking::cli {

int cmd_batch_join(int argc, char** argv) {
    if (batch::launched_by_mpirun()) throw UsageError("join runs in one process: not under mpirun");
    // rocking batch join A B ... --output FILE [--quiet]: the files, then the options.
    std::vector<std::string> shards;
    int at = 3;
    for (; at < argc && std::string(argv[at]).rfind("--", 0) != 0; ++at) shards.push_back(argv[at]);
    if (shards.empty()) throw UsageError("join: give the shards' results files, then --output FILE");
    bool quiet = false;
    std::string output;
    for (; at < argc; ++at) {
        const std::string flag = argv[at];
        if (flag == "--quiet") quiet = true;
        else if (flag == "--output" && at + 1 < argc) output = argv[++at];
        else if (flag == "--output") throw UsageError("--output: needs a FILE");
        else throw UsageError("join: unknown option '" + flag + "' (join takes --output FILE and --quiet)");
    }
    if (output.empty()) throw UsageError("join: --output FILE is required (the joined results)");
    const batch::JoinOutcome o = batch::join_shards(shards, output);
    if (!quiet)
        std::fprintf(stderr, "rocking batch join: %zu shards, %zu jobs, %zu failed; results in %s\n", o.shards, o.jobs,
                     o.failed, output.c_str());
    return 0;
}

}  // namespace rocking::cli
