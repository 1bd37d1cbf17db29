#!/usr/bin/env bash
# rocking record synth: the synthetic records on the command line, their files
# read back by record info, their seeds, and errors that name the option.
set -u
rocking="$1"
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
json_field() {  # field, command...: the field's value as printed in the command's --json
    local field="$1"; shift
    "$@" 2>/dev/null | /usr/bin/python3 -c "import json, sys; print(repr(json.load(sys.stdin)$field))" 2>/dev/null
}
same() {  # description, value, value
    if [[ -n "$2" && "$2" == "$3" ]]; then echo "ok: $1 ($2)"; else echo "FAIL: $1: '$2' against '$3'"; fail=1; fi
}

# The pulse: t0 defaults to gamma/(2 fp) = 1 s, on the grid, where v = A at nu = 0;
# the trapezoid at dt = 0.001 misses A by about dt^2/12 |a'| ~ 2e-6 m/s.
check "pulse states its generator" "generator: Mavroeidis & Papageorgiou (2003)" \
    "$rocking" record synth --pulse 0.5,1,0,2 --dt 0.001 --duration 3
check "pulse states its parameters" $'gamma = 2\n  nu_rad = 0\n  t0_s = 1' \
    "$rocking" record synth --pulse 0.5,1,0,2 --dt 0.001 --duration 3
check "pulse PGV is A" "PGV = 0.5000 m/s" "$rocking" record synth --pulse 0.5,1,0,2 --dt 0.001 --duration 3

# --output: '#' lines with the generator and parameters, then t,a that record info reads back.
"$rocking" record synth --pulse 0.5,1,0.3,2.5,2 --dt 0.005 --duration 5 --output "$tmp/pulse.txt" >/dev/null
check "file states the generator" "# generator: Mavroeidis & Papageorgiou (2003)" cat "$tmp/pulse.txt"
check "file states gamma" "# gamma: 2.5" cat "$tmp/pulse.txt"
for field in '["samples"]' '["pga_ms2"]' '["pgv_ms"]'; do
    same "record info reads the pulse's $field back" \
        "$(json_field "$field" "$rocking" record synth --pulse 0.5,1,0.3,2.5,2 --dt 0.005 --duration 5 --json)" \
        "$(json_field "$field" "$rocking" record info "$tmp/pulse.txt" --unit m/s2 --json)"
done
same "record info reads the pulse's to_5 back" \
    "$(json_field '["to5_s"]' "$rocking" record synth --pulse 0.5,1,0.3,2.5,2 --dt 0.005 --duration 5 --json)" \
    "$(json_field '["to"][4]' "$rocking" record info "$tmp/pulse.txt" --unit m/s2 --json)"

# The stochastic record: a seed gives the same file twice, another seed another file.
"$rocking" record synth --stochastic 11 --dt 0.01 --duration 40 --output "$tmp/a.txt" >/dev/null
"$rocking" record synth --stochastic 11 --dt 0.01 --duration 40 --output "$tmp/b.txt" >/dev/null
"$rocking" record synth --stochastic 12 --dt 0.01 --duration 40 --output "$tmp/c.txt" >/dev/null
if cmp -s "$tmp/a.txt" "$tmp/b.txt"; then echo "ok: seed 11 twice, the same file"; else echo "FAIL: seed 11 twice differs"; fail=1; fi
if cmp -s "$tmp/a.txt" "$tmp/c.txt"; then echo "FAIL: seeds 11 and 12 give the same file"; fail=1; else echo "ok: seeds 11 and 12 differ"; fi
check "file states the seed and generator" $'# rng: gsl_rng_mt19937, gsl_ran_gaussian_ziggurat\n# seed: 11' cat "$tmp/a.txt"
same "record info reads the stochastic PGA back" \
    "$(json_field '["pga_ms2"]' "$rocking" record synth --stochastic 11 --dt 0.01 --duration 40 --json)" \
    "$(json_field '["pga_ms2"]' "$rocking" record info "$tmp/a.txt" --unit m/s2 --json)"
