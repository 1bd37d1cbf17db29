"""The pages of the imperfection scene (issue 41): the paper's closed forms toward each corner of
a leaning, out-of-plumb or set-back block against the perfect block's q (how far the paper's q
overstates the imperfect block's capacity), then eq. 27's share of non-conservative cases per
to_k on the shared records with each imperfection beside the perfect block's.
"""
from report_findings import BY_ID, entry_verdicts, verdicts
from report_outputs import dict_rows, num, read, run_status, scene_status, short

COLOURS = ["#444444", "#b3261e", "#f08c00", "#1f5fbf", "#1a7f37", "#6a3d9a", "#9a6700", "#17becf"]
FINDINGS = [i for i in ("I1", "I2") if i in BY_ID]


def closed_forms(L):
    q = read("imperfection", "imperfection_q.csv")
    cap = read("imperfection", "imperfection_capacity.csv")
    if not q:
        return
    Q = dict_rows(q)
    names = list(dict.fromkeys(r["imperfection"] for r in Q))  # the imperfections, each against the perfect block

    def draw(L, rect):
        axs = L.grid(rect, 1, 2, pad_l=0.62, pad_t=0.25, pad_b=0.5)
        for ax, p in zip(axs, ("1.5", "3.0")):
            for c, n in zip(COLOURS[1:], names):
                for case, style in (("eq. 27", "o-"), ("case 4", "x:")):
                    rs = [r for r in Q if (r["imperfection"], r["case"], r["p"]) == (n, case, p)]
                    ax.plot([num(r["x"]) for r in rs], [num(r["q_block"]) / num(r["q_perfect"]) for r in rs], style,
                            c=c, ms=2.5, lw=1, label=n if case == "eq. 27" else None)
            ax.axhline(1, c="k", lw=1.5)
            ax.set_ylim(0.6, 1.02)
            ax.set_title(f"α = 0.10, p = {p} rad/s: eq. 27 (o, solid), case 4 (x, dotted)", fontsize=7.5)
            ax.set_xlabel("x = p·to (p of the perfect block) [-]", fontsize=7)
            ax.set_ylabel("capacity / perfect block's q [-]", fontsize=7)
            ax.tick_params(labelsize=6.5)
            ax.grid(True, alpha=0.3)
        axs[0].legend(fontsize=6, loc="lower left", ncol=2)

    L.page("Imperfect blocks: the closed forms toward each corner",
           "Compares the collapse PGA of the paper's pulse trains (cases 1, 2, 4 and eq. 27) toward each corner of "
           "an imperfect block (each corner's own α and p in (S2), the smaller the block's capacity) with the "
           f"perfect block's q at the same to ({verdicts(FINDINGS[:1]) or 'no finding yet'}); "
           f"{run_status(['imperfection'])}.")
    scene_status(L, "imperfection", q[0])
    L.figure(3.0, draw)
    if cap:
        C = dict_rows(cap)
        L.text("How far the perfect block's q overstates the imperfect block's capacity, q_perfect / q_block - 1 "
               "(imperfection_capacity.csv: over cases 1, 2, 4, eq. 27 and x = 0.1-2.0; the weaker corner is "
               "always theta > 0, the side the block leans to, and no excursion leaves its corner):", 8,
               weight="bold", gap=0.04)
        blocks = list(dict.fromkeys((r["alpha"], r["p"]) for r in C))
        rows = []
        for n in dict.fromkeys(r["imperfection"] for r in C):
            cells = [n]
            for a, p in blocks:
                r = next(r for r in C if (r["imperfection"], r["alpha"], r["p"]) == (n, a, p))
                lo, hi = 100 * num(r["overstatement_min"]), 100 * num(r["overstatement_max"])
                cells.append(f"{lo:.3g} %" if abs(hi - lo) < 0.005 else f"{lo:.3g}-{hi:.3g} %")
            rows.append(cells)
        L.table(["imperfection"] + [f"α {a}, p {p}" for a, p in blocks], rows, [14] + [13] * len(blocks), size=7)
        corners = read("imperfection", "imperfection_corners.csv")
        if corners:
            K = [r for r in dict_rows(corners) if r["fc_MPa"] not in ("0", "-")]
            L.text("Setbacks (imperfection_corners.csv, NTC 2018 eq. 7.8.2's stress block 0.85 fc under the "
                   "block's own weight, 1800 kg/m³): " + "; ".join(
                       f"{r['imperfection']} at α {r['alpha']}, p {r['p']}: {short(r['setback_mm'], 3)} mm = "
                       f"{100 * num(r['setback_over_b']):.2g} % of b" for r in K if r["alpha"] != "0.05"), 7,
                   color="#333333")


