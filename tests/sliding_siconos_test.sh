#!/usr/bin/env bash
# rocking simulate --friction (src/dynamics/sliding/, event-driven) against a
# second, independent method (issue 41, item 3): tools/siconos_block.py, the
# same block as a free rigid body with two frictional unilateral corners,
# Siconos's Moreau-Jean time-stepping.  Skips (77) without python3-siconos.
#
# The rule.  Moreau-Jean without event location is first order in dt, and
# its error depends on where in a step each impact or input jump falls; so
# each Siconos value S(dt) is the mean of K runs on grids offset by dt/K
# (tools/siconos_block.py --phases), which samples that phase evenly.  With
# S(h), S(h/2), S(h/4) and the engine's E, every quantity must satisfy
#   converging:  |S(h/2) - S(h/4)| < |S(h) - S(h/2)|
#   agreeing:    |S(h/4) - E| <= 2 |S(h/2) - S(h/4)| + r(h/2) + 2 r(h/4) + floor
# First order, S(h/4) - E = S(h/2) - S(h/4) up to higher order: the factor 2
# leaves room for those.  r(dt) = V/K, V the total variation of the K runs'
# values around the cycle of offsets, bounds how far a mean of K evenly
# offset samples lies from the mean over all offsets (each sample differs
# from the values over its 1/K of the cycle by at most the variation there),
# in S(h/4) and, through the difference, in S(h/2).  The floor is 1e-7 (of
# alpha, m or s): a hundred times the engine's own error at --rtol 1e-11.
# Overturned and the impacts must be the engine's in every run at every dt
# (the engine counts impacts over its whole run and Siconos to t_fin: every
# case here ends at t_fin or falls before it, where both count the same).
# Each case ends with a decoy: the engine with an input 1 % off or a friction
# 4-5 % off must be rejected by the same rule, or the rule cannot fail.
#
#   tests/sliding_siconos_test.sh ROCKING
set -u
rocking="$1"
py=/usr/bin/python3
here="$(cd "$(dirname "$0")" && pwd)"
tool="$here/../tools/siconos_block.py"
compare=("$py" "$here/sliding_siconos_compare.py" "$rocking" "$tool")
source "$here/check_lib.sh"
if ! $py -c 'import siconos.kernel' 2>/dev/null; then
    echo "skip: /usr/bin/python3 cannot import siconos.kernel (make deps installs python3-siconos)"
    exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The contact plugin as Siconos reads it: each corner's (gap, x) against the
# corner placed here by the rotation matrix, and its Jacobian against central
# differences (step 1e-6: truncation 1e-13 R, rounding 1e-10).
for block in "0.2 1.5305082674117891" "0.3 1.0467516015380856"; do
    set -- $block
    if $py "$tool" --alpha "$1" --R "$2" --mu 1 --dt 1 --check-kinematics | $py -c "
import json, sys
d = json.load(sys.stdin)
print('  gap error %.3g m, Jacobian error %.3g' % (d['gap_error_m'], d['jacobian_error']))
assert d['gap_error_m'] < 1e-14 and d['jacobian_error'] < 1e-8, d
"; then echo "ok: the corners' kinematics, alpha $1"; else echo "FAIL: the corners' kinematics, alpha $1"; fail=1; fi
done

run_case() {
    if "${compare[@]}" "$@"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi
}
h=4e-4

# (a) alpha 0.3, mu 0.2 < tan(alpha): 0.5 g for 0.4 s slides the block without
# rocking; Newmark's slip at t_fin, (a - mu) g T^2/2 = 0.3 x 9.81 x 0.16/2.
a=(--train 1:1 --to 0.4 --pga 0.5)
run_case "(a) sliding only" --h $h --phases 4 --quantities slip_tfin_m,max_theta_input_over_alpha \
    --engine "${a[*]} --alpha 0.3 --height 2 --friction 0.2" --siconos "${a[*]} --mu 0.2" \
    --closed-form slip_tfin_m=0.23544 --decoy "${a[*]} --alpha 0.3 --height 2 --friction 0.21"

