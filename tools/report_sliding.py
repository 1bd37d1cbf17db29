"""The pages of the sliding scene (issue 41): the paper's claims retested on a base with Coulomb friction.
Per (α, μ) how often sliding changes the outcome or the peak rotation on the shared records, against the
paper's "negligible below α = 0.35" (S1); eq. 27's non-conservative share per to_k with friction beside
the ideal and the full model's (S2); Figure 5's Rd < 1 on the full model and with friction (S3); the
closed forms the engine meets and the rows Siconos computed again.  Without the shared records the
record parts are missing, and the page says so.
"""
import csv
import math
import os

from matplotlib.lines import Line2D

import report_outputs as outputs
from report_findings import verdicts
from report_outputs import dict_rows, num, read, run_status, scene_status

MUS = ("0.8", "0.6", "0.4")
COLOURS = {"0.8": "#1f5fbf", "0.6": "#1a7f37", "0.4": "#b3261e", "full": "#555555", "ideal": "#999999"}


def claim_section(L, claim, verdict, control):
    C = dict_rows(claim)
    V = {r["mu"]: r for r in dict_rows(verdict)}
    alphas = sorted({r["alpha"] for r in C}, key=float)
    by = {(r["alpha"], r["mu"]): r for r in C}

    def draw(L, rect):
        x, y, w, h = rect
        axs = L.grid((x, y, w, h - 0.3), 1, 2, pad_l=0.62, pad_t=0.3, pad_b=0.45)
        for ax, what, label in ((axs[0], ("outcome_changed", "peak_changed"), "cases changed by sliding (of 64)"),
                                (axs[1], ("rocking_near_ties", "sliding_near_ties", "peak_near_ties"),
                                 "near-ties set apart (of 64)")):
            width = 0.012
            for i, mu in enumerate(MUS):
                xs = [float(a) + (i - 1) * width for a in alphas]
                ys = [sum(int(by[(a, mu)][c]) for c in what) for a in alphas]
                ax.bar(xs, ys, width=width, color=COLOURS[mu])
                tan_line = math.atan(float(mu))
                ax.axvline(tan_line, color=COLOURS[mu], ls=":", lw=0.9)
            ax.axvline(0.35, color="k", ls="--", lw=1)
            ax.set_xlabel("α [rad] (dashed: the paper's 0.35; dotted: tan α = μ)", fontsize=6.5)
            ax.set_ylabel(label, fontsize=6.5)
            ax.set_ylim(0, 64)
            ax.tick_params(labelsize=6)
            ax.grid(True, axis="y", alpha=0.25)
        axs[0].set_title("outcome or peak (> 5 %) changed", fontsize=7.5)
        axs[1].set_title("the rocking model's own near-ties, and sliding's", fontsize=7.5)
        handles = [Line2D([], [], c=COLOURS[m], lw=6) for m in MUS]
        L.legend(handles, [f"μ = {m}" for m in MUS], rect, 0.3, ncol=3)

    L.page("Sliding: \"negligible below α = 0.35\" on the shared records",
           "Compares the rocking-only full model (eq. 1, Housner's restitution) with the same block on Coulomb "
           "friction μ = 0.8, 0.6, 0.4 on the 16 records here, scaled to q = 1.5, 2, 3, 4, blocks 2 m tall of "
           f"α = 0.05-0.70 ({verdicts(['S1'])}); {run_status(['sliding'])}.")
    scene_status(L, "sliding", claim[0])
    L.text(f"rule: {claim[0].get('rule', '')}", 7, color="#333333")
    L.figure(3.0, draw)
    L.text("Per μ, below α = 0.35 (sliding_claim_verdict.csv):", 8, weight="bold", gap=0.04)
    L.table(["μ", "cases below 0.35", "changed", "near-ties", "smallest α with a change", "tan α there", "claim"],
            [[m, V[m]["cases_below_0.35"], V[m]["effects_below_0.35"], V[m]["ties_below_0.35"],
              V[m]["smallest_alpha_with_effect"], f"{num(V[m]['tan_alpha_there']):.3f}"
              if math.isfinite(num(V[m]["tan_alpha_there"])) else "-", V[m]["claim_below_0.35"]] for m in MUS if m in V],
            [5, 9, 7, 7, 12, 8, 6], size=7)
    K = dict_rows(control) if control else []
    if K:
        disagree = sum(int(r["control_disagrees"]) for r in K)
        tol = sum(int(r["full_tolerances_disagree"]) for r in K)
        within = sum(int(r["peak_within_1e-3"]) for r in K)
        safe = sum(int(r["safe_agreeing"]) for r in K)
        L.text(f"The control: the sliding engine at μ = 10⁶ against the full model (sliding_control.csv). Their "
               f"outcomes differ in {disagree} of {sum(int(r['cases']) for r in K)} cases and the full model's two "
               f"tolerances in {tol}; where all four runs stand, their peaks agree within 1e-3 in {within} of "
               f"{safe}. Where they disagree the case is a near-tie of the rocking model (right), never a sliding "
               "effect.", 7.5, color="#333333")
    worst = [r for r in C if num(r["alpha"]) < 0.35 and r["negligible"] == "no"]
    if worst:
        L.text("Below 0.35, sliding changes: " + "; ".join(
            f"α {r['alpha']}, μ {r['mu']}: {r['outcome_changed']} outcomes, {r['peak_changed']} peaks, the largest "
            f"peak change {100 * num(r['largest_peak_change']):.3g} %, the largest slip of a standing block "
            f"{1000 * num(r['largest_slip_standing_m']):.3g} mm" for r in worst) + ".", 8)


