"""The pages of the rocking spectrum (scene spectrum, issue 28): the set of p at which each
Norcia record overturns the block, against Table 1's single p; the checks of each interval's
boundaries; two spectra picked from the data; the table per record and α.  Without the shared
records the scene writes nothing, and the page says so.  Also record_label, a record's short
name on the axes, and ratio_text, a ratio near 1 with the digits that show how near.
"""
import math
import os

from matplotlib.lines import Line2D
from matplotlib.ticker import MaxNLocator

import report_outputs as outputs
from report_findings import verdicts
from report_layout import plain_log_ticks
from report_outputs import dict_rows, num, read, run_status, scene_status, short


def record_label(path):
    """esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC -> NRC HGE 2016-08-24 01:36; otherwise the file's name."""
    base = os.path.basename(path)
    f = base.split(".")
    if len(f) >= 7 and len(f[5]) == 8 and len(f[6]) == 6 and f[5].isdigit():
        return f"{f[1]} {f[3]} {f[5][:4]}-{f[5][4:6]}-{f[5][6:]} {f[6][:2]}:{f[6][2:4]}"
    return base


def ratio_text(v):
    """A ratio near 1 with the digits that show how near: 0.999994, not 1."""
    x = num(v)
    return f"{x:.6f}" if math.isfinite(x) else v


