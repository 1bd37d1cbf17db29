#!/usr/bin/env bash
# Files are never left half-written or mixed, and a failed write is an error
# (issue 31, item 5): simulate --output and reproduce's tables go through a
# temporary file renamed into place (src/harness/atomic_file.hpp), and a
# failed write to standard output exits non-zero.
#
#   tests/output_test.sh ROCKING REPRODUCE
set -u
rocking="$1"
reproduce="$2"
tmp=$(mktemp -d) || exit 1
trap 'umount "$tmp/disk" 2>/dev/null; chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT
fail=0
ok() { echo "ok: $1"; }
bad() { echo "FAIL: $1"; fail=1; }

# expect_error WHAT STATUS MESSAGE... -- COMMAND...: COMMAND exits STATUS and
# what it prints holds every MESSAGE (the file and the problem).
expect_error() {
    local what="$1" want="$2"; shift 2
    local messages=()
    while [[ "$1" != -- ]]; do messages+=("$1"); shift; done
    shift
    "$@" >"$tmp/err" 2>&1
    local got=$?
    local err; err=$(cat "$tmp/err")
    if [[ $got != "$want" ]]; then bad "$what: exit $got, wanted $want ($err)"; return; fi
    for m in "${messages[@]}"; do
        if [[ "$err" != *"$m"* ]]; then bad "$what: wanted '$m' in: $err"; return; fi
    done
    ok "$what (exit $got: $(grep -F -m1 -- "${messages[0]}" "$tmp/err"))"
}

# No temporary file may remain beside a target, whatever happened.
no_leftovers() {  # what, folder
    local left; left=$(find "$2" -name '.*.tmp*' 2>/dev/null)
    if [[ -n "$left" ]]; then bad "$1: temporary files left: $left"; else ok "$1: no temporary file left"; fi
}

block=(--case 2 --x 0.5 --alpha 0.15 --p 2)

# --- Two runs writing the same --output at once: one complete file, never a mix.
# Their headers and bodies differ (the PGA), so a mix matches neither.
"$rocking" simulate "${block[@]}" --rd 0.9 --output "$tmp/a.csv" --dt 2e-4 >/dev/null || bad "simulate --output a"
"$rocking" simulate "${block[@]}" --rd 0.95 --output "$tmp/b.csv" --dt 2e-4 >/dev/null || bad "simulate --output b"
mixed=0
for k in $(seq 1 30); do
    "$rocking" simulate "${block[@]}" --rd 0.9 --output "$tmp/same.csv" --dt 2e-4 >/dev/null 2>&1 &
    "$rocking" simulate "${block[@]}" --rd 0.95 --output "$tmp/same.csv" --dt 2e-4 >/dev/null 2>&1 &
    wait
    cmp -s "$tmp/same.csv" "$tmp/a.csv" || cmp -s "$tmp/same.csv" "$tmp/b.csv" || mixed=$((mixed + 1))
    rm -f "$tmp/same.csv"
done
if [[ $mixed == 0 ]]; then ok "30 pairs of runs on one --output: each left one run's complete file"
else bad "30 pairs of runs on one --output: $mixed left a file that is neither run's"; fi
no_leftovers "concurrent runs" "$tmp"

# --- Standard output on a full disk, or a closed pipe.
expect_error "q to a full disk"          1 "rocking: error writing standard output" "No space left on device" -- \
    sh -c '"$0" q --case 2 --x 1 >/dev/full' "$rocking"
expect_error "q --json to a full disk"   1 "rocking: error writing standard output" -- \
    sh -c '"$0" q --case 2 --x 1 --json >/dev/full' "$rocking"
expect_error "response to a full disk"   1 "rocking: error writing standard output" -- \
    sh -c '"$0" response --case 2 --x 0.5 --steps 100000 >/dev/full' "$rocking"
expect_error "a usage error keeps exit 2 on a full disk" 2 "--x: 'abc' is not a number" -- \
    sh -c '"$0" q --case 2 --x abc >/dev/full' "$rocking"
