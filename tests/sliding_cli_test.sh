#!/usr/bin/env bash
# rocking simulate --friction MU (issue 41): the sliding-rocking model from the
# command line.  Newmark's slip of a block that only slides under a
# rectangular pulse, recomputed here; friction 1e6 against --model full on a
# pulse that rocks the block through an impact; the energy balance it
# reports; refusals of the options that do not apply.
#
#   tests/sliding_cli_test.sh ROCKING
set -u
rocking="$1"
py=/usr/bin/python3
source "$(dirname "$0")/check_lib.sh"

# alpha 0.3, mu 0.2 < tan(0.3): 0.5 g for 0.4 s slides it without rocking.
if "$rocking" simulate --train 1:1 --to 0.4 --pga 0.5 --alpha 0.3 --height 2 --friction 0.2 --rtol 1e-12 --json | $py -c "
import json, sys
d = json.load(sys.stdin)
g, a, mu, T = 9.81, 0.5, 0.2, 0.4
vT = (a - mu) * g * T
tau = vT / (mu * g)
slip = 0.5 * (a - mu) * g * T * T + vT * tau - 0.5 * mu * g * tau * tau
assert abs(d['final_slip_m'] - slip) < 1e-9 * slip, (d['final_slip_m'], slip)
assert abs(d['time_in']['slide'] - (T + tau)) < 1e-9 and d['time_in']['rock'] == 0, d['time_in']
assert abs(d['energy']['input_work'] - d['energy']['friction_loss']) < 1e-9 * d['energy']['input_work'], d['energy']
assert d['friction'] == 0.2 and 'Coulomb friction mu = 0.2' in d['model']
"; then echo "ok: Newmark's slip"; else echo "FAIL: Newmark's slip"; fail=1; fi

# Friction 1e6 never slips before the fall: the rocking-only full model's run.
"$rocking" simulate --case 1 --x 1.5 --rd 0.9 --alpha 0.2 --height 3 --friction 1e6 --rtol 1e-11 --json >"${TMPDIR:-/tmp}/friction.$$.json"
"$rocking" simulate --case 1 --x 1.5 --rd 0.9 --alpha 0.2 --height 3 --model full --rtol 1e-11 --json >"${TMPDIR:-/tmp}/full.$$.json"
if $py - "${TMPDIR:-/tmp}/friction.$$.json" "${TMPDIR:-/tmp}/full.$$.json" <<'PY'
import json, sys
s, r = (json.load(open(f)) for f in sys.argv[1:3])
for key in ("max_theta_input_over_alpha", "theta_tfin_over_alpha"):
    assert abs(s[key] - r[key]) < 1e-8, (key, s[key], r[key])
assert s["impacts"] == r["impacts"] == 1 and s["overturned"] == r["overturned"]
assert s["time_in"]["slide"] == 0 and s["energy"]["balance_error_over_gR"] < 1e-8, s
PY
then echo "ok: friction 1e6 is the full model"; else echo "FAIL: friction 1e6 against --model full"; fail=1; fi
rm -f "${TMPDIR:-/tmp}/friction.$$.json" "${TMPDIR:-/tmp}/full.$$.json"

# --output: theta(t) and the slip every --dt.  Newmark's slip at each row of the slide, and at
# friction 1e6 the rocking-only full model's theta(t) while the block has not slipped.
"$rocking" simulate --train 1:1 --to 0.4 --pga 0.5 --alpha 0.3 --height 2 --friction 0.2 --rtol 1e-12 \
    --output "${TMPDIR:-/tmp}/slide.$$.csv" --dt 0.05 >/dev/null
"$rocking" simulate --case 1 --x 1.5 --rd 0.9 --alpha 0.2 --height 3 --friction 1e6 --rtol 1e-11 \
    --output "${TMPDIR:-/tmp}/stuck.$$.csv" --dt 0.001 >/dev/null
"$rocking" simulate --case 1 --x 1.5 --rd 0.9 --alpha 0.2 --height 3 --model full --rtol 1e-11 \
    --output "${TMPDIR:-/tmp}/rock.$$.csv" --dt 0.001 >/dev/null
