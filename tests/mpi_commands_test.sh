#!/usr/bin/env bash
# Every subcommand under mpirun -np 2 gives one report, or one refusal: the
# commands that share their work across the ranks (spectrum, fragility, eq27,
# batch) print the bytes of a run without mpirun; the others exit 2, said
# once, with nothing on standard output.  The list is checked against the
# commands that `rocking --help` names, so that a new one is not left out.
# eq27's IDAs shared on 1, 2 and 3 ranks give the bytes of one process on 1
# or 2 threads (JSON, text and CSV).  An input the ranks cannot share (a
# pipe, a FIFO, a descriptor's path: /dev/stdin, <(...), /dev/fd/N,
# /proc/self/fd/N, /proc/PID/fd/N) is refused before any work, said once,
# exit 2; in a batch manifest every rank refuses it in its rows alike.
# Threads that cannot start on the ranks end batch and fragility with exit 2,
# said once under the command's name, no resume state left.  Built without
# MPI it exits 77 (a skip) and says so.
#
#   tests/mpi_commands_test.sh ROCKING MPIEXEC     (MPIEXEC: "none" when built without MPI)
set -u
rocking=$(realpath "$1")
mpiexec="${2:-none}"
if [[ $mpiexec == none || ! -x $mpiexec ]]; then
    echo "skipped: this rocking was built without MPI (make deps installs libopenmpi-dev and openmpi-bin)"
    exit 77
fi
py=/usr/bin/python3
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
# Tests run as root in containers: OpenMPI refuses root unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi() { local np=$1; shift; timeout 300 "$mpiexec" --oversubscribe -np "$np" "$rocking" "$@"; }
# How many times a file says `text` (rank 0 alone should), counted as text: two ranks'
# lines may interleave.
said() { grep -o -F -- "$2" "$1" | wc -l; }

for f in 0.7 1 1.5; do
    $py -c "
import math
for k in range(1000):
    t = k * 0.01
    print('%.10f' % (0.3 * math.sin(2 * math.pi * $f * t) * math.exp(-t / 3)))" >"sine$f.txt"
done
plain=(--unit g --dt 0.01)
printf 'kind,record,unit,record_dt,alpha,p\nsimulate,sine1.txt,g,0.01,0.1,2\ncollapse,sine1.txt,g,0.01,0.15,\n' >m.csv

# ---- Every subcommand: one report or one refusal.
declare -A shares=([spectrum]=1 [fragility]=1 [eq27]=1 [batch]=1)
invocations=(
    "q --case 2 --x 1 --json"
    "response --case 2 --x 1 --json"
    "simulate --case 2 --x 1 --rd 0.9 --alpha 0.15 --p 2 --json"
    "record info sine1.txt ${plain[*]} --json"
    "record synth --pulse 0.5,1,0,2 --dt 0.01 --duration 3 --json"
    "record floor sine1.txt ${plain[*]} --period 0.5 --participation 1.5 --json"
    "collapse sine1.txt ${plain[*]} --alpha 0.15 --json"
    "assess sine1.txt ${plain[*]} --alpha 0.15 --height 2 --json"
    "spectrum sine1.txt ${plain[*]} --alpha 0.1,0.2 --points 10 --json"
    "fragility sine0.7.txt sine1.txt ${plain[*]} --alpha 0.1 --p 2,3 --points 10 --json"
    "eq27 sine0.7.txt sine1.txt ${plain[*]} --alpha 0.1 --p-min 1 --p-max 4 --p-points 2 --q-max 8 --json"
    "batch m.csv --quiet"
)
covered=" "
for line in "${invocations[@]}"; do
    read -r -a args <<<"$line"
    name=${args[0]}
    covered+="$name "
    "$rocking" "${args[@]}" >"one.out" 2>/dev/null
    mpi 2 "${args[@]}" >"np2.out" 2>"np2.err"
    code=$?
    if [[ -n ${shares[$name]:-} ]]; then
        if [[ $code == 0 ]]; then echo "ok: $name under mpirun exits 0"; else echo "FAIL: $name under mpirun exits $code"; fail=1; fi
        same "$name under mpirun -np 2 prints one report, the bytes of one process" np2.out one.out
    else
        [[ $name == record ]] && name="record ${args[1]}"
        if [[ $code == 2 && ! -s np2.out && $(said np2.err "does not share its work across the ranks") == 1 ]]; then
            echo "ok: $name refused under mpirun, exit 2, said once"
        else
            echo "FAIL: $name under mpirun: exit $code, $(wc -c <np2.out) bytes out, stderr: $(head -c 300 np2.err)"; fail=1
        fi
    fi
