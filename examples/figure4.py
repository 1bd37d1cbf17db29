#!/usr/bin/python3
"""Figure 4 of Coccia (Buildings 2025, 15, 2622), redrawn from Python.

q = PGA/(alpha g) of the five step inputs of Figure 3 (eqs. 12, 15, 19, 22, 24) against
x = p*to, their minimum, the q >= 2 that cases 3 and 5 need to rock at all, and the point
where the minimum changes from case 4 to case 2 (q2 = q4).  The same curves as the scene
fig04 (`build/reproduce fig04`, expected/fig04/), which the tests check this script against.

    PYTHONPATH=build/python /usr/bin/python3 examples/figure4.py --out out/examples
"""
import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a file, no display: runs headless
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rocking_q as rq  # noqa: E402


def curves():
    """q1..q5 on the scene's grid x = k/100, k = 5..200, their minimum and which case gives it."""
    x = np.arange(5, 201) / 100.0
    q = np.array([rq.q_case(i, x) for i in range(1, 6)])
    table = {"x": x}
    for i in range(5):
        table["q%d" % (i + 1)] = q[i]
    table["q_min"] = q.min(axis=0)
    table["case_min"] = q.argmin(axis=0) + 1  # the first case at a tie, as the scene
    return table


def root(f, lo, hi):
    """f's root in [lo, hi] (a sign change) by bisection, down to adjacent doubles."""
    f_lo = f(lo)
    while True:
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            return mid
        if (f(mid) < 0) == (f_lo < 0):
            lo, f_lo = mid, f(mid)
        else:
            hi = mid


def marked_points():
    """The figure's marked points: (name, x, q)."""
    x24 = root(lambda x: rq.q2(x) - rq.q4(x), 0.1, 2.0)
    points = [("q2 = q4 (minimum changes from case 4 to case 2)", x24, rq.q2(x24))]
    for i in (1, 2, 4):
        points.append(("q%d = 2" % i, root(lambda x: rq.q_case(i, x) - 2.0, 0.05, 5.0), 2.0))
    for i in (3, 5):  # they start with a half pulse: q -> 2 from above as x -> infinity
        points.append(("q%d at x = 50 (limit 2)" % i, 50.0, rq.q_case(i, 50.0)))
    return points


def plot(table, points, png):
    fig, ax = plt.subplots(figsize=(10, 7))
    ax.plot(table["x"], table["q_min"], color="black", lw=4, label="min(q1..q5)")
    labels = ["q1 (eq. 12)", "q2 (eq. 15)", "q3 (eq. 19)", "q4 (eq. 22)", "q5 (eq. 24)"]
    for i, label in enumerate(labels, start=1):
        ax.plot(table["x"], table["q%d" % i], lw=2, label=label)
    ax.axhline(2, ls="--", color="gray", lw=1)
    ax.text(0.03, 1.87, "q = 2: cases 3 and 5 need q ≥ 2 to start rocking", color="gray", va="top")
    name, x24, q24 = points[0]
    ax.plot([x24], [q24], "o", color="red", ms=10, label="q2 = q4 (min changes case)")
    ax.set(xscale="linear", yscale="log", xlim=(0, 2), ylim=(1, 100), xlabel="x = p·to  [-]",
           ylabel="q = PGA / (α g)  [-]",
           title="Figure 4: q-factor of the five step inputs (linearised eq. 3, collapse θ(t_fin) = α)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="upper right")
    fig.savefig(png, dpi=100)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="folder for figure4.png (default: here)")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    table, points = curves(), marked_points()
    plot(table, points, out / "figure4.png")
    for name, x, q in points:
        print("%-50s x = %.17g, q = %.17g" % (name, x, q))
    print("wrote %s" % (out / "figure4.png"))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
