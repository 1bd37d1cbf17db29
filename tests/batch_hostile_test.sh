#!/usr/bin/env bash
# rocking batch against the hostile probes of issue 38, on synthetic records:
# a resume refused when a record it read has changed (edited, replaced by
# another file of its name, removed, read from a pipe) or the manifest has;
# RFC 4180 rows (a quoted line break, "" escapes, a quote never closed, CRLF,
# a byte-order mark) and results that Python's csv module reads back; no
# more threads than jobs, and threads that cannot start named by --jobs with
# nothing left behind; an output that is an input refused before any job;
# the folder relative records resolve from, said; a run still holding its
# results said as such, not "add --resume"; and the probe of the merged
# build: every file the engine writes for --output (X.partial.state.tmp too)
# refused as an input, rows the solvers cannot follow refused by their
# column, CR-only line ends refused, results on a full disk leaving nothing
# or resumable rows.
#
#   tests/batch_hostile_test.sh ROCKING
set -u
rocking=$(realpath "$1")
py=/usr/bin/python3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1

"$here/batch_mixed_manifest.sh" "$rocking" "$tmp" || exit 1   # records/ and m.csv
"$rocking" batch m.csv --jobs 2 --output clean.csv --quiet || { echo "FAIL: the clean run"; exit 1; }
same() {  # description, file, reference
    if cmp -s "$2" "$3"; then echo "ok: $1"; else echo "FAIL: $1: $2 differs from $3"; fail=1; fi
}
absent() {  # description, paths...
    local what="$1"; shift
    for p in "$@"; do [[ -e $p ]] && { echo "FAIL: $what: $p was left"; fail=1; return; }; done
    echo "ok: $what"
}
scale() {  # file, factor: every sample of a one-column record times the factor
    $py - "$1" "$2" <<'PY'
import sys
v = [float(l) for l in open(sys.argv[1])]
open(sys.argv[1], "w").write("".join("%.10f\n" % (x * float(sys.argv[2])) for x in v))
PY
}
# A batch killed once some rows are counted: OUTPUT.partial and its state stay.
killed_midway() {  # output
    rm -f "$1" "$1.partial" "$1.partial.state"
    ROCKING_BATCH_FLUSH_SECONDS=0 "$rocking" batch m.csv --jobs 1 --output "$1" --quiet &
    local pid=$!
    for _ in $(seq 500); do
        [[ -f $1.partial.state ]] && (( $(awk '{print $5}' "$1.partial.state") > 2 )) && break
        sleep 0.01
    done
    kill -KILL $pid 2>/dev/null; wait $pid 2>/dev/null
    [[ -f $1.partial.state ]] || { echo "FAIL: no partial file to resume"; fail=1; }
}

# ---- Item 2: a resume proves that every input is the one the first part used.
cp records/sine1.txt sine1.orig
killed_midway k.csv
scale records/sine1.txt 1.1
check  "edited record refused"      "records/sine1.txt, a record the manifest names, has changed since k.csv.partial was begun" \
       "$rocking" batch m.csv --output k.csv --resume
status "edited record refused"      1   "$rocking" batch m.csv --output k.csv --resume
cp records/sine1.5.txt records/sine1.txt      # another file under the record's name
check  "replaced record refused"    "records/sine1.txt, a record the manifest names, has changed since" \
       "$rocking" batch m.csv --output k.csv --resume
rm records/sine1.txt
check  "removed record refused"     "it is now none (the file could not be read)" "$rocking" batch m.csv --output k.csv --resume
cp sine1.orig records/sine1.txt
cp m.csv m.orig; echo "# a comment added" >>m.csv
check  "edited manifest refused"    "the manifest has changed since" "$rocking" batch m.csv --output k.csv --resume
cp m.orig m.csv
"$rocking" batch m.csv --output k.csv --resume --quiet
same   "the original records resume it to the clean file" k.csv clean.csv
# Complete results are "already complete" only for the records they were computed from.
cp records/sine1.5.txt sine1.5.orig
scale records/sine1.5.txt 1.1
check  "complete results, edited record" "records/sine1.5.txt, a record the manifest names, has changed since k.csv was written" \
       "$rocking" batch m.csv --output k.csv --resume