if $py - "${TMPDIR:-/tmp}/slide.$$.csv" "${TMPDIR:-/tmp}/stuck.$$.csv" "${TMPDIR:-/tmp}/rock.$$.csv" <<'PY'
import csv, sys
def rows(f):
    return list(csv.DictReader(l for l in open(f) if not l.startswith("#")))
g, a, mu, T = 9.81, 0.5, 0.2, 0.4
vT = (a - mu) * g * T
slide = rows(sys.argv[1])
assert len(slide) >= 19, len(slide)
for r in slide:
    t = float(r["t"])
    if t <= T:
        want, rate = 0.5 * (a - mu) * g * t * t, (a - mu) * g * t
    else:
        want, rate = 0.5 * (a - mu) * g * T * T + vT * (t - T) - 0.5 * mu * g * (t - T) ** 2, vT - mu * g * (t - T)
    assert abs(float(r["slip_m"]) - want) < 1e-9 and abs(float(r["slip_rate_m_s"]) - rate) < 1e-9, (r, want, rate)
    assert r["regime"] == ("rest" if t == 0 else "slide") and float(r["theta_over_alpha"]) == 0, r
stuck, rock = rows(sys.argv[2]), rows(sys.argv[3])
n = 0
for s, r in zip(stuck, rock):
    if s["regime"] == "slide_rock" or abs(float(r["theta_over_alpha"])) > 1:
        break
    assert s["t"] == r["t"] and abs(float(s["theta_over_alpha"]) - float(r["theta_over_alpha"])) < 1e-7, (s, r)
    assert float(s["slip_m"]) == 0, s
    n += 1
assert n > 1000, n
PY
then echo "ok: --output with friction: Newmark's slip per row, the full model's theta(t)"; else echo "FAIL: --output with friction"; fail=1; fi
rm -f "${TMPDIR:-/tmp}/slide.$$.csv" "${TMPDIR:-/tmp}/stuck.$$.csv" "${TMPDIR:-/tmp}/rock.$$.csv"

base=(--case 1 --x 1.5 --rd 0.9 --alpha 0.2 --height 3)
check "friction states its model" "Coulomb friction mu = 0.6" "$rocking" simulate "${base[@]}" --friction 0.6
check "friction states its solver" "event-driven Dormand-Prince 5(4), rtol 1e-09" "$rocking" simulate "${base[@]}" --friction 0.6
check "friction's range" "--friction: the friction coefficient must be in (0, 1e6] (got 0)" "$rocking" simulate "${base[@]}" --friction 0
status "friction's range" 2 "$rocking" simulate "${base[@]}" --friction -1
check "no solver with friction" "--solver does not apply with --friction" "$rocking" simulate "${base[@]}" --friction 0.6 --solver exact
check "no restitution with friction" "--restitution does not apply with --friction" "$rocking" simulate "${base[@]}" --friction 0.6 --restitution 0.9
check "no --paper with friction" "--paper does not apply with --friction" "$rocking" simulate "${base[@]}" --friction 0.6 --paper
# The studies take --friction (issue 41): a synthetic record, a spectrum and an IDA on the
# sliding-rocking model, each boundary seen by simulate --friction on either side.
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
"$rocking" record synth --stochastic 3 --dt 0.01 --duration 15 --output "$tmp/s.txt" >/dev/null || { echo "FAIL: synth"; exit 1; }
"$rocking" spectrum "$tmp/s.txt" --unit m/s2 --alpha 0.1 --points 30 --p-min 1 --p-max 10 --friction 0.4 --json >"$tmp/sp.json" \
    || { echo "FAIL: spectrum --friction"; fail=1; }
"$rocking" fragility "$tmp/s.txt" --unit m/s2 --alpha 0.1 --p 6.5 --points 30 --q-max 5 --friction 0.4 --json >"$tmp/fr.json" \
    || { echo "FAIL: fragility --friction"; fail=1; }
if $py - "$tmp/sp.json" "$tmp/fr.json" "$rocking" "$tmp/s.txt" <<'PY'
import json, subprocess, sys
sp, fr = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
rocking, record = sys.argv[3], sys.argv[4]
def falls(*args):
    out = subprocess.run([rocking, "simulate", "--record", record, "--unit", "m/s2", "--friction", "0.4", *args, "--json"],
                         capture_output=True, check=True).stdout
    return json.loads(out)["collapse_overturning"]