def records(L):
    e = read("imperfection", "imperfection_eq27.csv")
    if not e:
        L.section("Imperfect blocks: eq. 27 on the shared records",
                  "Would compare eq. 27's share of non-conservative cases per to_k with imperfect blocks against "
                  "the perfect block's.")
        L.text("No imperfection_eq27.csv: the scene writes its record files only with the records folder "
               "(../shared/records or $ROCKING_RECORDS).", 8.5)
        return
    E = dict_rows(e)
    names = list(dict.fromkeys(r["imperfection"] for r in E))

    def draw(L, rect):
        axs = L.grid(rect, 1, 2, pad_l=0.62, pad_t=0.25, pad_b=0.5)
        w = 0.8 / len(names)
        for ax, (col, title) in zip(axs, (("share", "eq. 27 as the paper states it (perfect α, p)"),
                                          ("share_corners", "eq. 27 toward each corner of the imperfect block"))):
            for j, (c, n) in enumerate(zip(COLOURS, names)):
                rows = [r for r in E if r["imperfection"] == n]
                ax.bar([num(r["k"]) + (j - (len(names) - 1) / 2) * w for r in rows], [num(r[col]) for r in rows],
                       width=w, color=c, label=n)
            ax.set_xticks(range(1, 12))
            ax.set_xticklabels([f"to_{k}" for k in range(1, 12)], fontsize=6)
            ax.set_ylim(0, 1)
            ax.set_title(title, fontsize=7.5)
            ax.set_ylabel("share of cases non-conservative", fontsize=7)
            ax.tick_params(labelsize=6.5)
            ax.grid(True, axis="y", alpha=0.3)
        axs[0].legend(fontsize=6, loc="upper left", ncol=2)

    L.page("Imperfect blocks: eq. 27 on the shared records",
           "Compares eq. 27's share of non-conservative cases per to_k (a record overturning a block at a q below "
           "eq. 27's, the fragility scene's rule, on its four blocks and the shared records) with imperfect blocks "
           f"against the perfect block's ({verdicts(FINDINGS[1:]) or 'no finding yet'}); "
           f"{run_status(['imperfection'])}.")
    scene_status(L, "imperfection", e[0])
    L.figure(3.0, draw)
    header = ["to_k"] + names
    rows = []
    for k in range(1, 12):
        cells = [f"to_{k}"]
        for n in names:
            r = next(r for r in E if r["imperfection"] == n and int(num(r["k"])) == k)
            und = int(num(r["undecided"])) + int(num(r["undecided_corners"]))
            cells.append(f"{r['non_conservative']} / {r['non_conservative_corners']}" + (f" ({und}?)" if und else ""))
        rows.append(cells)
    L.text("Non-conservative cases of 64 (16 records x 4 blocks): eq. 27 as stated / toward each corner; '(n?)': n "
           "verdicts left undecided (an ill-conditioned first collapse whose grid gap holds eq. 27's q).", 8,
           weight="bold", gap=0.04)
    L.table(header, rows, [6] + [14] * len(names), size=6.5)
    if "columns" in e[0]:
        L.text(f"columns: {e[0]['columns']}", 7, color="#333333", gap=0.03)


def pages(L):
    closed_forms(L)
    records(L)
    if FINDINGS:
        entry_verdicts(L, FINDINGS)