status "complete results, edited record" 1 "$rocking" batch m.csv --output k.csv --resume
cp sine1.5.orig records/sine1.5.txt
check  "complete results, records restored" "already complete" "$rocking" batch m.csv --output k.csv --resume
# The header names every record with its digest (sha256sum's), in the order first named.
want=$(for r in records/sine1.txt records/sine1.5.txt records/pulse.txt; do echo "# record sha256: $(sha256sum "$r" | cut -d' ' -f1) $r"; done)
if [[ $(sed -n 2,4p clean.csv) == "$want" ]]; then echo "ok: the records' digests in the header"
else echo "FAIL: the header's record lines: $(sed -n 2,4p clean.csv)"; fail=1; fi
# A record read from a pipe cannot be read again: its results cannot be resumed.
printf 'record,unit,record_dt,alpha,p\n/dev/stdin,g,0.01,0.1,2\n/dev/stdin,g,0.01,0.12,2\n' >pipe.csv
cat records/sine1.txt | "$rocking" batch pipe.csv --output pipe_r.csv --quiet
check  "a piped record runs"        "# end: 2 jobs, 0 failed" tail -1 pipe_r.csv
check  "a piped record's digest"    "# record sha256: unverifiable /dev/stdin" sed -n 2p pipe_r.csv
check  "a piped record not resumed" "/dev/stdin, a record the manifest names, is not a regular file when resumed" \
       sh -c "cat records/sine1.txt | '$rocking' batch pipe.csv --output pipe_r.csv --resume"
check  "a piped record, then a file" "/dev/stdin, a record the manifest names, was not a regular file when pipe_r.csv was written" \
       sh -c "'$rocking' batch pipe.csv --output pipe_r.csv --resume <records/sine1.txt"
status "a piped record not resumed" 1 sh -c "'$rocking' batch pipe.csv --output pipe_r.csv --resume <records/sine1.txt"

# ---- Item 8: RFC 4180.  A quoted line break, "" and commas in record paths;
# the results read back by Python's csv module; a quote never closed refused.
cp records/sine1.txt 'records/a, "b".txt'
cp records/sine1.txt "$(printf 'records/two\nlines.txt')"
cat >rfc.csv <<'EOF'
id,record,unit,record_dt,alpha,p
"first
of two lines","records/a, ""b"".txt",g,0.01,0.1,2
second,"records/two
lines.txt",g,0.01,0.1,2
third,records/missing.txt,g,0.01,0.1,2
EOF
"$rocking" batch rfc.csv --output rfc_r.csv --quiet
status=$?
if [[ $status == 3 ]]; then echo "ok: three rows, one failed (exit 3)"; else echo "FAIL: rfc.csv exit $status, wanted 3"; fail=1; fi
if $py - rfc_r.csv <<'PY'
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1], newline="") if not l.startswith("#")))
assert [r["line"] for r in rows] == ["2", "4", "6"], [r["line"] for r in rows]   # the line each row starts on
assert rows[0]["id"] == "first\nof two lines" and rows[0]["record"] == 'records/a, "b".txt', rows[0]
assert rows[1]["id"] == "second" and rows[1]["record"] == "records/two\nlines.txt", rows[1]
assert rows[0]["status"] == rows[1]["status"] == "ok" and rows[0]["max_theta"] == rows[1]["max_theta"] != "", rows
assert rows[2]["error"].startswith("manifest line 6: records/missing.txt"), rows[2]["error"]
assert open(sys.argv[1]).read().endswith("# end: 3 jobs, 1 failed\n")
PY
then echo "ok: quoted line breaks, \"\" and commas read, the results read back by csv"
else echo "FAIL: RFC 4180 rows"; fail=1; fi
printf 'id,record,unit,record_dt,alpha,p\nok,records/sine1.txt,g,0.01,0.1,2\n"open,records/sine1.txt,g,0.01,0.1,2\nphantom,records/sine1.txt,g,0.01,0.1,2\n' >open.csv
check  "a quote never closed"       "open.csv:3: the row has an unterminated quote: the quoted cell opened on line 3 is never closed" \
       "$rocking" batch open.csv --output open_r.csv
