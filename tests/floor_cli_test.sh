#!/usr/bin/env bash
# rocking record floor: a floor's motion from a ground record on the command line; its
# file read back by record info and simulate --record, its samples against the step's
# closed form (Python's math), G = 0 as the ground's own rows, and errors that name the option.
set -u
rocking="$1"
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
json_field() {  # field, command...: the field's value as printed in the command's --json
    local field="$1"; shift
    "$@" 2>/dev/null | /usr/bin/python3 -c "import json, sys; print(repr(json.load(sys.stdin)$field))" 2>/dev/null
}
equal() {  # description, value, value
    if [[ -n "$2" && "$2" == "$3" ]]; then echo "ok: $1 ($2)"; else echo "FAIL: $1: '$2' against '$3'"; fail=1; fi
}

# A ground record (RDK2008, seed 7) and its roof: T1 = 0.5 s, G = 1.5, zeta the default 0.05.
"$rocking" record synth --stochastic 7 --dt 0.01 --duration 30 --output "$tmp/ground.txt" >/dev/null
floor=("$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 0.5 --participation 1.5)
"${floor[@]}" --output "$tmp/roof.txt" >/dev/null
check "states the model" "model: first-mode oscillator T1 = 0.5 s, zeta = 0.05, G = Gamma phi = 1.5" "${floor[@]}"
check "states the method" "solution: Nigam & Jennings (1969), exact for the ground record read linear between samples" "${floor[@]}"
check "states both PGAs and their ratio" "floor/ground = " "${floor[@]}"
check "the file states the model" "# model: first-mode oscillator, floor absolute acceleration a_f = a_g + G D''" cat "$tmp/roof.txt"
check "the file states the method" "# method: Nigam & Jennings (1969)" cat "$tmp/roof.txt"
check "the file states T1" $'# T1_s: 0.5\n' cat "$tmp/roof.txt"
check "the file states zeta" $'# zeta: 0.05\n' cat "$tmp/roof.txt"
check "the file states G" $'# G: 1.5\n' cat "$tmp/roof.txt"
check "the file names its ground record" "# ground_path: $tmp/ground.txt" cat "$tmp/roof.txt"
check "the file says it ends with the ground record" "# samples: as many as the ground record's, at its dt" cat "$tmp/roof.txt"

# Read back: record info finds the samples and PGA the command reported.
equal "record info reads the floor's samples back" \
    "$(json_field '["samples"]' "${floor[@]}" --json)" \
    "$(json_field '["samples"]' "$rocking" record info "$tmp/roof.txt" --unit m/s2 --json)"
equal "record info reads the floor's PGA back" \
    "$(json_field '["floor_pga_ms2"]' "${floor[@]}" --json)" \
    "$(json_field '["pga_ms2"]' "$rocking" record info "$tmp/roof.txt" --unit m/s2 --json)"
equal "the ground's PGA is record info's" \
    "$(json_field '["ground_pga_ms2"]' "${floor[@]}" --json)" \
    "$(json_field '["pga_ms2"]' "$rocking" record info "$tmp/ground.txt" --unit m/s2 --json)"
ratio_ok=$("${floor[@]}" --json | /usr/bin/python3 -c "
import json, sys
d = json.load(sys.stdin)
print(d['pga_ratio'] == d['floor_pga_ms2'] / d['ground_pga_ms2'] and d['samples'] == 3001 and d['dt'] == 0.01
      and d['model'] == {'T1_s': 0.5, 'zeta': 0.05, 'G': 1.5} and d['warnings'] == [] and d['output'] is None)")
equal "JSON: the ratio, samples, dt, model, warnings" "$ratio_ok" "True"

# simulate --record takes the floor file; its input line gives the floor's PGA in g.
pga_g=$(json_field '["floor_pga_ms2"]' "${floor[@]}" --json | /usr/bin/python3 -c "import sys; print('%g' % (float(sys.stdin.read()) / 9.81))")
check "simulate --record reads the floor file" "(3001 samples, dt = 0.01 s, PGA $pga_g g)" \
    "$rocking" simulate --record "$tmp/roof.txt" --unit m/s2 --alpha 0.15 --height 1
status "simulate --record on the floor file exits 0" 0 "$rocking" simulate --record "$tmp/roof.txt" --unit m/s2 --alpha 0.15 --height 1

# G = 0: the floor is the ground, row for row, and simulate answers as on the ground.
"$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 0.5 --participation 0 --output "$tmp/base.txt" >/dev/null
grep -v '^#' "$tmp/ground.txt" > "$tmp/ground.rows"
grep -v '^#' "$tmp/base.txt" > "$tmp/base.rows"
same "G = 0 writes the ground's rows" "$tmp/base.rows" "$tmp/ground.rows"
"$rocking" simulate --record "$tmp/base.txt" --unit m/s2 --alpha 0.1 --p 3 --json | sed 's|"input": "[^"]*"||' > "$tmp/sim_base.json"
"$rocking" simulate --record "$tmp/ground.txt" --unit m/s2 --alpha 0.1 --p 3 --json | sed 's|"input": "[^"]*"||' > "$tmp/sim_ground.json"
same "simulate on the G = 0 floor answers as on the ground" "$tmp/sim_base.json" "$tmp/sim_ground.json"

# The step's closed form, through the command line: a one-column record of a constant A
# from t = 0 (a jump at t = 0, the oscillator at rest), a_f = A - G A e^(-zeta w t)
# (cos w_d t - zeta/sqrt(1 - zeta^2) sin w_d t); rounding only (2000 steps: 2000 eps).
/usr/bin/python3 -c "print('\n'.join(['0.2'] * 2000))" > "$tmp/step.txt"
"$rocking" record floor "$tmp/step.txt" --unit g --dt 0.01 --period 0.7 --damping 0.1 --participation 1.3 \
    --output "$tmp/step_floor.txt" >/dev/null
step_ok=$(/usr/bin/python3 - "$tmp/step_floor.txt" <<'EOF'
import math, sys
A, G, zeta, w = 0.2 * 9.81, 1.3, 0.1, 2 * math.pi / 0.7
wd = w * math.sqrt(1 - zeta * zeta)
worst = 0.0
for line in open(sys.argv[1]):
    if line.startswith('#'):
        continue
    t, a = map(float, line.split(','))
    truth = A - G * A * math.exp(-zeta * w * t) * (math.cos(wd * t) - zeta / math.sqrt(1 - zeta * zeta) * math.sin(wd * t))
    worst = max(worst, abs(a - truth) / A)
print('ok' if worst < 2000 * 2.2e-16 else 'off by %g' % worst)
EOF
)
equal "the floor of a step is the closed form" "$step_ok" "ok"

# A ground at rest: no ratio (null, and said), not a NaN.
/usr/bin/python3 -c "print('\n'.join(['0'] * 100))" > "$tmp/rest.txt"
check "a ground at rest has no ratio" "floor/ground = undefined (the ground is at rest)" \
    "$rocking" record floor "$tmp/rest.txt" --unit g --dt 0.01 --period 0.5 --participation 1.5
equal "a ground at rest: pga_ratio null" \
    "$(json_field '["pga_ratio"]' "$rocking" record floor "$tmp/rest.txt" --unit g --dt 0.01 --period 0.5 --participation 1.5 --json)" "None"

# A record's name with a line break stays on its '#' line: the file reads back.
odd="$tmp/a"$'\n'"b.txt"
cp "$tmp/ground.txt" "$odd"
"$rocking" record floor "$odd" --unit m/s2 --period 0.5 --participation 1.5 --output "$tmp/odd_floor.txt" >/dev/null
status "a floor of a file named across lines reads back" 0 "$rocking" record info "$tmp/odd_floor.txt" --unit m/s2

# Below 10 steps a period: kept, and warned of on standard error and in --json.
check "T1 below 10 dt is warned of" "rocking record: warning: T1 = 0.09 s has 9 samples per period at dt = 0.01 s" \
    "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 0.09 --participation 1.5
equal "and in --json's warnings" \
    "$(json_field '["warnings"][0][:36]' "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 0.09 --participation 1.5 --json)" \
    "'T1 = 0.09 s has 9 samples per period'"

# Errors name the option and exit 2; an unreadable record exits 1.
check  "--period is required"   "--period is required" "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --participation 1
check  "--participation is required" "--participation is required" "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 1
check  "T1 <= 0 names --period" "--period: T1 must be > 0 and finite, in s (got -1)" \
    "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period -1 --participation 1
status "T1 <= 0 exits 2" 2 "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period -1 --participation 1
check  "zeta = 1 names --damping" "--damping: zeta must be in [0, 1)" \
    "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 1 --participation 1 --damping 1
status "zeta = 1 exits 2" 2 "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 1 --participation 1 --damping 1
check  "G not finite names --participation" "--participation: 'inf' is not a finite number" \
    "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 1 --participation inf
check  "T1 at 2 dt names --period and the Nyquist frequency" \
    "--period: T1 = 0.02 s is at most 2 dt = 0.02 s: the building's frequency 1/T1 = 50 Hz lies at or above the record's Nyquist frequency" \
    "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 0.02 --participation 1
status "T1 at 2 dt exits 2" 2 "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 0.02 --participation 1
check  "an output over the input is refused" "writing it would replace the input" \
    "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 1 --participation 1 --output "$tmp/ground.txt"
check  "an unknown option is named" "unknown option '--floor'" \
    "$rocking" record floor "$tmp/ground.txt" --unit m/s2 --period 1 --participation 1 --floor 2
status "an unreadable record exits 1" 1 "$rocking" record floor "$tmp/missing.txt" --unit m/s2 --period 1 --participation 1
# A record the floor's resonance lifts beyond a double: the input's fault, exit 1, the file and sample named.
/usr/bin/python3 -c "
import math
print('\n'.join('%.17g' % (1e306 * math.sin(2 * math.pi * 0.01 * k / 0.5)) for k in range(2000)))" > "$tmp/huge.txt"
check  "a floor beyond a double is named" "huge.txt: the floor's acceleration at sample" \
    "$rocking" record floor "$tmp/huge.txt" --unit g --dt 0.01 --period 0.5 --damping 0.01 --participation 1.5
status "a floor beyond a double exits 1" 1 \
    "$rocking" record floor "$tmp/huge.txt" --unit g --dt 0.01 --period 0.5 --damping 0.01 --participation 1.5

exit $fail
