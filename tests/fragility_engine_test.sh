#!/usr/bin/env bash
# rocking fragility on the batch engine (issue 29): the study's JSON is the
# same bytes on 1 and 2 threads, with its IDAs kept in a rows file, from a
# resume of the finished file, after a SIGKILL or a Ctrl-C resumed, and on
# 1, 2 and 3 ranks under mpirun; a resume on another study is refused, and
# one over an edited record refused naming that record.  The records are synthetic (rocking record synth), so
# that it runs without ../shared.  The MPI part is skipped, saying so, in a
# build without MPI.
#
#   tests/fragility_engine_test.sh ROCKING MPIEXEC   (MPIEXEC: "none" when built without MPI)
set -u
rocking=$(realpath "$1")
mpiexec="${2:-none}"
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# Four stochastic records of 20 s (Rezaeian-Der Kiureghian, seeds 1-4), in m/s^2.
files=()
for seed in 1 2 3 4; do
    "$rocking" record synth --stochastic $seed --dt 0.01 --duration 20 --output "$tmp/s$seed.txt" >/dev/null || exit 1
    files+=("$tmp/s$seed.txt")
done
study=("${files[@]}" --unit m/s2 --alpha 0.1,0.2 --p 1.5,3 --points 40 --bootstrap 100 --seed 7 --json --quiet)
jobs=16  # 4 records x 4 blocks

# ---- The reference: one thread, no rows file.
"$rocking" fragility "${study[@]}" --jobs 1 >"$tmp/ref.json" || { echo "FAIL: the reference run"; exit 1; }
check "the reference fits the blocks" '"median": ' cat "$tmp/ref.json"
"$rocking" fragility "${study[@]}" --jobs 2 >"$tmp/j2.json"
same "2 threads = 1 thread" "$tmp/j2.json" "$tmp/ref.json"
"$rocking" fragility "${study[@]}" --jobs 2 --rows "$tmp/rows.csv" >"$tmp/rows.json"
same "with --rows = without" "$tmp/rows.json" "$tmp/ref.json"
check "the rows file is finished" "# end: $jobs jobs, 0 failed" tail -1 "$tmp/rows.csv"
rows=$(grep -vc '^#' "$tmp/rows.csv")
if [[ $rows == $((jobs + 1)) ]]; then echo "ok: a row per IDA under the column line"; else echo "FAIL: $rows lines of rows, wanted $((jobs + 1))"; fail=1; fi
"$rocking" fragility "${study[@]}" --rows "$tmp/rows.csv" --resume >"$tmp/again.json"
same "--resume of the finished rows runs nothing and prints the same" "$tmp/again.json" "$tmp/ref.json"
touch -d '2000-01-01' "$tmp/rows.csv"
"$rocking" fragility "${study[@]}" --rows "$tmp/rows.csv" --resume >/dev/null
if [[ $(stat -c %Y "$tmp/rows.csv") == $(date -d '2000-01-01' +%s) ]]; then echo "ok: the finished rows file is left as it is"
else echo "FAIL: a resume of the finished rows file rewrote it"; fail=1; fi

# ---- Refusals.
status "--resume without --rows, exit 2" 2 "$rocking" fragility "${study[@]}" --resume
check "--resume without --rows says why" "--resume needs --rows FILE" "$rocking" fragility "${study[@]}" --resume
check "a resume of a finished file on another study is refused" "holds no results of this study" \
    "$rocking" fragility "${files[@]}" --unit m/s2 --alpha 0.1,0.2 --p 1.5,4 --points 40 --json --quiet \
    --rows "$tmp/rows.csv" --resume
cp "$tmp/rows.csv" "$tmp/edit.csv"
awk -F, 'NR == 2000 { $2 = 2 * $2 } 1' OFS=, "$tmp/s4.txt" >"$tmp/s4.edit" && mv "$tmp/s4.edit" "$tmp/s4.txt"  # one sample doubled
check "a resume over an edited record names it" "$tmp/s4.txt, a record the study names, has changed since $tmp/edit.csv was written" \
    "$rocking" fragility "${study[@]}" --rows "$tmp/edit.csv" --resume
"$rocking" record synth --stochastic 4 --dt 0.01 --duration 20 --output "$tmp/s4.txt" >/dev/null
status "a resume on another study exits 1" 1 \
    "$rocking" fragility "${files[@]}" --unit m/s2 --alpha 0.1 --p 1.5 --json --quiet --rows "$tmp/rows.csv" --resume

