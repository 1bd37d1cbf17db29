"""The pages of the paper's Figures 4 to 8 (Sections 2-3): q1..q5 against x (Figure 4), θ/α
below the collapse PGA (5), the full eq. 1 against the linearised eq. 3 (6), q with N pulses
(7) and eq. 27 against the one-sine overturning threshold (8); each with its comparison with
expected/, the scene's model and solver, and the verdicts of its findings.  A figure whose
scene did not run is left out.
"""
from report_findings import entry_verdicts, verdicts
from report_outputs import col, read, run_status, scene_status, short


def figure4(L):
    """Figure 4: q1..q5 against x = p·to (scene fig04)."""
    f4 = read("fig04", "fig04.csv")
    if f4:
        def draw4(L, rect):
            ax = L.grid(rect, 1, 1, pad_l=0.7, pad_t=0.1)[0]
            x = col(f4, "x")
            for i in range(1, 6):
                ax.semilogy(x, col(f4, f"q{i}"), label=f"q{i} (eq. {[12, 15, 19, 22, 24][i - 1]})")
            ax.semilogy(x, col(f4, "q_min"), "k", lw=2.5, label="min")
            ax.axhline(2, ls="--", c="gray", label="q = 2 (cases 3, 5 need q ≥ 2)")
            ax.set_xlabel("x = p·to  [-]"); ax.set_ylabel("q = PGA/(α g)  [-]"); ax.set_ylim(1, 100)
            ax.grid(True, which="both", alpha=0.3); ax.legend(fontsize=7, loc="upper right")
        L.page("Figure 4: q1..q5 against x = p·to",
               "Compares q1..q5 of the closed forms (eqs. 12-24) and their minimum against x = p·to with the paper's "
               "Figure 4, whose claims are that the minimum is q4 below x = 0.51 and q2 above and that cases 3 and 5 "
               f"need q ≥ 2 ({verdicts(['C1', 'C2'])}); {run_status(['fig04'])}.")
        scene_status(L, "fig04", f4[0])
        L.figure(5.0, draw4)
        p4 = read("fig04", "fig04_points.csv")
        if p4:
            L.text("Marked points: " + "; ".join(f"{r[0]} at x = {float(r[1]):.4f}" for r in p4[2][:4]) + ".", 7.5)
        entry_verdicts(L, ["C1", "C2"])


def figure5(L):
    """Figure 5: θ/α below the collapse PGA, Rd < 1 (scene fig05)."""
    h5, s5 = read("fig05", "fig05_histories.csv"), read("fig05", "fig05_summary.csv")
    if h5:
        def draw5(L, rect):
            axs = L.grid(rect, 3, 3, pad_l=0.5, pad_t=0.25, pad_b=0.42)
            t = col(h5, "t_over_to")
            for ci, case in enumerate([1, 2, 4]):
                for xi, xv in enumerate(["0.2", "0.5", "0.8"]):
                    ax = axs[3 * ci + xi]
                    for rd in ["0.99", "0.90", "0.70"]:
                        ax.plot(t, col(h5, f"case{case}_x{xv}_Rd{rd}"), label=f"Rd {rd}")
                    ax.axhline(1, c="r", ls="--", lw=0.8); ax.axhline(-1, c="r", ls="--", lw=0.8)
                    ax.axvline(3 if case == 4 else 2, c="gray", ls=":")
                    ax.set_ylim(-2, 2); ax.set_title(f"case {case}, x = {xv}", fontsize=8)
                    ax.tick_params(labelsize=6)
                    ax.set_xlabel("t/to [-]", fontsize=7)
                    if xi == 0:
                        ax.set_ylabel("θ/α [-]", fontsize=7)
            axs[0].legend(fontsize=6, loc="lower left")
        L.page("Figure 5: θ/α below the collapse PGA (Rd < 1)",
               "Compares θ/α against t/to under the reduced inputs PGA = q_i α g Rd (Rd < 1; exact solver with "
               "impacts, restitution 1) with the paper's Figure 5, whose claim is no collapse for Rd < 1 "
               f"({verdicts(['F5a', 'F5b', 'F5c', 'F5d'])}); {run_status(['fig05'])}.")
        scene_status(L, "fig05", h5[0])
        L.text("Red dashed: θ = ±α; dotted: t_fin.", 7.5)
        L.figure(5.3, draw5)
        if s5:
            L.text("Collapses below the closed-form PGA (Rd < 1), x = 0.2..0.8 (fig05_summary.csv):", 8, gap=0.03)
            for crit in ("final-rotation", "peak-rotation", "overturning"):
                L.text(f"{crit}: " + "; ".join(f"case {r[0]} {r[3]}/{r[2]}" for r in s5[2] if r[1] == crit), 7.5,
                       indent=0.15, gap=0.03)
            L.y += 0.06
        entry_verdicts(L, ["F5a", "F5b", "F5c", "F5d"])