status "a quote never closed"       1   "$rocking" batch open.csv --output open_r.csv
absent "no row of it runs"          open_r.csv open_r.csv.partial
# CRLF and a byte-order mark: the same rows as the plain file.
printf 'id,record,unit,record_dt,alpha,p\nx,records/sine1.txt,g,0.01,0.1,2\ny,"records/sine1.5.txt",g,0.01,0.12,3\n' >plain.csv
$py -c "import sys; t = open('plain.csv').read(); open('crlf.csv', 'w', newline='').write('\ufeff' + t.replace('\n', '\r\n'))"
"$rocking" batch plain.csv --output plain_r.csv --quiet
"$rocking" batch crlf.csv --output crlf_r.csv --quiet
if [[ $(grep -v '^#' plain_r.csv) == "$(grep -v '^#' crlf_r.csv)" ]]; then echo "ok: CRLF and a byte-order mark read as the plain file"
else echo "FAIL: CRLF/BOM rows differ: $(grep -v '^#' crlf_r.csv | head -3)"; fail=1; fi

# ---- Item 7: threads within the jobs, and threads that cannot start.
grep -v -e '^#' -e '^$' m.csv | head -6 >five.csv
$py -c "
rows = ['record,unit,record_dt,alpha,p'] + ['records/sine1.txt,g,0.01,0.2,%d' % (1 + k % 5) for k in range(2000)]
open('many.csv', 'w').write('\n'.join(rows) + '\n')"
limit=1048576   # KiB, 1 GiB: room for rocking and a few threads, not for 1500 stacks of 8 MiB
check  "--jobs 1500 for 5 jobs under a memory limit" "rocking batch: 5 jobs, 0 failed" \
       bash -c "ulimit -v $limit; '$rocking' batch five.csv --jobs 1500 --output five_r.csv"
check  "threads that cannot start name --jobs" "--jobs: 1500 threads were needed and the system refused one" \
       bash -c "ulimit -v $limit; '$rocking' batch many.csv --jobs 1500 --output many_r.csv"
status "threads that cannot start: exit 2" 2 \
       bash -c "ulimit -v $limit; '$rocking' batch many.csv --jobs 1500 --output many_r.csv"
absent "no resume state behind them" many_r.csv.partial many_r.csv.partial.state many_r.csv
status "the next plain run"          0   "$rocking" batch many.csv --jobs 2 --output many_r.csv

# ---- Items 6 and 9: an output that is an input, refused before any job (exit 2), the input untouched.
ln -s m.csv m_link.csv; ln m.csv m_hard.csv
for out in m.csv ./m.csv m_link.csv m_hard.csv "$tmp/m.csv" records/sine1.txt; do
    check  "--output $out (an input) refused" "is the input" "$rocking" batch m.csv --output "$out"
    status "--output $out (an input) refused" 2              "$rocking" batch m.csv --output "$out"
done
same   "the manifest untouched" m.csv m.orig
# Every file the engine writes for --output X (X, X.partial, X.partial.state, its .tmp):
# none may be the manifest or a record, with or without --resume.
for suffix in .partial .partial.state .partial.state.tmp; do
    case $suffix in
        .partial) what="partial file" ;;
        .partial.state) what="state file" ;;
        *) what="state file's temporary" ;;
    esac
    for resume in "" --resume; do
        cp m.csv "x.csv$suffix"
        check  "the manifest as x.csv$suffix $resume" "--output's $what 'x.csv$suffix' is the input the manifest" \
               "$rocking" batch "x.csv$suffix" --output x.csv $resume
        status "the manifest as x.csv$suffix $resume" 2 "$rocking" batch "x.csv$suffix" --output x.csv $resume
        same   "the manifest as x.csv$suffix $resume: untouched" "x.csv$suffix" m.csv
        rm -f x.csv x.csv.partial*
    done
    cp records/sine1.txt "y.csv$suffix"
    printf 'record,unit,record_dt,alpha,p\ny.csv%s,g,0.01,0.1,2\n' "$suffix" >y.csv.in
    check  "a record as y.csv$suffix" "--output's $what 'y.csv$suffix' is the input the record of manifest line 2" \
           "$rocking" batch y.csv.in --output y.csv
    same   "a record as y.csv$suffix: untouched" "y.csv$suffix" records/sine1.txt
    rm -f y.csv y.csv.partial*