ia=$(json_field '["parameters"]["expected_Ia_m_s"]' "$rocking" record synth --stochastic 1 --dt 0.01 --duration 40 --params Ia=1,fc=0.1 --json)
if /usr/bin/python3 -c "import sys; sys.exit(abs(float('$ia') - 1) > 1e-12)" 2>/dev/null; then echo "ok: params: Ia = 1 gives the expected Arias intensity ($ia m/s)"
else echo "FAIL: params: Ia = 1 gave an expected Arias intensity of '$ia' m/s"; fail=1; fi
check "params: fc sets the corner" '"omega_c_rad_s": 0.6283185307179586' \
    "$rocking" record synth --stochastic 1 --dt 0.01 --duration 40 --params Ia=1,fc=0.1 --json
check "params: alphas as given" '"alpha2": 3,' \
    "$rocking" record synth --stochastic 1 --dt 0.01 --duration 40 --params alpha1=0.01,alpha2=3,alpha3=0.3 --json

# Errors name the option and exit 2.
check  "gamma 1 is named"          "--pulse: gamma must be > 1"  "$rocking" record synth --pulse 0.5,1,0,1 --dt 0.01 --duration 5
status "gamma 1 exits 2"           2 "$rocking" record synth --pulse 0.5,1,0,1 --dt 0.01 --duration 5
check  "a pulse cut short is named" "lengthen the duration" "$rocking" record synth --pulse 0.5,1,0,2 --dt 0.01 --duration 1
check  "seed 0 is named"           "--stochastic: the seed must be a whole number from 1 to 4294967295" \
    "$rocking" record synth --stochastic 0 --dt 0.01 --duration 5
status "seed 0 exits 2"            2 "$rocking" record synth --stochastic 0 --dt 0.01 --duration 5
check  "a step above Nyquist is named" "--dt: the filter's frequency reaches" \
    "$rocking" record synth --stochastic 1 --dt 0.1 --duration 30
# An alpha2 whose gamma inverse GSL cannot find aborted the process (GSL's default handler).
check  "a huge alpha2 is named"    "--params: alpha2 must be in (1, 100000] (got 1e+300)" \
    "$rocking" record synth --stochastic 1 --dt 0.01 --duration 20 --params alpha1=1,alpha2=1e300,alpha3=1
status "a huge alpha2 exits 2"     2 "$rocking" record synth --stochastic 1 --dt 0.01 --duration 20 --params alpha1=1,alpha2=1e300,alpha3=1
# A sum of 1e13 terms (5e6 samples, each within the filter's ~9 s memory) ran for hours.
check  "a sum too long is named"   "--duration: duration/dt gives 5000001 samples, and the filter's memory spans up to" \
    timeout 20 "$rocking" record synth --stochastic 3 --dt 1e-6 --duration 5
status "a sum too long exits 2"    2 timeout 20 "$rocking" record synth --stochastic 3 --dt 1e-6 --duration 5
check  "an unknown key is named"   "--params: unknown key 'foo'" \
    "$rocking" record synth --stochastic 1 --dt 0.01 --duration 10 --params foo=1
status "an unknown key exits 2"    2 "$rocking" record synth --stochastic 1 --dt 0.01 --duration 10 --params foo=1
check  "--dt is required"          "--dt is required" "$rocking" record synth --pulse 0.5,1,0,2 --duration 5
status "both generators exit 2"    2 "$rocking" record synth --pulse 0.5,1,0,2 --stochastic 1 --dt 0.01 --duration 5
# An --output that cannot be written is an input error (exit 1) naming the file; nothing lands.
status "an unwritable output exits 1" 1 "$rocking" record synth --pulse 0.5,1,0,2 --dt 0.01 --duration 5 --output "$tmp/no/x.txt"
check  "the usage lists record synth" "rocking record synth (--pulse" "$rocking" --help
exit $fail