def eq27_section(L, eq27):
    E = dict_rows(eq27)
    models = ["ideal", "full", "0.8", "0.6", "0.4"]
    ks = sorted({int(r["k"]) for r in E})
    by = {(int(r["k"]), r["model"]): r for r in E}

    def draw(L, rect):
        x, y, w, h = rect
        ax = L.grid((x, y, w, h - 0.3), 1, 1, pad_l=0.62, pad_t=0.3, pad_b=0.45)[0]
        width = 0.16
        for i, m in enumerate(models):
            ax.bar([k + (i - 2) * width for k in ks], [num(by[(k, m)]["share"]) for k in ks], width=width,
                   color=COLOURS[m])
        ax.set_xticks(ks)
        ax.set_xticklabels([f"to_{k}" for k in ks], fontsize=6)
        ax.set_ylabel("non-conservative share of the 64 cases", fontsize=6.5)
        ax.set_ylim(0, 1)
        ax.tick_params(labelsize=6)
        ax.grid(True, axis="y", alpha=0.25)
        handles = [Line2D([], [], c=COLOURS[m], lw=6) for m in models]
        L.legend(handles, ["ideal (linearised, F11b)", "full (μ = 10⁶)"] + [f"μ = {m}" for m in MUS], rect, 0.3,
                 ncol=5)

    L.section("Sliding: eq. 27's non-conservative share per to_k with friction",
              "Compares eq. 27 against each record's first collapse q on the fragility scene's four blocks under the "
              f"ideal model, the rocking-only full one and friction μ = 0.8, 0.6, 0.4 ({verdicts(['S2'])}).",
              room=3.8)
    L.text(f"model: {eq27[0].get('model', '')}", 7, color="#333333", gap=0.03)
    L.text(f"solver: {eq27[0].get('solver', '')}", 7, color="#333333")
    L.figure(2.8, draw)
    moved = [(k, m, by[(k, m)]) for k in ks for m in MUS if by[(k, m)]["more_than_full"] != "0" or
             by[(k, m)]["fewer_than_full"] != "0"]
    L.text("Verdicts friction moves against the full model: " + ("; ".join(
        f"to_{k} at μ = {m}: {r['more_than_full']} more, {r['fewer_than_full']} fewer" for k, m, r in moved)
        if moved else "none") + ".", 8)