# ---- Killed midway (SIGKILL) or stopped (SIGINT), then resumed: the same study.
long=("${files[@]}" --unit m/s2 --alpha 0.1,0.15,0.2 --p 1,1.5,2,3,4 --points 60 --bootstrap 100 --seed 7 --json --quiet)
long_jobs=60
"$rocking" fragility "${long[@]}" --jobs 2 >"$tmp/long.json"
export ROCKING_BATCH_FLUSH_SECONDS=0
midway=0
# Job control on: a script's background job would otherwise start with SIGINT ignored.
set -m
for sig in KILL INT; do
    out="$tmp/k$sig.csv"
    "$rocking" fragility "${long[@]}" --jobs 2 --rows "$out" >/dev/null 2>"$tmp/k$sig.err" &
    pid=$!
    for _ in $(seq 1000); do
        [[ -f $out.partial.state ]] && (( $(awk '{print $5}' "$out.partial.state") > 2 )) && break
        sleep 0.01
    done
    kill -$sig $pid
    wait $pid 2>/dev/null; code=$?
    done_jobs=$(awk '{print $5}' "$out.partial.state" 2>/dev/null || echo 0)
    (( done_jobs > 0 && done_jobs < long_jobs )) && midway=$((midway + 1))
    if [[ $sig == INT ]]; then
        if [[ $code == 130 ]]; then echo "ok: Ctrl-C exits 130"; else echo "FAIL: Ctrl-C exits $code"; fail=1; fi
        check "Ctrl-C says how to resume" "the same command with --resume completes them" cat "$tmp/k$sig.err"
    else
        check "a resume of the partial rows on another study is refused" "the study has changed since" \
            "$rocking" fragility "${files[@]}" --unit m/s2 --alpha 0.1 --p 1 --json --quiet --rows "$out" --resume
        # One sample of the second record edited: the resume names that record.
        cp "$tmp/s2.txt" "$tmp/s2.orig"
        awk -F, 'NR == 1500 { $2 = 2 * $2 } 1' OFS=, "$tmp/s2.orig" >"$tmp/s2.txt"
        check "a resume of the partial rows over an edited record names it" \
            "$tmp/s2.txt, a record the study names, has changed since $out.partial was begun" \
            "$rocking" fragility "${long[@]}" --jobs 1 --rows "$out" --resume
        cp "$tmp/s2.orig" "$tmp/s2.txt"
    fi
    "$rocking" fragility "${long[@]}" --jobs 1 --rows "$out" --resume >"$tmp/k$sig.json"
    same "SIG$sig after $done_jobs of $long_jobs IDAs, resumed" "$tmp/k$sig.json" "$tmp/long.json"
done
set +m
if (( midway == 2 )); then echo "ok: both signals landed midway"; else echo "FAIL: $midway of 2 signals landed midway"; fail=1; fi
unset ROCKING_BATCH_FLUSH_SECONDS

# ---- Under mpirun: the bytes of the threaded run on 1, 2 and 3 ranks (3 on 2 cores).
if [[ $mpiexec == none || ! -x $mpiexec ]]; then
    echo "skipped: the MPI checks (this rocking was built without MPI; make deps installs libopenmpi-dev and openmpi-bin)"
    exit $fail
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi() { local np=$1; shift; timeout 300 "$mpiexec" --oversubscribe -np "$np" "$rocking" fragility "$@"; }
for np in 1 2 3; do
    mpi $np "${study[@]}" >"$tmp/np$np.json" 2>"$tmp/np$np.err"
    code=$?
    if [[ $code == 0 ]]; then echo "ok: -np $np exits 0"; else echo "FAIL: -np $np exits $code: $(head -3 "$tmp/np$np.err")"; fail=1; fi
    same "-np $np = threads" "$tmp/np$np.json" "$tmp/ref.json"
done
mpi 3 "${study[@]}" --rows "$tmp/mpi_rows.csv" >"$tmp/np3rows.json" 2>/dev/null
same "-np 3 with a rows file = threads" "$tmp/np3rows.json" "$tmp/ref.json"
same "-np 3's rows file = the threaded one" "$tmp/mpi_rows.csv" "$tmp/rows.csv"
check "a bad command line under mpirun, said once" "--jobs: must be a whole number" mpi 2 "${study[@]}" --jobs 0
status "a bad command line under mpirun, exit 2" 2 mpi 2 "${study[@]}" --jobs 0
check "a missing record under mpirun" "cannot open the file" mpi 2 "$tmp/none.txt" --unit g --dt 0.01 --alpha 0.1 --p 1
exit $fail