expect_error "reproduce to a full disk"  1 "reproduce: error writing standard output" -- \
    sh -c '"$0" --no-plot --out "$1" fig04 >/dev/full' "$reproduce" "$tmp/reproduced"
# A closed pipe ends rocking by SIGPIPE, quietly (exit 141 in the shell), as
# other tools end; with SIGPIPE ignored, the write error is reported, exit 1.
first=$("$rocking" response --case 2 --x 0.5 --steps 100000 | head -1)
[[ "$first" == "# case 2, N = 2, x = 0.5"* ]] && ok "response | head -1: the first line, whole" || bad "response | head -1 printed: $first"
"$rocking" response --case 2 --x 0.5 --steps 100000 2>"$tmp/err" | head -1 >/dev/null
status=${PIPESTATUS[0]}
if [[ ( $status == 141 && ! -s "$tmp/err" ) || ( $status == 1 && "$(cat "$tmp/err")" == *"error writing standard output"* ) ]]; then
    ok "response | head -1: ends by SIGPIPE quietly or reports the error (exit $status)"
else bad "response | head -1: exit $status, stderr: $(cat "$tmp/err")"; fi
(trap '' PIPE; "$rocking" response --case 2 --x 0.5 --steps 100000 2>"$tmp/err" | head -1 >/dev/null; echo "${PIPESTATUS[0]}" >"$tmp/status")
status=$(cat "$tmp/status")
if [[ $status == 1 && "$(cat "$tmp/err")" == "rocking: error writing standard output: Broken pipe" ]]; then
    ok "response | head -1 with SIGPIPE ignored: exit 1, 'Broken pipe' reported once"
else bad "response | head -1 with SIGPIPE ignored: exit $status, stderr: $(cat "$tmp/err")"; fi

# --- --output that cannot be written: exit 1, the file and the problem named, nothing left.
expect_error "--output to a full disk"   1 "/dev/full" "No space left on device" -- \
    "$rocking" simulate "${block[@]}" --rd 0.9 --output /dev/full
expect_error "--output in a missing folder" 1 "$tmp/missing/o.csv" "No such file or directory" -- \
    "$rocking" simulate "${block[@]}" --rd 0.9 --output "$tmp/missing/o.csv"
[[ ! -e "$tmp/missing" ]] && ok "the missing folder is not created" || bad "the missing folder was created"
mkdir "$tmp/folder.csv"
expect_error "--output naming a folder" 1 "$tmp/folder.csv" "is a folder" -- \
    "$rocking" simulate "${block[@]}" --rd 0.9 --output "$tmp/folder.csv"
mkdir "$tmp/ro" && chmod 555 "$tmp/ro"
# root writes anywhere: the check runs as nobody then (setpriv), or is skipped.
as_user=()
if [[ $(id -u) == 0 ]]; then
    if command -v setpriv >/dev/null && setpriv --reuid=65534 --regid=65534 --clear-groups true 2>/dev/null &&
       setpriv --reuid=65534 --regid=65534 --clear-groups test -x "$rocking"; then
        as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups)
        chmod 755 "$tmp"
    else as_user=(skip); fi
fi
if [[ "${as_user[*]}" == skip ]]; then
    echo "skipped: an unwritable folder (running as root without setpriv, or nobody cannot run $rocking)"
else
    expect_error "--output in an unwritable folder" 1 "$tmp/ro/o.csv" "Permission denied" -- \
        "${as_user[@]}" "$rocking" simulate "${block[@]}" --rd 0.9 --output "$tmp/ro/o.csv"
    [[ -z "$(ls -A "$tmp/ro")" ]] && ok "the unwritable folder stays empty" || bad "files in the unwritable folder: $(ls -A "$tmp/ro")"
