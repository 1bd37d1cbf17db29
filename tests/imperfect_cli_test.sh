#!/usr/bin/env bash
# Imperfect blocks from the command line and Python (issue 41): --lean,
# --out-of-plumb, --fc, --density.  Each corner's geometry against the
# formulas recomputed here (NTC 2018 eq. 7.8.2's setback included); the
# collapse of a leaning block under case 2 at eq. 15's PGA on its weaker
# corner, evaluated here; the set-back block's uplift at tan(alpha') =
# b'/h; Python's simulate equal to --json; a spectrum and an IDA of a
# leaning block whose every boundary simulate confirms on either side; the
# refusals.
#
#   tests/imperfect_cli_test.sh ROCKING [PYTHONPATH]
set -u
rocking="$1"
pypath="${2:-}"
py=/usr/bin/python3
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# The corners of a 0.4 x 3 m wall 0.02 rad out of plumb, pivots set back by fc 2 MPa.
"$rocking" simulate --case 2 --x 1 --rd 0.5 --thickness 0.4 --height 3 --out-of-plumb 0.02 --fc 2 --density 2000 \
    --json >"$tmp/g.json" || { echo "FAIL: simulate --out-of-plumb --fc"; fail=1; }
if $py - "$tmp/g.json" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))["imperfection"]
g, b, h, phi, fc, rho = 9.81, 0.2, 1.5, 0.02, 2e6, 2000.0
sigma0 = rho * g * 2 * h
mu_ntc = (2 * b) ** 2 * sigma0 / 2 * (1 - sigma0 / (0.85 * fc))   # NTC 2018 eq. 7.8.2, per unit thickness
bp = mu_ntc / (sigma0 * 2 * b)                                     # the weight's arm about the pivot
e = h * math.tan(phi)
k2 = (b * b + e * e + h * h) / 3
rp, rm = (e - bp, h), (e + bp, h)
for key, r, side in (("corner_plus", rp, 1), ("corner_minus", rm, -1)):
    R = math.hypot(*r)
    want = {"alpha": math.atan2(-side * r[0], r[1]), "R": R, "p": math.sqrt(g * R / (k2 + R * R)),
            "restitution_onto": (k2 + rp[0] * rm[0] + h * h) / (k2 + R * R)}
    for k, v in want.items():
        assert abs(d[key][k] - v) < 1e-12 * abs(v), (key, k, d[key][k], v)
assert abs(d["setback_m"] - (b - bp)) < 1e-15 and abs(d["sigma0_kpa"] - sigma0 / 1e3) < 1e-9, d
PY
then echo "ok: corners and setback against NTC 2018 eq. 7.8.2"; else echo "FAIL: corners and setback"; fail=1; fi

# A block 0.1 rad leaning 0.02 rad rocks under case 2 on its corner theta > 0 (alpha 0.08):
# eq. 15 at x = p to gives its collapse PGA q2 alpha_+ g; just above it theta(t_fin) passes
# alpha_+, just below it does not (final-rotation criterion, no impact).
if $py - "$rocking" <<'PY'
import json, math, subprocess, sys
rocking = sys.argv[1]
x = 1.3
c = math.cosh(x)
q2 = (4 * c * c - 2) / (4 * c * c - 3 * c - 1)                    # eq. 15
pga = q2 * (0.1 - 0.02)
def run(f):
    out = subprocess.run([rocking, "simulate", "--case", "2", "--x", repr(x), "--pga", repr(pga * f), "--alpha", "0.1",
                          "--height", "2", "--lean", "0.02", "--criterion", "final-rotation", "--json"],
                         capture_output=True, check=True).stdout
    return json.loads(out)
hi, lo = run(1 + 1e-9), run(1 - 1e-9)
assert hi["collapse"] and not lo["collapse"], (hi["collapse"], lo["collapse"])
assert hi["peak_plus_over_alpha_plus"] >= 1 - 1e-7, hi["peak_plus_over_alpha_plus"]
assert hi["peak_minus_over_alpha_minus"] == 0
assert "imperfect, on theta < 0: alpha = 0.12" in hi["model"], hi["model"]
PY
then echo "ok: a leaning block collapses at eq. 15's PGA on its weaker corner"; else echo "FAIL: eq. 15 on the leaning block"; fail=1; fi