done
check "the refusal names the commands that do share" "the commands that run under mpirun: spectrum, fragility, eq27, batch" \
    mpi 2 q --case 2 --x 1
# Every command the usage names is among those tried.
for name in $("$rocking" --help | sed -n 's/^ *\(usage: \)\{0,1\}rocking \([a-z0-9]*\).*/\2/p' | sort -u); do
    if [[ $covered == *" $name "* ]]; then echo "ok: $name is tried under mpirun"
    else echo "FAIL: the usage names '$name', not tried under mpirun here"; fail=1; fi
done
mpi 2 --help >help.out 2>/dev/null
# Counted as text, not lines: two ranks' copies may interleave within a line.
copies=$(grep -o 'usage: rocking q' help.out | wc -l)
if [[ $copies == 1 ]]; then echo "ok: --help under mpirun, printed once"
else echo "FAIL: --help under mpirun printed $copies times"; fail=1; fi
mpi 2 frobnicate >/dev/null 2>err.txt
if [[ $(said err.txt "unknown command 'frobnicate'") == 1 ]]; then echo "ok: an unknown command under mpirun, said once"
else echo "FAIL: an unknown command under mpirun, said $(said err.txt "unknown command") times"; fail=1; fi

# ---- eq27's IDAs shared by the ranks: the bytes of one process, on 1 or 2 threads.
study=(sine0.7.txt sine1.txt sine1.5.txt "${plain[@]}" --alpha 0.1,0.2 --p-min 1 --p-max 4 --p-points 3 --q-max 10
       --bootstrap 50 --seed 3)
"$rocking" eq27 "${study[@]}" --jobs 1 --json >ref.json
"$rocking" eq27 "${study[@]}" --jobs 1 --output ref.csv >ref.txt
"$rocking" eq27 "${study[@]}" --jobs 2 --json >j2.json
same "eq27 on 2 threads = 1 thread" j2.json ref.json
for np in 1 2 3; do
    mpi $np eq27 "${study[@]}" --json >"np$np.json" 2>"np$np.err"
    code=$?
    if [[ $code == 0 ]]; then echo "ok: eq27 -np $np exits 0"; else echo "FAIL: eq27 -np $np exits $code: $(head -3 "np$np.err")"; fail=1; fi
    same "eq27 JSON on $np rank(s) = one process" "np$np.json" ref.json
done
mpi 3 eq27 "${study[@]}" --jobs 2 --output np3.csv >np3.txt 2>/dev/null
same "eq27 text on 3 ranks of 2 threads = one process" np3.txt ref.txt
same "eq27 CSV on 3 ranks of 2 threads = one process" np3.csv ref.csv
# --method refine: each row carries both capacities, the same bytes on ranks.
"$rocking" eq27 "${study[@]}" --method refine --width 1e-3 --json >refine.json
mpi 2 eq27 "${study[@]}" --method refine --width 1e-3 --json >np2r.json 2>/dev/null
same "eq27 --method refine JSON on 2 ranks = one process" np2r.json refine.json
if grep -qF '"first_robust_collapse": {' refine.json; then echo "ok: eq27 --method refine has both capacities"
else echo "FAIL: eq27 --method refine without the robust collapse's shares"; fail=1; fi
mpi 2 eq27 sine1.txt "${plain[@]}" --alpha 0.1,0.1 >/dev/null 2>err.txt
code=$?
if [[ $code == 2 && $(said err.txt "--alpha: 0.1 is given twice") == 1 ]]; then echo "ok: eq27's bad argument under mpirun, exit 2, said once"
else echo "FAIL: eq27's bad argument under mpirun: exit $code, $(cat err.txt)"; fail=1; fi
cp sine1.txt copy.txt
mpi 2 eq27 sine1.txt copy.txt "${plain[@]}" >/dev/null 2>err.txt
code=$?
if [[ $code == 2 && $(said err.txt "copy.txt: the same record as sine1.txt") == 1 ]]; then
    echo "ok: eq27's repeated record under mpirun, exit 2, said once"
