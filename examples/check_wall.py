#!/usr/bin/python3
"""Check a wall against a record, then follow the block itself and plot θ(t).

First the paper's check, as `rocking assess`: the wall's p (eqs. 2, 4), the record's to_5,
eq. 27's q at x = p·to_5 against the record's q = PGA/(α g).  It is the paper's design
check, not a proof of safety (eq. 27 is not conservative everywhere: docs/findings.md).
Then the block under the record itself, as `rocking simulate --record`: the linearised
equation, Housner's restitution, overturning at any time; θ(t)/α plotted with its impacts.

    PYTHONPATH=build/python /usr/bin/python3 examples/check_wall.py \\
        ../shared/records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC --alpha 0.15 --height 3
"""
import argparse

import matplotlib

matplotlib.use("Agg")  # a file, no display: runs headless
import matplotlib.pyplot as plt  # noqa: E402

import rocking_q as rq  # noqa: E402


def check(record, alpha, height):
    """The paper's check and the block's own motion (θ every 0.01 s)."""
    record = rq.read_record(record) if not isinstance(record, rq.Record) else record
    verdict = rq.assess(record, alpha=alpha, height=height)
    motion = rq.simulate(record=record, alpha=alpha, height=height, restitution="housner",
                         criterion="overturning", dt=0.01)
    return record, verdict, motion


def plot(record, verdict, motion, png):
    fig, ax = plt.subplots(figsize=(11, 5))
    ax.plot(motion.t, motion.theta_over_alpha, lw=1, color="black", label="θ/α")
    for side in (1, -1):
        ax.axhline(side, ls="--", color="red", lw=1)
    ax.plot(motion.impact_times, [0] * len(motion.impact_times), "|", color="gray", ms=6,
            label="impacts (%d)" % motion.impacts)
    ax.set(xlabel="t [s]", ylabel="θ / α", title="%s: α = %g, p = %.4g rad/s; eq. 27 check %s; %s" % (
        record.name, verdict.alpha, verdict.p, "passes" if verdict.passes else "fails",
        "overturns" if motion.overturned else "does not overturn"))
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper right")
    fig.savefig(png, dpi=100)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("record", help="a record file (ESM/ITACA ASCII or PEER AT2)")
    parser.add_argument("--alpha", type=float, required=True, help="the wall's slenderness, rad")
    parser.add_argument("--height", type=float, required=True, help="the wall's full height, m")
    parser.add_argument("--png", default="check_wall.png", help="the plot of θ(t)/α (default: check_wall.png)")
    args = parser.parse_args(argv)
    record, verdict, motion = check(args.record, args.alpha, args.height)
    print("%s: %s" % (record.name, "PASSES (the record's q is below eq. 27's)" if verdict.passes else "FAILS"))
    print("  block: alpha = %g, p = %.4f rad/s (half-height %.4f m)" % (verdict.alpha, verdict.p, verdict.half_height))
    print("  record: PGA = %.4f g, to_5 = %.4f s; x = p to_5 = %.4f" % (verdict.pga_g, verdict.to5, verdict.x))
    print("  q from eq. 27 = %.4f; the record's q = PGA/(alpha g) = %.4f" % (verdict.q_eq27, verdict.q_record))
    print("  the block itself (%s, %s): %s, %d impacts, max |theta|/alpha during the record %.4f" % (
        motion.model, motion.solver_description,
        "overturns" if motion.overturned else "does not overturn", motion.impacts, motion.max_theta_input_over_alpha))
    plot(record, verdict, motion, args.png)
    print("wrote %s" % args.png)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
