#!/usr/bin/python3
"""The sliding-rocking block of docs/sliding.md by a second, independent method:
Siconos's Moreau-Jean time-stepping (issue 41, item 3).

Nothing here comes from src/dynamics/sliding/: the block is a free rigid body
in the plane, (x, y, phi) with mass diag(m, m, I_G), and its two base corners
are unilateral contacts with Coulomb friction and no rebound, solved at every
step as a 2D frictional contact problem (Lemke).  The regimes the engine
switches between (rest, slide, rock, slide-rock) and its impact laws are not
written anywhere here: they come out of the contact problem.

    tools/siconos_block.py --alpha A --R R --mu MU --dt DT INPUT [--t-end T]
                           [--phases K] [--overturn-angle RAD]
    INPUT: --train A:d,... --to T --pga G  |  --record FILE --record-dt DT
    tools/siconos_block.py --alpha A --R R --mu MU --dt DT --check-kinematics

Prints one JSON object (simulate()): max |theta| over [0, t_fin], theta and
the slip at t_fin (t_fin: the input's end), whether and when |theta| passed
the overturn angle (1 rad unless given; the run stops there), the impacts,
the CPU time.  Moreau-Jean is first order in dt without event location:
compare with the engine within its convergence in dt
(tests/sliding_siconos_test.sh), not to a fixed tolerance.

Standard library, numpy and siconos (Debian python3-siconos, /usr/bin/python3)
only; gcc compiles the contact kinematics into a temporary plugin, because a
relation subclassed in Python crashes Siconos 4.4 (../shared/notes/siconos.md).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

G = 9.81  # m/s^2, the engine's kGravity
OVERTURN = 1.0  # rad: |theta| beyond this is called overturned (alpha < pi/4 here), the run stops
# A corner counts as lifted once its gap exceeds LIFT times 2b (theta about
# LIFT rad), and as landed again below a tenth of that: the hysteresis keeps
# Moreau-Jean's velocity-level contact (a landed corner may sit a few dt |v|
# inside the ground) from counting one landing twice.
LIFT = 1e-4
SINK = 1e-10  # times R: the corners' depth at rest (Block)

# The contact kinematics of one base corner.  q = (x, y, phi): G's position
# in the ground's frame (x along the ground, y up, G at (0, h) at rest) and
# the block's rotation phi, counterclockwise-positive.  The paper's theta is
# clockwise-positive (theta > 0: turned about the +x corner, G towards +x), so
# theta = -phi.  The corner sigma sits at (sigma b, -h) in the block, so at
#     x_c = x + sigma b cos(phi) + h sin(phi),   y_c = y + sigma b sin(phi) - h cos(phi).
# Siconos's relation output is (normal gap, tangential position) = (y_c, x_c),
# and H = d(y_c, x_c)/dq, which Siconos stores column-major (2 x 3).
PLUGIN = r"""
#include <math.h>
static void corner(double s, const double* q, double* y) {
    const double c = cos(q[2]), n = sin(q[2]);
    y[0] = q[1] + s * HALF_WIDTH * n - HALF_HEIGHT * c;
    y[1] = q[0] + s * HALF_WIDTH * c + HALF_HEIGHT * n;
}
static void corner_jacobian(double s, const double* q, double* H) {
    const double c = cos(q[2]), n = sin(q[2]);
    H[0] = 0.0; H[1] = 1.0;                                       /* d/dx   */
    H[2] = 1.0; H[3] = 0.0;                                       /* d/dy   */
    H[4] = s * HALF_WIDTH * c + HALF_HEIGHT * n;                  /* d/dphi */
    H[5] = -s * HALF_WIDTH * n + HALF_HEIGHT * c;
}
void h_plus(unsigned int nq, double* q, unsigned int ny, double* y, unsigned int nz, double* z) { corner(1.0, q, y); }
void h_minus(unsigned int nq, double* q, unsigned int ny, double* y, unsigned int nz, double* z) { corner(-1.0, q, y); }
void H_plus(unsigned int nq, double* q, unsigned int ny, double* H, unsigned int nz, double* z) { corner_jacobian(1.0, q, H); }
void H_minus(unsigned int nq, double* q, unsigned int ny, double* H, unsigned int nz, double* z) { corner_jacobian(-1.0, q, H); }
"""
CORNERS = ((1, "plus"), (-1, "minus"))


class InputError(ValueError):
    pass


def number(text, what):
    try:
        v = float(text)
    except ValueError:
        raise InputError(f"{what}: not a number ({text!r})") from None
    if not math.isfinite(v):
        raise InputError(f"{what}: not finite ({text!r})")
    return v


class Train:
    """Step pulses of amplitude A_k PGA for d_k to, back to back from t = 0
    (as rocking simulate --train reads them); 0 from the end on."""

    def __init__(self, text, to, pga):
        self.edges, self.values = [0.0], []
        for k, item in enumerate(text.split(","), 1):
            if ":" not in item:
                raise InputError(f"--train item {k} {item!r}: expected amplitude:duration")
            a, d = item.split(":", 1)
            a, d = number(a, f"--train item {k} amplitude"), number(d, f"--train item {k} duration")
            if d <= 0:
                raise InputError(f"--train item {k} {item!r}: the duration must be > 0")
            self.edges.append(self.edges[-1] + d * to)
            self.values.append(a * pga)
        if self.values[0] <= 0:
            raise InputError("--train: the first pulse must be positive (as rocking simulate's)")
        self.t_end = self.edges[-1]

    def integral(self, t):
        """int_0^t a dt (g s)."""
        total = 0.0
        for t0, t1, a in zip(self.edges, self.edges[1:], self.values):
            if t <= t0:
                break
            total += a * (min(t, t1) - t0)
        return total


class Record:
    """Samples a_k (g) at t = k dt, linear between them; 0 from the last on."""

    def __init__(self, path, dt):
        self.dt = dt
        samples = []
        try:
            with open(path) as f:
                for line_no, line in enumerate(f, 1):
                    line = line.strip()
                    if not line or line.startswith("#"):
                        continue
                    if len(line.split()) != 1:
                        raise InputError(f"{path} line {line_no}: expected one column (acceleration in g)")
                    samples.append(number(line, f"{path} line {line_no}"))
        except OSError as e:
            raise InputError(f"--record {path}: {e.strerror}") from None
        if len(samples) < 2:
            raise InputError(f"--record {path}: fewer than two samples")
        self.a = np.array(samples)
        # The running integral at the samples (trapezoids: exact for linear pieces).
        self.cumulative = np.concatenate(([0.0], np.cumsum(0.5 * (self.a[1:] + self.a[:-1]) * dt)))
        self.t_end = dt * (len(samples) - 1)

    def integral(self, t):
        if t <= 0:
            return 0.0
        if t >= self.t_end:
            return self.cumulative[-1]
        k = min(int(t / self.dt), len(self.a) - 2)
        s = t - k * self.dt
        slope = (self.a[k + 1] - self.a[k]) / self.dt
        return self.cumulative[k] + self.a[k] * s + 0.5 * slope * s * s


def build_plugin(b, h, directory):
    """Compiles PLUGIN for this block; returns the path Siconos's plugin names
    take (without '.so')."""
    source = os.path.join(directory, "corner.c")
    with open(source, "w") as f:
        f.write(PLUGIN)
    lib = os.path.join(directory, "corner")
    cmd = ["gcc", "-O2", "-fPIC", "-shared", f"-DHALF_WIDTH={b!r}", f"-DHALF_HEIGHT={h!r}", source, "-o", lib + ".so", "-lm"]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError("gcc failed on the contact plugin: " + done.stderr)
    return lib


class Block:
    """The Siconos model of one block: the dynamical system, the two corner
    interactions and the Moreau-Jean time-stepping, built at q0."""

    def __init__(self, alpha, R, mu, dt, t_end, plugin, q0=(None, None, 0.0), m=1.0):
        import siconos.kernel as sk
        import siconos.numerics as sn

        self.b, self.h, self.m = R * math.sin(alpha), R * math.cos(alpha), m
        # At rest the corners sit SINK below the ground, not on it: Moreau-Jean
        # enrols a contact when its gap predicted at mid-step is <= 0, and a
        # gap of exactly 0 with a round-off velocity of +1e-18 m/s is not, so
        # the block would fall freely for a step at random.
        q0 = [0.0 if q0[0] is None else q0[0], self.h - SINK * R if q0[1] is None else q0[1], q0[2]]
        self.ds = sk.LagrangianLinearTIDS(q0, [0.0, 0.0, 0.0], np.diag([m, m, m * R * R / 3.0]))
        self.ds.setFExtPtr(np.array([0.0, -m * G, 0.0]))
        nsds = sk.NonSmoothDynamicalSystem(0.0, t_end)
        nsds.insertDynamicalSystem(self.ds)
        law = sk.NewtonImpactFrictionNSL(0.0, 0.0, mu, 2)  # e_n = 0: no rebound
        self.relations, self.interactions = [], []
        for _, name in CORNERS:
            rel = sk.LagrangianScleronomousR(f"{plugin}:h_{name}", f"{plugin}:H_{name}")
            inter = sk.Interaction(law, rel)
            nsds.link(inter, self.ds)
            self.relations.append(rel)
            self.interactions.append(inter)
        self.sim = sk.TimeStepping(nsds, sk.TimeDiscretisation(0.0, dt), sk.MoreauJeanOSI(0.5),
                                   sk.FrictionContact(2, sn.SICONOS_FRICTION_2D_LEMKE))
        self.sim.initialize()

    def outputs(self):
        """Each corner's (gap, x) and H as Siconos computes them at the current q."""
        self.sim.updateOutput(0)
        out = []
        for rel, inter in zip(self.relations, self.interactions):
            rel.computeJach(0.0, inter)
            out.append((np.array(inter.y(0)), np.array(rel.jachq())))
        return out


