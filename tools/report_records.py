"""The pages of the paper's records (Section 4): Tables 1 and 2 recomputed from their columns and
the same pipeline on the records here (scenes table1, table2), Figure 11 (the eleven
definitions to_k against eq. 27) and Figure 12 (to_5 and the code's q = 2); each with its
comparison with expected/ and the verdicts of its findings.  Also q27, eq. 27's q at x = p·to,
drawn on Figures 11 and 12.
"""
import math

from report_findings import entry_verdicts, verdicts
from report_outputs import col, read, run_status, scene_status, short, status_line


def q27(x):
    """Eq. 27: q at x = p·to (case 2 with 6 + 1 pulses), the curve of Figures 11 and 12."""
    s2 = lambda v: math.sinh(v) ** 2
    return (2 / 3 * s2(3 * x) + 1 / 3) / (s2(x) - s2(x / 2) + s2(2 * x) - s2(2.5 * x) - s2(1.5 * x) + 2 / 3 * s2(3 * x))


def tables(L):
    """Tables 1 and 2, then the same pipeline on the records here (scenes table1, table2)."""
    t1, t2 = read("table1", "table1.csv"), read("table2", "table2.csv")
    if t1 and t2:
        L.page("Tables 1 and 2",
               "Compares q = PGA/(α g) and to_5 = π PGV/PGA recomputed from Table 1's columns, and eqs. 29-30 on Table "
               "2's columns, with the printed Tables 1 and 2, then runs the same pipeline on the real records "
               f"available here, not the paper's ({verdicts(['T1a', 'T1b', 'T1c', 'T2a', 'T2b'])}); "
               f"{run_status(['table1', 'table2'])}.")
        L.text("Reproduction: " + status_line("table1"), 8, gap=0.02)
        L.text("Reproduction: " + status_line("table2"), 8)
        entry_verdicts(L, ["T1a", "T1b", "T1c", "T2a", "T2b"])
        L.text("Below: the same pipeline on the real records available here (NOT the paper's records): PGA, PGV, "
               "to_5, and the smallest p overturning the block for each α on the search's 1 % grid (linearised, exact "
               "solver, Housner restitution, overturning; brackets confirmed by GSL rk8pd at 1e-13 in make test).",
               8)
        r1, r2 = read("table1", "table1_records.csv"), read("table2", "table2_records.csv")
        if r1 and r2:
            ps = {}
            for r in r1[2]:
                ps.setdefault(r[1], []).append(short(r[5], 4) if not r[5].startswith("none") else "-")
            rows = [[r[1], short(r[2], 4), short(r[3], 4), short(r[9], 3)] + ps.get(r[1], [])[:5] for r in r2[2]]
            L.table(["record", "PGA cm/s²", "PGV cm/s", "to_5 s", "p α.05", "p α.10", "p α.15", "p α.20", "p α.25"],
                    rows, [28, 9, 9, 8, 8, 8, 8, 8, 8], size=6.5)
        else:
            L.text("(records folder absent: no record rows)", 8)
        if r2:
            L.page("Table 2 on the available records: the eleven half-periods [s]",
                   "Compares the eleven definitions of the half-period (Section 4, src/records/measures.hpp) on the "
                   "real records available here, not the paper's, which feed the record points of Figures 11 and 12; "
                   f"{run_status(['table2'])}.")
            L.text("Verified on a cosine, a half-sine pulse and a Ricker wavelet; every value re-implemented with "
                   "numpy in make test.", 8)
            L.table(["record"] + [f"to_{k}" for k in range(1, 12)],
                    [[r[1]] + [short(v, 3) for v in r[5:16]] for r in r2[2]], [26] + [6] * 11, size=6.5)


