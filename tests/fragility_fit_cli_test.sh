#!/usr/bin/env bash
# rocking fragility's fit on equal and censored collapse values (issue 38),
# on the shared Kocaeli DZC180 record and copies of it whose step differs by
# parts in 10^10 (a record given twice, or scaled, is refused; these overturn
# the block at the very same double q): 1-5 of them get one refusal that
# says why (every collapse at one q, nothing censored above), never a beta
# from rounding; a bootstrap whose resamples often draw one q only keeps no
# rounding beta; two copies and a record that never overturns the block (a
# 25 Hz burst written here as a PEER file, censored at q_max = 20) are fitted,
# as tools/censored_mle.py (mpmath) maximises the same points, and so is the
# bootstrap's every kind of resample.  Without ../shared/records it exits 77.
#
#   tests/fragility_fit_cli_test.sh ROCKING
set -u
rocking=$(realpath "$1")
here=$(realpath "$(dirname "$0")")
py=/usr/bin/python3
mle="$here/../tools/censored_mle.py"
records="${ROCKING_RECORDS:-$here/../../shared/records}"
k180="$records/peer/RSN1158_KOCAELI_DZC180.AT2"
k270="$records/peer/RSN1158_KOCAELI_DZC270.AT2"
n171="$records/esm/IT.NRC..HGN.D.20161026.171036.C.ACC.ASC"
if [[ ! -f $k180 || ! -f $k270 || ! -f $n171 ]]; then
    echo "skipped: the shared records are absent (wanted $k180, $k270 and $n171; ../shared/records or \$ROCKING_RECORDS)"
    exit 77
fi
source "$here/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
block=(--alpha 0.15 --p 2 --points 20)

# A 0.4 s burst of 25 Hz at 0.1 g: the block (alpha 0.15, p 2) does not overturn up to q = 20.
$py - "$tmp/burst.AT2" <<'PY'
import math, sys
n, dt = 2000, 0.005
a = [0.1 * math.sin(2 * math.pi * 25 * k * dt) if k * dt < 0.4 else 0.0 for k in range(n)]
with open(sys.argv[1], "w") as f:
    f.write("PEER NGA STRONG MOTION DATABASE RECORD\nA 0.4 s burst of 25 Hz, 0.1 g (tests/fragility_fit_cli_test.sh)\n"
            "ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=  %d, DT=   .0050 SEC\n" % n)
    for i in range(0, n, 5):
        f.write("".join("%15.7E" % v for v in a[i:i + 5]) + "\n")
PY

# The copies: DZC180 with its step lengthened by k parts in 10^10, k = 1..7.  To the
# check of repeated records each is another record (another step: a copy, even scaled,
# is refused), but the motion moves by 1e-10 of its time, far inside the IDA's last
# bracket (1e-6), so each overturns the block at the very same double q.
copies=("$k180")
for k in 1 2 3 4 5 6 7; do
    $py - "$k180" "$tmp/k180_$k.AT2" "$k" <<'PY'
import re, sys
lines = open(sys.argv[1]).read().splitlines()
dt = float(re.search(r"DT=\s*([0-9.Ee+-]+)", lines[3]).group(1)) * (1 + int(sys.argv[3]) * 1e-10)
lines[3] = re.sub(r"DT=\s*[0-9.Ee+-]+", "DT= %.17g" % dt, lines[3])
open(sys.argv[2], "w").write("\n".join(lines) + "\n")
PY
    copies+=("$tmp/k180_$k.AT2")
done

# 1-5 copies: one refusal, the same words each time, exit 0 (an answer about the records).
why="no fit: every record that overturned did so at the same q = 2.18965822 and no censored record lies above it: ln L grows without bound as beta -> 0 (no spread to fit)"
files=()
for n in 1 2 3 4 5; do
    files+=("${copies[$((n - 1))]}")
    check "copies: $n, refused" "$why" "$rocking" fragility "${files[@]}" "${block[@]}"
    status "copies: $n, exit" 0 "$rocking" fragility "${files[@]}" "${block[@]}"
    check_not "copies: $n, no beta" "beta =" "$rocking" fragility "${files[@]}" "${block[@]}"
done
check "the refusal in --json, as no_fit" '"fit": null, "no_fit": "every record that overturned did so at the same q = 2.18965822' \
    "$rocking" fragility "${copies[@]:0:2}" "${block[@]}" --json
check "3 copies bootstrap refused" "$why" "$rocking" fragility "${copies[@]:0:3}" "${block[@]}" --bootstrap 100 --seed 1