def check_kinematics(alpha, R, points=((0.0, 0.0, 0.0), (0.1, 0.05, -0.3), (-0.2, 0.3, 0.7), (0.05, -0.1, 1.2))):
    """The plugin as Siconos reads it against the corners' positions computed
    here from the rotation matrix, and its Jacobian against central
    differences of that output.  Returns the largest errors (m, m/rad)."""
    with tempfile.TemporaryDirectory(prefix="siconos_block.") as tmp:
        plugin = build_plugin(R * math.sin(alpha), R * math.cos(alpha), tmp)
        block = Block(alpha, R, 0.5, 1e-3, 1.0, plugin, q0=(0.0, None, 0.0))
        q = block.ds.q()  # Siconos's own storage: outputs() reads it
        gap_err = jac_err = 0.0
        eps = 1e-6
        for dq in points:
            base = np.array([dq[0], block.h + dq[1], dq[2]])
            q[:] = base
            got = block.outputs()
            rot = np.array([[math.cos(base[2]), -math.sin(base[2])], [math.sin(base[2]), math.cos(base[2])]])
            for (sigma, _), (y, H) in zip(CORNERS, got):
                corner = base[:2] + rot @ np.array([sigma * block.b, -block.h])
                gap_err = max(gap_err, abs(y[0] - corner[1]), abs(y[1] - corner[0]))
            for j in range(3):
                q[:] = base
                q[j] += eps
                up = [y for y, _ in block.outputs()]
                q[:] = base
                q[j] -= eps
                down = [y for y, _ in block.outputs()]
                for c, (_, H) in enumerate(got):
                    fd = (up[c] - down[c]) / (2 * eps)
                    jac_err = max(jac_err, float(np.max(np.abs(H[:, j] - fd))))
        return {"gap_error_m": gap_err, "jacobian_error": jac_err}