def figure11(L):
    """Figure 11: the eleven definitions of to against eq. 27 (scene fig11)."""
    p11, n11, n11r = read("fig11", "fig11_points.csv"), read("fig11", "fig11_counts.csv"), read("fig11", "fig11_counts_records.csv")
    if p11:
        def draw11(L, rect):
            axs = L.grid(rect, 4, 3, pad_l=0.5, pad_t=0.22, pad_b=0.4)
            xs = [0.05 + 0.01 * i for i in range(300)]
            rec = read("fig11", "fig11_records.csv")
            for k in range(1, 12):
                ax = axs[k - 1]
                pts = [(float(r[7]), float(r[4])) for r in p11[2] if int(r[2]) == k]
                ax.semilogy([p[0] for p in pts], [p[1] for p in pts], "bo", ms=2, mfc="none", label="paper")
                if rec:
                    pr = [(float(r[7]), float(r[4])) for r in rec[2] if int(r[2]) == k]
                    ax.semilogy([p[0] for p in pr], [p[1] for p in pr], "^", c="darkorange", ms=2, label="records here")
                ax.semilogy(xs, [q27(v) for v in xs], "r", label="eq. 27")
                ax.set_xlim(0, 3); ax.set_ylim(1, 40); ax.set_title(f"to_{k}", fontsize=7); ax.tick_params(labelsize=5)
                ax.set_xlabel("x = p·to_k [-]", fontsize=6); ax.set_ylabel("q [-]", fontsize=6)
            axs[11].axis("off")
            h, lab = axs[0].get_legend_handles_labels()
            axs[11].legend(h, lab, loc="center", fontsize=7)
        L.page("Figure 11: the eleven definitions of to against eq. 27",
               "Compares the points (p·to_k, q) of Tables 1-2 and of the real records here with eq. 27 for each "
               "definition to_k, as the paper's Figure 11, whose claim is that with to_5 nearly all points are "
               f"conservative ({verdicts(['F11'])}); {run_status(['fig11'])}.")
        scene_status(L, "fig11", p11[0])
        L.figure(7.4, draw11)
        L.text("Non-conservative points (eq. 27 above the collapse q), paper: " +
               ", ".join(f"to_{r[1]}: {r[3]}/{r[2]}" for r in n11[2]) + ".", 7.5, gap=0.03)
        if n11r:
            L.text("Available records: " + ", ".join(f"to_{r[1]}: {r[3]}/{r[2]}" for r in n11r[2]) + ".", 7.5)
        entry_verdicts(L, ["F11"])


def figure12(L):
    """Figure 12: to_5 and the code's q = 2 (scene fig12)."""
    s12 = read("fig12", "fig12_summary.csv")
    if s12:
        p12 = read("fig12", "fig12_points.csv")

        def draw12(L, rect):
            ax = L.grid(rect, 1, 1, pad_l=0.7, pad_t=0.1)[0]
            ax.semilogy(col(p12, "x"), col(p12, "q"), "bo", mfc="none", ms=4, label="paper")
            r12 = read("fig12", "fig12_records.csv")
            if r12:
                ax.semilogy(col(r12, "x"), col(r12, "q"), "^", c="darkorange", ms=4, label="available records")
            grid = [0.1 + 0.01 * i for i in range(190)]
            ax.semilogy(grid, [q27(x) for x in grid], "r", label="eq. 27")
            ax.axhline(2, c="k", ls="--", label="code q = 2")
            ax.set_xlabel("x = p·to_5 [-]"); ax.set_ylabel("q [-]"); ax.set_ylim(1, 40); ax.set_xlim(0, 2)
            ax.grid(True, which="both", alpha=0.3); ax.legend(fontsize=7, loc="upper right")
        L.page("Figure 12: to_5 and the code's q = 2",
               "Compares the points (p·to_5, q) with eq. 27 and the Italian code's q = 2, as the paper's Figure 12, "
               f"whose claim is that q = 2 is not conservative for p·to above 0.7 ({verdicts(['F12'])}); "
               f"{run_status(['fig12'])}.")
        scene_status(L, "fig12", p12[0])
        L.figure(5.2, draw12)
        L.text("fig12_summary.csv: " + "; ".join(f"{r[0]}: {short(r[1])}" for r in s12[2]) + ".", 7.5)
        entry_verdicts(L, ["F12"])


def pages(L):
    """Tables 1 and 2, then Figures 11 and 12."""
    for page in (tables, figure11, figure12):
        page(L)
