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
check "a tiny pulse's PGV in four significant digits, not 0.0000" "PGV = 5.0000e-08 m/s" "$rocking" record synth --pulse 5e-8,1,0,2 --dt 0.001 --duration 3

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
# The defaults' filter above 1/(2 dt): only the step is the user's, so --dt is named.
check  "a step above Nyquist is named" "--dt: fmid = 5.87 Hz, the filter's frequency at tmid = 12.4 s, is at or above the Nyquist frequency 1/(2 dt) = 5 Hz of dt = 0.1 s" \
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
# Every frequency of a generator at or above 1/(2 dt) is refused naming the option, the
# parameter and the limit (exit 2); just below it the record is kept and warned of, on
# standard error and in --json's "warnings".  dt = 0.01 s: 1/(2 dt) = 50 Hz.
refused() {  # description, expected message, synth arguments...
    local what="$1" want="$2"; shift 2
    check  "$what is named" "$want" "$rocking" record synth "$@"
    status "$what exits 2" 2 "$rocking" record synth "$@"
}
kept() {  # description, expected warning, synth arguments...
    local what="$1" want="$2"; shift 2
    status "$what is kept" 0 "$rocking" record synth "$@"
    check  "$what is warned of" "rocking record: warning: $want" "$rocking" record synth "$@"
    same   "$what: one warning in --json" "1" "$(json_field '["warnings"].__len__()' "$rocking" record synth "$@" --json)"
}
refused "the issue's pulse, fp = 100 Hz at dt = 0.02 s" \
    "--pulse: fp = 100 Hz, the pulse's carrier frequency, is at or above the Nyquist frequency 1/(2 dt) = 25 Hz of dt = 0.02 s: lower fp, or take dt below 0.003333 s" \
    --pulse 0.5,100,0,2 --dt 0.02 --duration 5
for fp in 50 50.001; do
    refused "the carrier fp = $fp Hz" "--pulse: fp = 50 Hz, the pulse's carrier frequency, is at or above the Nyquist frequency 1/(2 dt) = 50 Hz of dt = 0.01 s" \
        --pulse 0.5,$fp,0,2 --dt 0.01 --duration 2
done
for gamma in 4 3.99; do  # fp + fp/gamma = 50 Hz, then 50.03 Hz: the envelope widens the carrier's band
    refused "the envelope's sideband (gamma = $gamma)" "--pulse: fp + fp/gamma = 50" --pulse 0.5,40,0,$gamma --dt 0.01 --duration 2
done
kept "a sideband just below 1/(2 dt)" "fp + fp/gamma = 49.98 Hz, the pulse's highest frequency" --pulse 0.5,40,0,4.01 --dt 0.01 --duration 2
same "a well-sampled pulse: no warnings" "[]" "$(json_field '["warnings"]' "$rocking" record synth --pulse 0.5,1,0,2 --dt 0.001 --duration 3 --json)"
for fmid in 50 50.001; do
    refused "fmid = $fmid Hz" "--params: fmid = 50 Hz, the filter's frequency at tmid = 12.4 s, is at or above the Nyquist frequency 1/(2 dt) = 50 Hz of dt = 0.01 s" \
        --stochastic 1 --dt 0.01 --duration 20 --params fmid=$fmid,fprime=0,zeta=0.8
done
# fmid + fprime (t - tmid) = 50 Hz at the record's end (fprime = 1.25 Hz/s) or start (-5 Hz/s); tmid = 4 s.
for fprime in 1.2500001 1.3; do
    refused "the filter at the record's end (fprime = $fprime)" "--params: fmid + fprime (t - tmid) = 50" \
        --stochastic 1 --dt 0.01 --duration 20 --params fmid=30,fprime=$fprime,zeta=0.8,tmid=4,D5_95=5
done
kept "the filter just below 1/(2 dt) at the record's end" "the filter's band edge = 50 Hz" \
    --stochastic 1 --dt 0.01 --duration 20 --params fmid=30,fprime=1.2499999,zeta=0.8,tmid=4,D5_95=5
for fprime in -5.000001 -5.1; do
    refused "the filter at the record's start (fprime = $fprime)" "--params: fmid + fprime (t - tmid) = 50" \
        --stochastic 1 --dt 0.01 --duration 5 --params fmid=30,fprime=$fprime,zeta=0.8,tmid=4,D5_95=5