# Pivots set back: the full equation's block lifts above tan(alpha') = b'/h, not below.
if $py - "$rocking" <<'PY'
import json, subprocess, sys
rocking = sys.argv[1]
g, b, h, fc, rho = 9.81, 0.15, 1.0, 1.0e6, 1800.0
sigma0 = rho * g * 2 * h
thr = b * (1 - sigma0 / (0.85 * fc)) / h
def lifts(f):
    out = subprocess.run([rocking, "simulate", "--train", "1:1", "--to", "0.5", "--pga", repr(thr * f), "--thickness",
                          "0.3", "--height", "2", "--model", "full", "--fc", "1", "--json"], capture_output=True, check=True).stdout
    return json.loads(out)["max_theta_input_over_alpha"] > 0
assert lifts(1 + 1e-6) and not lifts(1 - 1e-6)
PY
then echo "ok: the set-back block lifts at b'/h"; else echo "FAIL: set-back uplift"; fail=1; fi

# Python's simulate(imperfection=...) is rocking simulate --json.
if [[ -n "$pypath" ]]; then
    "$rocking" simulate --case 4 --x 2 --rd 1.2 --alpha 0.15 --p 2 --lean -0.01 --out-of-plumb 0.015 --json >"$tmp/c.json"
    if PYTHONPATH="$pypath" $py - "$tmp/c.json" <<'PY'
import json, sys
import rocking_q as rq
cli = json.load(open(sys.argv[1]))
d = rq.simulate(case=4, x=2, rd=1.2, alpha=0.15, p=2, imperfection={"lean": -0.01, "out_of_plumb": 0.015})
for k in ("model", "collapse", "impacts", "max_theta_input_over_alpha", "peak_plus_over_alpha_plus",
          "peak_minus_over_alpha_minus", "imperfection", "collapse_peak_rotation"):
    assert d[k] == cli[k], (k, d[k], cli[k])
for bad, msg in (({"lean": 1}, "imperfection['lean']: an angle"), ({"tilt": 0.1}, "unknown key 'tilt'"),
                 ({"density": 2000}, "imperfection['density'] goes with imperfection['fc']")):
    try:
        rq.simulate(case=4, x=2, rd=1.2, alpha=0.15, p=2, imperfection=bad)
        raise SystemExit("accepted %r" % bad)
    except ValueError as e:
        assert msg in str(e), (msg, str(e))
PY
    then echo "ok: Python simulate(imperfection=) is --json"; else echo "FAIL: Python simulate(imperfection=)"; fail=1; fi
fi

# A leaning block's spectrum and IDA on a synthetic record: every boundary confirmed by
# simulate --lean on either side; the model states the lean.
"$rocking" record synth --stochastic 3 --dt 0.01 --duration 15 --output "$tmp/s.txt" >/dev/null || { echo "FAIL: synth"; exit 1; }
"$rocking" spectrum "$tmp/s.txt" --unit m/s2 --alpha 0.1 --points 30 --p-min 1 --p-max 10 --lean 0.03 --json >"$tmp/sp.json" \
    || { echo "FAIL: spectrum --lean"; fail=1; }
"$rocking" fragility "$tmp/s.txt" --unit m/s2 --alpha 0.1 --p 4 --points 30 --q-max 5 --lean 0.03 --json >"$tmp/fr.json" \
    || { echo "FAIL: fragility --lean"; fail=1; }
if $py - "$tmp/sp.json" "$tmp/fr.json" "$rocking" "$tmp/s.txt" <<'PY'
import json, subprocess, sys
sp, fr = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
rocking, record = sys.argv[3], sys.argv[4]
def falls(*args):
    out = subprocess.run([rocking, "simulate", "--record", record, "--unit", "m/s2", "--lean", "0.03", "--alpha", "0.1", *args,
                          "--json"], capture_output=True, check=True).stdout
    return json.loads(out)["collapse_overturning"]
