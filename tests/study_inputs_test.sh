#!/usr/bin/env bash
# Issue 38: what the studies refuse or read before their first simulation.
# --bootstrap 1 is refused at the start, with one message and exit 2, by
# fragility and eq27 alike (fragility used to run every IDA, then exit 1);
# --unit and --dt apply to plain-text records only, so that one study mixes
# ESM, AT2 and text records of the same motion and finds the same q for each.
#
#   tests/study_inputs_test.sh ROCKING
set -u
rocking="$1"
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# A missing record beside the bad option: the option's error comes first,
# so nothing was read, let alone run.
for study in fragility eq27; do
    case $study in
        fragility) more=(--alpha 0.1 --p 2) ;;
        eq27) more=() ;;
    esac
    for k in 1 -1 100001; do
        check "$study --bootstrap $k: refused first" "--bootstrap: must be 0 (none) or from 2 to 100000 resamples (got $k)" \
            "$rocking" $study "$tmp/no-such-record.txt" "${more[@]}" --bootstrap $k --seed 1
        status "$study --bootstrap $k: exit 2" 2 "$rocking" $study "$tmp/no-such-record.txt" "${more[@]}" --bootstrap $k --seed 1
    done
done

# Three motions (near-fault pulses of 1, 1.3 and 0.8 Hz), each as plain text
# in m/s^2; then the second as PEER AT2 (g = 9.81 m/s^2, as the reader takes
# it) and the third as ESM ASCII (cm/s^2).  Under --unit the mixed study reads
# each in its own format and finds the q the all-text study finds.
for f in 1 1.3 0.8; do
    "$rocking" record synth --pulse 1,$f,0,2 --dt 0.005 --duration 6 --output "$tmp/pulse$f.txt" >/dev/null ||
        { echo "FAIL: record synth"; exit 1; }
done
cp "$tmp/pulse1.txt" "$tmp/plain.txt"
cp "$tmp/pulse1.3.txt" "$tmp/other.txt"
/usr/bin/python3 - "$tmp" <<'PY' || { echo "FAIL: writing the AT2 and ESM copies"; exit 1; }
import sys
d = sys.argv[1]
def motion(name):
    rows = [l.split(",") for l in open(d + "/" + name) if not l.startswith("#")]
    return [float(r[1]) for r in rows], float(rows[1][0]) - float(rows[0][0])
a, dt = motion("pulse1.3.txt")
with open(d + "/motion.AT2", "w") as f:
    f.write("PEER NGA STRONG MOTION DATABASE RECORD\nsynthetic pulse\nACCELERATION TIME SERIES IN UNITS OF G\n")
    f.write("NPTS= %d, DT= %.4f SEC\n" % (len(a), dt))
    for k in range(0, len(a), 5):
        f.write("".join(" %.17e" % (v / 9.81) for v in a[k:k + 5]) + "\n")
a, dt = motion("pulse0.8.txt")
with open(d + "/motion.ASC", "w") as f:
    f.write("EVENT_NAME: synthetic\nSTATION_CODE: SYN\nSTREAM: HNE\nUNITS: cm/s^2\nSAMPLING_INTERVAL_S: %.6f\n" % dt)
    f.write("NDATA: %d\nPGA_CM/S^2: %.6f\nDATA_TYPE: ACCELERATION\n" % (len(a), max(abs(v) for v in a) * 100))
    f.write("".join("%.17e\n" % (v * 100) for v in a))