assert "Coulomb friction mu = 0.4" in sp["model"] and "Coulomb friction mu = 0.4" in fr["model"], (sp["model"], fr["model"])
s = sp["spectra"][0]
assert s["intervals"], "the friction spectrum overturns somewhere on [1, 10] rad/s"
seen = 0
for iv in s["intervals"]:
    for end in ("lower", "upper"):
        b = iv.get(end)
        if not b:
            continue
        assert falls("--alpha", "0.1", "--p", repr(b["p_collapse"])), (end, b)
        assert not falls("--alpha", "0.1", "--p", repr(b["p_safe"])), (end, b)
        seen += 1
assert seen >= 1, s["intervals"]
ida = fr["blocks"][0]["records"][0]
assert ida["collapsed"], ida
assert falls("--alpha", "0.1", "--p", "6.5", "--q", repr(ida["q"])), ida
print("ok: %d spectrum boundaries and the IDA's first collapse (q %s) seen by simulate --friction" % (seen, ida["q"]))
PY
then :; else echo "FAIL: the studies with --friction"; fail=1; fi
# Batch rows take a friction column: the same runs as the commands'.
cat >"$tmp/m.csv" <<CSV
kind,record,unit,alpha,p,friction,rtol
simulate,s.txt,m/s2,0.1,6.5,0.4,
collapse,s.txt,m/s2,0.1,,0.4,1e-10
simulate,s.txt,m/s2,0.1,6.5,0,
CSV
printf 'kind,record,unit,alpha,p,friction,restitution\nsimulate,s.txt,m/s2,0.1,6.5,0.4,0.9\n' >"$tmp/m2.csv"
"$rocking" batch "$tmp/m.csv" --output "$tmp/out.csv" >/dev/null 2>&1
"$rocking" batch "$tmp/m2.csv" --output "$tmp/out2.csv" >/dev/null 2>&1
"$rocking" simulate --record "$tmp/s.txt" --unit m/s2 --alpha 0.1 --p 6.5 --friction 0.4 --json >"$tmp/sim.json"
"$rocking" collapse "$tmp/s.txt" --unit m/s2 --alpha 0.1 --friction 0.4 --rtol 1e-10 --json >"$tmp/col.json"
if $py - "$tmp/out.csv" "$tmp/sim.json" "$tmp/col.json" <<'PY'
import csv, json, sys
rows = {int(r["line"]): r for r in csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#"))}
sim, col = json.load(open(sys.argv[2])), json.load(open(sys.argv[3]))
r = rows[2]
assert r["status"] == "ok" and r["model_used"].startswith("sliding-rocking mu 0.4"), r
assert float(r["max_theta"]) == sim["max_theta_input_over_alpha"] and int(r["impacts"]) == sim["impacts"], (r, sim)
assert (r["collapse"] == "yes") == sim["collapse"], (r, sim)
c = rows[3]
assert c["status"] == "ok" and float(c["p_collapse"]) == col["p"] and float(c["p_safe"]) == col["p_safe"], (c, col)
print("ok: batch friction rows are simulate's and collapse's runs")
PY
then :; else echo "FAIL: batch friction rows"; fail=1; fi
check "a batch row's friction range" "friction: the friction coefficient must be in (0, 1e6] (got 0)" cat "$tmp/out.csv"
check "a batch row refuses restitution with friction" "restitution: does not apply with friction" cat "$tmp/out2.csv"
check "a study's check is named for friction" "the sliding-rocking run at rtol 1e-12" cat "$tmp/fr.json"
check "a study refuses restitution with friction" "--restitution does not apply with --friction" \
    "$rocking" spectrum "$tmp/s.txt" --unit m/s2 --alpha 0.2 --friction 0.4 --restitution 0.9
check "collapse refuses a solver with friction" "--model and --solver do not apply with --friction" \
    "$rocking" collapse "$tmp/s.txt" --unit m/s2 --alpha 0.2 --friction 0.4 --solver dopri5
exit $fail
