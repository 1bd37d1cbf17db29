// Each command's help: its synopsis, what it does and every option its
// parse() takes, with units and defaults (tests/help_options_test.sh fails
// on an option a command takes and its help does not name).  The
// definitions several commands share are help.cpp's.
#include "cli/help_entries.hpp"

namespace rocking::cli {

namespace {

const char* kQ = R"(
rocking q --case I --x X [--pulses N] [--json]
rocking q --train A:d,A:d,... --x X [--json]
)";
const char* kQDetails = R"(
The collapse q of a pulse input on the paper's closed form: linearised eq. 3, rocking on one
corner, no impact, collapse when theta(t_fin) = alpha (eqs. 12-28; a train by superposition, S2).
It says whether that form holds at that q: the first pulse lifts the block, and theta stays above
0 up to t_fin (below 0 is outside the model: rocking simulate follows the impacts).
  --case I          the input of Figure 3, I = 1..5 (amplitudes in units of PGA, durations in to)
  --pulses N        the case's pattern repeated to N pulses, 1 to 1000 (default 2, the case itself);
                    case 2 with N = 6 is eq. 27, case 4 with N = 6 eq. 28 (corrected)
  --train A:d,...   any train of steps: amplitude:duration pairs, in units of PGA and to
  --x X             x = p to (dimensionless), X >= 1e-150
  --json            machine-readable output
)";

const char* kResponse = R"(
rocking response (--case I [--pulses N] | --train A:d,...) --x X [--q Q] [--steps K] [--json]
)";
const char* kResponseDetails = R"(
The motion up to t_fin on rocking q's closed form (linearised eq. 3, one corner, no impact):
rows t/to, theta/alpha, theta'/(alpha p), at the collapse q (evaluated exactly) or at --q. Off the
collapse q theta grows like e^(x t/to): the rows stop where it leaves the double range, saying so.
  --case I, --pulses N, --train A:d,...   the input, as for rocking q
  --x X             x = p to (dimensionless), X >= 1e-150
  --q Q             the response at q = Q (> 0) instead of at the collapse q
  --steps K         time steps over [0, t_fin], 1 to 10^6 (default 20)
  --json            machine-readable output
)";

const char* kSimulate = R"(
rocking simulate INPUT BLOCK [--paper] [--model M] [--solver S] [--rtol R] [--atol A]
                 [--criterion C] [--restitution E|housner] [--output FILE [--dt DT]]
                 [--friction MU | IMPERFECT] [--json]
)";
const char* kSimulateDetails = R"(
One block under a pulse train, a one-sine pulse or a record, with impacts, the free rocking
after the input followed; the outcome under --criterion and under each of the three criteria.
INPUT, exactly one of:
  --case I [--pulses N] | --train A:d,...   a step-pulse train, as for rocking q, of length
                    --to T (s, the half-period to) or --x X (to = X/p), and amplitude --pga G (g),
                    --q Q (PGA = Q alpha g) or --rd R (PGA = q_I(x) R alpha g, q_I(x) the train's
                    closed-form collapse q at x: R < 1 lies below it)
  --one-sine --ap A --wp W   a one-sine pulse (Makris): amplitude A (g, at most 1e9 times the
                    uplift threshold), circular frequency W (rad/s, at least 1e-6 p)
  --record FILE     a record (see Records), read linear between samples, as recorded or scaled to
                    --pga G (g) or --q Q (PGA = Q alpha g); a plain-text one with --unit U and, for
                    one column, --record-dt DT (s); --floor T1,G[,zeta] (see A floor) takes the
                    motion of a floor instead
BLOCK (see The block), alpha in (0, pi/4):
  --thickness B --height H   the block as built, full thickness and full height (m); or
                    --thickness B --half-height h (m)
  --alpha A         the slenderness (rad), with one of --p P (rad/s), --half-height h (m, the H of
                    eq. 2) or --height H (m). Given both ways (--thickness with --alpha or --p),
                    the two must agree to 0.1 %
