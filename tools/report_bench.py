"""The page of the speed-accuracy trade (make bench, not a claim of the paper): each solver's
error against its CPU time and its right-hand-side evaluations on a pulse scene and on a
record (OUT/bench/work_precision.csv), and make bench's summary; without make bench's output
the page says to run it.
"""
import csv
import os

import report_outputs as outputs


def pages(L):
    """The work-precision diagram and make bench's summary, or a page saying to run make bench."""
    wp = os.path.join(outputs.OUT, "bench", "work_precision.csv")
    compares_wp = ("Compares each solver's error against its CPU time and its right-hand-side evaluations (make bench) "
                   "on a pulse scene with a closed-form truth and on the Amatrice 2016 record at Norcia; not a claim of "
                   "the paper, whose integrations used MATLAB's ode45 at relative tolerance 1e-6 (T1c).")
    if os.path.exists(wp):
        rows = list(csv.reader(l for l in open(wp) if not l.startswith("#")))[1:]

        def drawwp(L, rect):
            x, y, w, h = rect
            axs = L.grid((x, y, w, h - 0.3), 2, 2, pad_l=0.65, pad_t=0.3, pad_b=0.5)
            for si, scene in enumerate(["pulse", "record"]):
                for solver in ["dopri5", "rkf78", "bulirsch-stoer", "gsl-rk8pd"]:
                    pts = [(float(r[4]), float(r[5]), max(float(r[3]), 1e-17)) for r in rows if r[0] == scene and r[1] == solver]
                    if not pts:
                        continue
                    axs[2 * si].loglog([p[0] for p in pts], [p[2] for p in pts], ".-", label=solver)
                    axs[2 * si + 1].loglog([p[1] for p in pts], [p[2] for p in pts], ".-", label=solver)
                ex = [r for r in rows if r[0] == scene and r[1] == "exact"]
                if ex:
                    axs[2 * si].loglog([float(ex[0][4])], [max(float(ex[0][3]), 1e-17)], "ko", label="exact")
                axs[2 * si].set_title(f"{scene}: error/α against CPU time", fontsize=8)
                axs[2 * si + 1].set_title(f"{scene}: error/α against RHS evaluations", fontsize=8)
                axs[2 * si].set_xlabel("CPU time per run [s]", fontsize=7)
                axs[2 * si + 1].set_xlabel("right-hand-side evaluations [-]", fontsize=7)
                for ax in axs[2 * si: 2 * si + 2]:
                    ax.set_ylabel("error / α [-]", fontsize=7)
                    ax.grid(True, which="both", alpha=0.3); ax.tick_params(labelsize=6)
            handles, labels = axs[0].get_legend_handles_labels()
            L.legend(handles, labels, rect, 0.3, ncol=5)
        L.page("The speed-accuracy trade (make bench)", compares_wp)
        L.text("Each solver swept from rtol 1e-3 to 1e-12 (atol = rtol α); the exact solver is one point. Pulse scene: "
               "error |θ(t_fin) − (S1)|/α; record: error in max|θ|/α against the exact solver.", 8)
        L.figure(5.0, drawwp)
        if outputs.BENCH_LINES:
            L.text("out/bench/summary.txt:", 8, weight="bold", gap=0.04)
            for line in outputs.BENCH_LINES:
                L.text(line, 7, indent=0.1, gap=0.025)
    else:
        L.section("The speed-accuracy trade", compares_wp)
        L.text("Run make bench to include the work-precision diagram.", 8.5)
