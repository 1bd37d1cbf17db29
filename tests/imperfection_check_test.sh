#!/usr/bin/env bash
# The imperfection scene's checks can fail.  (1) The scene's own diff: run without the records
# (its closed forms only, seconds) against a copy of expected/imperfection, it matches the
# unchanged copy and reports a mismatch naming the file when one value is moved beyond its
# tolerance.  (2) expected/imperfection/independent.py, on copies with one value changed the way
# a wrong program would change it, exits 1 naming it.  (3) independent_records.py, on a copy
# whose first collapse is moved by 2 % (one record's rows, for the time), exits 1; skipped
# without the records folder.
#
#   tests/imperfection_check_test.sh REPRODUCE
set -u
here=$(cd "$(dirname "$0")" && pwd)
reproduce=${1:?usage: imperfection_check_test.sh REPRODUCE}
py=/usr/bin/python3
src="$here/../expected/imperfection"
source "$here/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# fresh NAME: a copy of expected/imperfection in $tmp/NAME/imperfection (--expected takes $tmp/NAME).
fresh() {
    rm -rf "$tmp/$1" && mkdir -p "$tmp/$1" && cp -r "$src" "$tmp/$1/imperfection" || exit 1
}

# mutate FILE ROW COLUMN EXPR: data row ROW (0 = the first), COLUMN set to EXPR of v (the cell as
# a float) or of s (as text); the notes and every other cell kept.
mutate() {
    $py - "$@" <<'PY' || { echo "FAIL: could not mutate $1"; exit 1; }
import csv, io, sys
path, row, column, expr = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
lines = open(path).read().split("\n")
data = [i for i, l in enumerate(lines) if l and not l.startswith("#")]
header = next(csv.reader([lines[data[0]]]))
cells = next(csv.reader([lines[data[1 + row]]]))
k = header.index(column)
s = cells[k]
v = float(s) if s not in ("-", "") else None
cells[k] = str(eval(expr))
out = io.StringIO()
csv.writer(out, lineterminator="").writerow(cells)
lines[data[1 + row]] = out.getvalue()
open(path, "w").write("\n".join(lines))
PY
}

# expect_fail CHECKER NAME SUBSTRING [ARGS...]: the checker on copy NAME exits 1 naming SUBSTRING.
expect_fail() {
    local checker=$1 name=$2 want=$3; shift 3
    local out; out=$($py "$src/$checker" "$tmp/$name/imperfection" "$@" 2>&1); local rc=$?
    if [[ $rc != 1 || "$out" != *"$want"* ]]; then
        echo "FAIL: $checker on $name: wanted exit 1 naming '$want', got exit $rc:"; echo "$out" | tail -5; fail=1
    else
        echo "ok: $checker catches $name"
    fi
}

# 1. the scene's diff, without the records (ROCKING_RECORDS names no folder)
no_records="$tmp/no-records-folder"
fresh clean
status "the scene matches an unchanged copy" 0 \
    env ROCKING_RECORDS="$no_records" "$reproduce" --no-plot --expected "$tmp/clean" --out "$tmp/out" imperfection
fresh moved
mutate "$tmp/moved/imperfection/imperfection_q.csv" 12 q_plus "repr(v * (1 + 1e-9))"
check "the scene reports a q moved by 1e-9" "imperfection_q.csv: 1 of" \
    env ROCKING_RECORDS="$no_records" "$reproduce" --no-plot --expected "$tmp/moved" --out "$tmp/out" imperfection
status "... and exits 1" 1 \
    env ROCKING_RECORDS="$no_records" "$reproduce" --no-plot --expected "$tmp/moved" --out "$tmp/out" imperfection
fresh side
mutate "$tmp/side/imperfection/imperfection_capacity.csv" 3 weaker_minus "1"
check "the scene reports a changed weaker side" "imperfection_capacity.csv: 1 of" \
    env ROCKING_RECORDS="$no_records" "$reproduce" --no-plot --expected "$tmp/side" --out "$tmp/out" imperfection

# 2. independent.py
status "independent.py passes the unchanged copy" 0 $py "$src/independent.py" "$tmp/clean/imperfection"
fresh alpha   # rows: 5 blocks per imperfection; row 12 is out of plumb 0.01, alpha 0.10, p 3.0
mutate "$tmp/alpha/imperfection/imperfection_corners.csv" 12 alpha_plus "repr(v * (1 + 1e-10))"
expect_fail independent.py alpha "imperfection_corners.csv alpha_plus row 13"
fresh restitution
mutate "$tmp/restitution/imperfection/imperfection_corners.csv" 22 e_onto_minus "repr(v * (1 + 1e-10))"
expect_fail independent.py restitution "imperfection_corners.csv e_onto_minus row 23"
fresh qminus
mutate "$tmp/qminus/imperfection/imperfection_q.csv" 100 q_minus "repr(v * (1 + 1e-10))"
expect_fail independent.py qminus "imperfection_q.csv q_minus row 101"
fresh phi
mutate "$tmp/phi/imperfection/imperfection_q.csv" 7 min_phi_plus "repr(v + 1e-9)"
expect_fail independent.py phi "imperfection_q.csv min_phi_plus row 8"
fresh over
mutate "$tmp/over/imperfection/imperfection_capacity.csv" 20 overstatement_max "repr(v + 1e-9)"
expect_fail independent.py over "imperfection_capacity.csv overstatement_max row 21"
fresh count
mutate "$tmp/count/imperfection/imperfection_eq27.csv" 15 non_conservative "int(v) + 1"
expect_fail independent.py count "imperfection_eq27.csv non_conservative row 16"
fresh corners
mutate "$tmp/corners/imperfection/imperfection_eq27.csv" 15 non_conservative_corners "int(v) - 1"
expect_fail independent.py corners "imperfection_eq27.csv non_conservative_corners row 16"
fresh perfect  # the perfect block's first collapse no longer the fragility scene's
mutate "$tmp/perfect/imperfection/imperfection_points.csv" 0 q_collapse "repr(v * 1.0001)"
expect_fail independent.py perfect "not the fragility scene's point"

# 3. independent_records.py: a lean 0.01 first collapse moved 2 % down into its safe side
if [[ -d "${ROCKING_RECORDS:-$here/../../shared/records}" ]]; then
    fresh bracket
    $py - "$tmp/bracket/imperfection/imperfection_points.csv" <<'PY' || { echo "FAIL: could not trim"; exit 1; }
import sys
path = sys.argv[1]
lines = open(path).read().split("\n")
keep = [l for l in lines if l.startswith("#") or l.startswith("imperfection,") or "IT.AQK..HNN" in l]
open(path, "w").write("\n".join(keep))
PY
    status "independent_records.py passes the trimmed copy" 0 \
        $py "$src/independent_records.py" "$tmp/bracket/imperfection" --only brackets
    row=$($py -c "
import csv, sys
rows = [r for r in csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith('#'))]
print(next(i for i, r in enumerate(rows) if r['imperfection'] == 'lean 0.01' and r['check'] == 'confirmed'))
" "$tmp/bracket/imperfection/imperfection_points.csv")
    mutate "$tmp/bracket/imperfection/imperfection_points.csv" "$row" q_collapse "repr(v * 0.98)"
    mutate "$tmp/bracket/imperfection/imperfection_points.csv" "$row" q_safe "repr(v * 0.98)"
    expect_fail independent_records.py bracket "lean 0.01 esm/IT.AQK..HNN" --only brackets
else
    echo "skipped: independent_records.py's failure (no records folder)"
fi

exit $fail