def fig05_section(L, summary):
    S = dict_rows(summary)
    fr = [r for r in S if r["criterion"] == "final-rotation"]
    alphas = sorted({r["alpha"] for r in fr}, key=float)
    rows = []
    for a in alphas:
        for c in range(1, 6):
            here = {r["model"]: r for r in fr if r["alpha"] == a and r["case"] == str(c)}
            if not here:
                continue
            full = here.get("full")
            rows.append([a, str(c), full["points"], full["collapses"]] +
                        [f"{here[m]['caused_by_sliding']}" + (f" (Rd ≥ {num(here[m]['lowest_Rd_caused']):.3g}, "
                                                              f"{num(here[m]['lowest_pga_g_caused']):.2g} g)"
                                                              if here[m]["caused_by_sliding"] != "0" else "")
                         for m in MUS] + [full["outside_model"]])
    L.section("Sliding: Figure 5's Rd < 1 with friction",
              "Compares, under the paper's criterion |θ(t_fin)| ≥ α, Figure 5's points on the rocking-only full model "
              "(Housner's restitution) with the same block on friction μ = 0.8, 0.6, 0.4, whose impacts are physical "
              f"({verdicts(['S3'])}).", room=3.0)
    L.text("Per block (2 m tall) and case: the points, the full model's collapses, and the collapses sliding causes "
           "at each μ (with the lowest Rd and PGA); outside: points where the control leaves the ground or has no "
           "consistent contact force (sliding_fig05_summary.csv; the peak and overturning criteria are there too).",
           7.5, color="#333333")
    L.table(["α", "case", "points", "full", "μ = 0.8", "μ = 0.6", "μ = 0.4", "outside"], rows,
            [4, 4, 5, 4, 14, 14, 14, 5], size=6.5)


def truth_section(L, truth, siconos):
    T = dict_rows(truth)
    n = {k: [r for r in T if r["check"] == k] for k in ("regime", "newmark", "no-rock")}
    agree = sum(r["engine"] == r["closed_form"] for r in n["regime"])
    worst = max((abs(num(r["engine"]) - num(r["closed_form"])) for r in n["newmark"]), default=math.nan)
    L.section("Sliding: the closed forms, and the rows Siconos computed again",
              "Compares the sliding engine with closed forms, and the scene's decisive rows with a second method.",
              room=1.5)
    L.text(f"Regime from rest (sliding_truth.csv): {agree} of {len(n['regime'])} grid points enter the regime the "
           f"criteria give; Newmark's slip: {len(n['newmark'])} runs within {worst:.2g} m of the closed form; "
           f"no rocking below tan α: {sum(r['engine'] == '0' for r in n['no-rock'])} of {len(n['no-rock'])} runs.", 8)
    if siconos:
        R = dict_rows(siconos)
        for part, what in (("a", "record rows deciding S1"), ("fig05", "Figure 5 verdicts deciding S3")):
            rows = [r for r in R if r["part"] == part]
            if rows:
                L.text(f"Siconos (expected/sliding/siconos.csv), {what}: {sum(r['verdict'] == 'agree' for r in rows)} "
                       f"of {len(rows)} agree with the engine in every grid offset at its two finest steps.", 8)


def pages(L):
    """The sliding scene's pages; the record parts only with the shared records."""
    claim, verdict = read("sliding", "sliding_claim.csv"), read("sliding", "sliding_claim_verdict.csv")
    truth = read("sliding", "sliding_truth.csv")
    summary = read("sliding", "sliding_fig05_summary.csv")
    if not truth:
        L.section("Sliding: the paper's claims on a Coulomb base", "Would compare the block on friction with the paper's.")
        L.text(f"No sliding_truth.csv in {outputs.OUT}/sliding: the scene did not run.", 8.5)
        return
    if claim and verdict:
        claim_section(L, claim, verdict, read("sliding", "sliding_control.csv"))
    else:
        L.page("Sliding: the paper's claims on a Coulomb base",
               f"The record parts need the shared records folder (../shared/records); {run_status(['sliding'])}.")
        scene_status(L, "sliding", truth[0])
    eq27 = read("sliding", "sliding_eq27.csv")
    if eq27:
        eq27_section(L, eq27)
    if summary:
        fig05_section(L, summary)
    # Siconos's rows are made by hand (expected/sliding/siconos_rows.py), not by the scene: the expected copy.
    sic_path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "expected", "sliding", "siconos.csv")
    siconos = None
    if os.path.exists(sic_path):
        with open(sic_path, newline="") as f:
            lines = [l for l in f if not l.startswith("#")]
        rows = list(csv.reader(lines))
        siconos = ({}, rows[0], rows[1:])
    truth_section(L, truth, siconos)