# (b) mu 0.8: rocking on stuck corners, one impact at 0.92 s (Housner's
# restitution, not given to either), theta(t_fin) 0.23 s after it; the first
# excursion is the largest.  The engine's run ends at t_fin (cannot fall).
b=(--train 1:1,-1:0.8,1:0.5 --to 0.5)
run_case "(b) rocking through an impact" --h $h --phases 8 \
    --quantities max_theta_input_over_alpha,theta_tfin_over_alpha \
    --engine "${b[*]} --pga 0.3 --alpha 0.2 --height 3 --friction 0.8" --siconos "${b[*]} --pga 0.3 --mu 0.8" \
    --decoy "${b[*]} --pga 0.303 --alpha 0.2 --height 3 --friction 0.8"

# (c) mu 0.25, a little above tan(0.2) = 0.203: 0.7 g turns the block on its
# leading corner while that corner slips (slide-rock, 0.25 s), then it rocks
# stuck; no impact.
c=(--train 1:1,-1:1 --to 0.2 --pga 0.7)
run_case "(c) slide-rock" --h $h --phases 8 \
    --quantities max_theta_input_over_alpha,theta_tfin_over_alpha,slip_tfin_m \
    --engine "${c[*]} --alpha 0.2 --height 3 --friction 0.25" --siconos "${c[*]} --mu 0.25" \
    --decoy "${c[*]} --alpha 0.2 --height 3 --friction 0.26"

# (d) a record: L'Aquila 2009, AQK east-west, 8 s around its PGA (0.33 g; the
# record's first 8 s are before the event), converted by the harness (a floor
# of participation 0 is the ground) to one column in g that both read; the
# 0.3 m x 2 m block on mu 0.6 rocks through 6 impacts and falls.  Compared:
# the fall's time at |theta| = pi/2 (where both call it; the largest theta is
# that angle in both), the outcome, the impacts.
esm="$here/../../shared/records/esm/IT.AQK..HNE.D.20090406.013240.C.ACC.ASC"
if [[ -f "$esm" ]]; then
    "$rocking" record floor "$esm" --period 1 --participation 0 --output "$tmp/floor.txt" >/dev/null
    $py - "$tmp/floor.txt" "$tmp/window.txt" <<'PY'
import sys
rows = [line.split(",") for line in open(sys.argv[1]) if line.strip() and not line.startswith("#")]
a = [float(r[1]) for r in rows]
peak = max(range(len(a)), key=lambda k: abs(a[k]))
start = peak - 600  # 3 s at 0.005 s before the PGA, 5 s after
with open(sys.argv[2], "w") as out:
    out.writelines("%.17g\n" % (v / 9.81) for v in a[start:start + 1601])
PY
    w=(--record "$tmp/window.txt" --record-dt 0.005)
    run_case "(d) a record, the fall" --h $h --phases 4 --quantities t_overturn \
        --engine "${w[*]} --unit g --thickness 0.3 --height 2 --friction 0.6" \
        --siconos "${w[*]} --mu 0.6 --overturn-angle 1.5707963267948966" \
        --decoy "${w[*]} --unit g --thickness 0.3 --height 2 --friction 0.6 --pga 0.3333"
else
    echo "skip: (d) needs $esm"
fi

# The tool's refusals.
t=("$py" "$tool" --alpha 0.2 --R 1.5 --mu 0.5 --dt 1e-3)
check "tool: no input" "give exactly one input" "${t[@]}"
check "tool: train without --pga" "--train needs --to and --pga" "${t[@]}" --train 1:1 --to 0.5
check "tool: a train item" "--train item 2 '-1': expected amplitude:duration" "${t[@]}" --train 1:1,-1 --to 0.5 --pga 0.3
check "tool: alpha's range" "--alpha: must be in (0, pi/4)" "$py" "$tool" --alpha 0.8 --R 1.5 --mu 0.5 --dt 1e-3 --train 1:1 --to 0.5 --pga 0.3
check "tool: a missing record" "--record $tmp/none.txt: No such file" "${t[@]}" --record "$tmp/none.txt" --record-dt 0.01
printf '0.1\n0.2 0.3\n' >"$tmp/two.txt"
check "tool: a record's line" "$tmp/two.txt line 2: expected one column" "${t[@]}" --record "$tmp/two.txt" --record-dt 0.01
status "tool: bad input exits 2" 2 "${t[@]}" --train 1:1 --to 0.5 --pga x
exit $fail