done
check  "an output folder that does not exist" "--output: $tmp/no/r.csv: cannot create a file in $tmp/no" \
       "$rocking" batch m.csv --output "$tmp/no/r.csv"
status "an output folder that does not exist" 1 "$rocking" batch m.csv --output "$tmp/no/r.csv"

# ---- Issue 38 (hostile probe of the merged build): rows whose run the solvers
# cannot follow (p t beyond 1e9) are refused in their error cell by the column at
# fault, not by the solver's "no progress ... max_step_p".
cat >huge.csv <<'EOF'
id,kind,record,unit,record_dt,alpha,p,half_height,p_max
p,simulate,records/sine1.txt,g,0.01,0.1,1e300,,
dt,simulate,records/sine1.txt,g,1e300,0.1,2,,
hh,simulate,records/sine1.txt,g,0.01,0.1,,1e-300,
ida,ida,records/sine1.txt,g,1e300,0.1,2,,
collapse,collapse,records/sine1.txt,g,1e300,0.1,,,
spectrum,spectrum,records/sine1.txt,g,1e300,0.1,,,
fine,simulate,records/sine1.txt,g,0.01,0.1,2,,
EOF
"$rocking" batch huge.csv --output huge_r.csv --quiet
if $py - huge_r.csv <<'PY'
import csv, sys
rows = {r["id"]: r for r in csv.DictReader(l for l in open(sys.argv[1], newline="") if not l.startswith("#"))}
want = {"p": "p", "dt": "record_dt", "hh": "half_height", "ida": "record_dt", "collapse": "record_dt",
        "spectrum": "record_dt"}
for id, column in want.items():
    e = rows[id]["error"]
    assert rows[id]["status"] == "error", (id, rows[id]["status"])
    assert e.startswith("manifest line %d: %s: p t = " % (list(rows).index(id) + 2, column)), (id, e)
    assert "exceeds 1e+09" in e and "no progress" not in e, (id, e)
assert rows["fine"]["status"] == "ok" and rows["fine"]["error"] == "", rows["fine"]
PY
then echo "ok: unresolvable rows refused by their column (p, record_dt, half_height), the others run"
else echo "FAIL: unresolvable rows: $(grep -v '^#' huge_r.csv | cut -c1-400)"; fail=1; fi

# ---- CR-only line ends (classic Mac OS): refused naming the line, never read
# as one header row ("the header names column 'r.AT2' twice"); a CR inside
# quotes is the cell's.
printf 'id,record,unit,record_dt,alpha,p\rx,records/sine1.txt,g,0.01,0.1,2\ry,records/sine1.txt,g,0.01,0.1,3\r' >cr.csv
check  "CR-only line ends refused"  "cr.csv:1: a carriage return (CR) with no line feed after it, outside quotes" \
       "$rocking" batch cr.csv --output cr_r.csv
check_not "CR-only: not a header error" "twice" "$rocking" batch cr.csv --output cr_r.csv
status "CR-only line ends: exit 1"  1   "$rocking" batch cr.csv --output cr_r.csv
absent "CR-only: no row runs"       cr_r.csv cr_r.csv.partial
printf 'id,record,unit,record_dt,alpha,p\nx,records/sine1.txt,g,0.01,0.1,2\ry,records/sine1.txt,g,0.01,0.1,3\n' >cr2.csv
check  "a CR-only line end among LF ones: its line" "cr2.csv:2: a carriage return (CR)" "$rocking" batch cr2.csv
printf 'id,record,unit,record_dt,alpha,p\r\n"a\rb",records/sine1.txt,g,0.01,0.1,2\r\n' >cr3.csv
"$rocking" batch cr3.csv --output cr3_r.csv --quiet
if $py -c "
import csv
rows = list(csv.DictReader(l for l in open('cr3_r.csv', newline='') if not l.startswith('#')))
assert len(rows) == 1 and rows[0]['id'] == 'a\rb' and rows[0]['status'] == 'ok', rows"
then echo "ok: a CR inside quotes is the cell's, CRLF still ends rows"; else echo "FAIL: a quoted CR"; fail=1; fi