fi
# A disk that fills during the write (a file size limit, SIGXFSZ ignored so
# that write() fails with EFBIG): the previous file stays whole.
cp "$tmp/a.csv" "$tmp/limited.csv"
expect_error "a write that fails half-way" 1 "$tmp/limited.csv" "File too large" -- \
    sh -c 'trap "" XFSZ; ulimit -f 64; exec "$@"' sh "$rocking" simulate "${block[@]}" --rd 0.95 --output "$tmp/limited.csv" --dt 2e-4
cmp -s "$tmp/limited.csv" "$tmp/a.csv" && ok "after it, the previous file is whole" || bad "after a failed write the previous file changed"
no_leftovers "failed writes" "$tmp"

# --- SIGTERM while the file is being written: the target keeps the previous
# file, whole, and the temporary file is removed.  The signal is sent as soon
# as the write shows: a temporary file appears, or the target changes.
"$rocking" simulate "${block[@]}" --rd 0.9 --output "$tmp/big.csv" --dt 1.01e-4 >/dev/null || bad "simulate --output big"
cp "$tmp/big.csv" "$tmp/big.ref"
size=$(stat -c %s "$tmp/big.ref")
landed=0 broken=0
for k in 1 2 3 4 5; do
    "$rocking" simulate "${block[@]}" --rd 0.9 --output "$tmp/big.csv" --dt 1.01e-4 >/dev/null 2>&1 &
    pid=$!
    while kill -0 $pid 2>/dev/null; do
        if compgen -G "$tmp/.big.csv.tmp*" >/dev/null || [[ $(stat -c %s "$tmp/big.csv" 2>/dev/null) != "$size" ]]; then
            kill -TERM $pid 2>/dev/null && landed=$((landed + 1))
            break
        fi
    done
    wait $pid 2>/dev/null
    cmp -s "$tmp/big.csv" "$tmp/big.ref" || broken=$((broken + 1))
    cp "$tmp/big.ref" "$tmp/big.csv"
done
if [[ $landed == 0 ]]; then bad "SIGTERM never landed during a write: the test proved nothing"
elif [[ $broken != 0 ]]; then bad "SIGTERM during $landed of 5 writes: $broken left a target that is not the previous file"
else ok "SIGTERM during $landed of 5 writes: the target stayed the previous file, whole"; fi
no_leftovers "SIGTERM" "$tmp"

# --- A record named with a newline: its name goes into a '# input:' note,
# which must stay one line, or its second half reads as the header row.
printf '0 0.5\n0.01 -0.3\n0.02 0.1\n0.03 0\n' >"$tmp/"$'two\nlines.txt'
"$rocking" simulate --record "$tmp/"$'two\nlines.txt' --unit g --alpha 0.15 --p 2 --output "$tmp/named.csv" >/dev/null
header=$(grep -v '^#' "$tmp/named.csv" | head -1)
[[ "$header" == "t,theta_over_alpha,omega_over_alpha_p" ]] && ok "a record name with a newline stays in its note" ||
    bad "a record name with a newline: the first line after the notes is '$header'"

# --- What the temporary file must not change: a device is written in place
# (as root, a rename would replace /dev/null), a link stays a link, and a
# file keeps its permissions.
"$rocking" simulate "${block[@]}" --rd 0.9 --output /dev/null >/dev/null 2>&1 && [[ -c /dev/null ]] &&
    ok "--output /dev/null: written in place, still a device" || bad "--output /dev/null"
ln -s a.csv "$tmp/link.csv"
"$rocking" simulate "${block[@]}" --rd 0.95 --output "$tmp/link.csv" --dt 2e-4 >/dev/null
[[ -L "$tmp/link.csv" ]] && cmp -s "$tmp/a.csv" "$tmp/b.csv" && ok "--output through a link: the link stays, its file is replaced" ||
    bad "--output through a link"
chmod 640 "$tmp/b.csv"
"$rocking" simulate "${block[@]}" --rd 0.95 --output "$tmp/b.csv" --dt 2e-4 >/dev/null
[[ $(stat -c %a "$tmp/b.csv") == 640 ]] && ok "a replaced file keeps its permissions" || bad "permissions now $(stat -c %a "$tmp/b.csv")"

