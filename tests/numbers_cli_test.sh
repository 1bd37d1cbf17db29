#!/usr/bin/env bash
# The one number reader (src/numerics/number_text.hpp) on the command line:
# every option, a manifest's cells and a record's samples read a number by the
# same rules and say its problem in the same words; a whole number's message
# states its range; the searches' alpha range is one.  No real records needed.
#
#   tests/numbers_cli_test.sh ROCKING
set -u
rocking="$1"
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# A record that overturns any block at once: 2 g for 2 s.
{ echo "0 0"; for i in $(seq 1 200); do echo "$i 2"; done; } | awk '{ printf "%.2f %s\n", $1 / 100, $2 }' > "$tmp/strong.txt"
r="$tmp/strong.txt"
large="is too large for a double (magnitude beyond 1.7976931348623157e+308)"
small="is below the smallest normal double, 2.2250738585072014e-308"

# ---- Options: subnormal, overflowing, blanks; each command, exit 2.
check  "alpha 1e-320 is below the smallest normal" "--alpha: '1e-320' $small" "$rocking" collapse "$r" --alpha 1e-320 --unit g
status "and exits 2"                     2 "$rocking" collapse "$r" --alpha 1e-320 --unit g
check  "alpha 1e400 is too large"        "--alpha: '1e400' $large" "$rocking" collapse "$r" --alpha 1e400 --unit g
check  "alpha -1e400 is too large"       "--alpha: '-1e400' $large" "$rocking" spectrum "$r" --alpha -1e400 --unit g
check  "a spectrum alpha list item"      "--alpha: '1e400' $large" "$rocking" spectrum "$r" --alpha 0.1,1e400 --unit g
check  "a fragility alpha list item"     "--alpha: '1e-320' $small" "$rocking" fragility "$r" --alpha 1e-320 --p 2 --unit g
check  "an eq27 alpha list item"         "--alpha: '1e400' $large" "$rocking" eq27 "$r" --alpha 1e400 --unit g
check  "simulate --p 1e400"              "--p: '1e400' $large" "$rocking" simulate --case 2 --x 1 --alpha 0.1 --p 1e400
check  "q --x 1e-320"                    "--x: '1e-320' $small" "$rocking" q --case 2 --x 1e-320
check  "a --train duration 1e400"        "--train: train item 2 '1:1e400': duration '1e400' $large" "$rocking" q --train 1:1,1:1e400 --x 1
check  "a synth --params value"          "--params fc: '1e400' $large" "$rocking" record synth --stochastic 1 --dt 0.01 --duration 5 --params fc=1e400
check  "the record's --dt"               "--dt: '1e-320' $small" "$rocking" record info "$r" --unit g --dt 1e-320
check  "nan is not finite"               "--alpha: 'nan' is not a finite number" "$rocking" collapse "$r" --alpha nan --unit g
check  "hexadecimal is not read"         "--alpha: '0x0.1p1' is not a number (hexadecimal is not read)" "$rocking" collapse "$r" --alpha 0x0.1p1 --unit g
check  "a decimal comma is named"        "--x: '0,5' is not a number (decimal commas are not read)" "$rocking" q --case 2 --x 0,5
check  "trailing garbage is not a number" "--x: '0.5x' is not a number" "$rocking" q --case 2 --x 0.5x
# Blanks around a number are read alike at either end ('0.1 ' was refused, ' 0.1' read).
check  "alpha '0.1 ' is 0.1"             '"alpha": 0.10000000000000001' "$rocking" collapse "$r" --alpha '0.1 ' --unit g --json
check  "alpha ' 0.1' is 0.1"             '"alpha": 0.10000000000000001' "$rocking" collapse "$r" --alpha ' 0.1' --unit g --json
check  "a tab after x"                   "q = 4.388218723" "$rocking" q --case 2 --x $'0.5\t'
check  "blanks after a list's commas"    '"alpha": 0.20000000000000001' "$rocking" spectrum "$r" --alpha '0.1, 0.2' --points 2 --unit g --json
check  "a blank inside is not a number"  "--x: '0. 5' is not a number" "$rocking" q --case 2 --x '0. 5'

