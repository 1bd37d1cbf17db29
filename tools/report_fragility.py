"""The pages of the fragility study (scene fragility, issue 28): for each block (α, p) the
lognormal fragility curve fitted to the records' first collapse q, its bootstrap band and the
empirical share overturned, then eq. 27's share of non-conservative cases per definition to_k
of the half-period; first over the shared records (F11b), then over the synthetic pulses and
stochastic records (F11c) with the pulses' own half-periods.  fragility_section draws one such
group of pages from a set of four files; a later run's extra text column (group_label) marks a
set of rows drawn in its own colour.
"""
import math

from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle

import report_outputs as outputs
from report_findings import BY_ID, entry_verdicts, verdicts
from report_layout import plain_log_ticks
from report_outputs import dict_rows, num, read, run_status, scene_status, short


def group_label(row, known):
    """A set label from the columns a later run may add (a text column beside the known ones, such as
    one naming synthetic records): '' when there is none, so that today's files form one group."""
    return ", ".join(f"{k} {v}" for k, v in row.items()
                     if k not in known and v not in ("", "-") and not math.isfinite(num(v)) and v != "nan")


# The columns the fragility pages know; any other text column marks a set of rows (group_label).
FIT_COLUMNS = ["alpha", "p", "records", "collapsed", "censored", "ill_conditioned", "median", "beta",
               "log_likelihood", "median_lo", "median_hi", "beta_lo", "beta_hi", "median_ill", "beta_ill",
               "log_likelihood_ill", "median_lo_ill", "median_hi_ill", "beta_lo_ill", "beta_hi_ill", "resamples",
               "seed", "level"]
EQ27_COLUMNS = ["k", "non_conservative", "cases", "share", "wilson_lo", "wilson_hi", "boot_lo", "boot_hi",
                "blocks_with_any"]


def phi_cdf(z):
    return 0.5 * math.erfc(-z / math.sqrt(2))


# Line and band colours of a set of records (group_label); a set not named here is drawn in purple.
SET_COLOURS = {"": ("#b3261e", "#f2b8b5"), "set pulse": ("#1f5fbf", "#b9cdee"),
               "set stochastic": ("#1a7f37", "#b7dfc0")}


