#!/usr/bin/env bash
# Records read from pipes, FIFOs and /dev/stdin, and inputs without an end:
# read once, bounded, and ended by an error naming the file and the cap.
set -u
rocking="$1"
fail=0
# The hostile inputs below made the old readers grow without bound: a ceiling
# on memory makes such a regression fail in seconds instead of filling the
# machine, and `timeout` makes a reader that blocks fail instead of hanging CI.
ulimit -v 2097152
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

expect() {  # description, wanted exit status, wanted substring, command...
    local what="$1" want_status="$2" want="$3"; shift 3
    local out status
    out=$(timeout 40 "$@" 2>&1); status=$?
    if [[ $status == 124 ]]; then echo "FAIL: $what: still running after 40 s"; fail=1
    elif [[ $status != "$want_status" || "$out" != *"$want"* ]]; then
        echo "FAIL: $what: exit $status (wanted $want_status), wanted '$want' in: ${out:0:400}"; fail=1
    else echo "ok: $what"; fi
}
same() {  # description, output of the file, output of the pipe (paths written FILE in both)
    local what="$1" a="$2" b="$3"
    if [[ -z "$a" || "$a" != "$b" ]]; then
        echo "FAIL: $what: the file gave"; echo "$a" | head -3; echo "  and the pipe gave"; echo "$b" | head -3; fail=1
    else echo "ok: $what"; fi
}
# Runs rocking on `file` read through <(cat), /dev/stdin and a FIFO with a
# writer, each against the output of the file itself.
through_pipes() {  # description, file, arguments before FILE..., --, arguments after FILE...
    local what="$1" file="$2"; shift 2
    local before=() after=()
    while [[ $1 != -- ]]; do before+=("$1"); shift; done; shift; after=("$@")
    local direct procsub piped fromfifo fifo="$scratch/fifo"
    if ! direct=$(timeout 40 "$rocking" "${before[@]}" "$file" "${after[@]}" 2>&1); then
        echo "FAIL: $what: the file itself is refused: ${direct:0:400}"; fail=1; return
    fi
    direct=${direct//"$file"/FILE}
    procsub=$(timeout 40 "$rocking" "${before[@]}" <(cat "$file") "${after[@]}" 2>&1 | sed -E 's#/dev/fd/[0-9]+#FILE#g')
    same "$what: <(cat FILE)" "$direct" "$procsub"
    piped=$(cat "$file" | timeout 40 "$rocking" "${before[@]}" /dev/stdin "${after[@]}" 2>&1)
    same "$what: cat FILE | ... /dev/stdin" "$direct" "${piped//\/dev\/stdin/FILE}"
    rm -f "$fifo"; mkfifo "$fifo"
    cat "$file" > "$fifo" &
    fromfifo=$(timeout 40 "$rocking" "${before[@]}" "$fifo" "${after[@]}" 2>&1)
    kill $! 2>/dev/null; wait $! 2>/dev/null
    same "$what: a FIFO" "$direct" "${fromfifo//"$fifo"/FILE}"
}

# A small record of each format, made here, so that the test runs without the shared records.
awk 'BEGIN { n = 3000; p = 0
  for (k = 0; k < n; k++) { a = sprintf("%.6f", 300 * sin(0.02 * k) * exp(-0.001 * k)); s[k] = a
                            v = (a + 0 < 0) ? -a : a + 0; if (v > p) p = v }
  print "NETWORK: XX"; print "STATION_CODE: PIPE"; print "STREAM: HNE"
  print "EVENT_DATE_YYYYMMDD: 20260101"; print "EVENT_TIME_HHMMSS: 000000"
  print "SAMPLING_INTERVAL_S: 0.005000"; print "NDATA: " n; print "UNITS: cm/s^2"; printf "PGA_CM/S^2: %.6f\n", p
  for (k = 0; k < n; k++) print s[k] }' > "$scratch/rec.asc"