# --- reproduce: its tables and plots are written the same way.
"$reproduce" --out "$tmp/reproduced" fig04 >/dev/null 2>&1 && [[ -s "$tmp/reproduced/fig04/fig04.csv" ]] &&
    ok "reproduce fig04 writes its files" || bad "reproduce fig04"
no_leftovers "reproduce" "$tmp/reproduced"
# A plot that fails half-way (a script whose data file is missing) leaves the previous PNG.
if command -v gnuplot >/dev/null; then
    mkdir "$tmp/plots"
    printf '%s\n' 'set terminal pngcairo' 'set output (exists("png") ? png : dir."/fig04.png")' \
        'plot dir."/no-such-file.csv" using 1:2' >"$tmp/plots/fig04.gp"
    cp "$tmp/reproduced/fig04/fig04.png" "$tmp/fig04.png.ref"
    "$reproduce" --out "$tmp/reproduced" --plots "$tmp/plots" fig04 >"$tmp/err" 2>&1
    grep -q "plot failed" "$tmp/err" && cmp -s "$tmp/reproduced/fig04/fig04.png" "$tmp/fig04.png.ref" &&
        ok "reproduce: a failed plot leaves the previous PNG whole" || bad "reproduce: after a failed plot: $(cat "$tmp/err")"
    no_leftovers "a failed plot" "$tmp/reproduced"
else
    echo "skipped: a failed plot (gnuplot is not installed)"
fi
mkdir -p "$tmp/blocked/fig04/fig04.csv"
expect_error "reproduce: a table it cannot write" 1 "fig04/fig04.csv" "is a folder" -- \
    "$reproduce" --no-plot --out "$tmp/blocked" fig04

# --- Issue 38, item 5: every file the program writes, gnuplot's PNG included,
# is whole or absent, and a failed write exits non-zero.  gnuplot exits 0 when
# its own writes fail, so the PNG is read back to its IEND chunk before it lands.
"$rocking" record synth --stochastic 1 --dt 0.01 --duration 8 --output "$tmp/rec.txt" >/dev/null || bad "record synth"
"$rocking" record synth --stochastic 2 --dt 0.01 --duration 8 --output "$tmp/rec2.txt" >/dev/null || bad "record synth"
spectrum=(spectrum "$tmp/rec.txt" --unit m/s2 --alpha 0.1 --points 12 --quiet)
for writer in "spectrum --output" "spectrum --png" "fragility --output" "simulate --output" "record synth --output"; do
    case "$writer" in
        "spectrum --output") cmd=("${spectrum[@]}" --output /dev/full) ;;
        "spectrum --png") cmd=("${spectrum[@]}" --png /dev/full) ;;
        "fragility --output") cmd=(fragility "$tmp/rec.txt" "$tmp/rec2.txt" --unit m/s2 --alpha 0.2 --p 3 --points 4 --q-max 2 --quiet --output /dev/full) ;;
        "simulate --output") cmd=(simulate "${block[@]}" --rd 0.9 --output /dev/full) ;;
        "record synth --output") cmd=(record synth --stochastic 1 --dt 0.01 --duration 8 --output /dev/full) ;;
    esac
    [[ "$writer" == "spectrum --png" ]] && ! command -v gnuplot >/dev/null && { echo "skipped: --png (no gnuplot)"; continue; }
    expect_error "$writer /dev/full" 1 "/dev/full" "No space left on device" -- "$rocking" "${cmd[@]}"