PY
q_of() {  # the first collapse q of each record, as fragility --json gives them
    "$rocking" fragility "$@" --alpha 0.2 --p 3 --points 20 --quiet --json |
        /usr/bin/python3 -c 'import json,sys; print(" ".join("%.6g" % r["q"] for r in json.load(sys.stdin)["blocks"][0]["records"]))'
}
text=$(q_of "$tmp/pulse1.txt" "$tmp/pulse1.3.txt" "$tmp/pulse0.8.txt" --unit m/s2)
mixed=$(q_of "$tmp/pulse1.txt" "$tmp/motion.AT2" "$tmp/motion.ASC" --unit m/s2)
if [[ $(wc -w <<<"$text") == 3 && "$mixed" == "$text" ]]; then echo "ok: fragility mixes text, AT2 and ESM under --unit: q = $mixed"
else echo "FAIL: fragility with text, AT2 and ESM under --unit: q = '$mixed', all as text: '$text'"; fail=1; fi
check "eq27 mixes them too" "3 record(s)" "$rocking" eq27 "$tmp/plain.txt" "$tmp/motion.AT2" "$tmp/motion.ASC" --unit m/s2 \
    --alpha 0.2 --p-min 3 --p-max 3 --p-points 1
check "a plain-text record still needs --unit" "is read with its unit (rocking: --unit)" "$rocking" fragility "$tmp/plain.txt" "$tmp/motion.AT2" \
    --alpha 0.2 --p 3
# Every command that reads a record takes --unit and --dt for plain-text files only: an AT2
# or ESM file given --dt alone reads as it states (the same output as without it), where
# `record info r.AT2 --dt 0.01` said "--unit is required for a plain-text record"; a
# plain-text file given --dt alone still needs --unit (exit 2, naming the file).
for format in AT2 ASC; do
    for cmd in "record info" "collapse --alpha 0.2" "assess --alpha 0.2 --height 2" "spectrum --alpha 0.2 --points 3 --quiet" \
               "simulate --alpha 0.2 --p 3 --record"; do
        read -r -a words <<<"$cmd"
        dt_flag=--dt; [[ ${words[0]} == simulate ]] && dt_flag=--record-dt
        case ${words[0]} in
            record) run=(record info "$tmp/motion.$format") ;;
            simulate) run=("${words[@]}" "$tmp/motion.$format") ;;
            *) run=("${words[0]}" "$tmp/motion.$format" "${words[@]:1}") ;;
        esac
        plain=$("$rocking" "${run[@]}" 2>&1); plain_status=$?
        given=$("$rocking" "${run[@]}" $dt_flag 0.01 2>&1); given_status=$?
        if [[ $plain_status == 0 && $given_status == 0 && "$given" == "$plain" ]]; then echo "ok: ${words[0]} $format $dt_flag 0.01: read as the file states"
        else echo "FAIL: ${words[0]} $format $dt_flag 0.01: exit $given_status (${given:0:200}) against $plain_status"; fail=1; fi
    done
done
for study in "fragility --alpha 0.2 --p 3 --quiet" "eq27 --alpha 0.2 --p-min 3 --p-max 3 --p-points 1"; do
    read -r -a words <<<"$study"
    run=("${words[0]}" "$tmp/motion.AT2" "$tmp/motion.ASC" "${words[@]:1}")
    plain=$("$rocking" "${run[@]}" 2>&1); plain_status=$?
    given=$("$rocking" "${run[@]}" --dt 0.01 2>&1); given_status=$?
    if [[ $plain_status == 0 && $given_status == 0 && "$given" == "$plain" ]]; then echo "ok: ${words[0]} AT2 and ESM --dt 0.01: read as the files state"
    else echo "FAIL: ${words[0]} AT2 and ESM --dt 0.01: exit $given_status (${given:0:200}) against $plain_status"; fail=1; fi
done
grep -v '^#' "$tmp/plain.txt" | cut -d, -f2 >"$tmp/one-column-dt.txt"
check  "record info of plain text with --dt alone" "--unit is required for a plain-text record (g, m/s2, cm/s2), as $tmp/one-column-dt.txt is" \
    "$rocking" record info "$tmp/one-column-dt.txt" --dt 0.01