printf 'PEER NGA STRONG MOTION DATABASE RECORD\nTEST 1999, PIPE, 180\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    7, DT=   .0050 SEC\n  .1E-02  .2E-02 -.3E-02  .4E-02 -.5E-02\n  .6E-02 -.1E-02\n' > "$scratch/rec.at2"
awk 'BEGIN { for (k = 0; k < 500; k++) printf "%.6f\n", 0.3 * sin(0.05 * k) }' > "$scratch/one.txt"
awk 'BEGIN { for (k = 0; k < 500; k++) printf "%.2f,%.6f\n", 0.01 * k, 0.3 * sin(0.05 * k) }' > "$scratch/two.csv"

# They used to be opened twice (to sniff the format, then to read it) and
# failed with "missing header key SAMPLING_INTERVAL_S" or an empty record.
through_pipes "ESM, record info"          "$scratch/rec.asc" record info --
through_pipes "PEER, record info --json"  "$scratch/rec.at2" record info -- --json
through_pipes "one column, record info"   "$scratch/one.txt" record info -- --unit g --dt 0.01
through_pipes "two columns, record info"  "$scratch/two.csv" record info -- --unit g
through_pipes "simulate --record"         "$scratch/rec.asc" simulate --alpha 0.15 --p 2 --record --
through_pipes "collapse"                  "$scratch/rec.asc" collapse -- --alpha 0.15
through_pipes "assess"                    "$scratch/rec.asc" assess -- --alpha 0.15 --height 2
real=${ROCKING_RECORDS:-$(dirname "$0")/../../shared/records}/esm-extra/TV.MIR08..HNN.D.20120529.070002.C.ACC.ASC
if [[ -f "$real" ]]; then through_pipes "the largest real record" "$real" simulate --alpha 0.15 --p 2 --json --record --
else echo "skipped: the largest real record through pipes (shared records absent: $real)"; fi

# No end: a device, a file with one endless line, endless lines from a pipe.
expect "/dev/zero stops at the line cap" 1 "/dev/zero:1: a line longer than 1 MiB (the cap on a line's length)" \
    "$rocking" record info /dev/zero
head -c 3000000 /dev/zero | tr '\0' 7 > "$scratch/endless_line.txt"
expect "an endless line stops at the line cap" 1 "endless_line.txt:1: a line longer than 1 MiB" \
    "$rocking" record info "$scratch/endless_line.txt" --unit g --dt 0.01
expect "an endless line from a pipe" 1 "/dev/stdin:3: a line longer than 1 MiB" \
    bash -c '{ printf "0.1\n0.2\n"; tr "\0" 7 < /dev/zero; } | "$1" record info /dev/stdin --unit g --dt 0.01' _ "$rocking"
expect "endless lines stop at the size cap" 1 "/dev/stdin: larger than 256 MiB (the cap on a record file's size)" \
    bash -c 'yes 0.1 | "$1" simulate --record /dev/stdin --unit g --record-dt 0.01 --alpha 0.15 --p 2' _ "$rocking"

# No data: a FIFO nobody opens for writing, a writer that stalls mid-stream.
# Both wait the 10 s timeout, side by side.
mkfifo "$scratch/silent" "$scratch/stall"
expect "a FIFO without a writer times out" 1 \
    "silent: no data within 10 s (the read timeout): a pipe or FIFO that nobody writes to?" \
    "$rocking" record info "$scratch/silent" > "$scratch/silent.out" &
silent=$!
(printf 'EVENT_ID: X\nNDATA: 3\n'; exec sleep 60) > "$scratch/stall" &
writer=$!
expect "a writer that stalls times out" 1 "stall:3: no more data for 10 s after 21 bytes (the read timeout)" \
    "$rocking" collapse "$scratch/stall" --alpha 0.15
kill "$writer" 2>/dev/null
wait "$silent"; cat "$scratch/silent.out"
grep -q '^FAIL' "$scratch/silent.out" && fail=1

exit $fail