def pages(L):
    """The rocking spectrum of the Norcia records (scene spectrum): the overturning intervals in p against
    Table 1's p, two spectra picked from the data, and the table per record and α."""
    sp_iv, sp_sm = read("spectrum", "spectrum_intervals.csv"), read("spectrum", "spectrum_summary.csv")
    if sp_iv and sp_sm:
        IV, SM = dict_rows(sp_iv), dict_rows(sp_sm)
        sp_alphas = sorted({r["alpha"] for r in SM}, key=float)
        sp_records = list(dict.fromkeys(r["record"] for r in SM))
        by_pair = {}
        for r in IV:
            by_pair.setdefault((r["record"], r["alpha"]), []).append(r)
        table1_p = {(r["record"], r["alpha"]): num(r["table1_p"]) for r in SM}
        ends = [(r, s) for r in IV for s in ("from", "to")]
        checks = [r[f"{s}_check"] for r, s in ends]
        n_conf, n_ill = checks.count("confirmed"), checks.count("ill-conditioned")
        n_dis, n_grid = checks.count("second solver disagrees"), sum(c in ("grid start", "grid end") for c in checks)
        widths = sorted((num(r["to"]) - num(r["from"])) / num(r["from"]) for r in IV)
        narrow = [w for w in widths if w < 0.01]
        pairs_over = [k for k in table1_p if by_pair.get(k)]
        off_grid = [r for r in SM if r["table1_on_island_off_grid"] == "yes"]
        below = sorted((num(r["lowest_over_table1"]), r["record"], r["alpha"]) for r in SM
                       if num(r["lowest_over_table1"]) < 0.999)

        def draw_intervals(L, rect):
            x, y, w, h = rect
            axs = L.grid((x, y, w, h - 0.25), len(sp_alphas), 1, pad_l=1.5, pad_t=0.22, pad_b=0.36)
            for ax, a in zip(axs, sp_alphas):
                for y, rec in enumerate(sp_records):
                    for r in by_pair.get((rec, a), []):
                        lo, hi = num(r["from"]), num(r["to"])
                        ax.plot([lo, hi], [y, y], c="#c0392b", lw=4, solid_capstyle="butt")
                        if hi / lo < 1.01:      # an island narrower than 1 %: a tick, or it would not show
                            ax.plot([lo], [y], "|", c="#c0392b", ms=7, mew=1.2)
                        for s, at in (("from", lo), ("to", hi)):
                            c = r[f"{s}_check"]
                            if c == "ill-conditioned":
                                ax.plot([at], [y], "x", c="k", ms=7, mew=1.5)
                            elif c == "second solver disagrees":
                                ax.plot([at], [y], "D", c="orange", ms=5)
                    tp = table1_p.get((rec, a), math.nan)
                    if math.isfinite(tp):
                        ax.plot([tp], [y - 0.3], "v", c="#1f5fbf", ms=4.5, mec="white", mew=0.4)
                ax.set_xscale("log")
                ax.set_xlim(0.3, 30)
                plain_log_ticks(ax)
                ax.set_ylim(len(sp_records) - 0.5, -0.8)
                ax.set_yticks(range(len(sp_records)))
                ax.set_yticklabels([record_label(r) for r in sp_records], fontsize=5.5)
                ax.tick_params(axis="x", labelsize=6)
                ax.grid(True, axis="x", which="both", alpha=0.25)
                ax.set_title(f"α = {a}", fontsize=7.5)
                ax.set_xlabel("p [rad/s]", fontsize=6.5)
            handles = [Line2D([], [], c="#c0392b", lw=4), Line2D([], [], ls="", marker="v", c="#1f5fbf"),
                       Line2D([], [], ls="", marker="x", c="k", mew=1.5),
                       Line2D([], [], ls="", marker="D", c="orange")]
            L.legend(handles, ["overturning interval (tick: narrower than 1 %)", "Table 1's p",
                               "ill-conditioned end", "second solver disagrees"], rect, 0.25, ncol=4)

        L.page("The rocking spectrum of the Norcia records: overturning intervals in p",
               "Compares the set of p at which each Norcia record overturns the block (linearised eq. 3, exact "
               "solver, Housner's restitution, free rocking followed; a log grid of 200 + 199 p in 0.3-30 rad/s, "
               "boundaries bisected to 1e-6 and each checked) with Table 1's single p, the first collapse of its 1 % "
               f"scan ({verdicts(['T1d'])}); {run_status(['spectrum'])}.")
        scene_status(L, "spectrum", sp_iv[0])
        if "grid" in sp_iv[0]:
            L.text(f"grid: {sp_iv[0]['grid']}", 7, color="#333333")
        L.text(f"{len(IV)} intervals over the {len(pairs_over)} of {len(SM)} (record, α) pairs that overturn on the "
               f"grid ({len(SM) - len(pairs_over)} overturn nowhere up to 30 rad/s). Their {len(ends) - n_grid} "
               f"boundaries: {n_conf} confirmed (the input × (1 ± 1e-13) flips nothing and GSL rk8pd at 1e-13 sees "
               f"the same bracket), {n_ill} ill-conditioned (rounding places it: flagged, not confirmed), {n_dis} "
               f"where the second solver disagrees; {n_grid} ends are the grid's own (30 rad/s). "
               f"{len(narrow)} intervals are narrower than 1 % in p"
               + (f" (their median width {100 * narrow[len(narrow) // 2]:.2g} %, the narrowest "
                  f"{narrow[0]:.2g} relative)" if narrow else "") + ".", 8)
        L.figure(min(7.4, 0.95 + 1.3 * len(sp_alphas)), draw_intervals)
        L.text(f"Table 1's p lies on an island that no grid point reached (found only through its own bracket) in "
               f"{len(off_grid)} of the {len(pairs_over)} pairs. The spectrum's lowest overturning p is more than "
               f"0.1 % below Table 1's in {len(below)} pairs"
               + (": " + "; ".join(f"{record_label(rec)} α {a}: {100 * (1 - v):.2g} % lower"
                                   for v, rec, a in below[:4]) + ("; ..." if len(below) > 4 else "") if below else "")
               + ".", 8)
        for k, v in sp_iv[0].items():
            if k.startswith("detail "):
                L.text(f"Ill-conditioned: {k[len('detail '):]}: {v}.", 7.5, color="#333333", gap=0.03)
        L.text("Independent checks (make test): reference_spectrum re-simulates both ends of every confirmed "
               "bracket with rk8pd through table1's path; independent_spectrum does so with a Python "
               "re-implementation of the model that shares no code with the C++.", 7.5, color="#333333")

        # The spectra themselves, for two pairs picked by the data: the lowest p furthest below Table 1's,
        # and the first pair whose Table 1 p lies on an island no grid point reached.
        sp_gd = read("spectrum", "spectrum_grid.csv")
        picks = []
        if below:
            picks.append((below[0][1], below[0][2], "lowest p furthest below Table 1's"))
        if off_grid and (off_grid[0]["record"], off_grid[0]["alpha"]) not in [(p[0], p[1]) for p in picks]:
            picks.append((off_grid[0]["record"], off_grid[0]["alpha"], "Table 1's p on an island off the grid"))
        if sp_gd and picks:
            GD = {}
            for r in dict_rows(sp_gd):
                GD.setdefault((r["record"], r["alpha"]), []).append((num(r["p"]), num(r["max_theta_over_alpha"]),
                                                                     r["overturning"] == "yes"))

            def draw_spectra(L, rect):
                axs = L.grid(rect, 2, len(picks), pad_l=0.62, pad_t=0.42, pad_b=0.45)
                for c, (rec, a, why) in enumerate(picks):
                    pts = sorted(GD.get((rec, a), []))
                    tp = table1_p.get((rec, a), math.nan)
                    ivs = by_pair.get((rec, a), [])
                    lo_zoom = min([num(r["from"]) for r in ivs[:1]] + ([tp] if math.isfinite(tp) else [])) / 1.06
                    hi_zoom = (tp if math.isfinite(tp) else lo_zoom * 1.06) * 1.06
                    for row, (x0, x1) in enumerate([(0.3, 30), (lo_zoom, hi_zoom)]):
                        ax = axs[row * len(picks) + c]
                        for r in ivs:
                            lo, hi = num(r["from"]), num(r["to"])
                            if hi >= x0 and lo <= x1:
                                ax.axvspan(lo, hi, color="#f2b8b5", lw=0)
                                if hi / lo < 1.002:
                                    ax.axvline(lo, color="#e06666", lw=0.8)
                        ax.semilogy([p[0] for p in pts], [p[1] for p in pts], "k-", lw=0.7)
                        ax.plot([p[0] for p in pts if p[2]], [p[1] for p in pts if p[2]], ".", c="#c0392b", ms=2.5)
                        if math.isfinite(tp):
                            ax.axvline(tp, c="#1f5fbf", ls="--", lw=1)
                        if row == 0:
                            ax.set_xscale("log")
                            plain_log_ticks(ax)
                        else:
                            ax.xaxis.set_major_locator(MaxNLocator(5))
                        ax.set_xlim(x0, x1)
                        ax.set_ylim(1e-3, 100)
                        ax.tick_params(labelsize=6)
                        ax.set_xlabel("p [rad/s]", fontsize=6.5)
                        ax.set_ylabel("max |θ|/α during the record", fontsize=6.5)
                        ax.set_title(f"{record_label(rec)}, α = {a}" + ("" if row == 0 else ", near Table 1's p")
                                     + ("\n" + why if row == 0 else ""), fontsize=7)
                        ax.grid(True, which="both", alpha=0.25)

            L.need(5.0)
            L.text("Two spectra, picked from the data: max |θ|/α during the record at every grid point (black; red "
                   "dots: the block overturns there), the overturning intervals shaded (a thin red line for one "
                   "narrower than 0.2 %), Table 1's p dashed blue; below, the same near Table 1's p.", 8)
            L.figure(6.0, draw_spectra)

        L.text("Per record and α (spectrum_summary.csv): the number of intervals, the spectrum's lowest overturning p "
               "against Table 1's, and the checks of the boundaries.", 8, weight="bold", gap=0.04)
        L.text("Columns: intervals; the lowest overturning p [rad/s]; Table 1's p; their ratio; the boundaries, "
               "confirmed, ill-conditioned and where the second solver disagrees; whether Table 1's p lies on an "
               "island no grid point reached.", 7, color="#333333", gap=0.04)
        L.table(["record", "α", "int.", "lowest p", "Table 1's p", "ratio", "bound.", "conf.", "ill", "dis.",
                 "off grid"],
                [[record_label(r["record"]), r["alpha"], r["intervals"], short(r["lowest_p"], 7),
                  short(r["table1_p"], 7), ratio_text(r["lowest_over_table1"]), r["boundaries"], r["confirmed"],
                  r["ill_conditioned"], r["disagrees"], r["table1_on_island_off_grid"]] for r in SM],
                [20, 5, 5, 10, 13, 9, 6, 6, 5, 5, 7], size=6.5)
    else:
        L.section("The rocking spectrum of the Norcia records",
               "Would compare the Norcia records' overturning intervals in p with Table 1's p.")
        L.text(f"No spectrum_intervals.csv / spectrum_summary.csv in {outputs.OUT}/spectrum: the scene writes them "
               "only with the shared records folder (../shared/records or $ROCKING_RECORDS).", 8.5)