done
if command -v gnuplot >/dev/null; then
    "$rocking" "${spectrum[@]}" --png "$tmp/s.png" >/dev/null || bad "spectrum --png"
    cp "$tmp/s.png" "$tmp/s.png.ref"
    # A disk that fills while gnuplot draws: its write fails (EFBIG), it exits 0.
    expect_error "spectrum --png on a disk that fills" 1 "$tmp/s.png" "not written whole" "no IEND chunk" -- \
        sh -c 'trap "" XFSZ; ulimit -f 8; exec "$@"' sh "$rocking" "${spectrum[@]}" --png "$tmp/s.png"
    cmp -s "$tmp/s.png" "$tmp/s.png.ref" && ok "after it, the previous PNG is whole" || bad "a truncated PNG landed"
    no_leftovers "spectrum --png on a full disk" "$tmp"
    rm -f "$tmp/fresh.png"
    sh -c 'trap "" XFSZ; ulimit -f 8; exec "$@"' sh "$rocking" "${spectrum[@]}" --png "$tmp/fresh.png" >/dev/null 2>&1
    [[ ! -e "$tmp/fresh.png" ]] && ok "a PNG not written whole is absent" || bad "a truncated new PNG was left"
    "$reproduce" --out "$tmp/limited-out" fig04 >/dev/null 2>&1   # its CSVs, whole, before the limit below
    sh -c 'trap "" XFSZ; ulimit -f 120; exec "$@"' sh "$reproduce" --out "$tmp/limited-out" fig04 >"$tmp/err" 2>&1
    status=$?
    if [[ $status != 0 ]] && grep -q "not written whole" "$tmp/err"; then ok "reproduce: a PNG cut by a full disk is the scene's error (exit $status)"
    else bad "reproduce: a PNG cut by a full disk: exit $status, $(grep -m1 -i 'plot\|error' "$tmp/err")"; fi
    # The file gnuplot draws into has a plain name we created in the target's folder, and
    # gnuplot runs there: whatever the target's name or folder holds, the drawn file is the
    # one checked and renamed, and nothing is left.  A newline in the name reached the script
    # as '?': gnuplot drew into another file, left as a complete PNG (".nl?x.png.tmpXXXXXX"),
    # and the run failed with "empty: nothing was drawn".
    mkdir -p "$tmp/odd"$'\n'"folder's \\ \$(x)"
    for name in $'nl\nx.png' "it's.png" 'back\slash.png' '$(touch pwned).png' $'bad\xff.png' "odd"$'\n'"folder's \\ \$(x)/in.png"; do
        "$rocking" "${spectrum[@]}" --png "$tmp/$name" >"$tmp/err" 2>&1
        status=$?
        if [[ $status == 0 ]] && /usr/bin/python3 -c "import sys; b = open(sys.argv[1], 'rb').read(); sys.exit(not (b[:8] == b'\x89PNG\r\n\x1a\n' and b[-8:-4] == b'IEND'))" "$tmp/$name"
        then ok "--png $(printf '%q' "$name"): drawn whole at its name"
        else bad "--png $(printf '%q' "$name"): exit $status, $(head -c 300 "$tmp/err")"; fi
    done
    [[ ! -e pwned && ! -e "$tmp/pwned" ]] && ok "a name is never run by a shell" || bad "a name ran as a command"
    no_leftovers "--png at odd names" "$tmp"
    odd_out="$tmp/out's"$'\n'"dir"
    "$reproduce" --out "$odd_out" fig04 >"$tmp/err" 2>&1
    if /usr/bin/python3 -c "import sys; b = open(sys.argv[1], 'rb').read(); sys.exit(not b.endswith(b'IEND\xaeB\x60\x82'))" "$odd_out/fig04/fig04.png" 2>/dev/null
    then ok "reproduce --out with a quote and a newline: fig04.png drawn whole"
    else bad "reproduce --out with a quote and a newline: $(grep -m1 -i 'plot\|error' "$tmp/err")"; fi
    no_leftovers "reproduce at an odd --out" "$odd_out"
else
    echo "skipped: PNGs on a full disk (gnuplot is not installed)"
fi