The model (default: see The model):
  --paper           the paper's Section 3 setting: restitution 1 and the final-rotation criterion
                    (refused beside --restitution or --criterion)
  --model M         linearised (eq. 3, the default) or full (eq. 1)
  --solver S        exact (closed form between events, linearised only; the default there),
                    dopri5 (the default for full), rkf78, bulirsch-stoer or gsl-rk8pd
  --rtol R          the ODE solvers' relative tolerance, in [100 eps, 1) (default 1e-6)
  --atol A          their absolute tolerance, rad on theta and rad/s on theta' as ode45's AbsTol
                    (default R alpha; ode45's is 1e-6), in [100 eps, 1) alpha; both are stated in
                    every output
  --criterion C     overturning (the default), final-rotation (|theta(t_fin)| >= alpha, the
                    paper's) or peak-rotation (|theta| reaches alpha during the input)
  --restitution E   theta' after an impact over theta' before it, in [0, 1], or housner
                    (1 - 1.5 sin^2 alpha, the default)
  --friction MU     the base on Coulomb friction MU, in (0, 1e6]: the sliding-rocking model
                    (full equations; rest, slide, rock and slide-rock; impacts without rebound,
                    the new corner stuck or slipping), its own event-driven Dormand-Prince
                    solver at --rtol/--atol (default 1e-9); adds the base's slip (m), the time in
                    each regime and the energy balance; --output adds the slip (m), its rate
                    and the regime to each row; without --model, --solver, --restitution and
                    --paper (docs/sliding.md)
  --lean RAD, --out-of-plumb RAD, --fc MPA [--density KG/M3]   an imperfect block (see Beyond
                    the paper's block)
Output:
  --output FILE     writes t (s), theta/alpha, theta'/(alpha p) every --dt DT s (default 0.01), at
                    most 10^6 rows: a --dt that could write more over t_fin and the free rocking
                    after it (up to 200/p s) is refused
  --json            machine-readable output
)";

const char* kRecordInfo = R"(
rocking record info FILE [--unit U [--dt DT]] [--json]
)";
const char* kRecordInfoDetails = R"(
A record's PGA (m/s^2 and g), PGV (m/s), Amax (m/s, the area of its largest pulse) and its
eleven half-periods to_1..to_11 (s): its pulses' (to_3, to_4: eqs. 29, 30; to_5 = pi PGV/PGA,
eq. 31), Fourier and CWT measures. A CWT half-period at the edge of the band scanned (0.1 Hz to
min(25 Hz, 0.25/dt)) is warned of.
  --unit U          a plain-text record's unit: g, m/s2 or cm/s2
  --dt DT           a one-column record's sampling step (s)
  --json            machine-readable output
)";

const char* kRecordSynth = R"(
rocking record synth (--pulse A,fp,nu,gamma[,t0] | --stochastic SEED [--params K=V,...])
                     --dt DT --duration D [--output FILE] [--json]
)";
const char* kRecordSynthDetails = R"(
A synthetic record, its generator and parameters stated (docs/synthetic.md); prints its PGA,
PGV and to_5.
  --pulse A,fp,nu,gamma[,t0]   Mavroeidis & Papageorgiou (2003) velocity pulse: A (m/s), fp (Hz,
                    period 1/fp), nu (rad), gamma > 1, t0 (s, the envelope's peak; default
                    gamma/(2 fp): the pulse starts at t = 0); the acceleration is its exact
                    derivative
  --stochastic SEED Rezaeian & Der Kiureghian (2008) modulated filtered white noise (GSL mt19937
                    from SEED, 1 to 2^32 - 1), high-passed at fc
  --params K=V,...  the stochastic model's parameters: alpha1,alpha2,alpha3 (all three) or Ia (m/s),
                    D5_95 (s), tmid (s); fmid (Hz), fprime (Hz/s), zeta, fc (Hz); defaults: the
                    sample means of Rezaeian & Der Kiureghian (2010), fc = 0.2 Hz
  --dt DT           the sampling step (s, > 0); a frequency of the generator at or above 1/(2 DT)
                    is refused, one with fewer than 10 samples a period warned of
  --duration D      the record's length (s, > 0)
  --output FILE     writes t (s), acceleration (m/s^2) under '#' lines naming the generator and its
                    parameters: rocking record info FILE --unit m/s2 reads it
  --json            machine-readable output
)";