def run(block, dt, ground, t_end, offset, overturn=OVERTURN):
    """One Moreau-Jean run on the grid t = -offset + k dt (the ground at rest
    before 0, the block at rest on it), to the first grid time >= t_end."""
    b, h, m = block.b, block.h, block.m
    q, f_ext = block.ds.q(), block.ds.fExt()
    t_input = min(ground.t_end, t_end)
    max_theta = 0.0
    lifted = [False, False]
    impacts = impacts_input = 0
    overturned, t_overturn, at_tfin = False, None, None
    t, q_prev = -offset, q.copy()
    while t < t_end - 1e-9 * dt:
        t0, t1 = t, t + dt
        # The ground's inertial force +m a g on G (the paper's sign), its mean
        # over the step: the step's impulse exact, jumps inside it included.
        f_ext[0] = m * G * (ground.integral(t1) - ground.integral(t0)) / dt
        block.sim.computeOneStep()
        block.sim.nextStep()
        t = t1
        theta = -q[2]
        if at_tfin is None and t1 >= t_input:
            # theta at t_fin linear between the grid times around it: O(dt^2),
            # below the method's O(dt).
            w = (t_input - t0) / dt
            at_tfin = (1 - w) * q_prev + w * q
            max_theta = max(max_theta, abs(at_tfin[2]))
        during_input = t1 < t_input
        if during_input:
            max_theta = max(max_theta, abs(theta))
        for c, (sigma, _) in enumerate(CORNERS):
            gap = q[1] + sigma * b * math.sin(q[2]) - h * math.cos(q[2])
            if gap > LIFT * 2 * b:
                lifted[c] = True
            elif lifted[c] and gap < 0.1 * LIFT * 2 * b:
                lifted[c] = False
                impacts += 1
                impacts_input += during_input
        if abs(theta) > overturn:
            # The crossing time linear between the grid times around it.
            before = abs(q_prev[2])
            overturned, t_overturn = True, t0 + dt * (overturn - before) / (abs(theta) - before)
            if at_tfin is None:  # as the engine: the slip at the fall, the largest theta the fall angle
                at_tfin = q.copy()
                max_theta = overturn
            break
        q_prev = q.copy()
    if at_tfin is None:
        at_tfin = q.copy()
    theta_f = -at_tfin[2]
    # The slip as the engine defines it: the displacement of the corner on the
    # ground (the lower one) from its place at rest; and the base's midpoint's,
    # which differs from it by b (1 - cos theta) while the block rocks.
    sigma = 1 if theta_f >= 0 else -1
    x, phi = at_tfin[0], at_tfin[2]
    return {
        "max_theta_input_rad": max_theta, "theta_tfin_rad": theta_f,
        "slip_tfin_m": x + sigma * b * math.cos(phi) + h * math.sin(phi) - sigma * b,
        "base_midpoint_slip_tfin_m": x + h * math.sin(phi),
        "overturned": overturned, "t_overturn": t_overturn,
        "impacts": impacts, "impacts_input": impacts_input, "t_end": t,
    }


