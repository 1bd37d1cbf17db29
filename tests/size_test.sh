#!/usr/bin/env bash
# The command line at the extremes of size (issue 31, items 6 and 8): what
# assess computes and prints, simulate's bound on --output's rows, and the CWT
# half-periods clamped at the edge of their band.  Correctness only: the
# timings are the benchmark's (make bench-records).
set -u
rocking="$1"
source "$(dirname "$0")/check_lib.sh"
check_no_long_number() {  # description, command...: no run of more than 17 digits in the output
    local what="$1"; shift
    local out; out=$("$@" 2>&1)
    if [[ "$out" =~ [0-9]{18} ]]; then echo "FAIL: $what: a number of more than 17 digits in: $out"; fail=1; else echo "ok: $what"; fi
}
json_field() {  # field, command...: the field's value as printed in the command's --json
    local field="$1"; shift
    "$@" 2>/dev/null | /usr/bin/python3 -c "import json, sys; print(repr(json.load(sys.stdin)$field))"
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# assess: to_5 alone, the same number as record info's to_5 (one definition).
awk 'BEGIN { for (i = 0; i < 3000; i++) printf "%.9f\n", sin(0.02 * i) * exp(-((i - 1500) / 600.0)^2) + 0.3 * cos(0.37 * i) }' > "$tmp/rec.txt"
info=$(json_field '["to"][4]' "$rocking" record info "$tmp/rec.txt" --unit m/s2 --dt 0.01 --json)
assess=$(json_field '["records"][0]["to5"]' "$rocking" assess "$tmp/rec.txt" --unit m/s2 --dt 0.01 --alpha 0.15 --height 3 --json)
if [[ -n "$info" && "$info" == "$assess" ]]; then echo "ok: assess's to_5 is record info's ($info)"
else echo "FAIL: assess's to_5 ($assess) is not record info's ($info)"; fail=1; fi
records="$(dirname "$0")/../../shared/records"
norcia="$records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC"
if [ -f "$norcia" ]; then
    info=$(json_field '["to"][4]' "$rocking" record info "$norcia" --json)
    assess=$(json_field '["records"][0]["to5"]' "$rocking" assess "$norcia" --alpha 0.15 --height 3 --json)
    if [[ -n "$info" && "$info" == "$assess" ]]; then echo "ok: on Norcia too ($info)"
    else echo "FAIL: on Norcia, assess's to_5 ($assess) is not record info's ($info)"; fail=1; fi
    # A tiny height gives p = 3.8e150 rad/s, which %.4f printed in 150 digits.
    check_no_long_number "assess prints a huge p in exponent form" "$rocking" assess "$norcia" --alpha 0.15 --height 1e-300
    check "and refuses a p no search reads" "--height: the block's p, 3.81442e+150 rad/s, is outside the searches' (0.01, 1000) rad/s" "$rocking" assess "$norcia" --alpha 0.15 --height 1e-300
else
    echo "skipped: Norcia checks (no shared records folder at $records)"
fi
# A sampling step of 3 s leaves the CWT no band (0.1 Hz to 0.25/dt): record info
# refuses the half-periods; assess, which needs none of the CWT, still answers.
awk 'BEGIN { for (i = 0; i < 40; i++) printf "%.6f\n", sin(0.3 * i) }' > "$tmp/coarse.txt"
check "record info: no CWT band at dt = 3 s" "leaves the CWT no band" "$rocking" record info "$tmp/coarse.txt" --unit g --dt 3
status "assess at dt = 3 s" 0 "$rocking" assess "$tmp/coarse.txt" --unit g --dt 3 --alpha 0.15 --height 3

# The CWT scans 0.1 Hz to min(25 Hz, 0.25/dt).  A 0.02 Hz cosine peaks below it:
# its velocity measures are largest on the lowest scale, and to_9 and to_11 were
# printed as if measured there.  A 2 Hz one peaks inside, with no warning.
awk 'BEGIN { for (i = 0; i < 20000; i++) printf "%.9f\n", cos(2 * 3.141592653589793 * 0.02 * i * 0.05) }' > "$tmp/slow.txt"
check "a to at the band's edge is warned of" "warning: to_9 is the edge of the CWT's band (0.0970 to 5.0000 Hz), not a peak" \
    "$rocking" record info "$tmp/slow.txt" --unit m/s2 --dt 0.05
check "on the lowest-frequency side" "largest on the band's lowest-frequency scale" \
    "$rocking" record info "$tmp/slow.txt" --unit m/s2 --dt 0.05
check "its JSON lists the to at the edge" '"to_at_band_edge": [8, 9, 10, 11], "cwt_band_hz": [0.097020141568240931, 5]' \
    "$rocking" record info "$tmp/slow.txt" --unit m/s2 --dt 0.05 --json
awk 'BEGIN { for (i = 0; i < 20001; i++) printf "%.9f\n", cos(2 * 3.141592653589793 * 2 * i * 0.001) }' > "$tmp/mid.txt"
check_not "a peak inside the band: no warning" "warning" "$rocking" record info "$tmp/mid.txt" --unit m/s2 --dt 0.001
check "and an empty list" '"to_at_band_edge": []' "$rocking" record info "$tmp/mid.txt" --unit m/s2 --dt 0.001 --json

# simulate --output holds at most 10^6 rows: counted before the run up to t_fin
# plus the free rocking followed (200/p), here 0.5 + 100 s, so --dt must be at
# least 100.5 / 999999 = 1.005001e-4 s.  --dt 1e-7 had grown to 4.9 GB.
sim=("$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2)
check "a --dt that could write too many rows is refused, named" \
    "--dt: 1e-07 s could write 1.01e+09 rows to --output (t_fin = 0.5 s and up to 100 s of free rocking after it), more than its limit of 1000000 rows; give --dt >= 0.000101 s" \
    "${sim[@]}" --output "$tmp/o.csv" --dt 1e-7
status "and exits 2" 2 "${sim[@]}" --output "$tmp/o.csv" --dt 1e-7
if [ -e "$tmp/o.csv" ]; then echo "FAIL: the refused run wrote $tmp/o.csv"; fail=1; else echo "ok: and writes nothing"; fi
status "just below the bound is refused" 2 "${sim[@]}" --output "$tmp/o.csv" --dt 1.0049e-4
status "just above it runs" 0 "${sim[@]}" --output "$tmp/o.csv" --dt 1.0051e-4
check "the bound is in simulate's help" "most 10^6 rows" "$rocking" simulate --help

exit $fail