const char* kRecordFloor = R"(
rocking record floor FILE --period T1 --participation G [--damping Z] [--unit U [--dt DT]]
                     [--output FILE] [--json]
)";
const char* kRecordFloorDetails = R"(
The absolute acceleration of a floor, for an element at height (a parapet on a roof), the
building idealised as its first mode: a linear oscillator of period T1 and damping ratio Z driven
by the record FILE, a_f = a_g + G D'' with D the oscillator's displacement relative to the ground
(docs/floor_motion.md). Exact for the record read linear between samples (Nigam & Jennings 1969),
at the record's samples: the same dt and count, without the building's free vibration after the
record's end (its amplitude there is printed). Prints the ground's and the floor's PGA.
  --period T1       the building's first-mode period (s), above 2 dt (the record's Nyquist limit)
                    and at most 20 s
  --participation G the floor's participation Gamma phi(z) in that mode, in [-5, 5]: 0 at the
                    base; 3N/(2N + 1) at the roof of N equal storeys with a linear mode shape
  --damping Z       the damping ratio, in [0, 1) (default 0.05)
  --unit U, --dt DT the ground record's unit and step, for a plain-text record (see Records)
  --output FILE     writes t (s), acceleration (m/s^2) under '#' lines stating the model and the
                    ground record: --unit m/s2 reads it (record info, simulate --record, ...)
  --json            machine-readable output
The other commands take the same floor with --floor T1,G[,zeta], without the file.
)";