done
kept "the filter just below 1/(2 dt) at the record's start" "the filter's band edge = 50 Hz" \
    --stochastic 1 --dt 0.01 --duration 5 --params fmid=30,fprime=-4.999999,zeta=0.8,tmid=4,D5_95=5
# The band's upper half-power edge, fmid sqrt(1 - 2 zeta^2 + 2 zeta sqrt(1 - zeta^2)): 50 Hz at
# fmid = 42.373 Hz for zeta = 0.3; with zeta = 0.8 the band ends at fmid itself.
band_limit=$(/usr/bin/python3 -c "import math; z = 0.3; print(50 / math.sqrt(1 - 2*z*z + 2*z*math.sqrt(1 - z*z)))")
for factor in 1.000001 1.01; do
    refused "the band's edge (fmid = $factor x $band_limit Hz)" "--params: the filter's band edge = 50" \
        --stochastic 1 --dt 0.01 --duration 20 --params "fmid=$(/usr/bin/python3 -c "print($band_limit * $factor)"),fprime=0,zeta=0.3"
done
kept "the band's edge just below 1/(2 dt)" "the filter's band edge = 50 Hz" \
    --stochastic 1 --dt 0.01 --duration 20 --params "fmid=$(/usr/bin/python3 -c "print($band_limit * 0.999999)"),fprime=0,zeta=0.3"
refused "a band zeta widens past 1/(2 dt)" "--params: the filter's band edge = 51.81 Hz, the upper half-power frequency of its band around 45 Hz, widened by zeta = 0.213" \
    --stochastic 1 --dt 0.01 --duration 20 --params fmid=45,fprime=0
status "the same fmid with zeta = 0.8 is kept" 0 "$rocking" record synth --stochastic 1 --dt 0.01 --duration 20 --params fmid=45,fprime=0,zeta=0.8
refused "the issue's fc = 1000 Hz at dt = 0.02 s" \
    "--params: fc = 1000 Hz, the post-filter's corner, is at or above the Nyquist frequency 1/(2 dt) = 25 Hz of dt = 0.02 s: lower fc, or take dt below 0.0005 s" \
    --stochastic 1 --dt 0.02 --duration 5 --params fc=1000
for fc in 50 50.001; do
    refused "fc = $fc Hz" "--params: fc = 50 Hz, the post-filter's corner, is at or above the Nyquist frequency 1/(2 dt) = 50 Hz" \
        --stochastic 1 --dt 0.01 --duration 20 --params fc=$fc
done
kept "fc just below 1/(2 dt)" "fc = 49.99 Hz, the post-filter's corner, has 2" --stochastic 1 --dt 0.01 --duration 20 --params fc=49.99
same "the defaults at dt = 0.01 s: no warnings" "[]" "$(json_field '["warnings"]' "$rocking" record synth --stochastic 1 --dt 0.01 --duration 40 --json)"
check "a warning is written into the file" "# warning: the filter's band edge = 8.029 Hz" \
    sh -c "'$rocking' record synth --stochastic 1 --dt 0.02 --duration 40 --output '$tmp/coarse.txt' >/dev/null 2>&1; cat '$tmp/coarse.txt'"

# A bad physical parameter is named as given, not as the alpha it gives.
refused "tmid = 1000 s" "--params: tmid = 1000 s and D5_95 = 17.3 s (Ia = 0.459108 m/s) give alpha1 = 10^-46453, outside a double's range: with tmid 57.8 times D5_95" \
    --stochastic 1 --dt 0.01 --duration 20 --params tmid=1000
refused "tmid = 0.001 s" "--params: tmid/D5_95 must be in (0.203, 96.09) for a gamma modulating function with alpha2 > 1 (got 5.78e-05: tmid = 0.001 s and D5_95 = 17.3 s)" \
    --stochastic 1 --dt 0.01 --duration 20 --params tmid=0.001
refused "a q(t) that overflows within the record" "--params: q(t) = alpha1 t^(alpha2 - 1) exp(-alpha3 t) overflows a double before the record's end at 250 s" \
    --stochastic 1 --dt 0.02 --duration 250 --params tmid=100,fprime=0