for d in (sp, fr):
    assert "lean 0.03 rad" in d["model"], d["model"]
seen = 0
for iv in sp["spectra"][0]["intervals"]:
    for end in ("lower", "upper"):
        b = iv.get(end)
        if b:
            assert falls("--p", repr(b["p_collapse"])) and not falls("--p", repr(b["p_safe"])), (end, b)
            seen += 1
assert seen >= 1, sp["spectra"][0]["intervals"]
ida = fr["blocks"][0]["records"][0]
assert ida["collapsed"] and ida["point_check"]["confirmation"] == "confirmed", ida
for iv in ida["intervals"][:3]:
    for end in ("lower", "upper"):
        b = iv.get(end)
        if b:
            assert falls("--p", "4", "--q", repr(b["q_collapse"])) and not falls("--p", "4", "--q", repr(b["q_safe"])), (end, b)
PY
then echo "ok: a leaning block's spectrum and IDA boundaries"; else echo "FAIL: leaning spectrum and IDA"; fail=1; fi

# The stripes of a leaning block start where it lifts (q_start), on the command line as in
# Python: the IDAs read back from the engine's rows used to start at q_min = 1, so the first
# stripe ran from 1 and its fit moved (issue 42's review, 2026-11-26).
"$rocking" record synth --stochastic 5 --dt 0.01 --duration 15 --output "$tmp/s5.txt" >/dev/null
"$rocking" fragility "$tmp/s.txt" "$tmp/s5.txt" --unit m/s2 --alpha 0.1 --p 4 --points 30 --q-max 5 --lean 0.03 \
    --method refine --width 1e-3 --json >"$tmp/stripes.json" || { echo "FAIL: fragility --lean --method refine"; fail=1; }
if $py - "$tmp/stripes.json" <<'PY'
import json, sys
b = json.load(open(sys.argv[1]))["blocks"][0]
assert abs(b["q_start"] - 0.07 / 0.1) < 1e-12, b["q_start"]  # (alpha - lean) / alpha
assert b["stripes"][0]["from"] == b["q_start"], (b["stripes"][0], b["q_start"])
PY
then echo "ok: a leaning block's stripes start at its q_start"; else echo "FAIL: a leaning block's stripes"; fail=1; fi

# The outputs that a probe found wrong (2026-11-26): with a setback alone each side's peak read
# 0; --restitution housner took the nominal alpha's on both corners; input_lifts_block read the
# nominal alpha; the JSON's p was corner +1's.
if $py - "$rocking" "$tmp" <<'PY'
import json, subprocess, sys
rocking, tmp = sys.argv[1], sys.argv[2]
def sim(*args):
    return json.loads(subprocess.run([rocking, "simulate", *args, "--json"], capture_output=True, check=True).stdout)
d = sim("--case", "2", "--x", "1", "--rd", "1.01", "--alpha", "0.2", "--p", "2", "--fc", "1")
alpha_set_back = d["imperfection"]["corner_plus"]["alpha"]
assert "peak_plus_over_alpha_plus" not in d
assert abs(d["peak_over_own_alpha"] - d["max_theta_input_over_alpha"] * 0.2 / alpha_set_back) < 1e-12, d
assert d["p"] == 2, d["p"]
w = ["--record", tmp + "/s.txt", "--unit", "m/s2", "--alpha", "0.16", "--p", "2", "--out-of-plumb", "0.03", "--q", "1.4"]
h, n = sim(*w, "--restitution", "housner"), sim(*w)
assert h == n, [k for k in n if h.get(k) != n[k]]
g = sim(*w, "--restitution", "0.9")
assert g["imperfection"]["corner_plus"]["restitution_onto"] == 0.9 == g["imperfection"]["corner_minus"]["restitution_onto"]
with open(tmp + "/c.txt", "w") as f:
    f.write("-0.2249\n" * 50)     # below the corner -1's alpha 0.25, above the nominal 0.2