# A censored point above the one q: a fit, checked against an independent maximisation.
fit_check() {  # description, rocking fragility arguments...
    local what="$1"; shift
    "$rocking" fragility "$@" --json >"$tmp/f.json" 2>&1
    if $py - "$tmp/f.json" "$mle" <<'PY'
import json, subprocess, sys
b = json.load(open(sys.argv[1]))["blocks"][0]
col = [repr(r["q"]) for r in b["records"] if r["collapsed"]]
cen = [repr(r["q"]) for r in b["records"] if not r["collapsed"]]
want = json.loads(subprocess.run(["/usr/bin/python3", sys.argv[2], "--json", "--collapsed"] + col + ["--censored"] + cen,
                                 check=True, capture_output=True, text=True).stdout)
got = b["fit"]
for k in ("median", "beta"):
    assert abs(got[k] / want[k] - 1) < 1e-10, (k, got[k], want[k])
print("  median %.9g beta %.9g over %d collapsed, %d censored" % (got["median"], got["beta"], len(col), len(cen)))
PY
    then echo "ok: $what"; else echo "FAIL: $what"; cat "$tmp/f.json"; fail=1; fi
}
check "burst censored" "censored at q_max = 20" "$rocking" fragility "$tmp/burst.AT2" "${block[@]}"
# Issue 38's case: scipy's censored lognormal MLE gave median 6.09, beta 1.50.
check "issue's example" "lognormal median q = 6.089949, beta = 1.504204 (2 overturned, 1 censored)" \
    "$rocking" fragility "${copies[@]:0:2}" "$tmp/burst.AT2" "${block[@]}"
fit_check "two copies below a censored record" "${copies[@]:0:2}" "$tmp/burst.AT2" "${block[@]}"
# A second censored record: the burst's samples at half the step (50 Hz for 0.2 s).
sed '4s/DT=   .0050/DT=   .0025/' "$tmp/burst.AT2" >"$tmp/burst2.AT2"
fit_check "one collapse below two censored" "$k180" "$tmp/burst.AT2" "$tmp/burst2.AT2" "${block[@]}"
# Real records only: IT.NRC HGN (2016-10-26 17:10) first overturns the block at q = 17.8, so at --q-max 15 it is censored.
fit_check "real record censored at q_max 15" "${copies[@]:0:3}" "$n171" "${block[@]}" --q-max 15

# The bootstrap.  Eight copies and DZC270: a third of the resamples draw only the copies (no
# maximum) and are redrawn, so no beta is below the least spread of a resample with DZC270 in
# it, one draw among nine: ln(q270/q180) sqrt(8)/9.
"$rocking" fragility "${copies[@]:0:8}" "$k270" "${block[@]}" \
    --bootstrap 200 --seed 1 --json >"$tmp/b.json"
if $py - "$tmp/b.json" <<'PY'
import json, math, sys
b = json.load(open(sys.argv[1]))["blocks"][0]
q = sorted({r["q"] for r in b["records"]})
least = math.log(q[1] / q[0]) * math.sqrt(8) / 9
lo = b["fit"]["bootstrap"]["beta"][0]
assert lo >= least * (1 - 1e-12), (lo, least)
print("  beta's low end %.6g >= %.6g" % (lo, least))
PY
then echo "ok: bootstrap redraws resamples of one q"; else echo "FAIL: bootstrap redraws resamples of one q"; fail=1; fi
# Two copies and the burst: a resample holds one or two copies (the others have no maximum),
# so its beta and median are those of 1 collapse and 2 censored, or of the fit: the interval's
# ends are exactly those two (each is a third or more of the resamples).
"$rocking" fragility "${copies[@]:0:2}" "$tmp/burst.AT2" "${block[@]}" --bootstrap 200 --seed 1 --json >"$tmp/c.json"
if $py - "$tmp/c.json" "$mle" <<'PY'
import json, subprocess, sys
b = json.load(open(sys.argv[1]))["blocks"][0]
qc = repr(b["records"][0]["q"])
def mle(col, cen):
    out = subprocess.run(["/usr/bin/python3", sys.argv[2], "--json", "--collapsed"] + col + ["--censored"] + cen,
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)
one, two = mle([qc], ["20", "20"]), mle([qc, qc], ["20"])
boot = b["fit"]["bootstrap"]
for k in ("median", "beta"):
    want = sorted([one[k], two[k]])
    assert all(abs(g / w - 1) < 1e-10 for g, w in zip(boot[k], want)), (k, boot[k], want)
print("  median %s, beta %s" % (boot["median"], boot["beta"]))
PY
then echo "ok: bootstrap keeps one collapse below censored"; else echo "FAIL: bootstrap keeps one collapse below censored"; fail=1; fi

exit $fail