def simulate(alpha, R, mu, dt, ground, t_end, phases=1, overturn=OVERTURN):
    """The runs on `phases` grids offset by dt/phases from each other, and
    their mean: the dictionary printed as JSON.

    Without event location a Moreau-Jean run meets an impact at the first step
    whose mid-step gap is <= 0, up to a step after the corner reached the
    ground: the error is O(dt) with a factor that depends on where in its
    step each impact falls, and a rocking block amplifies it.  Over grids
    offset by dt/K that factor is sampled at K phases, so the mean's error is
    c dt plus O(dt/K): a sequence in dt that converges as first order should.
    """
    cpu0 = time.process_time()
    runs = []
    with tempfile.TemporaryDirectory(prefix="siconos_block.") as tmp:
        plugin = build_plugin(R * math.sin(alpha), R * math.cos(alpha), tmp)
        for j in range(phases):
            offset = j * dt / phases
            runs.append(run(Block(alpha, R, mu, dt, t_end + offset + 10 * dt, plugin), dt, ground, t_end, offset, overturn))
    out = {"alpha": alpha, "R": R, "mu": mu, "dt": dt, "phases": phases,
           "t_fin": min(ground.t_end, t_end), "t_end": t_end, "overturn_angle_rad": overturn}
    # The runs' values, by offset j dt/K (j = 0 .. K-1), and their mean.
    by_phase = {
        "max_theta_input_over_alpha": [r["max_theta_input_rad"] / alpha for r in runs],
        "theta_tfin_over_alpha": [r["theta_tfin_rad"] / alpha for r in runs],
        "slip_tfin_m": [r["slip_tfin_m"] for r in runs],
        "base_midpoint_slip_tfin_m": [r["base_midpoint_slip_tfin_m"] for r in runs],
        "overturned": [r["overturned"] for r in runs],
        "t_overturn": [r["t_overturn"] for r in runs],
        "impacts": [r["impacts"] for r in runs],
        "impacts_input": [r["impacts_input"] for r in runs],
    }
    for key in ("max_theta_input_over_alpha", "theta_tfin_over_alpha", "slip_tfin_m", "base_midpoint_slip_tfin_m"):
        out[key] = sum(by_phase[key]) / phases
    # null where the runs disagree: the outcome is then within the method's error.
    outcomes = set(by_phase["overturned"])
    out["overturned"] = outcomes.pop() if len(outcomes) == 1 else None
    out["t_overturn"] = sum(by_phase["t_overturn"]) / phases if all(by_phase["overturned"]) else None
    out["impacts"] = by_phase["impacts"][0] if len(set(by_phase["impacts"])) == 1 else None
    out["by_phase"] = by_phase
    out["cpu_s"] = time.process_time() - cpu0
    out["method"] = ("Siconos: LagrangianLinearTIDS (x, y, phi), two LagrangianScleronomousR corners, "
                     "NewtonImpactFrictionNSL(0, 0, mu, 2), MoreauJeanOSI(0.5), FrictionContact 2D Lemke; "
                     "means over %d grid offsets" % phases)
    return out