c = sim("--record", tmp + "/c.txt", "--unit", "g", "--record-dt", "0.01", "--alpha", "0.2", "--p", "2", "--lean", "0.05")
assert c["input_lifts_block"] is False and c["impacts"] == 0 and c["max_theta_input_over_alpha"] == 0, c
# A spectrum's "the record never lifts the block" reads the leaning block's lower corner (0.09 g
# lifts alpha 0.1 leaning 0.02 on its corner +1, not the perfect block).
with open(tmp + "/k.txt", "w") as f:
    f.write("0.09\n" * 300)
def spec(*extra):
    out = subprocess.run([rocking, "spectrum", tmp + "/k.txt", "--unit", "g", "--dt", "0.01", "--alpha", "0.1",
                          "--points", "20", *extra, "--json"], capture_output=True, check=True).stdout
    return json.loads(out)["spectra"][0]["lifts"]
assert spec("--lean", "0.02") is True and spec() is False
PY
then echo "ok: the probe's findings stay fixed"; else echo "FAIL: the probe's findings"; fail=1; fi

# Batch rows take lean, out_of_plumb, fc and density columns: the commands' runs.
cat >"$tmp/m.csv" <<CSV
kind,record,unit,alpha,p,lean,out_of_plumb,fc,density
simulate,s.txt,m/s2,0.1,4,0.03,,,
simulate,s.txt,m/s2,0.1,4,,0.02,2,2000
collapse,s.txt,m/s2,0.1,,0.03,,,
simulate,s.txt,m/s2,0.1,4,1,,,
CSV
"$rocking" batch "$tmp/m.csv" --output "$tmp/mo.csv" >/dev/null 2>&1
if $py - "$tmp/mo.csv" "$rocking" "$tmp/s.txt" <<'PY'
import csv, json, subprocess, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
rocking, record = sys.argv[2], sys.argv[3]
def cli(*args):
    return json.loads(subprocess.run([rocking, *args, "--json"], capture_output=True, check=True).stdout)
a = cli("simulate", "--record", record, "--unit", "m/s2", "--alpha", "0.1", "--p", "4", "--lean", "0.03")
b = cli("simulate", "--record", record, "--unit", "m/s2", "--alpha", "0.1", "--p", "4", "--out-of-plumb", "0.02", "--fc", "2",
        "--density", "2000")
c = cli("collapse", record, "--unit", "m/s2", "--alpha", "0.1", "--lean", "0.03")
assert float(rows[0]["max_theta"]) == a["max_theta_input_over_alpha"] and int(rows[0]["impacts"]) == a["impacts"], (rows[0], a)
assert float(rows[1]["max_theta"]) == b["max_theta_input_over_alpha"], (rows[1], b)
assert rows[0]["model_used"] == "linearised imperfect lean 0.03 out_of_plumb 0" and rows[0]["restitution_used"] == "per corner"
assert float(rows[2]["p_collapse"]) == c["p"], (rows[2], c)
assert rows[3]["status"] == "error" and "lean: an angle in rad within (-pi/4, pi/4)" in rows[3]["error"], rows[3]
PY
then echo "ok: batch rows of imperfect blocks are the commands' runs"; else echo "FAIL: batch imperfect rows"; fail=1; fi

base=(--case 2 --x 1 --rd 0.5 --alpha 0.1 --height 2)
check "a lean beyond alpha" "on its corner theta > 0 alpha = -0.1 rad: the centre of gravity is beyond the pivot" \
    "$rocking" simulate "${base[@]}" --lean 0.2