# ---- Results on a disk that fills (ulimit -f, SIGXFSZ ignored: a write past the
# limit fails with EFBIG): a run that kept no row leaves nothing, so the next plain
# run is not asked for a --resume; one that kept rows leaves them resumable, with no
# temporary state beside them, and a --resume completes the clean bytes.
full() {  # KiB, output, arguments...; its messages through a pipe, which the limit does not cut
    local kib=$1 out=$2; shift 2
    rm -f "$out" "$out".partial*
    ROCKING_BATCH_FLUSH_SECONDS=0 sh -c 'trap "" XFSZ; ulimit -f "$0"; exec "$@"' "$kib" "$rocking" batch "$@" \
        --output "$out" --jobs 1 --quiet 2>&1 >/dev/null | cat >full.err
    return "${PIPESTATUS[0]}"
}
for kib in 0 1; do   # no room for the header (about 700 bytes), then none for a row
    full $kib full_r.csv m.csv
    code=$?
    if [[ $code == 1 && $(cat full.err) == *"File too large"* ]]; then echo "ok: $kib KiB: exit 1, said"
    else echo "FAIL: $kib KiB: exit $code: $(cat full.err)"; fail=1; fi
    absent "$kib KiB: nothing left" full_r.csv full_r.csv.partial full_r.csv.partial.state full_r.csv.partial.state.tmp
done
status "after it, the next plain run" 0 "$rocking" batch m.csv --output full_r.csv --quiet
full 4 full_r.csv m.csv   # some rows
kept=$(awk '{print $5}' full_r.csv.partial.state 2>/dev/null)
if [[ -n $kept ]] && (( kept > 0 )); then echo "ok: a full disk after $kept rows: they are kept"
else echo "FAIL: a full disk after some rows: state '$kept', $(cat full.err)"; fail=1; fi
absent "a full disk after some rows: no temporary state" full_r.csv.partial.state.tmp
"$rocking" batch m.csv --output full_r.csv --resume --quiet
same   "a full disk after some rows, resumed: the clean file" full_r.csv clean.csv
# A partial file without its state (a run killed before its first state): the
# message names only the file there is.
rm -f full_r.csv*; touch full_r.csv.partial
check     "a partial file without state: said" "full_r.csv.partial exists, with no state file" \
          "$rocking" batch m.csv --output full_r.csv
check_not "a partial file without state: its state not named" "full_r.csv.partial.state" \
          "$rocking" batch m.csv --output full_r.csv

# ---- The folder relative records resolve from: a manifest read from
# /dev/stdin resolves them from the current folder, and a missing one says where.
"$rocking" batch /dev/stdin --output stdin_r.csv --quiet <plain.csv
check  "/dev/stdin: records from the current folder" "# end: 2 jobs, 0 failed" tail -1 stdin_r.csv
printf 'record,unit,record_dt,alpha,p\nrecords/none.txt,g,0.01,0.1,2\n' >none.csv
check  "/dev/stdin: the folder said" "records/none.txt is resolved from $tmp, the current folder, as the manifest is read from /dev/stdin" \
       sh -c "'$rocking' batch /dev/stdin <none.csv"
mkdir -p elsewhere && ln -s "$tmp/none.csv" elsewhere/link.csv
check  "a link: the folder said" "records/none.txt is resolved from $tmp/elsewhere, the folder of the link elsewhere/link.csv" \
       "$rocking" batch elsewhere/link.csv
check  "a manifest's own folder said" "records/none.txt is resolved from $tmp, the manifest's folder" \
       "$rocking" batch none.csv

# ---- A batch still running: say that another run holds it, not "add --resume".
rm -f held.csv*
ROCKING_BATCH_FLUSH_SECONDS=0 "$rocking" batch many.csv --jobs 1 --output held.csv --quiet &
pid=$!
for _ in $(seq 500); do [[ -f held.csv.partial.state ]] && break; sleep 0.01; done
check     "a running batch: said"           "held.csv.partial is being written by another run, which holds its lock" \
          "$rocking" batch many.csv --output held.csv
check_not "a running batch: no --resume advice" "Add --resume" "$rocking" batch many.csv --output held.csv
check     "a running batch, --resume: said" "is being written by another run" "$rocking" batch many.csv --output held.csv --resume
kill -KILL $pid 2>/dev/null; wait $pid 2>/dev/null
check     "once it is gone: add --resume"   "Add --resume to complete it" "$rocking" batch many.csv --output held.csv
exit $fail