const char* kCollapse = R"(
rocking collapse FILE (--alpha A | --thickness B (--height H | --half-height h)) [--model M]
                 [--solver S] [--rtol R] [--atol A] [--criterion C] [--restitution E|housner | --friction MU] [IMPERFECT]
                 [--floor T1,G[,zeta]] [--unit U [--dt DT]] [--json]
)";
const char* kCollapseDetails = R"(
Table 1's search: the first pulsation p (rad/s) at which the record overturns a block of
slenderness alpha, p raised from 0.3 by 1 % up to 30 rad/s, then bisected to 1e-4 relative inside
the last step. Not a bound: a lower p may overturn the block too (docs/findings.md, T1b; rocking
spectrum finds every interval).
  --alpha A         the slenderness (rad), in (0, pi/4)
  --thickness B --height H   the block as built, full thickness and height (m), or with
                    --half-height h: its alpha = atan(B/H) is searched and its own p printed beside
                    (an --alpha given too must agree to 0.1 %)
  --model M         linearised (eq. 3, the default) or full (eq. 1)
  --solver S        exact (the default; linearised only), dopri5 (the default for full), rkf78,
                    bulirsch-stoer or gsl-rk8pd
  --rtol R, --atol A   the ODE solvers' tolerances, as for rocking simulate (default 1e-6, R alpha)
  --criterion C     overturning (the default), final-rotation or peak-rotation
  --restitution E   a factor in [0, 1] or housner (the default)
  --friction MU     a base that slides (see Beyond the paper's block); without --restitution
  --lean RAD, --out-of-plumb RAD, --fc MPA [--density KG/M3]   an imperfect block (see Beyond
                    the paper's block)
  --unit U, --dt DT a plain-text record's unit and step (see Records)
  --floor T1,G[,zeta]   the motion of a floor of a building in place of the ground's (see A floor)
  --json            machine-readable output
)";

const char* kAssess = R"(
rocking assess FILE... (--thickness B (--height H | --half-height h)
                       | --alpha A (--height H | --half-height h | --p P))
               [--width W] [--restitution E|housner | --friction MU] [IMPERFECT] [--floor T1,G[,zeta]] [--unit U [--dt DT]]
               [--png PNG] [--json]
)";
const char* kAssessDetails = R"(
The engineer's check of one block against one record or several (1 to 1000 FILEs), the model
named in the output. For each record:
  - the paper's eq. 27 check: x = p to_5 (to_5 = pi PGV/PGA, eq. 31), q_27 = eq. 27 at x, and the
    record's q = PGA/(alpha g); it PASSES when q < q_27. Ratio q/q_27 and margin 1 - q/q_27
    (positive: it passes). Not a proof of safety: eq. 27 is not conservative everywhere
    (docs/findings.md, F11);
  - the run on the record as recorded: the peak |theta|/alpha during the input, and whether the
    block overturns, during the input or in the free rocking after it;
  - the record scaled (an IDA over q from 1 to 20, or to twice the record's q where higher, at
    most 1e4; the refine search at width W): the scale factors (q over the record's q) at which
    the block first overturns and first robustly collapses (the first interval of overturning
    wider than 5e-3 in ln q), or censored at the search's end;
  - where the outcome changes among the blocks of its alpha, larger (lower p) and smaller (higher
    p): the record's rocking spectrum at alpha (p from 0.3 to 30 rad/s, refine search at width W),
    the nearest overturning p on each side for a block the spectrum holds safe, the ends of its
    overturning interval for a block inside one, each as p (rad/s) and the height
    H = 2 R cos(alpha), R = 3 g/(4 p^2);
  - with two records or more: the lognormal fragility over their first overturnings (median q,
    beta) and each record's probability of overturning at its own q.
  --thickness B --height H   the block as built, full thickness and full height (m); or
                    --thickness B --half-height h (m)
  --alpha A         the slenderness (rad), with one of --height H (m), --half-height h (m, the H of
                    eq. 2) or --p P (rad/s). Given both ways (--thickness with --alpha or --p), the
                    two must agree to 0.1 %. alpha in (0, pi/4)
  --width W         the refine searches' width, in ln q and ln p, in [1e-7, 0.1] (default 1e-3):
                    an island of overturning narrower than W may be missed
  --restitution E   the restitution on angular velocity at impact, in [0, 1], or housner (the default)
  --friction MU     a base that slides (see Beyond the paper's block); without --restitution
  --lean RAD, --out-of-plumb RAD, --fc MPA [--density KG/M3]   an imperfect block (see Beyond
                    the paper's block)
  --unit U, --dt DT a plain-text record's unit and step (see Records)
  --floor T1,G[,zeta]   the motion of a floor of a building in place of the ground's (see A floor)
  --png PNG         the check on one record (gnuplot): above, max |theta|/alpha of 300 runs of
                    the record scaled against q, the IDA's overturning intervals, the record's
                    q, eq. 27's q and the first overturning and robust collapse, the scale
                    factor on the top axis; below, the record's spectrum at the block's alpha
                    with the block marked (as spectrum --mark); with one FILE only
  --json            machine-readable output, one member a record
A record given twice (the same samples, whatever the path) is refused: it would count twice in the fit.
)";

const char* kSpectrum = R"(
rocking spectrum FILE [--alpha A[,A...]] [--mark BxH[,BxH...]] [--p-min P] [--p-max P]
                 [--points N] [--method grid|refine [--width W] [--robust-width R]]
                 [--restitution E|housner | --friction MU] [IMPERFECT] [--floor T1,G[,zeta]] [--unit U [--dt DT]]
                 [--jobs N] [--output CSV] [--png PNG] [--json] [--rows FILE [--resume]]
                 [--quiet]
mpirun -np K rocking spectrum FILE --alpha A[,A...] ... [--rows FILE [--resume]]
)";
const char* kSpectrumDetails = R"(
Which blocks the record overturns. For each alpha, max |theta|/alpha and the three criteria over
a log grid of p (and a second grid offset by half a step), and the overturning intervals in p:
each end bisected to 1e-6 relative and confirmed by gsl-rk8pd at rtol 1e-13, or flagged
ill-conditioned (the record times 1 +- 1e-13 flips it); beside Table 1's first collapse (rocking
collapse), whose bracket joins the grid method's points. Islands narrower than half a step may be
missed.
  --alpha A[,A...]  slendernesses (rad), each in (0, pi/4), none twice; at least one of --alpha and
                    --mark, at most 20 alphas in all
  --mark BxH[,...]  the engineer's blocks, full thickness x full height in m (0.6x4; at most 50,
                    B < H, p in (0.01, 1000) rad/s): their alphas atan(B/H) join --alpha's; for
                    each, its outcome from a run at its own p, whether the spectrum's set holds
                    it, and the nearest overturning p below and above it as block heights
                    H = 2 R cos(alpha), R = 3 g/(4 p^2) (a higher p is a smaller block)
  --p-min P, --p-max P   the grid's range (rad/s), in [0.01, 1000] (default 0.3 and 30)
  --points N        the grid's points, log-spaced, 2 to 100000 (default 200)
  --method M        grid (the default) or refine (issue 39): every island and gap of overturning
                    wider than --width W in ln p (default 1e-5, in [1e-7, 0.1]), and each alpha's
                    first overturning, first robust collapse (the first interval wider than
                    --robust-width R in ln p, default 5e-3, in [1e-7, 1]) and overturned share per
                    band (docs/overturning_set.md)
  --restitution E   theta' after an impact over theta' before, in [0, 1], or housner (the default)
  --friction MU     a base that slides (see Beyond the paper's block); without --restitution
  --lean RAD, --out-of-plumb RAD, --fc MPA [--density KG/M3]   an imperfect block (see Beyond
                    the paper's block)
  --unit U, --dt DT a plain-text record's unit and step (see Records)
  --floor T1,G[,zeta]   the motion of a floor of a building in place of the ground's (see A floor)
  --output CSV      the grid: alpha, p, grid, max |theta|/alpha, the three criteria, t_overturn
  --png PNG         a plot (gnuplot): max |theta|/alpha against p, the overturned runs, the block
                    height H on the top axis, the --mark blocks
  --jobs N          threads, 1 to 4096 (default: the cores this process may use; under mpirun one
                    a rank); each alpha a job of the batch engine; the output does not depend on it
  --rows FILE       keeps each alpha's study as a row of FILE; --resume completes an interrupted
                    study from it
  --quiet           no progress line on standard error
  --json            machine-readable output
)";

const char* kFragility = R"(
rocking fragility FILE... (--alpha A[,A...] --p P[,P...] | --block BxH[,BxH...])
                  [--q-max Q] [--points N] [--bootstrap K --seed S] [--restitution E|housner | --friction MU] [IMPERFECT]
                  [--method grid|refine [--width W] [--robust-width R]]
                  [--floor T1,G[,zeta]] [--unit U [--dt DT]] [--jobs N] [--output CSV]
                  [--fits CSV] [--nrml XML] [--png PNG] [--json] [--rows FILE [--resume]] [--quiet]
mpirun -np K rocking fragility FILE... --alpha ... --p ... [--rows FILE [--resume]]
)";
const char* kFragilityDetails = R"(
At what intensity records overturn a block. For each block and record (1 to 1000 FILEs), the
record scaled so that q = PGA/(alpha g) runs over a log grid from 1 (and a second grid offset by
half a step), every overturning interval in q (ends bisected to 1e-6 relative), the first
collapse q or a point censored at --q-max; then, per block, the lognormal fit (median q, beta;
Baker 2015), a bootstrap interval over records on request, and the empirical curve. A record
given twice (the same samples, whatever the path) is refused.
  --alpha A[,A...]  slendernesses (rad), 1 to 50, each in (0, pi/4), none twice
  --p P[,P...]      pulsations (rad/s), 1 to 50, each in (0.01, 1000), none twice: the blocks are
                    every alpha with every p
  --block BxH[,...] instead of --alpha and --p: the blocks as built, full thickness x full height
                    in m (0.6x4; at most 50), each its alpha = atan(B/H), in (0, pi/4), and its p,
                    in (0.01, 1000) rad/s
  --q-max Q         the grid's top, in (1, 10000] (default 20)
  --points N        the grid's points, log-spaced, 2 to 10000 (default 100)
  --method M        grid (the default) or refine (issue 39): every island and gap wider than
                    --width W in ln q (default 1e-5, in [1e-7, 0.1]), and each record's first
                    overturning (its bracket and check), first robust collapse (the first interval
                    wider than --robust-width R in ln q, default 5e-3, in [1e-7, 1]) and overturned
                    share per band; the fit then takes the first overturning (docs/fragility.md)
  --bootstrap K     K resamples of the records (0, the default: none; or 2 to 100000), drawn by
  --seed S          GSL mt19937 from S (1 to 2^32 - 1), required with K; the records drawn in the
                    order of their samples' SHA-256, so that the listing's order changes nothing;
                    the intervals are 90 % percentile intervals
  --restitution E   theta' after an impact over theta' before, in [0, 1], or housner (the default)
  --friction MU     a base that slides (see Beyond the paper's block); without --restitution
  --lean RAD, --out-of-plumb RAD, --fc MPA [--density KG/M3]   an imperfect block (see Beyond
                    the paper's block)
  --unit U, --dt DT a plain-text record's unit and step (see Records)
  --floor T1,G[,zeta]   the motion of a floor of a building in place of the ground's (see A floor)
  --output CSV      one row per block and record
  --fits CSV        one row per block (and capacity): the fit's median, beta and bootstrap ends
  --nrml XML        each block's fit as an OpenQuake NRML 0.5 continuous logncdf fragility function
                    of PGA (g), limit state overturning: mean and stddev of the PGA itself, theta =
                    median q alpha (docs/fragility.md, The NRML export)
  --png PNG         each block's fitted curves, empirical points and bootstrap band (gnuplot)
  --jobs N          threads, 1 to 4096 (default: the cores this process may use; under mpirun one
                    a rank); each IDA a job of the batch engine; the results do not depend on it
  --rows FILE       keeps the IDAs in FILE.partial, renamed when complete; --resume completes an
                    interrupted study, refusing another study or an edited record (docs/batch.md)
  --quiet           no progress line on standard error
  --json            machine-readable output
)";

const char* kEq27 = R"(
rocking eq27 FILE... [--alpha A[,A...]] [--p-min P] [--p-max P] [--p-points N] [--q-max Q]
             [--method grid|refine [--width W] [--robust-width R]] [--bootstrap K --seed S]
             [--restitution E|housner | --friction MU] [IMPERFECT] [--floor T1,G[,zeta]] [--unit U [--dt DT]] [--jobs N]
             [--output CSV] [--png PNG] [--json] [--quiet]
mpirun -np K rocking eq27 FILE... [--alpha A,...] ...
)";
const char* kEq27Details = R"(
Whether eq. 27 is conservative on many blocks: each record's first collapse q (rocking
fragility's IDA) on every block (every alpha with every p) against eq. 27 at x = p to_k. For each
half-period to_k (k = 1..11, as record info), the share of non-conservative cases (the collapse q
below eq. 27's; a record censored at --q-max counts as conservative) with its 95 % Wilson interval
(cases taken as independent) and, with --bootstrap, a 90 % bootstrap interval over records. An
alpha or a record given twice (the same samples, whatever the path) is refused.
  --alpha A[,A...]  slendernesses (rad), 1 to 50, each in (0, pi/4) (default 0.05,0.1,0.15,0.2,0.25)
  --p-min P, --p-max P   the range of p (rad/s), in (0.01, 1000] (default 0.5 and 10)
  --p-points N      p log-spaced over that range, ends included, 1 to 1000 (default 10); 1 is the
                    one p --p-min (--p-max, if given, equal to it)
  --q-max Q         the IDA's top, in (1, 10000] (default 20)
  --method M, --width W, --robust-width R   as for rocking fragility; refine gives the shares
                    under each capacity, the first overturning and the first robust collapse
  --bootstrap K, --seed S   as for rocking fragility
  --restitution E   theta' after an impact over theta' before, in [0, 1], or housner (the default)
  --friction MU     a base that slides (see Beyond the paper's block); without --restitution
  --lean RAD, --out-of-plumb RAD, --fc MPA [--density KG/M3]   an imperfect block (see Beyond
                    the paper's block)
  --unit U, --dt DT a plain-text record's unit and step (see Records)
  --floor T1,G[,zeta]   the motion of a floor of a building in place of the ground's (see A floor)
  --output CSV      the map: per block, the records non-conservative for each to_k
  --png PNG         the shares with their intervals and every case's q against eq. 27's at to_5
                    (gnuplot)
  --jobs N          threads, 1 to 4096 (default: the cores; under mpirun one a rank)
  --quiet           no progress line on standard error
  --json            machine-readable output
  (--resume is refused: eq27 keeps no rows file to resume from.)
)";

const char* kBatch = R"(
rocking batch MANIFEST [--jobs N] [--output FILE] [--resume] [--quiet]
rocking batch MANIFEST --shard I/N --output FILE [--jobs N] [--resume] [--quiet]
rocking batch join SHARD... --output FILE
mpirun -np K rocking batch MANIFEST --output FILE [--resume]
)";
const char* kBatchDetails = R"(
Many studies from a CSV manifest, one job a row (docs/batch.md): one results row per job in
the manifest's order, whatever the threads or ranks; a job that fails gets its error in its row
and the rest run. Exit 0, or 3 when some job failed.
The manifest: a header row naming its columns in any order, then the jobs; '#' lines and blank
lines are skipped; an empty cell takes the default of the command that runs that study alone:
  id                a label of yours, echoed
  kind              simulate (as rocking simulate --record; the default), collapse (as rocking
                    collapse), ida (one cell of rocking fragility) or spectrum (one alpha of rocking
                    spectrum)
  record            the record (see Records), a relative path from the manifest's folder;
                    unit, record_dt: a plain-text record's unit and step (s)
  alpha             the slenderness (rad), in (0, pi/4)
  p, height, half_height   one of them: the block's p (rad/s), full height or half-height (m)
                    (simulate, ida)
  scaling           q=Q (PGA = Q alpha g) or pga=G (g); default: as recorded (not ida)
  model, solver, rtol, atol, restitution, criterion   as the commands' options; every kind's
                    defaults are housner and overturning, as the commands' (simulate --paper's
                    setting: restitution 1, final-rotation)
  friction          as --friction: the sliding-rocking model, without model, solver and restitution
  q_max, points, p_min, p_max, method, width, robust_width   as rocking fragility's options (ida)
                    and rocking spectrum's (spectrum)
  --jobs N          threads, 1 to 4096 (default: the cores this process may use; under mpirun one a
                    rank); the results do not depend on it
  --output FILE     the results, written as FILE.partial and renamed when complete (default:
                    standard output)
  --resume          completes an interrupted --output FILE (Ctrl-C, SIGTERM, a kill), refusing a
                    changed manifest
  --quiet           no progress on standard error
  --shard I/N       run only the I-th of N consecutive parts of the jobs (a scheduler's job array:
                    one shard a task), into its own FILE, resumable; not under mpirun
  join SHARD...     the results of one run from the N shards' complete files, in any order:
                    the same bytes as a run without --shard (--output FILE, required)
  (--json is refused: the results of a batch are CSV.)
)";

constexpr unsigned kStudy = kTheBlock | kTheModel | kTheRecords | kTheFloor | kBeyondThePaper;

}  // namespace

const std::vector<HelpEntry>& help_entries() {
    static const std::vector<HelpEntry> entries = {
        {"q", kQ, kQDetails, kTheBlock},
        {"response", kResponse, kResponseDetails, kTheBlock},
        {"simulate", kSimulate, kSimulateDetails, kStudy},
        {"record info", kRecordInfo, kRecordInfoDetails, kTheRecords},
        {"record synth", kRecordSynth, kRecordSynthDetails, 0},
        {"record floor", kRecordFloor, kRecordFloorDetails, kTheRecords},
        {"collapse", kCollapse, kCollapseDetails, kStudy},
        {"assess", kAssess, kAssessDetails, kStudy},
        {"spectrum", kSpectrum, kSpectrumDetails, kStudy},
        {"fragility", kFragility, kFragilityDetails, kStudy},
        {"eq27", kEq27, kEq27Details, kStudy},
        {"batch", kBatch, kBatchDetails, kTheBlock | kTheModel | kTheRecords},
    };
    return entries;
}

}  // namespace rocking::cli
