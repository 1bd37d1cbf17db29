#!/usr/bin/env bash
# rocking batch on the command line, on synthetic records (no real records
# needed): its exit codes; a mixed manifest (simulate, collapse, ida,
# spectrum) giving the same bytes on 1, 2 and 3 threads and on standard
# output; rows that do not depend on the order they run in; bad rows reported
# in their rows while the rest run; each kind's figures equal to those of the
# single commands on the same inputs; a batch killed (SIGKILL at random
# moments, SIGINT, SIGTERM) and resumed ending with the uninterrupted file;
# a changed manifest refused on resume; the progress line only on a terminal.
#
#   tests/batch_cli_test.sh ROCKING [MPI]     (MPI: "1" when built with MPI)
set -u
rocking=$(realpath "$1")
built_with_mpi="${2:-0}"
py=/usr/bin/python3
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# The synthetic records and the mixed manifest, $tmp/m.csv (batch_mixed_manifest.sh).
"$(dirname "$0")/batch_mixed_manifest.sh" "$rocking" "$tmp" || exit 1
jobs=$(grep -vc -e '^#' -e '^$' "$tmp/m.csv"); jobs=$((jobs - 1))

# ---- Exit codes: 2 for the command line, 1 for the manifest, 3 for failed jobs.
check  "no manifest"        "usage: rocking batch MANIFEST"     "$rocking" batch
status "no manifest"        2                                   "$rocking" batch
check  "jobs zero"          "--jobs: must be a whole number from 1 to 4096 (got 0)" "$rocking" batch "$tmp/m.csv" --jobs 0
status "jobs zero"          2                                   "$rocking" batch "$tmp/m.csv" --jobs 0
check  "resume needs output" "--resume needs --output"          "$rocking" batch "$tmp/m.csv" --resume
status "resume needs output" 2                                  "$rocking" batch "$tmp/m.csv" --resume
check  "no json"            "--json: the results of a batch are CSV" "$rocking" batch "$tmp/m.csv" --json
check  "unknown option"     "unknown option '--alpha'"          "$rocking" batch "$tmp/m.csv" --alpha 0.1
check  "empty output"       "--output: an empty file name"      "$rocking" batch "$tmp/m.csv" --output ""
check  "manifest missing"   "cannot open the manifest"          "$rocking" batch "$tmp/none.csv"
status "manifest missing"   1                                   "$rocking" batch "$tmp/none.csv"
printf 'record,alpha,mass\nr.txt,0.1,3\n' >"$tmp/unknown.csv"
check  "unknown column"     "unknown column 'mass' (the columns: id, kind, record" "$rocking" batch "$tmp/unknown.csv"
status "unknown column"     1                                   "$rocking" batch "$tmp/unknown.csv"
printf 'kind,alpha\nsimulate,0.1\n' >"$tmp/norecord.csv"
check  "no record column"   "no 'record' column"                "$rocking" batch "$tmp/norecord.csv"
printf '# only a comment\n\n' >"$tmp/noheader.csv"
status "no header"          1                                   "$rocking" batch "$tmp/noheader.csv"
printf 'record,alpha,record\n' >"$tmp/twice.csv"
check  "column twice"       "names column 'record' twice"       "$rocking" batch "$tmp/twice.csv"
if [[ $built_with_mpi != 1 ]]; then
    # Under mpirun, a build without MPI would run the whole batch once per copy.
    check  "mpirun without MPI" "this rocking was built without MPI" env OMPI_COMM_WORLD_SIZE=2 "$rocking" batch "$tmp/m.csv"
    status "mpirun without MPI" 2                                    env OMPI_COMM_WORLD_SIZE=2 "$rocking" batch "$tmp/m.csv"
fi

# ---- The same bytes on 1, 2 and 3 threads, and on standard output.
for j in 1 2 3; do
    "$rocking" batch "$tmp/m.csv" --jobs $j --output "$tmp/r$j.csv" 2>"$tmp/err$j"
    echo "exit $?" >"$tmp/status$j"
done
check "mixed manifest runs"  "exit 0"                           cat "$tmp/status1"
check "summary on stderr"    "rocking batch: $jobs jobs, 0 failed; results in" cat "$tmp/err1"
check_not "no progress off a terminal" "jobs/s"                  cat "$tmp/err2"
if cmp -s "$tmp/r1.csv" "$tmp/r2.csv" && cmp -s "$tmp/r1.csv" "$tmp/r3.csv"; then
    echo "ok: --jobs 1, 2, 3 identical"; else echo "FAIL: --jobs 1, 2, 3 differ"; fail=1; fi