# ---- Whole numbers: the range, whatever is wrong.
check  "spectrum --points 10000000"      "--points: must be a whole number from 2 to 100000 (got 10000000)" "$rocking" spectrum "$r" --alpha 0.1 --points 10000000 --unit g
status "and exits 2"                     2 "$rocking" spectrum "$r" --alpha 0.1 --points 10000000 --unit g
check  "fragility --points 10000000"     "--points: must be a whole number from 2 to 10000 (got 10000000)" "$rocking" fragility "$r" --alpha 0.1 --p 2 --points 10000000 --unit g
check  "fragility --bootstrap 10000000"  "--bootstrap: must be 0 (none) or from 2 to 100000 resamples (got 10000000)" "$rocking" fragility "$r" --alpha 0.1 --p 2 --bootstrap 10000000 --seed 1 --unit g
check  "eq27 --bootstrap 10000000"       "--bootstrap: must be 0 (none) or from 2 to 100000 resamples (got 10000000)" "$rocking" eq27 "$r" --bootstrap 10000000 --seed 1 --unit g
check  "eq27 --p-points 1e400"           "--p-points: must be a whole number from 1 to 1000 (got '1e400')" "$rocking" eq27 "$r" --p-points 1e400 --unit g
check  "response --steps 2.5"            "--steps: must be a whole number from 1 to 1000000 (got 2.5)" "$rocking" response --case 2 --x 1 --steps 2.5
check  "q --pulses abc"                  "--pulses: must be a whole number from 1 to 1000 (got 'abc')" "$rocking" q --case 2 --x 1 --pulses abc
check  "q --case 7"                      "--case: must be a whole number from 1 to 5 (got 7)" "$rocking" q --case 7 --x 1

# One rule for every whole-number option, seeds and --jobs included (numerics::whole_number):
# "10", "10.0" and "1e1" are the same number, and a refusal states the option's range.
# --seed 1.0, --stochastic 1e0 and --jobs 1e2 were refused ("must be an integer") while
# --points 1e1 was read.
same_run() {  # description, three spellings' commands as one string each (word-split)
    local what="$1" first; shift
    # shellcheck disable=SC2086
    first=$("$rocking" $1 2>&1); local a=$?
    for cmd in "$@"; do
        # shellcheck disable=SC2086
        local got; got=$("$rocking" $cmd 2>&1); local b=$?
        if [[ $a == 0 && $b == 0 && "$got" == "$first" ]]; then echo "ok: $what: '$cmd' as '$1'"
        else echo "FAIL: $what: '$cmd' (exit $b) differs from '$1' (exit $a): ${got:0:200}"; fail=1; fi
    done
}
same_run "--stochastic" "record synth --stochastic 7 --dt 0.01 --duration 5 --json" \
    "record synth --stochastic 7.0 --dt 0.01 --duration 5 --json" "record synth --stochastic 7e0 --dt 0.01 --duration 5 --json"
same_run "--seed and --bootstrap" "eq27 $r --unit g --bootstrap 100 --seed 3 --json" \
    "eq27 $r --unit g --bootstrap 100.0 --seed 3.0 --json" "eq27 $r --unit g --bootstrap 1e2 --seed 0.3e1 --json"
same_run "--jobs" "spectrum $r --unit g --alpha 0.1 --points 10 --jobs 2 --quiet --json" \
    "spectrum $r --unit g --alpha 0.1 --points 10.0 --jobs 2.0 --quiet --json" "spectrum $r --unit g --alpha 0.1 --points 1e1 --jobs 2e0 --quiet --json"
same_run "fragility --points, --seed" "fragility $r --unit g --alpha 0.1 --p 2 --points 10 --bootstrap 100 --seed 5 --jobs 1 --quiet --json" \
    "fragility $r --unit g --alpha 0.1 --p 2 --points 1e1 --bootstrap 1e2 --seed 5e0 --jobs 1e0 --quiet --json"
same_run "--case, --pulses" "q --case 2 --pulses 3 --x 1 --json" "q --case 2.0 --pulses 3e0 --x 1 --json"
same_run "--steps" "response --case 2 --x 1 --steps 10 --json" "response --case 2 --x 1 --steps 1e1 --json"
same_run "--p-points" "eq27 $r --unit g --p-min 1 --p-max 3 --p-points 3 --json" "eq27 $r --unit g --p-min 1 --p-max 3 --p-points 3.0 --json"
check  "--jobs 1e4: the range"           "--jobs: must be a whole number from 1 to 4096 (got 1e4)" "$rocking" spectrum "$r" --alpha 0.1 --jobs 1e4 --unit g
check  "--jobs 2.5: the range"           "--jobs: must be a whole number from 1 to 4096 (got 2.5)" "$rocking" batch "$r" --jobs 2.5
status "and exits 2"                     2 "$rocking" batch "$r" --jobs 2.5
check  "--seed 0: the range"             "--seed: the seed must be a whole number from 1 to 4294967295 (got 0)" "$rocking" eq27 "$r" --bootstrap 100 --seed 0 --unit g
check  "--seed 2^32: the range"          "--seed: the seed must be a whole number from 1 to 4294967295 (got 4294967296)" "$rocking" fragility "$r" --alpha 0.1 --p 2 --bootstrap 100 --seed 4294967296 --unit g
check  "--stochastic 1.5: the range"     "--stochastic: the seed must be a whole number from 1 to 4294967295 (got 1.5)" "$rocking" record synth --stochastic 1.5 --dt 0.01 --duration 5
check  "--stochastic x: the range"       "--stochastic: the seed must be a whole number from 1 to 4294967295 (got 'x')" "$rocking" record synth --stochastic x --dt 0.01 --duration 5
status "and exits 2"                     2 "$rocking" record synth --stochastic 1.5 --dt 0.01 --duration 5

