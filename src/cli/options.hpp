// The command line's shared pieces: options, their errors and the inputs they
// name (JSON: json_text.hpp).  Each subcommand is one file (q.cpp, response.cpp, ...)
// over the library; main.cpp only dispatches.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/atomic_file.hpp"
#include "harness/table.hpp"
#include "pulse/pulse_train.hpp"
#include "dynamics/simulate.hpp"
#include "records/collapse.hpp"
#include "records/measures.hpp"
#include "records/record.hpp"
#include "qfactor/superposition.hpp"

namespace rocking::cli {

// A bad argument: main() prints it on one line and exits 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Args {
    std::map<std::string, std::string> values;
    bool json = false;
};

// A parameter's number by numerics::parameter_number's rules (blanks around
// it ignored; finite, normal or 0), its problem a UsageError naming the flag.
double number(const std::string& flag, const std::string& text);
double restitution_option(const std::string& text);
// --restitution E|housner into a study's model (default: Housner's, Table 1's).
void restitution_into(const Args& a, records::CollapseOptions& model);
// With --floor, what a study's inputs then are (every record replaced by its
// floor's motion, the model named; q and to_k the floor's), for
// IdaOptions::input_note; empty without it.
std::string floor_input_note(const Args& a);
// --friction's value, in (0, 1e6]; a UsageError otherwise.
double friction_option(const Args& a);
// --friction MU into a search's model (the sliding-rocking model, issue 41);
// refused beside --restitution, which that model's impact law replaces.
void friction_into(const Args& a, records::CollapseOptions& model);
std::string smallest_tolerance();
double rtol_option(const std::string& text);
void tolerance_options(const std::map<std::string, std::string>& values, double alpha,
                       dynamics::SolverOptions& solver);
// A whole number in [lo, hi]; anything else is "FLAG: must be a whole number
// from lo to hi (got TEXT)".
int integer(const std::string& flag, const std::string& text, int lo, int hi);
// "1,2.5,-3": every comma-separated piece a finite number.
std::vector<double> number_list(const std::string& flag, const std::string& text);
// "key=value,key=value": each key among `keys`, at most once, each value a finite number.
std::map<std::string, double> key_values(const std::string& flag, const std::string& text,
                                         const std::vector<std::string>& keys);
// A random generator's seed: a whole number in [1, 2^32 - 1].
std::uint64_t seed_option(const std::string& flag, const std::string& text);
// --bootstrap K --seed S of the studies (fragility, eq27): K = 0 (the
// default: none) or 2 to 100000 resamples, refused before any work (a
// percentile interval of one resample is no interval), with the seed the
// interval is reproduced from.
struct Bootstrap {
    int resamples = 0;
    std::uint64_t seed = 0;
};
Bootstrap bootstrap_options(const Args& a);
// How a study finds its set of collapse (issue 39): --method grid (the
// default) or refine, with refine's --width W (default 1e-5) and
// --robust-width R (default 5e-3), both in ln of the study's parameter
// (`unit`: "q" or "p"), refused with the grid and out of [1e-7, 0.1] and
// [1e-7, 1].
struct MethodChoice {
    bool refine = false;
    double width = 1e-5, robust_width = 5e-3;
};
MethodChoice method_options(const Args& a, const std::string& unit);
// The batch engine's threads: --jobs N (1 to 4096), by default the cores
// this process may use.  The results do not depend on it.
int jobs_option(const Args& a);
std::string file_argument(int argc, char** argv, int at, const std::string& usage);
// Every argument from argv[2] up to the first option; sets first_option to its
// index.  Throws UsageError (with the usage) when there is none.
std::vector<std::string> file_arguments(int argc, char** argv, int& first_option, const std::string& usage);
Args parse(int argc, char** argv, int first, const std::vector<std::string>& allowed);
// argv without --resume and --quiet, the batch engine's switches of a study
// on it (fragility, spectrum): parse() knows only --json among the options
// without a value.
std::vector<char*> without_engine_switches(int argc, char** argv, bool& resume, bool& quiet);
// Before any work (issue 38): the outputs the options in output_flags name
// are not empty, neither one of the input files (UsageErrors) nor one another,
// and each can be written (a runtime_error, as a failed write at the end was).
void check_outputs(const Args& a, const std::vector<std::string>& output_flags, const std::vector<std::string>& inputs,
                   const std::string& input_role = "FILE");
// Refuses a run the solvers cannot follow (dynamics::unresolvable_run: p
// times the input's duration above 1e9), naming those of `culprits` given
// on the command line (a record's --dt, --p, ...: a UsageError), or else
// the file the duration came from.
void refuse_unresolvable_run(double p, double duration, const Args& a, const std::vector<std::string>& culprits,
                             const std::string& path);
// A record's samples as "t,acceleration" lines (m/s^2, to the last bit), the
// body of a two-column record file under its '#' lines: what record synth
// and record floor write, and record info reads back with --unit m/s2.
void write_record_samples(harness::AtomicFile& out, const records::Record& r);
// table written to path (atomically), a failure named as --output's.
void write_output(const harness::Table& table, const std::string& path);

// simulate --output's note on its rows: every dt while the run lasts, so a
// dt above the run's length leaves the row at t = 0 alone; the last row's t.
std::string rows_note(double dt, double t_fin, double last_t);
PulseTrain train_from(const Args& a, std::string& equation);
double x_from(const Args& a);
// Four decimals (%.4f); %.4e at or above 1e9 and below 1e-3 (not 0), where
// four decimals would print 0.0000 or a run of digits.
std::string four(double v);
// v to n significant digits (%.*g), as the messages and tables of several commands print it.
std::string significant(double v, int n);
records::HalfPeriods half_periods_of(const records::Record& r, const std::string& path);
// Refuses, naming the file, a record whose velocity (sum of |a| dt) overflows a double.
void refuse_overflowing_velocity(const records::Record& r, const std::string& path);
records::Record load_record(const std::string& path, const Args& a, const std::string& dt_flag = "--dt");

// The subcommands, one file each; argv[1] is the subcommand's name.
int cmd_q(int argc, char** argv);
int cmd_response(int argc, char** argv);
int cmd_simulate(int argc, char** argv);
int cmd_record(int argc, char** argv);
int cmd_collapse(int argc, char** argv);
int cmd_assess(int argc, char** argv);
int cmd_record_synth(int argc, char** argv);  // rocking record synth (synth.cpp)
int cmd_record_floor(int argc, char** argv);  // rocking record floor (floor.cpp)
int cmd_spectrum(int argc, char** argv);
int cmd_fragility(int argc, char** argv);
int cmd_eq27(int argc, char** argv);
int cmd_batch(int argc, char** argv);
int cmd_batch_join(int argc, char** argv);

}  // namespace rocking::cli