"$rocking" batch "$tmp/m.csv" --jobs 2 >"$tmp/stdout.csv" 2>/dev/null
if cmp -s "$tmp/r1.csv" "$tmp/stdout.csv"; then echo "ok: standard output = --output"; else echo "FAIL: standard output differs from --output"; fail=1; fi
want="# manifest sha256: $(sha256sum "$tmp/m.csv" | cut -d' ' -f1)"
if [[ $(head -1 "$tmp/r1.csv") == "$want" ]]; then echo "ok: the header's digest is the manifest's sha256"
else echo "FAIL: first line $(head -1 "$tmp/r1.csv"), wanted $want"; fail=1; fi
check "end line"             "# end: $jobs jobs, 0 failed"      tail -1 "$tmp/r1.csv"

# ---- Each kind's figures are those of the single command on the same inputs,
# and every job ran what its row says (defaults filled in).
if $py "$(dirname "$0")/batch_compare.py" "$tmp/r1.csv" "$rocking" "$tmp"
then echo "ok: the rows agree with simulate, collapse, fragility and spectrum"; else echo "FAIL: a row differs from its single command"; fail=1; fi

# ---- Issue 39: the method columns.  A manifest without them has no robust
# columns (the results of before); one with them: each ida and spectrum row,
# grid or refine (w 1e-3), with the first robust collapse and the bands, a
# refine row equal to fragility and spectrum --method refine, and a width on
# a grid row refused in its row (exit 3), the manifest's line named.
check_not "no method, no robust columns" "robust_collapse" grep -v '^#' "$tmp/r1.csv"
printf '%s\n' "id,kind,record,unit,record_dt,alpha,p,points,q_max,p_min,p_max,method,width,robust_width" \
    "g1,ida,records/sine1.txt,g,0.01,0.08,2.5,60,12,,,,," \
    "r1,ida,records/sine1.txt,g,0.01,0.08,2.5,60,12,,,refine,1e-3," \
    "r2,ida,records/pulse.txt,m/s2,,0.12,1,,8,,,refine,1e-3,1e-2" \
    "r3,spectrum,records/sine1.5.txt,g,0.01,0.1,,20,,1,6,refine,1e-3,1e-2" \
    "g2,spectrum,records/sine1.5.txt,g,0.01,0.1,,20,,1,6,grid,," >"$tmp/refine.csv"
"$rocking" batch "$tmp/refine.csv" --output "$tmp/refine_r.csv" 2>/dev/null
check "method columns run"   "robust_collapse,q_robust,p_robust,bands,error" grep '^line,' "$tmp/refine_r.csv"
if $py "$(dirname "$0")/batch_compare.py" "$tmp/refine_r.csv" "$rocking" "$tmp" --kinds ida,spectrum
then echo "ok: the refine rows agree with fragility and spectrum --method refine"; else echo "FAIL: a refine row differs from its command"; fail=1; fi
printf '%s\n' "kind,record,unit,record_dt,alpha,p,method,width" "ida,records/sine1.txt,g,0.01,0.1,2,grid,1e-3" >"$tmp/badw.csv"
check  "width on a grid row" "manifest line 2: width: goes with method refine" "$rocking" batch "$tmp/badw.csv"
status "width on a grid row" 3                                   "$rocking" batch "$tmp/badw.csv"

# ---- The rows do not depend on the order the jobs run in, nor on their neighbours.
$py - "$tmp/m.csv" "$tmp/reversed.csv" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
header = next(i for i, l in enumerate(lines) if l and not l.startswith("#"))
data = [l for l in lines[header + 1:] if l]
open(sys.argv[2], "w").write("\n".join([lines[header]] + data[::-1]) + "\n")
PY
"$rocking" batch "$tmp/reversed.csv" --jobs 3 --output "$tmp/rev.csv" 2>/dev/null
if $py - "$tmp/r1.csv" "$tmp/rev.csv" <<'PY'
import sys
def rows(p): return [l.split(",", 1)[1] for l in open(p) if not l.startswith("#")][1:]
a, b = rows(sys.argv[1]), rows(sys.argv[2])
assert a == b[::-1], "rows differ when the manifest is reversed"
PY
then echo "ok: a reversed manifest gives the same rows reversed"; else echo "FAIL: the rows depend on the order"; fail=1; fi

