#!/usr/bin/env bash
# expected/fragility/independent_capacities.py can fail: each of its five checks (structure,
# fits, stripes, eq27, brackets) is run on a copy of expected/fragility with one value changed the
# way a wrong program would change it, and must name that value and exit 1; on the unchanged copy
# each part passes.  The brackets are re-simulated on the synthetic records only (regenerated
# here, no ../shared needed), the stripe fits on the shared records' four blocks only (the cost).
#
#   tests/fragility_capacities_check_test.sh
set -u
here=$(cd "$(dirname "$0")" && pwd)
py=/usr/bin/python3
checker="$here/../expected/fragility/independent_capacities.py"
source "$here/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# fresh NAME [drop-shared|drop-synthetic]: a copy of expected/fragility in $tmp/NAME.
fresh() {
    rm -rf "$tmp/$1" && cp -r "$here/../expected/fragility" "$tmp/$1" || exit 1
    case "${2:-}" in
        drop-shared) rm -f "$tmp/$1"/fragility_capacit* "$tmp/$1"/fragility_stripe_* ;;
        drop-synthetic) rm -f "$tmp/$1"/fragility_synthetic_* ;;
    esac
}

# mutate FILE ROW COLUMN EXPR: data row ROW (0 = the first), COLUMN set to EXPR of v (the cell as
# a float) or of s (as text); the notes and every other cell kept.
mutate() {
    $py - "$@" <<'PY' || { echo "FAIL: could not mutate $1"; exit 1; }
import sys
path, row, column, expr = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
lines = open(path).read().split("\n")
data = [i for i, l in enumerate(lines) if l and not l.startswith("#")]
header = lines[data[0]].split(",")
cells = lines[data[1 + row]].split(",")
k = header.index(column)
s = cells[k]
v = float(s) if s not in ("-", "") else None
cells[k] = str(eval(expr))
lines[data[1 + row]] = ",".join(cells)
open(path, "w").write("\n".join(lines))
PY
}

# expect_fail PART NAME SUBSTRING: the checker, on copy NAME, part PART, exits 1 naming SUBSTRING.
expect_fail() {
    local out; out=$($py "$checker" "$tmp/$2" --only "$1" 2>&1); local rc=$?
    if [[ $rc != 1 || "$out" != *"$3"* ]]; then
        echo "FAIL: $1 on $2: wanted exit 1 naming '$3', got exit $rc: $out" | tail -5; fail=1
    else
        echo "ok: $1 catches $2"
    fi
}

# The unchanged files pass each part (the records folder aside: brackets on the synthetic set).
fresh clean
status "structure, fits and eq27 on the unchanged files" 0 $py "$checker" "$tmp/clean" --only structure,fits,eq27
fresh clean-synthetic drop-shared
status "the synthetic brackets on the unchanged files" 0 $py "$checker" "$tmp/clean-synthetic" --only brackets

# 1. structure
fresh percent
mutate "$tmp/percent/fragility_capacities.csv" 0 below_robust_percent "v + 1e-3"
expect_fail structure percent "below_robust_percent"
fresh below
mutate "$tmp/below/fragility_stripe_shares.csv" 0 stripe_1 "0.01"
expect_fail structure below "a stripe share > 0 below the first overturning"
fresh overlap  # row 0: the robust collapse 4.0495 lies in stripe 47 ([4.0169, 4.1403])
mutate "$tmp/overlap/fragility_stripe_shares.csv" 0 stripe_47 "0.0"
expect_fail structure overlap "below its overlap"
fresh order
mutate "$tmp/order/fragility_synthetic_capacities.csv" 30 q_safe "v * 1.00001"
expect_fail structure order "bracket"

# 2. the fits on the points
fresh median
mutate "$tmp/median/fragility_capacity_fits.csv" 0 median "repr(v * (1 + 1e-6))"
expect_fail fits median "first_overturning alpha 0.10 p 1.50 median"
fresh point  # a robust collapse moved (with its bracket): its fit no longer the points'
mutate "$tmp/point/fragility_capacities.csv" 0 q_robust_collapse "repr(v * 1.001)"
mutate "$tmp/point/fragility_capacities.csv" 0 q_robust_safe "repr(v * 1.001)"
expect_fail fits point "first_robust_collapse alpha 0.10 p 1.50 median"
fresh boot
mutate "$tmp/boot/fragility_synthetic_capacity_fits.csv" 5 median_hi "repr(v * (1 + 1e-6))"
expect_fail fits boot "median_hi"

# 3. the stripe fit (the shared records' blocks only)
fresh share drop-synthetic  # row 0, stripe 62: a share strictly between 0 and 1 (0.727)
mutate "$tmp/share/fragility_stripe_shares.csv" 0 stripe_62 "repr(v + 1e-3) if 0 < v < 1 else 1/0"
expect_fail stripes share "stripes alpha 0.10 p 1.50 median"
fresh stripeboot drop-synthetic
mutate "$tmp/stripeboot/fragility_stripe_fits.csv" 3 beta_lo "repr(v * (1 + 1e-8))"
expect_fail stripes stripeboot "stripes alpha 0.20 p 3.00 beta_lo"

# 4. eq. 27 under each capacity
fresh count
mutate "$tmp/count/fragility_capacity_eq27.csv" 4 non_conservative "int(v) + 1"
expect_fail eq27 count "first_overturning eq27 to_5 non_conservative"
fresh censored
mutate "$tmp/censored/fragility_synthetic_capacity_eq27.csv" 11 censored "int(v) + 1"
expect_fail eq27 censored "censored"
fresh robustshare  # the robust collapse's bootstrap bound
mutate "$tmp/robustshare/fragility_capacity_eq27.csv" 15 boot_hi "repr(v + 1/64)"
expect_fail eq27 robustshare "first_robust_collapse eq27 to_5 boot_hi"

# 5. the brackets, re-simulated (synthetic: row 9 is the pulse fp=0.32 Hz on (0.10, 1.50))
fresh bracket drop-shared
mutate "$tmp/bracket/fragility_synthetic_capacities.csv" 9 q_first_overturning "repr(v * 0.98)"
mutate "$tmp/bracket/fragility_synthetic_capacities.csv" 9 q_safe "repr(v * 0.98)"
expect_fail brackets bracket "first overturning: at q"
fresh robustbracket drop-shared  # a robust collapse's bracket moved into its interval
mutate "$tmp/robustbracket/fragility_synthetic_capacities.csv" 40 q_robust_safe "repr(float(s) * 1.002)"
mutate "$tmp/robustbracket/fragility_synthetic_capacities.csv" 40 q_robust_collapse "repr(v * 1.002)"
expect_fail brackets robustbracket "first robust collapse: at q"

exit $fail