refused "fc = -1" "--params: fc must be > 0 and finite (got -1)" --stochastic 1 --dt 0.01 --duration 20 --params fc=-1
refused "zeta = 1" "--params: zeta must be in (0, 1) (got 1)" --stochastic 1 --dt 0.01 --duration 20 --params zeta=1

# Each generator parameter at its lower extreme: the record is the model's limit, or it
# is refused naming the parameter; never a silent wrong record (issue 38).  The post-filter's
# corner toward 0 Hz passes its input: every fc below 1e-9 Hz gives fc = 1e-9's summary (at
# 1e-14 Hz the PGV was 27 m/s, at 1e-300 the record was NaN).
limit_summary=$("$rocking" record synth --stochastic 1 --dt 0.01 --duration 20 --params fc=1e-9 | grep 'PGA =')
for fc in 1e-13 1e-14 3e-15 1e-200 1e-300; do
    same "fc = $fc Hz: the post-filter passes its input" "$limit_summary" \
        "$("$rocking" record synth --stochastic 1 --dt 0.01 --duration 20 --params fc=$fc | grep 'PGA =')"
done
same "fc toward 0 Hz: the unfiltered record's PGA" "  PGA = 1.4394 m/s^2 (0.1467 g), PGV = 0.2417 m/s, to_5 = 0.5275 s" "$limit_summary"
# The filter's frequency toward 0 Hz (h underflowed at 1e-100 Hz: a record of 0/0).
limit_summary=$("$rocking" record synth --stochastic 1 --dt 0.01 --duration 20 --params fmid=1e-9,fprime=0 | grep 'PGA =')
for fmid in 1e-100 1e-300; do
    same "fmid = $fmid Hz: the filter's limit" "$limit_summary" \
        "$("$rocking" record synth --stochastic 1 --dt 0.01 --duration 20 --params fmid=$fmid,fprime=0 | grep 'PGA =')"
done
# A modulation narrower than the step holds none of its Arias intensity.
for width in 0.01 0.001 1e-9; do
    refused "D5_95 = tmid = $width s at dt = 0.01 s" "--params: D5_95 = $(/usr/bin/python3 -c "print('%.4g' % $width)") s, the modulation's 5-95 % duration" \
        --stochastic 1 --dt 0.01 --duration 20 --params D5_95=$width,tmid=$width
done
kept "a modulation of 15 steps" "D5_95 = 0.1472 s, the modulation's 5-95 % duration (tmid = 0.02989 s), spans 14.72 steps" \
    --stochastic 1 --dt 0.01 --duration 20 --params alpha1=1,alpha2=1.0000000001,alpha3=10
# A phase far from 0: the pulse of nu mod 2 pi, whose PGV is at most A (1.55 m/s for A = 0.5 at nu = -1e17).
for nu in -1e17 1e17 -1e300; do
    pgv=$(json_field '["pgv_ms"]' "$rocking" record synth --pulse 0.5,1,$nu,2 --dt 0.01 --duration 5 --json)
    if /usr/bin/python3 -c "import sys; sys.exit(not 0.4 < float('$pgv') <= 0.5)" 2>/dev/null; then echo "ok: nu = $nu: PGV $pgv within A"
    else echo "FAIL: nu = $nu: PGV '$pgv' m/s for A = 0.5"; fail=1; fi
done
same "nu = 1e17 is the pulse of nu mod 2 pi" \
    "$(json_field '["pga_ms2"]' "$rocking" record synth --pulse 0.5,1,3.6246965700849060518,2 --dt 0.01 --duration 5 --json | cut -c1-10)" \
    "$(json_field '["pga_ms2"]' "$rocking" record synth --pulse 0.5,1,1e17,2 --dt 0.01 --duration 5 --json | cut -c1-10)"

check  "--dt is required"          "--dt is required" "$rocking" record synth --pulse 0.5,1,0,2 --duration 5
status "both generators exit 2"    2 "$rocking" record synth --pulse 0.5,1,0,2 --stochastic 1 --dt 0.01 --duration 5
# An --output that cannot be written is an input error (exit 1) naming the file; nothing lands.
status "an unwritable output exits 1" 1 "$rocking" record synth --pulse 0.5,1,0,2 --dt 0.01 --duration 5 --output "$tmp/no/x.txt"
check  "the usage lists record synth" "rocking record synth (--pulse" "$rocking" --help
exit $fail