# ---- Bad rows: each reports its error in its row, naming its line; the rest run; exit 3.
cat >"$tmp/bad.csv" <<'EOF'
kind,record,unit,record_dt,alpha,p,solver
simulate,records/sine1.txt,g,0.01,0.1,2,
simulate,records/missing.txt,g,0.01,0.1,2,
simulate,records/sine1.txt,g,0.01,0,2,
collapse,records/sine1.txt,g,0.01,-0.2,,
simulate,records/sine1.txt,g,0.01,0.1,2,rk45
simulate,records/sine1.txt,g,0.01,abc,2,
simulate,records/sine1.txt,g,0.01,0.1,two,
simulate,records/sine1.txt,g,0.01,0.1
simulate,records/missing.txt,g,0.01,0.12,2,
collapse,records/sine1.txt,g,0.01,0.1,,
EOF
"$rocking" batch "$tmp/bad.csv" --jobs 2 --output "$tmp/bad_r.csv" 2>/dev/null
status=$?
if [[ $status == 3 ]]; then echo "ok: failed jobs exit 3"; else echo "FAIL: failed jobs exit $status, wanted 3"; fail=1; fi
if $py - "$tmp/bad_r.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
want = {2: None, 3: "manifest line 3: records/missing.txt: cannot open",
        4: "manifest line 4: alpha: must be in (0, pi/4) (got 0)",
        5: "manifest line 5: alpha: must be in (0, pi/4) (got -0.2)",
        6: "manifest line 6: solver: unknown solver 'rk45'",
        7: "manifest line 7: alpha: 'abc' is not a number",
        8: "manifest line 8: p: 'two' is not a number",
        9: "manifest line 9: 5 cells, the header has 7",
        10: "manifest line 10: records/missing.txt: cannot open", 11: None}
assert [int(r["line"]) for r in rows] == sorted(want), [r["line"] for r in rows]
for r in rows:
    w = want[int(r["line"])]
    if w is None:
        assert r["status"] == "ok" and r["error"] == "" and r["collapse"] in ("yes", "no"), r
    else:
        assert r["status"] == "error" and r["error"].startswith(w), (w, r["error"])
assert open(sys.argv[1]).read().endswith("# end: 10 jobs, 8 failed\n")
PY
then echo "ok: each bad row's error in its row, the good rows ran"; else echo "FAIL: bad rows"; fail=1; fi

# ---- Killed and resumed: the uninterrupted file, byte for byte.  The rows
# are flushed after each one here (ROCKING_BATCH_FLUSH_SECONDS=0), so that
# kills land between many flushes, and inside them.
export ROCKING_BATCH_FLUSH_SECONDS=0
midway=0
for trial in 1 2 3 4 5; do
    out="$tmp/k$trial.csv"
    delay=$($py -c "import random; print(round(random.uniform(0.05, 1.2), 3))")
    "$rocking" batch "$tmp/m.csv" --jobs 2 --output "$out" --quiet &
    pid=$!
    sleep "$delay"
    kill -KILL $pid 2>/dev/null
    wait $pid 2>/dev/null
    if [[ -f $out.partial.state ]]; then
        done_jobs=$(awk '{print $5}' "$out.partial.state")
        (( done_jobs > 0 && done_jobs < jobs )) && midway=$((midway + 1))
    fi
    "$rocking" batch "$tmp/m.csv" --jobs 3 --output "$out" --resume --quiet
    if cmp -s "$out" "$tmp/r1.csv" && [[ ! -e $out.partial && ! -e $out.partial.state ]]; then
        echo "ok: SIGKILL after ${delay}s, resumed: identical"
    else echo "FAIL: SIGKILL after ${delay}s, resumed: differs"; fail=1; fi
done
# A second run of the kill at a point where rows are written, so that the check above is not empty.
if (( midway == 0 )); then
    out="$tmp/kmid.csv"
    "$rocking" batch "$tmp/m.csv" --jobs 1 --output "$out" --quiet &
    pid=$!
    for _ in $(seq 200); do
        [[ -f $out.partial.state ]] && (( $(awk '{print $5}' "$out.partial.state") > 2 )) && break
        sleep 0.02
    done
    kill -KILL $pid 2>/dev/null; wait $pid 2>/dev/null
    done_jobs=$(awk '{print $5}' "$out.partial.state" 2>/dev/null || echo 0)
    (( done_jobs > 0 && done_jobs < jobs )) && midway=1
    "$rocking" batch "$tmp/m.csv" --output "$out" --resume --quiet
    if cmp -s "$out" "$tmp/r1.csv"; then echo "ok: SIGKILL midway ($done_jobs jobs written), resumed: identical"
    else echo "FAIL: SIGKILL midway, resumed: differs"; fail=1; fi
