#!/usr/bin/python3
"""Check a wall against a record, then follow the block itself and plot θ(t).

First the check as `rocking assess`: the wall's α and p from its thickness and height (eqs. 2,
4), the record's to_5, eq. 27's q at x = p·to_5 against the record's q = PGA/(α g) with their
ratio and margin (the paper's design check, not a proof of safety: docs/findings.md), and the
margins of the model itself: the scale of the record at which the wall first overturns.  Then
the block under the record, as `rocking simulate --record` (its default model: the linearised
equation, Housner's restitution, overturning at any time); θ(t)/α plotted with its impacts.

    PYTHONPATH=build/python /usr/bin/python3 examples/check_wall.py \\
        ../shared/records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC --thickness 0.45 --height 3
"""
import argparse

import matplotlib

matplotlib.use("Agg")  # a file, no display: runs headless
import matplotlib.pyplot as plt  # noqa: E402

import rocking_q as rq  # noqa: E402


def check(record, height, thickness=None, alpha=None):
    """The check with its margins and the block's own motion (θ every 0.01 s)."""
    record = rq.read_record(record) if not isinstance(record, rq.Record) else record
    block = dict(thickness=thickness, height=height, alpha=alpha)
    verdict = rq.assess(record, **block)
    motion = rq.simulate(record=record, dt=0.01, **block)
    return record, verdict, motion


def plot(record, verdict, motion, png):
    fig, ax = plt.subplots(figsize=(11, 5))
    ax.plot(motion.t, motion.theta_over_alpha, lw=1, color="black", label="θ/α")
    for side in (1, -1):
        ax.axhline(side, ls="--", color="red", lw=1)
    ax.plot(motion.impact_times, [0] * len(motion.impact_times), "|", color="gray", ms=6,
            label="impacts (%d)" % motion.impacts)
    ax.set(xlabel="t [s]", ylabel="θ / α", title="%s: α = %.4g, p = %.4g rad/s; eq. 27 check %s; %s" % (
        record.name, verdict.alpha, verdict.p, "passes" if verdict.records[0].passes else "fails",
        "overturns" if motion.overturned else "does not overturn"))
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper right")
    fig.savefig(png, dpi=100)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("record", help="a record file (ESM/ITACA ASCII or PEER AT2)")
    parser.add_argument("--thickness", type=float, help="the wall's full thickness B, m (alpha = atan(B/H))")
    parser.add_argument("--alpha", type=float, help="or the wall's slenderness, rad")
    parser.add_argument("--height", type=float, required=True, help="the wall's full height H, m")
    parser.add_argument("--png", default="check_wall.png", help="the plot of θ(t)/α (default: check_wall.png)")
    args = parser.parse_args(argv)
    if (args.thickness is None) == (args.alpha is None):
        parser.error("give the wall as --thickness B --height H, or --alpha A --height H")
    record, verdict, motion = check(args.record, args.height, thickness=args.thickness, alpha=args.alpha)
    r = verdict.records[0]
    print("%s: eq. 27 check %s (ratio %.4f, margin %+.1f %%)" % (
        record.name, "PASSES" if r.passes else "FAILS", r.ratio, 100 * r.margin))
    print("  block: alpha = %.6g rad, p = %.4f rad/s, B x H = %.4g x %.4g m" % (
        verdict.alpha, verdict.p, verdict.thickness, verdict.height))
    print("  record: PGA = %.4f g, to_5 = %.4f s; x = p to_5 = %.4f" % (r.pga_g, r.to5, r.x))
    print("  q from eq. 27 = %.4f; the record's q = PGA/(alpha g) = %.4f" % (r.q_eq27, r.q_record))
    first = r.first_overturning
    print("  the record scaled by x%.4f first overturns the wall (q = %.4f)" % (first.scale, first.q)
          if first.found else "  the record scaled up to q = 20 does not overturn the wall")
    print("  the block itself (%s, %s): %s, %d impacts, max |theta|/alpha during the record %.4f" % (
        motion.model, motion.solver_description,
        "overturns" if motion.overturned else "does not overturn", motion.impacts, motion.max_theta_input_over_alpha))
    plot(record, verdict, motion, args.png)
    print("wrote %s" % args.png)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