def main(argv):
    ap = argparse.ArgumentParser(prog="siconos_block.py", description=__doc__.split("\n\n")[0])
    ap.add_argument("--alpha", required=True, help="slenderness, rad, in (0, pi/4)")
    ap.add_argument("--R", required=True, help="half-diagonal, m, > 0")
    ap.add_argument("--mu", required=True, help="Coulomb friction coefficient, > 0")
    ap.add_argument("--dt", required=True, help="time step, s, > 0")
    ap.add_argument("--train", help="A:d,... step pulses (amplitude in PGA, duration in to)")
    ap.add_argument("--to", help="the train's to, s")
    ap.add_argument("--pga", help="the train's PGA, g")
    ap.add_argument("--record", help="one column of accelerations in g, linear between samples")
    ap.add_argument("--record-dt", help="the record's step, s")
    ap.add_argument("--t-end", help="simulate to this time, s (default: the input's end)")
    ap.add_argument("--phases", default="1", help="runs on grids offset by dt/K, averaged (default 1)")
    ap.add_argument("--overturn-angle", default=str(OVERTURN),
                    help="|theta| (rad) called overturned, where a run stops (default 1; pi/2 as the engine)")
    ap.add_argument("--check-kinematics", action="store_true",
                    help="print the plugin's gap and Jacobian errors (against geometry and central differences)")
    args = ap.parse_args(argv)

    def positive(name, text):
        v = number(text, name)
        if v <= 0:
            raise InputError(f"{name}: must be > 0 (got {text})")
        return v

    alpha = positive("--alpha", args.alpha)
    if alpha >= math.pi / 4:
        raise InputError(f"--alpha: must be in (0, pi/4) (got {args.alpha})")
    R, mu, dt = positive("--R", args.R), positive("--mu", args.mu), positive("--dt", args.dt)
    if args.check_kinematics:
        print(json.dumps(check_kinematics(alpha, R)))
        return 0
    if (args.train is None) == (args.record is None):
        raise InputError("give exactly one input: --train with --to and --pga, or --record with --record-dt")
    if args.train is not None:
        if args.to is None or args.pga is None:
            raise InputError("--train needs --to and --pga")
        if args.record_dt is not None:
            raise InputError("--record-dt applies to --record only")
        ground = Train(args.train, positive("--to", args.to), positive("--pga", args.pga))
    else:
        if args.record_dt is None:
            raise InputError("--record needs --record-dt")
        if args.to is not None or args.pga is not None:
            raise InputError("--to and --pga apply to --train only")
        ground = Record(args.record, positive("--record-dt", args.record_dt))
    t_end = positive("--t-end", args.t_end) if args.t_end is not None else ground.t_end
    try:
        phases = int(args.phases)
    except ValueError:
        raise InputError(f"--phases: not an integer ({args.phases!r})") from None
    if not 1 <= phases <= 64:
        raise InputError(f"--phases: must be in [1, 64] (got {phases})")
    overturn = positive("--overturn-angle", args.overturn_angle)
    if overturn > math.pi / 2:
        raise InputError(f"--overturn-angle: must be in (0, pi/2] (got {args.overturn_angle})")
    print(json.dumps(simulate(alpha, R, mu, dt, ground, t_end, phases, overturn)))
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except InputError as e:
        print(f"siconos_block.py: {e}", file=sys.stderr)
        sys.exit(2)