else echo "FAIL: eq27's repeated record under mpirun: exit $code, $(cat err.txt)"; fail=1; fi

# ---- Inputs the ranks cannot share: refused before any work, said once, exit 2.
piped() {  # description, command...; sine1.txt on standard input
    local what="$1"; shift
    mpi 2 "$@" <sine1.txt >out.txt 2>err.txt
    local code=$?
    if [[ $code == 2 && ! -s out.txt && $(said err.txt "which the ranks of an MPI run cannot share") == 1 &&
          $(said err.txt "save it to a file") == 1 ]]; then echo "ok: $what refused under mpirun, exit 2, said once"
    else echo "FAIL: $what under mpirun: exit $code, stderr: $(head -c 400 err.txt)"; fail=1; fi
}
piped "spectrum of /dev/stdin" spectrum /dev/stdin "${plain[@]}" --alpha 0.1 --points 10
piped "fragility of /dev/stdin" fragility sine0.7.txt /dev/stdin "${plain[@]}" --alpha 0.1 --p 2 --points 10
piped "eq27 of /dev/stdin" eq27 sine0.7.txt /dev/stdin "${plain[@]}" --alpha 0.1 --p-points 2 --p-min 1 --p-max 2
piped "a batch manifest on /dev/stdin" batch /dev/stdin --quiet
mkfifo fifo.txt
piped "a FIFO given to spectrum" spectrum fifo.txt "${plain[@]}" --alpha 0.1 --points 10
check "the refusal names the file" "/dev/stdin: a descriptor of the process that names it" \
    mpi 2 spectrum /dev/stdin "${plain[@]}" --alpha 0.1
# A descriptor's path (bash's <(...), /dev/fd/N, /proc/self/fd/N, /proc/PID/fd/N) is the
# process's own, whatever file is behind it: the ranks, started by mpirun, cannot open it
# (rank 1 said "/dev/fd/63:0: cannot open the file", exit 1).
piped "spectrum of <(cat FILE)" spectrum <(cat sine1.txt) "${plain[@]}" --alpha 0.1 --points 10
exec 7<sine1.txt
for path in /dev/fd/7 /proc/self/fd/7 "/proc/$$/fd/7"; do
    piped "spectrum of $path (a regular file behind it)" spectrum "$path" "${plain[@]}" --alpha 0.1 --points 10
    piped "fragility of $path" fragility sine0.7.txt "$path" "${plain[@]}" --alpha 0.1 --p 2 --points 10
    piped "a batch manifest on $path" batch "$path" --quiet
done
exec 7<&-
check "a descriptor refused by its name" "/dev/fd/63: a descriptor of the process that names it" \
    mpi 2 spectrum /dev/fd/63 "${plain[@]}" --alpha 0.1
# A manifest's row on /dev/stdin: every rank refuses it in its row, so that the results do
# not depend on the rank that ran the job (rank 0 alone reads mpirun's standard input).
printf 'kind,record,unit,record_dt,alpha,p\nsimulate,/dev/stdin,g,0.01,0.1,2\nsimulate,sine1.txt,g,0.01,0.1,2\nsimulate,/dev/stdin,g,0.01,0.1,3\nsimulate,sine1.txt,g,0.01,0.1,3\n' >stdin.csv
for np in 1 2 3; do
    mpi $np batch stdin.csv --output "stdin$np.csv" --quiet <sine1.txt >/dev/null 2>&1
    code=$?
    if [[ $code == 3 ]]; then echo "ok: a manifest row on /dev/stdin, $np rank(s): exit 3"; else echo "FAIL: $np rank(s): exit $code, wanted 3"; fail=1; fi