# --- Issue 38, items 6 and 9: an output that is an input is refused before
# any work, and the input stays as it was; an output that cannot be written
# is found before the study, not after it.
cp "$tmp/rec.txt" "$tmp/rec.ref"
guarded() {  # what, output flag, command...
    local what="$1" flag="$2"; shift 2
    expect_error "$what" 2 "$flag '$tmp/rec.txt' is the input" -- "$rocking" "$@"
    cmp -s "$tmp/rec.txt" "$tmp/rec.ref" || { bad "$what: the input changed"; cp "$tmp/rec.ref" "$tmp/rec.txt"; }
}
guarded "spectrum --output is its record" --output "${spectrum[@]}" --output "$tmp/rec.txt"
guarded "spectrum --png is its record" --png "${spectrum[@]}" --png "$tmp/rec.txt"
guarded "spectrum --rows is its record" --rows "${spectrum[@]}" --rows "$tmp/rec.txt"
guarded "fragility --output is a record" --output fragility "$tmp/rec.ref" "$tmp/rec.txt" --unit m/s2 --alpha 0.2 --p 3 --output "$tmp/rec.txt"
guarded "fragility --rows is a record" --rows fragility "$tmp/rec.ref" "$tmp/rec.txt" --unit m/s2 --alpha 0.2 --p 3 --rows "$tmp/rec.txt"
guarded "eq27 --output is a record" --output eq27 "$tmp/rec.ref" "$tmp/rec.txt" --unit m/s2 --output "$tmp/rec.txt"
guarded "simulate --output is its --record" --output simulate --record "$tmp/rec.txt" --unit m/s2 --alpha 0.2 --p 3 --output "$tmp/rec.txt"
ln -s rec.txt "$tmp/rec-link.txt"
expect_error "spectrum --output through a link to its record" 2 "is the input" -- "$rocking" "${spectrum[@]}" --output "$tmp/rec-link.txt"
cmp -s "$tmp/rec.txt" "$tmp/rec.ref" && ok "the record behind the link is untouched" || bad "the record behind the link changed"
expect_error "spectrum --output and --png on one file" 2 "are one file" -- \
    "$rocking" "${spectrum[@]}" --output "$tmp/one.out" --png "$tmp/./one.out"
# An output in a missing folder is found before any record is read, so
# before the first simulation: the error is the output's, not the missing record's.
for study in spectrum fragility eq27; do
    case $study in
        spectrum) cmd=(spectrum "$tmp/no-such-record.txt" --unit m/s2 --alpha 0.1 --quiet) ;;
        fragility) cmd=(fragility "$tmp/rec.txt" "$tmp/no-such-record.txt" --unit m/s2 --alpha 0.1 --p 2 --quiet) ;;
        eq27) cmd=(eq27 "$tmp/rec.txt" "$tmp/no-such-record.txt" --unit m/s2) ;;
    esac
    expect_error "$study --output in a missing folder, before the records are read" 1 "--output: $tmp/missing/o.csv" \
        "cannot create a file" -- "$rocking" "${cmd[@]}" --output "$tmp/missing/o.csv"
done
# An empty file name is a bad argument for every output option of every command: exit 2,
# before any work (each input but simulate's is missing, so work would fail on it first), nothing left
# behind.  simulate --output '' ran the simulation, then failed to move its temporary file
# into place (exit 1); record synth --output '' exited 0 and wrote nothing.
mkdir "$tmp/empty-names" && cd "$tmp/empty-names" || exit 1
for writer in "simulate --output" "record synth --output" "spectrum --output" "spectrum --png" "spectrum --rows" \
              "fragility --output" "fragility --rows" "eq27 --output" "batch --output"; do
    flag=${writer##* }
    case "$writer" in
        simulate*) cmd=(simulate --record "$tmp/rec.txt" --unit m/s2 --alpha 0.2 --p 3) ;;  # read before, run after
        "record synth"*) cmd=(record synth --pulse 0.5,1,0,2 --dt 0.01 --duration 5) ;;
        spectrum*) cmd=(spectrum no-such-record.txt --unit m/s2 --alpha 0.1 --quiet) ;;
        fragility*) cmd=(fragility no-such-record.txt no-such-record-2.txt --unit m/s2 --alpha 0.1 --p 2 --quiet) ;;
        eq27*) cmd=(eq27 no-such-record.txt no-such-record-2.txt --unit m/s2) ;;
        batch*) cmd=(batch no-such-manifest.csv) ;;
    esac
    expect_error "$writer ''" 2 "$flag: an empty file name" -- "$rocking" "${cmd[@]}" "$flag" ""
