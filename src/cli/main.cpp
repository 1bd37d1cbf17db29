// rocking: the q-factor of a slender rigid block under step pulses, for engineers.
// One file per subcommand (src/cli/*.cpp), the help in help.cpp; this one
// dispatches, and turns errors into exit codes: 2 for a bad argument, 1 for
// a bad input file or an input the model refuses.
#include <iostream>
#include <optional>
#include <string>

#include "batch/pool.hpp"
#include "batch/ranks.hpp"
#include "cli/cluster_front.hpp"
#include "cli/help.hpp"
#include "cli/options.hpp"
#include "harness/atomic_file.hpp"

using namespace rocking::cli;

namespace {

// Every subcommand, and whether it shares its work across the ranks of an
// MPI run (on the batch engine): under mpirun the others are refused here,
// before they start, so that a new command cannot print K reports.
struct Subcommand {
    const char* name;
    int (*run)(int, char**);
    bool shares_ranks;
};

const Subcommand kSubcommands[] = {
    {"q", cmd_q, false},           {"response", cmd_response, false},   {"simulate", cmd_simulate, false},
    {"record", cmd_record, false}, {"collapse", cmd_collapse, false},   {"assess", cmd_assess, false},
    {"spectrum", cmd_spectrum, true}, {"fragility", cmd_fragility, true}, {"eq27", cmd_eq27, true},
    {"batch", cmd_batch, true},
};

std::string sharing_ranks() {
    std::string names;
    for (const Subcommand& s : kSubcommands)
        if (s.shares_ranks) names += (names.empty() ? "" : ", ") + std::string(s.name);
    return names;
}

int dispatch(const std::string& command, int argc, char** argv) {
    for (const Subcommand& s : kSubcommands) {
        if (command != s.name) continue;
        if (!s.shares_ranks) refuse_unshared(command, sharing_ranks());
        refuse_piped_inputs(argc, argv, command);
        return s.run(argc, argv);
    }
    throw UsageError(command.empty() ? "no command given" : "unknown command '" + command + "'");
}

int run(int argc, char** argv) {
    const std::string command = argc > 1 ? argv[1] : "";
    if (const std::optional<std::string> topic = help_request(argc, argv)) {
        try {
            const std::string text = help_text(*topic);
            if (first_rank()) std::cout << text;  // once under mpirun
            return 0;
        } catch (const UsageError& e) {
            if (first_rank()) std::cerr << "rocking: " << e.what() << "\n";
            return 2;
        }
    }
    try {
        return dispatch(command, argc, argv);
    } catch (const EndQuietly& e) {
        return e.status;  // under mpirun, a rank other than the one that said why
    } catch (const rocking::batch::OtherRankFailed& e) {
        return e.status;
    } catch (const rocking::batch::ThreadsUnavailable& e) {
        // --jobs asked for more threads than this system gives: the command line's to change.
        std::cerr << "rocking " << command << ": " << e.what() << "\n";
        return 2;
    } catch (const UsageError& e) {
        // Under mpirun every copy finds the same bad argument: rank 0 says it.
        if (rocking::batch::launched_by_mpirun() && !first_rank()) return 2;
        // The whole usage would bury the one line that says what is wrong.
        std::cerr << "rocking" << (command.empty() ? "" : " " + command) << ": " << e.what() << "\n";
        const std::string topic = topic_of(argc, argv);
        if (command.empty()) std::cerr << overview();
        else if (topic.empty()) std::cerr << "run 'rocking --help' for the commands\n";
        else std::cerr << "run 'rocking " << topic << " --help' for its usage\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "rocking " << command << ": " << e.what() << "\n";
        return 1;
    }
}

}  // namespace

// Output that never arrived (a full disk behind > FILE) exited 0 as if printed.
int main(int argc, char** argv) { return rocking::harness::finish_standard_output("rocking", run(argc, argv)); }