done
same "a manifest row on /dev/stdin: 2 ranks = 1" stdin2.csv stdin1.csv
same "a manifest row on /dev/stdin: 3 ranks = 1" stdin3.csv stdin1.csv
check "the row says why" "manifest line 2: /dev/stdin: a descriptor of the process that names it" grep -F ',error,' stdin1.csv
check "the row says what to do" "save it to a file and name that file in the manifest" grep -F ',error,' stdin1.csv
check "the other rows run" "# end: 4 jobs, 2 failed" tail -1 stdin1.csv
# A manifest's record on /proc/self/fd/N: refused in its row alike.
printf 'kind,record,unit,record_dt,alpha,p\nsimulate,/proc/self/fd/0,g,0.01,0.1,2\nsimulate,sine1.txt,g,0.01,0.1,2\n' >fd.csv
mpi 2 batch fd.csv --output fd_r.csv --quiet <sine1.txt >/dev/null 2>&1
check "a manifest row on /proc/self/fd/0" "manifest line 2: /proc/self/fd/0: a descriptor of the process" \
    grep -F ',error,' fd_r.csv

# ---- Threads that cannot start on the ranks (issue 38, item 7): every command on the
# engine ends with exit 2, the refusal said once under its own name, and no resume state
# is left to block the next run (MPI_ABORT had left the .partial and its state, "jobs 0").
$py -c "
rows = ['record,unit,record_dt,alpha,p'] + ['sine1.txt,g,0.01,0.2,%d' % (1 + k % 5) for k in range(2000)]
open('many.csv', 'w').write('\n'.join(rows) + '\n')"
alphas=$(seq -s, 0.10 0.01 0.29); ps=$(seq -s, 1 1 20)   # 400 IDAs
limited() {  # description, command, output, arguments...: under ulimit -v, 1500 threads asked
    local what="$1" command="$2" out="$3"; shift 3
    rm -f "$out" "$out".partial*
    (ulimit -v 1048576; mpi 2 "$command" "$@" --jobs 1500) >/dev/null 2>err.txt
    local code=$?
    if [[ $code == 2 && $(said err.txt "rocking $command: --jobs: ") == 1 && $(said err.txt "threads were needed") == 1 ]]
    then echo "ok: $what: threads refused on the ranks, exit 2, said once as rocking $command"
    else echo "FAIL: $what: exit $code, stderr: $(head -c 600 err.txt)"; fail=1; fi
    local left; left=$(ls "$out".partial* 2>/dev/null)
    if [[ -z $left && ! -e $out ]]; then echo "ok: $what: nothing left"; else echo "FAIL: $what: left $left $out"; fail=1; fi
}
limited "batch --output" batch many_r.csv many.csv --output many_r.csv
status  "the next plain batch runs" 0 mpi 2 batch many.csv --output many_r.csv --quiet
limited "fragility --rows" fragility fr.rows sine1.txt "${plain[@]}" --alpha "$alphas" --p "$ps" --points 4 --rows fr.rows

# Without mpirun standard input is one process's: read once, as before.
"$rocking" spectrum /dev/stdin "${plain[@]}" --alpha 0.1 --points 10 --json <sine1.txt >stdin.json
"$rocking" spectrum sine1.txt "${plain[@]}" --alpha 0.1 --points 10 --json >file.json
if cmp -s <(sed 's#/dev/stdin#sine1.txt#g' stdin.json) file.json; then echo "ok: /dev/stdin without mpirun, read"
else echo "FAIL: /dev/stdin without mpirun differs from the file"; fail=1; fi
exit $fail