status "and exits 2" 2 "$rocking" record info "$tmp/one-column-dt.txt" --dt 0.01
check  "fragility: a plain-text file among AT2s with --dt alone" "--unit is required for a plain-text record (g, m/s2, cm/s2), as $tmp/one-column-dt.txt is" \
    "$rocking" fragility "$tmp/motion.AT2" "$tmp/one-column-dt.txt" --dt 0.005 --alpha 0.2 --p 3

# A run the solvers cannot follow (p t above 1e9, at 4.5e15 not a step moves
# t) is refused by the option that made it, not by the solver's "no progress".
grep -v '^#' "$tmp/plain.txt" | cut -d, -f2 >"$tmp/one-column.txt"
long="p t = "
check "simulate --record --p 1e300" "--p 1e300: $long" "$rocking" simulate --record "$tmp/plain.txt" --unit m/s2 --alpha 0.15 --p 1e300
check "simulate --to 1e300" "--to 1e300, --p 2: $long" "$rocking" simulate --case 2 --to 1e300 --alpha 0.15 --p 2 --pga 1
for study in spectrum fragility eq27 collapse; do
    case $study in
        spectrum) more=(--alpha 0.1) ;; fragility) more=(--alpha 0.1 --p 2) ;; eq27) more=() ;; collapse) more=(--alpha 0.1) ;;
    esac
    for dt in 1e300 1e8; do
        check "$study --dt $dt" "--dt $dt" "$rocking" $study "$tmp/one-column.txt" --unit m/s2 --dt $dt "${more[@]}"
        check "$study --dt $dt: p t" "$long" "$rocking" $study "$tmp/one-column.txt" --unit m/s2 --dt $dt "${more[@]}"
        status "$study --dt $dt: exit 2" 2 "$rocking" $study "$tmp/one-column.txt" --unit m/s2 --dt $dt "${more[@]}"
    done
done
# A value or a record given twice counts its cases twice (issue 38 item 4, as
# eq27 refuses it): fragility and spectrum refuse it too, exit 2, before any run.
cp "$tmp/plain.txt" "$tmp/copy.txt"
check "fragility: a record given twice by a copy" "the same record as $tmp/plain.txt" \
    "$rocking" fragility "$tmp/plain.txt" "$tmp/copy.txt" --unit m/s2 --alpha 0.2 --p 3
status "fragility: a record given twice, exit 2" 2 "$rocking" fragility "$tmp/plain.txt" "$tmp/copy.txt" --unit m/s2 --alpha 0.2 --p 3
check "fragility: an alpha given twice" "--alpha: 0.2 is given twice" \
    "$rocking" fragility "$tmp/plain.txt" "$tmp/other.txt" --unit m/s2 --alpha 0.2,0.20 --p 3
check "fragility: a p given twice" "--p: 3 is given twice" \
    "$rocking" fragility "$tmp/plain.txt" "$tmp/other.txt" --unit m/s2 --alpha 0.2 --p 3,2,3.0
# A copy scaled, or with its sign flipped, is the same case to a study that
# scales each record to every q on a symmetric block.
awk -F, '!/^#/ { printf "%s,%.17g\n", $1, -1.5 * $2 }' "$tmp/plain.txt" >"$tmp/scaled.txt"
check "fragility: a record given twice, scaled by -1.5" "the same record as $tmp/plain.txt scaled" \
    "$rocking" fragility "$tmp/plain.txt" "$tmp/other.txt" "$tmp/scaled.txt" --unit m/s2 --alpha 0.2 --p 3
check "eq27: a record given twice, scaled by -1.5" "the same record as $tmp/plain.txt scaled" \
    "$rocking" eq27 "$tmp/plain.txt" "$tmp/scaled.txt" --unit m/s2
check "spectrum: an alpha given twice" "--alpha: 0.1 is given twice" "$rocking" spectrum "$tmp/plain.txt" --unit m/s2 --alpha 0.1,0.1
status "spectrum: an alpha given twice, exit 2" 2 "$rocking" spectrum "$tmp/plain.txt" --unit m/s2 --alpha 0.1,0.1
exit $fail