def figure6(L):
    """Figure 6: the full eq. 1 against the linearised eq. 3 (scene fig06)."""
    f6 = read("fig06", "fig06.csv")
    if f6:
        def draw6(L, rect):
            axs = L.grid(rect, 1, 3, pad_l=0.55, pad_t=0.28)
            a, to, H, full = col(f6, "alpha"), col(f6, "to"), col(f6, "H"), col(f6, "theta_tfin_full")
            for ax, tov in zip(axs, [0.1, 0.25, 0.5]):
                for av in [0.05, 0.1, 0.15, 0.2, 0.25]:
                    pts = [(h, f) for h, f, aa, tt in zip(H, full, a, to) if abs(aa - av) < 1e-9 and abs(tt - tov) < 1e-9]
                    ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=".", label=f"α {av}")
                ax.axhline(1, c="k", ls="--", lw=0.8)
                ax.set_title(f"to = {tov} s", fontsize=8); ax.set_xlabel("H (half-height) [m]", fontsize=7)
                ax.set_ylim(0.8, 1.01); ax.tick_params(labelsize=6)
            axs[0].set_ylabel("θ(t_fin)/α, full eq. 1 [-]", fontsize=7); axs[0].legend(fontsize=6, loc="lower right")
        L.page("Figure 6: full eq. 1 against linearised eq. 3",
               "Compares θ(t_fin)/α of the full eq. 1 with the linearised eq. 3 (dashed, 1 at the collapse PGA) for "
               "case 2 against the half-height H, as the paper's Figure 6, whose claims are that eq. 1 always gives "
               "less rotation, about 16 % less at H = 1 m and α = 0.25, negligibly less above 3 m, with p ≈ 1.6 s⁻¹ "
               f"at H = 1 m ({verdicts(['F6a', 'F6b', 'F6c', 'F6d'])}); {run_status(['fig06'])}.")
        scene_status(L, "fig06", f6[0])
        L.figure(3.3, draw6)
        entry_verdicts(L, ["F6a", "F6b", "F6c", "F6d"])


def figure7(L):
    """Figure 7: q with N pulses (scene fig07)."""
    f7 = read("fig07", "fig07.csv")
    if f7:
        def draw7(L, rect):
            axs = L.grid(rect, 3, 1, pad_l=0.7, pad_t=0.28, pad_b=0.45)
            x = col(f7, "x")
            for ax, case in zip(axs, [1, 2, 4]):
                for n in [2, 4, 6, 8, 10, 12]:
                    ax.semilogy(x, col(f7, f"case{case}_N{n}"), lw=2.5 if n == 6 else 1, label=f"N = {n}")
                ax.set_title(f"case {case}" + {2: " (N = 6: eq. 27)", 4: " (N = 6: eq. 28)", 1: " (N = 6: Coccia & Como)"}[case], fontsize=8)
                ax.set_ylim(1, 100); ax.set_ylabel("q [-]", fontsize=7); ax.grid(True, alpha=0.3); ax.tick_params(labelsize=6)
                ax.set_xlabel("x = p·to [-]", fontsize=7)
            axs[0].legend(fontsize=6, ncol=3, loc="upper right")
        L.page("Figure 7: q with N pulses",
               "Compares q of cases 1, 2 and 4 repeated to N = 2..12 pulses (the superposition engine) with the "
               "paper's Figure 7, whose claims are that q decreases with N, settles at 6 + 1 pulses and is lowest "
               f"for eq. 27 ({verdicts(['C3', 'C4', 'C5'])}); {run_status(['fig07'])}.")
        scene_status(L, "fig07", f7[0])
        L.figure(7.2, draw7)
        entry_verdicts(L, ["C3", "C4", "C5"])


def figure8(L):
    """Figure 8: eq. 27 against the one-sine overturning curve (scene fig08)."""
    f8, s8 = read("fig08", "fig08.csv"), read("fig08", "fig08_summary.csv")
    if f8:
        def draw8(L, rect):
            ax = L.grid(rect, 1, 1, pad_l=0.7, pad_t=0.1)[0]
            w = col(f8, "wp_over_p")
            ax.semilogy(w, col(f8, "q_eq27"), "r", lw=2.5, label="eq. 27")
            ax.semilogy(w, col(f8, "q_coccia_como"), "b", label="Coccia & Como")
            ax.semilogy(w, col(f8, "makris_lin_e1"), "k.-", label="one-sine threshold, linearised, e = 1")
            ax.semilogy(w, col(f8, "makris_lin_housner_a0.10"), "k--", lw=0.8, label="linearised, Housner e (α 0.1)")
            ax.semilogy(w, col(f8, "makris_full_e1_a0.25"), "g:", lw=1, label="full, e = 1 (α 0.25)")
            ax.semilogy(w, col(f8, "makris_full_housner_a0.25"), "m:", label="full, Housner e (α 0.25)")
            ax.semilogy(w, col(f8, "makris_fit"), c="orange", ls="-.", label="1 + ω/(6p)")
            ax.set_xlabel("ω_p/p = π/(p·to) [-]"); ax.set_ylabel("q or a_p/(α g) [-]"); ax.set_ylim(0.9, 30)
            ax.grid(True, which="both", alpha=0.3); ax.legend(fontsize=7, loc="upper left")
        L.page("Figure 8: eq. 27 against the one-sine overturning curve",
               "Compares eq. 27 against ω/p = π/(p·to) with the one-sine overturning threshold of Makris et al. "
               "(computed here, four variants) and Coccia & Como, as the paper's Figure 8, whose claim is that eq. 27 "
               f"offers a safety margin, particularly at high ω/p ({verdicts(['F8'])}); {run_status(['fig08'])}.")
        scene_status(L, "fig08", f8[0])
        L.figure(5.2, draw8)
        if s8:
            L.text("fig08_summary.csv: " + "; ".join(f"{r[0]}: {short(r[1])}" for r in s8[2]) + ".", 7.5)
        entry_verdicts(L, ["F8"])


def pages(L):
    """Figures 4 to 8, in the paper's order."""
    for page in (figure4, figure5, figure6, figure7, figure8):
        page(L)
