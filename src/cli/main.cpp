// rocking: the q-factor of a slender rigid block under step pulses, for engineers.
// One file per subcommand (src/cli/*.cpp); this one prints the usage and
// dispatches, and turns errors into exit codes: 2 for a bad argument, 1 for
// a bad input file or an input the model refuses.
#include <iostream>
#include <string>

#include "batch/pool.hpp"
#include "batch/ranks.hpp"
#include "cli/cluster_front.hpp"
#include "cli/options.hpp"
#include "harness/atomic_file.hpp"

using namespace rocking::cli;

namespace {

const char* kUsage =
    "usage: rocking q --case I --x X [--pulses N] [--json]\n"
    "       rocking q --train A:d,A:d,... --x X [--json]\n"
    "       rocking response --case I --x X [--pulses N] [--q Q] [--steps K] [--json]\n"
    "       rocking simulate INPUT GEOMETRY [--model M] [--solver S] [--rtol R] [--atol A] [--criterion C]\n"
    "                        [--restitution E|housner] [--output FILE --dt DT] [--json]\n"
    "       rocking record info FILE [--json]\n"
    "       rocking record synth (--pulse A,fp,nu,gamma[,t0] | --stochastic SEED [--params K=V,...])\n"
    "                            --dt DT --duration D [--output FILE] [--json]\n"
    "       rocking record floor FILE --period T1 [--damping Z] --participation G [--unit U [--dt DT]]\n"
    "                            [--output FILE] [--json]\n"
    "       rocking collapse FILE --alpha A [--model M] [--solver S] [--rtol R] [--atol A] [--criterion C]\n"
    "                        [--restitution E|housner] [--json]\n"
    "       rocking assess FILE --alpha A (--height H | --half-height h) [--json]\n"
    "       rocking spectrum FILE --alpha A[,A...] [--p-min P] [--p-max P] [--points N] [--unit U [--dt DT]]\n"
    "                        [--jobs N] [--output CSV] [--png PNG] [--json]\n"
    "                        [--rows FILE [--resume]] [--quiet]\n"
    "       mpirun -np K rocking spectrum FILE --alpha A[,A...] ... [--rows FILE [--resume]]\n"
    "       rocking fragility FILE... --alpha A[,A...] --p P[,P...] [--q-max Q] [--points N]\n"
    "                        [--method grid|refine [--width W] [--robust-width R]] [--bootstrap K --seed S]\n"
    "                        [--unit U [--dt DT]] [--jobs N] [--output CSV] [--fits CSV] [--png PNG] [--json]\n"
    "                        [--nrml XML] [--rows FILE [--resume]] [--quiet]\n"
    "       mpirun -np K rocking fragility FILE... --alpha ... --p ... [--rows FILE [--resume]]\n"
    "       rocking eq27 FILE... [--alpha A,...] [--p-min P] [--p-max P] [--p-points N] [--q-max Q]\n"
    "                        [--bootstrap K --seed S] [--unit U [--dt DT]] [--jobs N] [--output CSV] [--png PNG]\n"
    "                        [--json] [--quiet]\n"
    "       mpirun -np K rocking eq27 FILE... [--alpha A,...] ...\n"
    "       rocking batch MANIFEST [--jobs N] [--output FILE] [--resume] [--quiet]\n"
    "       mpirun -np K rocking batch MANIFEST --output FILE [--resume]\n"
    "\n"
    "  --case I     input of Figure 3, I = 1..5 (amplitudes in PGA, durations in to)\n"
    "  --pulses N   repeat the case's pattern to N pulses (case 2, N = 6 is eq. 27)\n"
    "  --train ...  any train: amplitude:duration pairs, in units of PGA and to\n"
    "  --x X        x = p*to, X >= 1e-150\n"
    "  --q Q        response at this q instead of the collapse q\n"
    "  --steps K    number of time steps over [0, t_fin] (default 20)\n"
    "  --json       machine-readable output\n"
    "q and response: linearised eq. 3, one corner, no impact, collapse theta(t_fin) = alpha.\n"
    "\n"
    "simulate: INPUT is --case I [--pulses N] or --train A:d,...  with --to T (s) or --x X, and the\n"
    "  amplitude as --pga G (in g), --q Q (PGA = Q alpha g) or --rd R (PGA = q_I(x) R alpha g);\n"
    "  or --one-sine --ap A (in g, at most 1e9 times the uplift threshold) --wp W (rad/s);\n"
    "  or --record FILE (as for record FILE, with --record-dt for --dt), piecewise linear between\n"
    "  samples, as recorded or scaled to --pga G (in g) or --q Q (PGA = Q alpha g).\n"
    "  GEOMETRY is --alpha A with --p P (rad/s), --half-height h (m, the H of eq. 2) or --height H (m).\n"
    "  --model linearised|full (default linearised); --solver exact|dopri5|rkf78|bulirsch-stoer|gsl-rk8pd\n"
    "  (default exact for linearised, dopri5 for full); --rtol in [100 eps, 1) (default 1e-6);\n"
    "  --atol in rad on theta and rad/s on theta', as ode45's AbsTol (default rtol times alpha; ode45's\n"
    "  default is 1e-6), in [100 eps, 1) alpha; the ODE solvers' tolerances, stated in every output;\n"
    "  --criterion final-rotation|peak-rotation|overturning (default final-rotation, the paper's);\n"
    "  --restitution on angular velocity at impact (default 1) or housner (1 - 1.5 sin^2 alpha);\n"
    "  --output FILE writes t,theta/alpha,theta'/(alpha p) every --dt seconds (default 0.01), at most\n"
    "  10^6 rows: a --dt that could write more over t_fin and the free rocking after it (up to 200/p s)\n"
    "  is refused.\n"
    "\n"
    "record FILE: ESM/ITACA ASCII or PEER AT2 (by content); a one-column (add --dt DT --unit U) or\n"
    "  two-column time,acceleration file (add --unit U), U = g, m/s2 or cm/s2; decimal commas are refused.\n"
    "  FILE may be a pipe, a FIFO or /dev/stdin: read once, up to 256 MiB, lines up to 1 MiB, 10 s of\n"
    "  silence at most.\n"
    "record synth: a synthetic record, its generator and parameters stated (docs/synthetic.md).\n"
    "  --pulse: Mavroeidis & Papageorgiou (2003) velocity pulse, A (m/s), fp (Hz, period 1/fp), nu (rad),\n"
    "  gamma > 1, t0 (s, the envelope's peak; default gamma/(2 fp): the pulse starts at t = 0); the\n"
    "  acceleration is its exact derivative. --stochastic SEED (1 to 2^32 - 1): Rezaeian & Der Kiureghian\n"
    "  (2008) modulated filtered white noise (GSL mt19937), high-passed at fc; --params alpha1,alpha2,alpha3\n"
    "  or Ia (m/s), D5_95 (s), tmid (s), and fmid (Hz), fprime (Hz/s), zeta, fc (Hz); defaults: the sample\n"
    "  means of Rezaeian & Der Kiureghian (2010), fc = 0.2 Hz (sources: docs/synthetic.md). --output FILE\n"
    "  writes t,acceleration (m/s^2) under '#' lines naming the generator and parameters: record info\n"
    "  FILE --unit m/s2 reads it.\n"
    "record floor: the absolute acceleration of a floor (for an element at height, as a parapet on a roof),\n"
    "  the building idealised as its first mode: a linear oscillator of period T1 (s) and damping ratio Z\n"
    "  in [0, 1) (default 0.05) driven by the record, with the floor's participation G = Gamma phi(z) in\n"
    "  that mode: a_f = a_g + G D'', D the oscillator's displacement relative to the ground\n"
    "  (docs/floor_motion.md). Exact for the record read linear between samples (Nigam & Jennings 1969),\n"
    "  at the record's samples: the same dt and count. T1 <= 2 dt is refused (the resonance above the\n"
    "  record's Nyquist frequency). Prints the ground's and the floor's PGA; --output FILE writes\n"
    "  t,acceleration (m/s^2) under '#' lines stating the model and the ground record: record info,\n"
    "  simulate --record, ... read it with --unit m/s2.\n"
    "collapse: the first p (rad/s), raising p from 0.3 by 1 %, at which the record overturns a block of\n"
    "  slenderness A (Table 1's search; not a bound: a lower p may overturn it too). Defaults:\n"
    "  linearised, exact solver, Housner restitution, overturning.\n"
    "assess: the block's p (eqs. 2, 4), the record's to_5 (eq. 31), q from eq. 27, the record's\n"
    "  q = PGA/(alpha g), and the paper's check: it passes when the record's q < eq. 27's (not a proof\n"
    "  of safety: eq. 27 is not conservative everywhere; simulate --record follows the block).\n"
    "spectrum: for each alpha, max |theta|/alpha and the three criteria over a log grid of p (default\n"
    "  200 points from 0.3 to 30 rad/s, and a second grid offset by half a step), and the overturning\n"
    "  intervals in p: ends bisected to 1e-6 relative, each confirmed by gsl-rk8pd at rtol 1e-13 or\n"
    "  flagged ill-conditioned (the record times 1 +- 1e-13 flips it), beside Table 1's first collapse.\n"
    "  Islands narrower than half a step may be missed (Table 1's bracket joins the grid). Table 1's\n"
    "  model (linearised, exact solver, Housner restitution, overturning). --output writes the grid as\n"
    "  CSV, --png plots it (gnuplot: max |theta|/alpha, the overturned runs, the block height H on the top\n"
    "  axis, the --mark blocks); --unit and --dt as for record info. Each alpha a job of the batch\n"
    "  engine: --jobs N threads (under mpirun 1 a rank unless --jobs); --rows FILE keeps each alpha's study\n"
    "  as a row, and --resume completes an interrupted one from it; --quiet: no progress line. The output\n"
    "  does not depend on the threads, the ranks or a resume.\n"
    "fragility: for each block (every --alpha with every --p, rad/s) and record, the record scaled so that\n"
    "  q = PGA/(alpha g) runs over a log grid (default 100 points from 1 to --q-max 20, and a second grid\n"
    "  offset by half a step), every overturning interval in q (ends bisected to 1e-6 relative), the first\n"
    "  collapse q or a censored point at q-max; then the lognormal fit (median, beta; Baker 2015), with a\n"
    "  bootstrap interval over records (--bootstrap K resamples, GSL mt19937 from --seed), and the\n"
    "  empirical curve. Table 1's model. --output writes one row per block and record as CSV, --fits CSV\n"
    "  one per block (and capacity) with the fit's median, beta and bootstrap ends, --png plots each\n"
    "  block's fitted curves, empirical points and bootstrap band (gnuplot). --jobs N\n"
    "  threads (default: the cores this process may use); the results do not depend on it. Each IDA is a\n"
    "  job of the batch engine: under mpirun the ranks share them (one thread a rank unless --jobs) and\n"
    "  rank 0 prints the same bytes; --rows FILE keeps the IDAs as FILE.partial, renamed when complete, and\n"
    "  --resume completes an interrupted study, refusing another study or an edited record. Progress on\n"
    "  stderr when a terminal, unless --quiet (docs/batch.md). --method refine (issue 39) finds every\n"
    "  island and gap wider than --width W in ln q (default 1e-5, in [1e-7, 0.1]) instead of the grid's,\n"
    "  and adds each record's first overturning (its bracket and check), first robust collapse (the first\n"
    "  interval wider than --robust-width R, default 5e-3) and overturned share per band; the fit takes\n"
    "  the first overturning (docs/fragility.md). The bootstraps draw the records in the order of their\n"
    "  samples' SHA-256, whatever the order given. --nrml XML writes each block's fit as an OpenQuake NRML\n"
    "  0.5 continuous fragility function (PGA in g, limit state overturning; docs/fragility.md).\n"
    "eq27: each record's first collapse q (fragility's IDA) on every block (--alpha, default 0.05..0.25 by\n"
    "  0.05, with --p-points p log-spaced from --p-min to --p-max, default 10 from 0.5 to 10 rad/s) against\n"
    "  eq. 27 at x = p to_k: per to_k the share of non-conservative cases (collapse q below eq. 27's; a\n"
    "  record censored at --q-max counts as conservative) with its 95 % Wilson interval (cases taken as\n"
    "  independent) and, with --bootstrap K --seed S, a 90 % bootstrap over records. --output writes the\n"
    "  map: per block, the records non-conservative for each to_k; --png plots the shares with their\n"
    "  intervals and every case's q against eq. 27's at to_5 (gnuplot). --p-points 1 is one p, --p-min (and\n"
    "  --p-max, if given, equal to it). A repeated alpha or record (the same samples, whatever the path)\n"
    "  is refused: its cases would count twice. --jobs N, mpirun and --quiet as for fragility.\n"
    "batch: a CSV manifest, one job a row (kind simulate|collapse|ida|spectrum, record, alpha, p|height|\n"
    "  half_height, scaling q=Q|pga=G, model, solver, rtol, atol, restitution, criterion, q_max, points,\n"
    "  p_min, p_max; relative record paths from the manifest's folder; an empty cell takes the default of\n"
    "  the command that runs that study alone): one results row per job in the manifest's order, whatever\n"
    "  the threads (--jobs N, default the cores) or ranks (mpirun; 1 thread a rank unless --jobs); a job\n"
    "  that fails gets its error in its row and the rest run. --output FILE is written as FILE.partial\n"
    "  and renamed when complete; --resume completes an interrupted one (Ctrl-C, SIGTERM, a kill), refusing\n"
    "  a changed manifest. Progress on stderr when a terminal, unless --quiet. Exit 0, or 3 when some job\n"
    "  failed (docs/batch.md).\n"
    "mpirun: spectrum, fragility, eq27 and batch share their work across the ranks; the other commands\n"
    "  refuse to start under mpirun (exit 2), as does an input on standard input or a pipe, which the ranks\n"
    "  cannot share (save it to a file).\n";

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
    // "rocking simulate --help" asks for the usage, not for an option named
    // --help (no option takes a value spelled like this).
    bool help = command == "help";
    for (int i = 1; i < argc; ++i) help = help || std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h";
    if (help) {
        if (first_rank()) std::cout << kUsage;  // once under mpirun
        return 0;
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
        if (command.empty()) std::cerr << kUsage;
        else std::cerr << "run 'rocking --help' for the usage\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "rocking " << command << ": " << e.what() << "\n";
        return 1;
    }
}

}  // namespace

// Output that never arrived (a full disk behind > FILE) exited 0 as if printed.
int main(int argc, char** argv) { return rocking::harness::finish_standard_output("rocking", run(argc, argv)); }