status "a lean beyond alpha" 2 "$rocking" simulate "${base[@]}" --lean 0.2
check "an angle beyond pi/4" "--out-of-plumb: an angle in rad within (-pi/4, pi/4)" "$rocking" simulate "${base[@]}" --out-of-plumb 1
check "density without fc" "--density goes with --fc" "$rocking" simulate "${base[@]}" --density 2000
check "a crushing base" "the block's weight crushes its base" "$rocking" simulate "${base[@]}" --fc 0.02
check "no friction with a lean" "--friction does not apply to an imperfect block" "$rocking" simulate "${base[@]}" --lean 0.01 --friction 0.6
check "a study states the lean" "lean 0.01 rad" "$rocking" collapse "$tmp/s.txt" --unit m/s2 --alpha 0.1 --lean 0.01
check "a mirrored train with a lean" "flip the signs of --lean and --out-of-plumb with it" \
    "$rocking" simulate --train -1:1 --x 1 --q 2 --alpha 0.1 --p 2 --lean 0.01

# assess and collapse state the imperfect block, and assess checks eq. 27 toward each corner:
# the paper's q2_n6(p to_5) at the nominal block (recomputed here by (S2) from the to_5 given),
# times the weaker corner's alpha over alpha; collapse's simulate hint keeps --lean; spectrum
# with --fc and no --p-min starts where the blocks stand (collapse's p at its range's start).
if $py - "$rocking" "$tmp/s.txt" <<'PY'
import json, math, subprocess, sys
rocking, record = sys.argv[1], sys.argv[2]
def cli(*args, js=True):
    out = subprocess.run([rocking, *args] + (["--json"] if js else []), capture_output=True, check=True).stdout
    return json.loads(out) if js else out.decode()
alpha, psi = 0.1, 0.02
a = cli("assess", record, "--unit", "m/s2", "--alpha", repr(alpha), "--p", "3", "--lean", repr(psi), "--width", "0.01")
r = a["records"][0]
x = 3 * r["to5"]
# The paper's q2_n6 from `rocking q` (checked against eq. 27 by the q scenes): what is
# checked here is the scaling by the weaker corner's alpha, the imperfect block's own.
q27 = cli("q", "--case", "2", "--pulses", "6", "--x", repr(x))["q"]
assert abs(r["q_eq27_as_printed"] - q27) < 1e-12 * q27, (r["q_eq27_as_printed"], q27)
assert abs(r["q_eq27"] - q27 * (alpha - psi) / alpha) < 1e-12 * q27, (r["q_eq27"], q27)
assert r["eq27_side"] == 1 and r["passes"] == (r["q_record"] < r["q_eq27"]), r
im = a["imperfection"]
assert abs(im["corner_plus"]["alpha"] - (alpha - psi)) < 1e-15 and abs(im["corner_minus"]["alpha"] - (alpha + psi)) < 1e-15, im
assert "toward each corner" in a["check"], a["check"]
c = cli("collapse", record, "--unit", "m/s2", "--alpha", "0.1", "--lean", repr(psi))
assert c["found"] and abs(c["imperfection"]["corner_plus"]["alpha"] - (alpha - psi)) < 1e-15, c
t = cli("collapse", record, "--unit", "m/s2", "--thickness", "0.3", "--height", "3", "--lean", repr(psi), js=False)
assert "--thickness 0.3 --height 3 --unit m/s2 --lean 0.02" in t, t
s = cli("spectrum", record, "--unit", "m/s2", "--alpha", "0.1", "--fc", "1", "--points", "4")
f = cli("collapse", record, "--unit", "m/s2", "--alpha", "0.1", "--fc", "1")
assert s["grid"]["p_min"] > 0.3 and f["below_range"] and s["grid"]["p_min"] == f["p"], (s["grid"], f)
PY
then echo "ok: assess's eq. 27 toward each corner, the imperfection stated, spectrum from standing blocks"
else echo "FAIL: assess/collapse/spectrum with an imperfect block"; fail=1; fi
check "a spectrum of crushed blocks asked for" "the block's weight crushes its base" \
    "$rocking" spectrum "$tmp/s.txt" --unit m/s2 --alpha 0.1 --fc 1 --p-min 0.3 --points 4
exit $fail