done
expect_error "simulate --output '' with a block of its own" 2 "--output: an empty file name" -- \
    "$rocking" simulate "${block[@]}" --rd 0.9 --output ""
[[ -z "$(ls -A "$tmp/empty-names")" ]] && ok "empty names: nothing written" || bad "empty names left: $(ls -A "$tmp/empty-names")"
cd - >/dev/null || exit 1
[[ ! -e "$tmp/missing" ]] && ok "the missing folder is still not created" || bad "the missing folder was created"
no_leftovers "outputs checked before the work" "$tmp"

# --- The probe of the merged build (issue 38): every file the engine writes for
# --rows X (X.partial, X.partial.state and its X.partial.state.tmp) is refused as
# an input, with or without --resume, before any work, and the input stays as it
# was (spectrum REC.partial.state --rows REC removed the record; fragility
# Q.partial --rows Q --resume took it for its rows).
for suffix in .partial .partial.state .partial.state.tmp; do
    for resume in "" --resume; do
        for study in spectrum fragility; do
            cp "$tmp/rec.ref" "$tmp/in$suffix"
            case $study in
                spectrum) cmd=(spectrum "$tmp/in$suffix" --unit m/s2 --alpha 0.1 --points 4 --quiet) ;;
                fragility) cmd=(fragility "$tmp/in$suffix" --unit m/s2 --alpha 0.2 --p 3 --points 4 --quiet) ;;
            esac
            expect_error "$study: its record is --rows X's X$suffix $resume" 2 "--rows's" \
                "'$tmp/in$suffix' is the input FILE" -- "$rocking" "${cmd[@]}" --rows "$tmp/in" $resume
            cmp -s "$tmp/in$suffix" "$tmp/rec.ref" && ok "$study: X$suffix $resume: the record untouched" ||
                bad "$study: X$suffix $resume: the record changed or went"
            rm -f "$tmp/in" "$tmp/in".partial*
        done
    done
done
expect_error "spectrum: --output is --rows X's X.partial" 2 "--rows's partial file" "are one file" -- \
    "$rocking" "${spectrum[@]}" --rows "$tmp/r" --output "$tmp/r.partial"

# --- A rows file on a disk that fills (ulimit -f, SIGXFSZ ignored: a write past
# the limit fails with EFBIG): a run that kept no row leaves nothing behind, so
# that the next plain run is not asked for a --resume (an empty sp.rows.partial
# was left, and the advice named a state file that was not there).
rows_on_full() {  # KiB, study...; its messages through a pipe, which the limit does not cut
    local kib=$1; shift
    ROCKING_BATCH_FLUSH_SECONDS=0 sh -c 'trap "" XFSZ; ulimit -f "$0"; exec "$@"' "$kib" "$rocking" "$@" \
        --rows "$tmp/full.rows" 2>&1 >/dev/null | cat >"$tmp/err"
    return "${PIPESTATUS[0]}"
}
for study in spectrum fragility; do
    case $study in
        spectrum) cmd=(spectrum "$tmp/rec.txt" --unit m/s2 --alpha 0.1,0.2 --points 4 --quiet) ;;
        fragility) cmd=(fragility "$tmp/rec.txt" --unit m/s2 --alpha 0.2 --p 3,4 --points 4 --quiet) ;;
    esac
    for kib in 0 1; do
        rows_on_full $kib "${cmd[@]}"
        code=$?
        left=$(ls "$tmp"/full.rows* 2>/dev/null)
        if [[ $code == 1 && -z $left ]] && grep -q "File too large" "$tmp/err"; then
            ok "$study --rows, $kib KiB to write: exit 1, nothing left"
        else bad "$study --rows, $kib KiB to write: exit $code, left: $left; $(cat "$tmp/err")"; fi
        "$rocking" "${cmd[@]}" --rows "$tmp/full.rows" >/dev/null 2>"$tmp/err" && ok "$study: the next plain run" ||
            bad "$study: the next plain run: $(cat "$tmp/err")"
        rm -f "$tmp"/full.rows*
    done