fi
if (( midway > 0 )); then echo "ok: kills landed midway ($midway)"; else echo "FAIL: no kill landed midway"; fail=1; fi

# SIGINT and SIGTERM: the rows delivered are flushed, the process ends by the signal, and --resume completes it.
# Job control on: a script's background job would otherwise start with SIGINT ignored, and keep ignoring it.
set -m
for sig in INT TERM; do
    out="$tmp/s$sig.csv"
    "$rocking" batch "$tmp/m.csv" --jobs 2 --output "$out" --quiet 2>"$tmp/s$sig.err" &
    pid=$!
    for _ in $(seq 200); do
        [[ -f $out.partial.state ]] && (( $(awk '{print $5}' "$out.partial.state") > 2 )) && break
        sleep 0.02
    done
    kill -$sig $pid
    wait $pid
    code=$?
    want_code=$(( 128 + $(kill -l $sig) ))
    if [[ $code == "$want_code" ]]; then echo "ok: SIG$sig ends it with $code"; else echo "FAIL: SIG$sig: exit $code, wanted $want_code"; fail=1; fi
    check "SIG$sig says how to resume" "interrupted by SIG$sig: the rows of" cat "$tmp/s$sig.err"
    check "SIG$sig names --resume"     "the same command with --resume completes them" cat "$tmp/s$sig.err"
    "$rocking" batch "$tmp/m.csv" --output "$out" --resume --quiet
    if cmp -s "$out" "$tmp/r1.csv"; then echo "ok: SIG$sig, resumed: identical"; else echo "FAIL: SIG$sig, resumed: differs"; fail=1; fi
done
set +m

# A partial file is never overwritten by a run without --resume, nor resumed on another manifest.
out="$tmp/changed.csv"
"$rocking" batch "$tmp/m.csv" --jobs 1 --output "$out" --quiet &
pid=$!
for _ in $(seq 200); do [[ -f $out.partial.state ]] && break; sleep 0.02; done
kill -KILL $pid 2>/dev/null; wait $pid 2>/dev/null
check  "partial needs --resume"   "Add --resume to complete it"      "$rocking" batch "$tmp/m.csv" --output "$out"
status "partial needs --resume"   1                                  "$rocking" batch "$tmp/m.csv" --output "$out"
cp "$tmp/m.csv" "$tmp/m_orig.csv"
echo "extra,simulate,records/sine1.txt,g,0.01,0.1,2,,,,,,,," >>"$tmp/m.csv"
check  "changed manifest refused" "the manifest has changed since"   "$rocking" batch "$tmp/m.csv" --output "$out" --resume
status "changed manifest refused" 1                                  "$rocking" batch "$tmp/m.csv" --output "$out" --resume
cp "$tmp/m_orig.csv" "$tmp/m.csv"
"$rocking" batch "$tmp/m.csv" --output "$out" --resume --quiet
if cmp -s "$out" "$tmp/r1.csv"; then echo "ok: the original manifest resumes it"; else echo "FAIL: resumed after a refusal: differs"; fail=1; fi
check  "complete already"         "already complete: $jobs jobs, 0 failed" "$rocking" batch "$tmp/m.csv" --output "$out" --resume
status "complete bad rows"        3                                  "$rocking" batch "$tmp/bad.csv" --output "$tmp/bad_r.csv" --resume
unset ROCKING_BATCH_FLUSH_SECONDS

# ---- Progress: on a terminal (script gives one), not with --quiet.
head -6 "$tmp/m.csv" >"$tmp/small.csv"
script -qec "'$rocking' batch '$tmp/small.csv' --output '$tmp/tty.csv'" /dev/null >"$tmp/tty.out" 2>&1
check     "progress on a terminal"  "jobs, 0 failed"                  cat "$tmp/tty.out"
check     "progress rate"           "jobs/s"                           cat "$tmp/tty.out"
script -qec "'$rocking' batch '$tmp/small.csv' --output '$tmp/tty.csv' --quiet" /dev/null >"$tmp/tty.out" 2>&1
check_not "no progress when quiet"  "jobs/s"                           cat "$tmp/tty.out"
exit $fail