# ---- Samples: a subnormal is itself, an overflowing one too large; file and line, exit 1.
printf '0.1\n1.9e-308\n-0.2\n0.05\n-1e-320\n0.0\n' > "$tmp/tiny.txt"
check  "a sample 1.9e-308 reads"         '"samples": 6' "$rocking" record info "$tmp/tiny.txt" --unit g --dt 0.01 --json
printf '0.1\n1e400\n-0.2\n0.05\n' > "$tmp/big.txt"
check  "a sample 1e400 is too large"     "big.txt:2: '1e400' $large" "$rocking" record info "$tmp/big.txt" --unit g --dt 0.01
status "and exits 1"                     1 "$rocking" record info "$tmp/big.txt" --unit g --dt 0.01
printf 'H1\nH2\nACCELERATION IN UNITS OF G\nNPTS= 4, DT= .01 SEC\n0.1 1.9e-308 -0.2\n0.05\n' > "$tmp/tiny.at2"
check  "a PEER sample 1.9e-308 reads"    '"samples": 4' "$rocking" record info "$tmp/tiny.at2" --json
printf 'H1\nH2\nACCELERATION IN UNITS OF G\nNPTS= 4, DT= .01 SEC\n0.1 0.2 -0.2\n-1e400\n' > "$tmp/big.at2"
check  "a PEER sample -1e400"            "big.at2:6: sample '-1e400' $large" "$rocking" record info "$tmp/big.at2"

# ---- A manifest's cells: the same reader and messages, in the row's error column.
printf '0.1\n0.2\n-0.2\n0.05\n0.3\n-0.1\n0.0\n0.1\n' > "$tmp/rec.txt"
cat > "$tmp/m.csv" <<CSV
kind,record,unit,record_dt,alpha,p,points
simulate,rec.txt,g,0.01,1e400,2,
simulate,rec.txt,g,0.01,0.1,1e-320,
spectrum,rec.txt,g,0.01,0.1,,10000000
spectrum,rec.txt,g,0.01,0.8,,
ida,rec.txt,g,0.01,0.8,2,
simulate,rec.txt,g,0.01,0.1 ,2,
CSV
"$rocking" batch "$tmp/m.csv" --output "$tmp/out.csv" >/dev/null 2>&1
check  "a cell 1e400"                    "manifest line 2: alpha: '1e400' $large" cat "$tmp/out.csv"
check  "a cell 1e-320"                   "manifest line 3: p: '1e-320' $small" cat "$tmp/out.csv"
check  "a points cell 10000000"          "manifest line 4: points: must be a whole number from 2 to 100000 (got 10000000)" cat "$tmp/out.csv"
check  "a spectrum row's alpha 0.8"     "manifest line 5: alpha: must be in (0, pi/4) (got 0.8)" cat "$tmp/out.csv"
check  "an ida row's alpha 0.8"         "manifest line 6: alpha: must be in (0, pi/4) (got 0.8)" cat "$tmp/out.csv"
check  "a cell '0.1 ' runs"              "7,simulate,rec.txt,g,0.01,0.1,2,,ok," cat "$tmp/out.csv"

# ---- The searches' alpha range, one for every command.
for cmd in "collapse $r --alpha 0.8" "spectrum $r --alpha 0.8" "fragility $r --alpha 0.8 --p 2" "eq27 $r --alpha 0.8"; do
    # shellcheck disable=SC2086
    check "${cmd%% *} alpha 0.8"        "must be in (0, pi/4) (got 0.8)" "$rocking" $cmd --unit g
done
exit $fail