def fragility_section(L, title, compares, files, what, pts_text, extra=None):
    """One page group: the fits per block (the sets of a file overlaid, one colour a set), the eq. 27 shares."""
    fr_fit, fr_emp, fr_27, fr_pts = (read("fragility", n) for n in files)
    if not fr_fit:
        return False
    FITS = dict_rows(fr_fit)
    known_fit = set(FIT_COLUMNS)
    EMP = dict_rows(fr_emp) if fr_emp else []
    blocks, sets = [], []
    for r in FITS:
        if (r["alpha"], r["p"]) not in blocks:
            blocks.append((r["alpha"], r["p"]))
        if group_label(r, known_fit) not in sets:
            sets.append(group_label(r, known_fit))

    def fit_of(r):
        """(median, beta, lo/hi of each, ill): the block's fit, or its fit with the ill-conditioned point."""
        for suffix, ill in (("", False), ("_ill", True)):
            m, b = num(r.get("median" + suffix)), num(r.get("beta" + suffix))
            if math.isfinite(m) and math.isfinite(b):
                return (m, b, [num(r.get(f"median_lo{suffix}")), num(r.get(f"median_hi{suffix}"))],
                        [num(r.get(f"beta_lo{suffix}")), num(r.get(f"beta_hi{suffix}"))], ill)
        return None

    def draw_fragility(L, rect):
        ncol = 2 if len(blocks) > 1 else 1
        nrow = (len(blocks) + ncol - 1) // ncol
        x, y, w, h = rect
        axs = L.grid((x, y, w, h - 0.4), nrow, ncol, pad_l=0.6, pad_t=0.18 + 0.13 * (len(sets) + 1),
                     pad_b=0.45)
        q_hi = max([20.0] + [num(r["q"]) for r in EMP if math.isfinite(num(r["q"]))])
        qs = [math.exp(math.log(q_hi) * i / 300) for i in range(301)]
        for ax, (a, p) in zip(axs, blocks):
            title = f"α = {a}, p = {p} rad/s"
            counts = []
            for grp in sets:
                line, band = SET_COLOURS.get(grp, ("#6a3d9a", "#d9c8ea"))
                rows = [r for r in FITS if (r["alpha"], r["p"], group_label(r, known_fit)) == (a, p, grp)]
                fit = fit_of(rows[0]) if rows else None
                name = grp.replace("set ", "") + ": " if grp else ""
                if fit:
                    m, b, mlh, blh, ill = fit
                    ax.plot(qs, [phi_cdf(math.log(q / m) / b) for q in qs], c=line, lw=1.6,
                            ls="--" if ill else "-")
                    if all(math.isfinite(v) for v in mlh + blh):
                        corners = [(mm, bb) for mm in mlh for bb in blh]
                        env = [[phi_cdf(math.log(q / mm) / bb) for mm, bb in corners] for q in qs]
                        ax.fill_between(qs, [min(e) for e in env], [max(e) for e in env], color=band,
                                        alpha=0.55 if len(sets) > 1 else 0.7, lw=0)
                    title += (f"\n{name}median {m:.3g} [{mlh[0]:.3g}, {mlh[1]:.3g}], β {b:.3g} "
                              f"[{blh[0]:.3g}, {blh[1]:.3g}]" + (" (with its ill-conditioned point)" if ill else ""))
                else:
                    title += f"\n{name}no fit"
                em = [r for r in EMP if (r["alpha"], r["p"]) == (a, p)
                      and group_label(r, {"alpha", "p", "q", "share"}) == grp]
                ax.plot([num(r["q"]) for r in em], [num(r["share"]) for r in em], "o",
                        c="k" if len(sets) == 1 else line, ms=3)
                if rows:
                    counts.append(f"{name}{rows[0].get('records', '?')} records: {rows[0].get('collapsed', '?')} "
                                  f"overturn, {rows[0].get('censored', '?')} censored")
            ax.set_xscale("log")
            ax.set_xlim(1, q_hi)
            plain_log_ticks(ax)
            ax.set_ylim(0, 1.02)
            ax.set_title(title, fontsize=6.5 if len(sets) > 1 else 7)
            ax.set_xlabel("q = PGA/(α g) [-]", fontsize=6.5)
            ax.set_ylabel("P(overturn | q)", fontsize=6.5)
            ax.tick_params(labelsize=6)
            ax.grid(True, which="both", alpha=0.25)
            ax.text(0.98, 0.04, "\n".join(counts), transform=ax.transAxes, ha="right", va="bottom", fontsize=5.5)
        if len(sets) == 1:
            handles = [Line2D([], [], c="#b3261e", lw=1.6), Rectangle((0, 0), 1, 1, color="#f2b8b5"),
                       Line2D([], [], ls="", marker="o", c="k", ms=3),
                       Line2D([], [], c="#b3261e", lw=1.6, ls="--")]
            labels = ["lognormal fit (maximum likelihood, censored kept)",
                      "bootstrap band (curves over the 90 % intervals of median and β)",
                      "empirical share", "fit with an ill-conditioned first collapse"]
        else:
            handles, labels = [], []
            for grp in sets:
                line, band = SET_COLOURS.get(grp, ("#6a3d9a", "#d9c8ea"))
                handles += [Line2D([], [], c=line, lw=1.6, marker="o", ms=3)]
                labels += [f"{grp.replace('set ', '')}: lognormal fit, empirical share (points), bootstrap band"]
        L.legend(handles, labels, rect, 0.3, ncol=2)

    L.page(title, compares)
    scene_status(L, "fragility", fr_fit[0])
    if fr_pts:
        PTS = dict_rows(fr_pts)
        n_checks = {}
        for r in PTS:
            n_checks[r.get("check", "-")] = n_checks.get(r.get("check", "-"), 0) + 1
        L.text(f"{files[3]}: {len(PTS)} (record, block) points {pts_text}; their first-collapse brackets: "
               + ", ".join(f"{v} {k}" for k, v in sorted(n_checks.items()) if k != "-")
               + f"; {n_checks.get('-', 0)} censored (no collapse up to q_max).", 8)
    band_note = "The band is the envelope of the lognormal curves over the rectangle of the bootstrap's " \
                "percentile intervals of median and β (marginal intervals, not a joint band)."
    L.figure(min(7.0, 0.4 + 0.13 * len(sets) + 3.2 * ((len(blocks) + 1) // 2)), draw_fragility)
    L.text(band_note, 7, color="#333333")
    if extra:
        extra(L)

    if fr_27:
        E27 = dict_rows(fr_27)
        known_27 = set(EQ27_COLUMNS)
        groups = list(dict.fromkeys(group_label(r, known_27) for r in E27))
        intervals = [(lo, hi, name) for lo, hi, name in
                     (("wilson_lo", "wilson_hi", "Wilson 95 %"), ("boot_lo", "boot_hi", "bootstrap"))
                     if lo in fr_27[1] and hi in fr_27[1]]
        # any other *_lo / *_hi pair a later run may add
        for c in fr_27[1]:
            if c.endswith("_lo") and c[:-3] + "_hi" in fr_27[1] and c not in [i[0] for i in intervals]:
                intervals.append((c, c[:-3] + "_hi", c[:-3]))

        def draw27(L, rect):
            ax = L.grid(rect, 1, 1, pad_l=0.65, pad_t=0.12, pad_b=0.5)[0]
            n = len(groups) * max(1, len(intervals))
            w = 0.7 / max(n, 1)
            colours = ["#1f5fbf", "#b3261e", "#1a7f37", "#9a6700", "#6a3d9a", "#444444"]
            j = 0
            for g in groups:
                rows = [r for r in E27 if group_label(r, known_27) == g]
                for lo, hi, name in intervals or [(None, None, "")]:
                    off = (j - (n - 1) / 2) * w
                    ks = [num(r["k"]) + off for r in rows]
                    sh = [num(r["share"]) for r in rows]
                    lab = " ".join(v for v in (g.replace("set ", ""), name) if v)
                    if lo:
                        err = [[max(0.0, s - num(r[lo])) for s, r in zip(sh, rows)],
                               [max(0.0, num(r[hi]) - s) for s, r in zip(sh, rows)]]
                        ax.errorbar(ks, sh, yerr=err, fmt="o", ms=4 if n <= 2 else 3, capsize=2.5 if n <= 2 else 1.5,
                                    lw=1, c=colours[j % len(colours)],
                                    label=f"share, {lab} interval" if lab else "share")
                    else:
                        ax.plot(ks, sh, "o", c=colours[j % len(colours)], label="share")
                    j += 1
            if any(num(r["k"]) == 5 for r in E27):
                ax.axvspan(4.6, 5.4, color="#e8e8e8", lw=0, zorder=0)
                ax.text(5, 0.01, "the paper's to_5", ha="center", va="bottom", fontsize=6)
            ax.set_xticks(sorted({int(num(r["k"])) for r in E27}))
            ax.set_xticklabels([f"to_{int(num(r))}" for r in sorted({num(r['k']) for r in E27})], fontsize=6.5)
            # room above 1 for the legend, which would otherwise cover the largest shares
            ax.set_ylim(0, 1.04 + 0.075 * math.ceil(j / 2))
            ax.set_yticks([0, 0.2, 0.4, 0.6, 0.8, 1.0])
            ax.set_ylabel("share of cases non-conservative", fontsize=7)
            ax.set_xlabel("definition of the half-period", fontsize=7)
            ax.tick_params(labelsize=6.5)
            ax.grid(True, axis="y", alpha=0.3)
            ax.legend(fontsize=6.5, loc="upper center", ncol=2 if n <= 4 else 3, frameon=False)

        L.need(4.2)
        L.text(f"Eq. 27's share of non-conservative cases per to_k ({files[2]}){what}: a case (record, block) is "
               "non-conservative when its first collapse q lies below eq. 27's q at x = p·to_k; a censored record "
               "never is.", 8, weight="bold", gap=0.04)
        L.figure(3.0 + 0.15 * max(0, len(groups) - 1), draw27)
        header = ["to_k"] + (["set"] if any(groups) else []) + ["non-conservative", "share"] \
            + [name + " interval" for _, _, name in intervals] + (["blocks with any"] if "blocks_with_any" in fr_27[1] else [])
        rows = []
        for r in E27:
            g = group_label(r, known_27)
            rows.append([f"to_{int(num(r['k']))}"] + ([g.replace("set ", "")] if any(groups) else [])
                        + [f"{r['non_conservative']} of {r['cases']}", short(r["share"], 3)]
                        + [f"[{short(r[lo], 3)}, {short(r[hi], 3)}]" for lo, hi, _ in intervals]
                        + ([r["blocks_with_any"]] if "blocks_with_any" in r else []))
        L.table(header, rows, [6] + ([10] if any(groups) else []) + [12, 7] + [12] * len(intervals)
                + ([9] if "blocks_with_any" in fr_27[1] else []), size=7)
        for key in ["columns", "margin", "pulse half-period"] + [f"margin {g.replace('set ', '')}" for g in groups]:
            if key in fr_27[0]:
                L.text(f"{key}: {fr_27[0][key]}", 7, color="#333333", gap=0.03)
    return True


def pulse_table(L):
    """Which to_k recover each pulse's own half-period (fragility_synthetic_records.csv)."""
    recs = read("fragility", "fragility_synthetic_records.csv")
    if not recs:
        return
    R = [r for r in dict_rows(recs) if r.get("to_pulse", "-") != "-"]
    if not R:
        return
    L.need(1.2 + 0.16 * len(R))
    L.text("The pulses' half-periods (fragility_synthetic_records.csv): to_k / (T_p/2) for the paper's to_5 and the "
           "velocity measures, which to_k lie within 5 % of T_p/2 and the closest (docs/synthetic.md has the "
           "same ratios over 36 pulses).", 8, weight="bold", gap=0.04)

    def name(label):
        f = dict(kv.split("=", 1) for kv in label.split() if "=" in kv)
        nu = num(f.get("nu"))
        nu_text = "π/2" if abs(nu - math.pi / 2) < 1e-12 else f"{nu:g}"
        return f"T_p {1 / num(f['fp']):g} s, γ {f['gamma']}, ν {nu_text}"

    L.table(["pulse", "T_p/2 [s]", "to_5", "to_7", "to_9", "to_11", "within 5 %", "closest"],
            [[name(r["record"]), short(r["to_pulse"], 4)]
             + [f"{num(r['to_' + k]) / num(r['to_pulse']):.3f}" for k in ("5", "7", "9", "11")]
             + [" ".join("to_" + k for k in r["recovers"].split()) if r["recovers"] != "none" else "none",
                f"to_{r['closest']} ({num(r['closest_ratio']):.4f})"] for r in R],
            [22, 8, 6, 6, 6, 6, 18, 14], size=6.5)


def pages(L):
    """The fragility over the shared records (F11b), then over the synthetic set (F11c)."""
    if fragility_section(
            L,
            "Fragility over the shared records, and eq. 27 at scale",
            "Compares, for each block (α, p), the lognormal fragility curve fitted to the records' first collapse q "
            "(incremental dynamic analysis, q = PGA/(α g) from 1 to 20; linearised eq. 3, exact solver, Housner's "
            "restitution, overturning) with the empirical share of records overturned, and then eq. 27 with the "
            f"same collapse points for every definition to_k of the half-period ({verdicts(['F11b'])}); "
            f"{run_status(['fragility'])}.",
            ("fragility_fits.csv", "fragility_empirical.csv", "fragility_eq27.csv", "fragility_points.csv"),
            "", "of the shared records"):
        entry_verdicts(L, ["F11b"])
    else:
        L.section("Fragility over the shared records, and eq. 27 at scale",
               "Would compare each block's lognormal fragility curve with the records' empirical share, and eq. 27's "
               "share of non-conservative cases per to_k.")
        L.text(f"No fragility_fits.csv in {outputs.OUT}/fragility: the scene writes its shared records' files only "
               "with the records folder (../shared/records or $ROCKING_RECORDS); its synthetic set follows.", 8.5)

    fragility_section(
        L,
        "Fragility over the synthetic set, and eq. 27 on pulses and stochastic records",
        "Compares the same blocks and the same study on records generated at run time: 10 Mavroeidis & "
        "Papageorgiou (2003) near-fault pulses (T_p 0.5-3.125 s, two shapes) and 10 Rezaeian & Der Kiureghian "
        "(2008) stochastic far-field records (the documented defaults, seeds 1-10), each set fitted and bootstrapped "
        "on its own; then eq. 27 per set, and for the pulses the half-period they truly have "
        f"({verdicts(['F11c'])}); {run_status(['fragility'])}." if "F11c" in BY_ID else
        "Compares the same blocks and the same study on records generated at run time: 10 Mavroeidis & "
        "Papageorgiou (2003) near-fault pulses and 10 Rezaeian & Der Kiureghian (2008) stochastic records, each "
        f"set fitted and bootstrapped on its own; then eq. 27 per set; {run_status(['fragility'])}.",
        ("fragility_synthetic_fits.csv", "fragility_synthetic_empirical.csv", "fragility_synthetic_eq27.csv",
         "fragility_synthetic_points.csv"),
        " per set (pulse, stochastic, and both: synthetic)", "of the synthetic set", extra=pulse_table)
    if "F11c" in BY_ID:
        entry_verdicts(L, ["F11c"])