done

# A real full disk (a 40 KiB tmpfs, as root), filled to every depth: the state's
# temporary can fail too (a stray fr.rows.partial.state.tmp was left).  Each run
# ends complete, or leaves nothing, or leaves rows its state counts and no
# temporary, which a --resume completes into the bytes of a clean run; and
# its advice names no file to remove that is not there.
"$rocking" fragility "$tmp/rec.txt" --unit m/s2 --alpha 0.2,0.25 --p 3,4,5 --points 4 --quiet \
    --rows "$tmp/clean.rows" >/dev/null || bad "fragility --rows, the clean run"
disk="$tmp/disk"
mkdir -p "$disk"
if mount -t tmpfs -o size=40k tmpfs "$disk" 2>/dev/null; then
    outcomes=""
    for fill in 26000 28000 30000 31000 32000 33000 34000 35000 36000 38000; do
        rm -rf "${disk:?}"/*
        head -c $fill /dev/zero >"$disk/fill" 2>/dev/null
        ROCKING_BATCH_FLUSH_SECONDS=0 "$rocking" fragility "$tmp/rec.txt" --unit m/s2 --alpha 0.2,0.25 --p 3,4,5 \
            --points 4 --quiet --rows "$disk/fr.rows" >/dev/null 2>"$tmp/err"
        code=$?
        rm -f "$disk/fill"
        named=$(sed -n 's/.*[Rr]emove //p' "$tmp/err" | grep -o "$disk/[^ :;,)]*" | sort -u)
        for f in $named; do [[ -e $f ]] || bad "fill $fill: the advice names $f, which is not there: $(cat "$tmp/err")"; done
        [[ -e $disk/fr.rows.partial.state.tmp ]] && bad "fill $fill: the state's temporary was left"
        if [[ $code == 0 ]]; then outcomes+=" complete"
        elif [[ ! -e $disk/fr.rows.partial && ! -e $disk/fr.rows.partial.state ]]; then outcomes+=" nothing"
            "$rocking" fragility "$tmp/rec.txt" --unit m/s2 --alpha 0.2,0.25 --p 3,4,5 --points 4 --quiet \
                --rows "$disk/fr.rows" >/dev/null 2>"$tmp/err2" || bad "fill $fill: the next plain run: $(cat "$tmp/err2")"
        elif [[ -e $disk/fr.rows.partial.state ]] && (( $(awk '{print $5}' "$disk/fr.rows.partial.state") > 0 )); then
            outcomes+=" kept"
            "$rocking" fragility "$tmp/rec.txt" --unit m/s2 --alpha 0.2,0.25 --p 3,4,5 --points 4 --quiet \
                --rows "$disk/fr.rows" --resume >/dev/null 2>"$tmp/err2" || bad "fill $fill: --resume: $(cat "$tmp/err2")"
        else bad "fill $fill: exit $code left $(ls "$disk"): $(cat "$tmp/err")"; continue; fi
        cmp -s "$disk/fr.rows" "$tmp/clean.rows" || bad "fill $fill: the rows file, run again, differs from the clean one"
    done
    ok "fragility --rows on a 40 KiB disk filled to 10 depths:$outcomes"
    umount "$disk"
else
    echo "skipped: a real full disk (mount -t tmpfs is not permitted here)"
fi

exit $fail
