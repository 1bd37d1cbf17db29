#!/usr/bin/env bash
# Every --json output parses, always (issue 31, item 4).  Each subcommand gets
# extreme arguments and hostile record files (names and titles with newlines,
# tabs, quotes, backslashes, control characters and invalid UTF-8), and its
# output is read by Python's json module in strict mode: NaN and Infinity
# rejected, raw control characters rejected, invalid UTF-8 rejected, numbers
# that overflow to inf rejected, and null allowed only where the output says
# why beside it.  A command may refuse an input instead: then it exits 1 or 2
# with a message and prints nothing on standard output.
#
#   tests/json_test.sh ROCKING     (the ESM case needs ../shared/records or $ROCKING_RECORDS)
set -u
rocking="$1"
records="${ROCKING_RECORDS:-$(dirname "$0")/../../shared/records}"
py=/usr/bin/python3
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail=0

cat >"$tmp/check.py" <<'EOF'
import json, math, os, re, sys

out_path, err_path, rc, mode, condition = sys.argv[1:6]
command = sys.argv[6:]          # ROCKING SUBCOMMAND ...: arg(k) is command[k]
rc = int(rc)
out = open(out_path, "rb").read()
err = open(err_path, "rb").read()

def arg(k):
    """The k-th word of the command as a JSON reader should see it: its bytes, ill-formed UTF-8 replaced."""
    return os.fsencode(command[k]).decode("utf-8", "replace")

def line(path_arg, number):
    """A header line of the record named by arg(path_arg), trimmed as the readers trim it."""
    with open(os.fsencode(command[path_arg]), "rb") as f:
        return f.read().split(b"\n")[number - 1].strip(b" \t\r").decode("utf-8", "replace")

def finite(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)

# The only nulls allowed, each with the fields that say why (a list's
# elements as [], shares[3].bootstrap as shares[].bootstrap).
NULL_REASONS = {
    "theta_tfin_over_alpha": lambda o: o.get("overturned_during_input") is True,
    "t_overturn": lambda o: o.get("overturned") is False or o.get("overturned_during_input") is False,
    "p": lambda o: o.get("found") is False,
    "p_safe": lambda o: o.get("found") is False or o.get("below_range") is True,
    "rows_end_at": lambda o: o.get("rows_complete") is True,
    "rows_end_reason": lambda o: o.get("rows_complete") is True,
    "bootstrap": lambda o: o.get("bootstrap_run") is False and "bootstrap_note" in o,
    "shares[].bootstrap": lambda o: o.get("bootstrap_run") is False and "bootstrap_note" in o,
    "thickness": lambda o: o.get("given") == "alpha and p",
    "height": lambda o: o.get("given") == "alpha and p",
    "R": lambda o: o.get("given") == "alpha and p",
}

def unexplained(value, top, where):
    if isinstance(value, dict):
        for k, v in value.items():
            yield from unexplained(v, top, where + "." + k if where else k)
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from unexplained(v, top, "%s[%d]" % (where, i))
    elif value is None:
        key = re.sub(r"\[\d+\]", "[]", where)
        if not (key in NULL_REASONS and NULL_REASONS[key](top)):
            yield "%s is null without a reason beside it" % where
    elif isinstance(value, float) and not math.isfinite(value):
        yield "%s overflows to %r" % (where, value)

def reject(constant):
    raise ValueError("bare " + constant)

def problem():
    if rc != 0:
        if mode == "ok":
            return "exit %d, expected 0 and JSON: %r" % (rc, err[:300])
        if rc not in (1, 2):
            return "exit %d (a crash or a signal), expected 0, 1 or 2: %r" % (rc, err[:300])
        if out:
            return "refused (exit %d) but printed %r" % (rc, out[:300])
        if not err.startswith(b"rocking "):
            return "refused (exit %d) without a message naming the command: %r" % (rc, err[:300])
        return None
    if mode == "refuse":
        return "exit 0, expected a refusal: %r" % out[:300]
    try:
        # strict (the default) rejects raw control characters inside strings
        o = json.loads(out.decode("utf-8"), parse_constant=reject)
    except (ValueError, UnicodeDecodeError) as e:
        return "not JSON (%s): %r" % (e, out[:400])
    if out.count(b"\n") != 1 or not out.endswith(b"\n"):
        return "not one line of JSON: %r" % out[:400]
    bad = list(unexplained(o, o, ""))
    if bad:
        return "; ".join(bad[:5]) + ": %r" % out[:400]
    if condition and not eval(condition, {"o": o, "arg": arg, "line": line, "finite": finite}):
        return "fails %s: %r" % (condition, out[:400])
    return None

why = problem()
if why:
    print(why)
    sys.exit(1)
EOF

# json_case WHAT MODE CONDITION COMMAND...: MODE is ok (exit 0 and JSON), refuse
# (exit 1 or 2, a message, no output) or either; CONDITION is a Python
# expression on the parsed object o ("" for none), with arg(k) the command's
# k-th word (0 is rocking) as JSON should spell it.
json_case() {
    local what="$1" mode="$2" condition="$3"; shift 3
    "$@" >"$tmp/out" 2>"$tmp/err"
    local rc=$? why
    if why=$("$py" "$tmp/check.py" "$tmp/out" "$tmp/err" "$rc" "$mode" "$condition" "$@"); then
        echo "ok: $what"
    else
        echo "FAIL: $what: $why"
        fail=1
    fi
}

# A name with every character JSON must escape and every kind of ill-formed
# UTF-8: a newline, a tab, quotes, a backslash, ESC and SOH, C1 NEL, DEL, a
# stray 0xFF, a truncated two-byte and three-byte sequence, a surrogate, an
# overlong encoding and a code point above U+10FFFF.
hostile=$'rec \n\t"q"\\ \x01\x1b[1m \xc2\x85\x7f \xff \xc3( \xe2\x82 \xed\xa0\x80 \xe0\x80\xaf \xf4\x90\x80\x80 end'
mkdir "$tmp/d" || exit 1
two="$tmp/d/$hostile.txt"          # time, acceleration in g
one="$tmp/d/$hostile one.txt"      # acceleration in g, --dt 0.01
peer="$tmp/d/$hostile.AT2"         # PEER, its title line hostile too
"$py" - "$two" "$one" "$peer" <<'EOF' || exit 1
import math, os, sys
two, one, peer = (os.fsencode(a) for a in sys.argv[1:4])
a = [0.5 * math.sin(2 * math.pi * k * 0.01) for k in range(400)]
with open(two, "w") as f:
    f.writelines("%.2f %.6f\n" % (0.01 * k, v) for k, v in enumerate(a))
with open(one, "w") as f:
    f.writelines("%.6f\n" % v for v in a)
title = b'\x01title\t"q"\\ \x1b[31m \xc2\x9b \xff\xc3( \xe2\x82 \xed\xa0\x80 end'
with open(peer, "wb") as f:
    f.write(b"PEER NGA STRONG MOTION DATABASE RECORD\n" + title + b"\n")
    f.write(b"ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=  400, DT=   .0100 SEC\n")
    f.write("".join("%15.7E\n" % v for v in a).encode())
EOF
# Valid UTF-8 with control characters only: escaping alone must make it JSON.
controls="$tmp/d/"$'ctl \n\t"q"\\ \x01\x1b[1m \x7f \xc3\xa9 \xe2\x82\xac end.txt'
# Another record than $two (0.9 times it): eq27 refuses a record given twice.
awk '{printf "%s %.6f\n", $1, 0.9 * $2}' "$two" >"$controls" || exit 1
printf '0\n0\n0\n0\n0\n0\n' >"$tmp/zero.txt"
printf '1e300\n1e300\n-1e300\n-1e300\n1e300\n0\n' >"$tmp/big.txt"      # m/s2: finite, but q = PGA/(alpha g) overflows at tiny alpha
printf '1e308\n1e308\n-1e308\n-1e308\n1e308\n0\n' >"$tmp/huge.txt"    # m/s2: its velocity overflows

# q: q itself must be a finite number wherever it is printed.
for x in 1e-150 1e-8 1e3 1e300; do
    for c in 1 2 3 4 5; do
        json_case "q case $c at x = $x" ok 'finite(o["q"]) and o["q"] > 0' "$rocking" q --case "$c" --x "$x" --json
    done
done
json_case "q at x = 1e-150, 1000 pulses" ok 'finite(o["q"])' "$rocking" q --case 1 --pulses 1000 --x 1e-150 --json
json_case "q at x = 1e3, 1000 pulses"    ok 'finite(o["q"])' "$rocking" q --case 4 --pulses 1000 --x 1e3 --json
json_case "q case 2 at x = 20"          ok 'finite(o["q"])' "$rocking" q --case 2 --x 20 --json
json_case "q, a pulse of 1e-160 to"      either 'finite(o["q"])' "$rocking" q --train 1:1e-160 --x 1 --json
json_case "q, a pulse of 1e-300 to"      either 'finite(o["q"])' "$rocking" q --train 1:1e-300 --x 1 --json
json_case "q, amplitudes of 1e300"       either 'finite(o["q"])' "$rocking" q --train 1e300:1,-1e300:1 --x 1 --json
json_case "q, amplitudes of 1e-300"      either 'finite(o["q"])' "$rocking" q --train 1e-300:1,1e-300:1 --x 1e-10 --json

# response: every sample a finite number (or a refusal).
samples_finite='all(finite(v) for s in o["samples"] for v in s)'
json_case "response case 2 at x = 0.5"   ok "$samples_finite" "$rocking" response --case 2 --x 0.5 --json
json_case "response case 2 at x = 1e-8"  either "$samples_finite" "$rocking" response --case 2 --x 1e-8 --json
json_case "response case 5 at x = 1e-150" either "$samples_finite" "$rocking" response --case 5 --x 1e-150 --json
json_case "response at q = 1e300"        either "$samples_finite" "$rocking" response --case 2 --x 1 --q 1e300 --json
json_case "response case 4 at x = 15"    either "$samples_finite" "$rocking" response --case 4 --x 15 --json
# These printed nan and inf samples before the response's per-jump forms
# (src/qfactor/superposition.cpp); a q off the collapse q now ends its rows
# where theta leaves the double range, and says so (rows_complete false).
json_case "response case 2 at x = 700"   either "$samples_finite" "$rocking" response --case 2 --x 700 --json
json_case "response case 2, x = 1000, q = 5" either "$samples_finite" "$rocking" response --case 2 --x 1000 --q 5 --json
json_case "response 400 pulses at x = 2" either "$samples_finite" "$rocking" response --case 1 --pulses 400 --x 2 --json
json_case "response 1000 pulses at x = 1e3" either "$samples_finite" "$rocking" response --case 1 --pulses 1000 --x 1e3 --json

# simulate: huge amplitudes, the smallest and largest scales, on both equations.
for model in linearised full; do
    for input in "--case 2 --x 1 --pga 1e300" "--case 2 --x 1e-100 --pga 1e300" "--case 2 --x 1e100 --pga 1e300" \
                 "--case 1 --pulses 1000 --x 1e3 --rd 0.5" "--one-sine --ap 1e300 --wp 1" "--one-sine --ap 1e300 --wp 1e300"; do
        for geometry in "--alpha 0.15 --p 2" "--alpha 1e-300 --p 1e300" "--alpha 0.785 --p 1e-300" "--alpha 1e-300 --height 1e300"; do
            # shellcheck disable=SC2086  # the option lists split on purpose
            json_case "simulate $input $geometry, $model" either 'finite(o["t_fin"])' \
                "$rocking" simulate $input $geometry --model "$model" --json
        done
    done
    json_case "simulate a hostile record, $model" ok 'arg(3) in o["input"]' \
        "$rocking" simulate --record "$two" --unit g --alpha 0.15 --p 2 --model "$model" --json
    json_case "simulate a hostile record at 1e300 g, $model" either 'arg(3) in o["input"]' \
        "$rocking" simulate --record "$two" --unit g --pga 1e300 --alpha 0.15 --p 2 --model "$model" --json
    json_case "simulate a PEER title, $model" ok 'line(3, 2) in o["input"]' \
        "$rocking" simulate --record "$peer" --alpha 0.15 --p 2 --model "$model" --json
    json_case "simulate a record of 1e308 m/s2, $model" either '' \
        "$rocking" simulate --record "$tmp/huge.txt" --record-dt 1 --unit m/s2 --alpha 0.15 --p 2 --model "$model" --json
done

# record info: names and titles come back as their bytes read, and measures
# that overflow are refused, not printed as inf or nan (nor a crash).
json_case "record info, a hostile two-column name" ok 'o["file"] == arg(3) and o["name"] == arg(3)' \
    "$rocking" record info "$two" --unit g --json
json_case "record info, control characters in a name" ok 'o["file"] == arg(3) and "\u00e9 \u20ac" in o["file"]' \
    "$rocking" record info "$controls" --unit g --json
json_case "record info, a hostile one-column name" ok 'o["file"] == arg(3) and o["samples"] == 400' \
    "$rocking" record info "$one" --dt 0.01 --unit g --json
json_case "record info, a PEER title"     ok 'o["file"] == arg(3) and o["name"] == line(3, 2)' \
    "$rocking" record info "$peer" --json
json_case "record info, all zero"         either '' "$rocking" record info "$tmp/zero.txt" --dt 0.01 --unit g --json
json_case "record info, PGV overflows"    either '' "$rocking" record info "$tmp/huge.txt" --dt 1 --unit m/s2 --json
json_case "record info, PGV overflows (dt 10)" either '' "$rocking" record info "$tmp/huge.txt" --dt 10 --unit m/s2 --json
json_case "record info, dt = 1e-300"      either '' "$rocking" record info "$one" --dt 1e-300 --unit g --json
json_case "record info, 1e300 m/s2"       either '' "$rocking" record info "$tmp/big.txt" --dt 0.01 --unit m/s2 --json

# collapse
json_case "collapse, a hostile name"      ok 'o["file"] == arg(2) and o["found"] in (True, False)' \
    "$rocking" collapse "$two" --alpha 0.15 --unit g --json
json_case "collapse, a PEER title"        ok 'o["file"] == arg(2)' "$rocking" collapse "$peer" --alpha 0.15 --json
json_case "collapse, nothing found"       ok 'o["found"] is False and o["p"] is None' \
    "$rocking" collapse "$tmp/zero.txt" --alpha 0.15 --dt 0.01 --unit g --json
json_case "collapse, 1e308 m/s2"          either '' "$rocking" collapse "$tmp/huge.txt" --alpha 0.15 --dt 1 --unit m/s2 --json

# assess
json_case "assess, a hostile name"        ok 'o["records"][0]["file"] == arg(2) and finite(o["records"][0]["q_record"])' \
    "$rocking" assess "$two" --alpha 0.15 --height 2 --unit g --json
json_case "assess, a PEER title"          ok 'o["records"][0]["file"] == arg(2)' "$rocking" assess "$peer" --alpha 0.15 --height 2 --json
json_case "assess, q overflows at tiny alpha" either '' \
    "$rocking" assess "$tmp/big.txt" --alpha 1e-10 --height 2 --dt 0.01 --unit m/s2 --json
json_case "assess, PGV overflows"         either '' "$rocking" assess "$tmp/huge.txt" --alpha 0.15 --height 2 --dt 10 --unit m/s2 --json
json_case "assess, the smallest height"   either '' "$rocking" assess "$one" --alpha 0.15 --height 1e-300 --dt 0.01 --unit g --json
json_case "assess, the largest height"    either '' "$rocking" assess "$one" --alpha 1e-300 --height 1e300 --dt 0.01 --unit g --json

# eq27: hostile names back as their bytes, the shares and both intervals
# finite and in [0, 1], the bootstrap null (and said so) unless asked for.
shares_ok='all(0 <= s["wilson"][0] <= s["share"] <= s["wilson"][1] <= 1 for s in o["shares"])'
boot_ok='all(0 <= s["bootstrap"][0] <= s["bootstrap"][1] <= 1 for s in o["shares"])'
small_grid=(--alpha 0.15 --p-min 2 --p-max 4 --p-points 2)
json_case "eq27, hostile names, no bootstrap" ok \
    "o['files'] == [arg(2), arg(3)] and o['by_record'][1]['file'] == arg(3) and o['bootstrap'] is None and $shares_ok" \
    "$rocking" eq27 "$two" "$controls" --unit g "${small_grid[@]}" --json
json_case "eq27, hostile names, bootstrap" ok \
    "o['files'] == [arg(2), arg(3)] and o['bootstrap']['resamples'] == 50 and $shares_ok and $boot_ok" \
    "$rocking" eq27 "$two" "$controls" --unit g "${small_grid[@]}" --bootstrap 50 --seed 9 --json
json_case "eq27, a PEER title, one record" ok "o['files'] == [arg(2)] and o['records'] == 1 and $boot_ok" \
    "$rocking" eq27 "$peer" "${small_grid[@]}" --bootstrap 2 --seed 4294967295 --json
json_case "eq27, a record that never moves" either '' \
    "$rocking" eq27 "$tmp/zero.txt" --dt 0.01 --unit g "${small_grid[@]}" --json
json_case "eq27, 1e300 m/s2 at tiny alpha" either '' \
    "$rocking" eq27 "$tmp/big.txt" --dt 0.01 --unit m/s2 --alpha 1e-10 --json

# An ESM file with a hostile station code and event name: the header layout
# is read from a real ESM file at run time; the samples are ours.
esm_source=$(ls "$records"/esm/*.ASC 2>/dev/null | head -1)
if [[ -z "$esm_source" ]]; then
    echo "skipped: the ESM cases need an ESM file under $records/esm (../shared/records or \$ROCKING_RECORDS)"
else
    esm="$tmp/d/$hostile.ASC"
    "$py" - "$esm_source" "$esm" <<'EOF' || exit 1
import math, os, sys
source, target = sys.argv[1], os.fsencode(sys.argv[2])
a = [50 * math.sin(2 * math.pi * k * 0.01) for k in range(400)]  # cm/s^2
values = {b"NDATA": b"400", b"SAMPLING_INTERVAL_S": b"0.010000", b"PGA_CM/S^2": b"%.6f" % max(map(abs, a)),
          b"STATION_CODE": b'S\tT"A\\ \x01\x1b[2J \xff\xc3( \xe2\x82', b"EVENT_NAME": b'EV\x07\xed\xa0\x80 \xc2\x85'}
header = []
for raw in open(source, "rb"):
    key = raw.split(b":", 1)[0].strip()
    if b":" not in raw:
        break  # the first sample
    header.append(key + b": " + values[key] + b"\n" if key in values else raw)
with open(target, "wb") as f:
    f.writelines(header)
    f.writelines(b"%.6f\n" % v for v in a)
EOF
    station='b"S\tT\"A\\ \x01\x1b[2J \xff\xc3( \xe2\x82".decode("utf-8", "replace")'
    json_case "record info, an ESM station code" ok "o['file'] == arg(3) and $station in o['name']" \
        "$rocking" record info "$esm" --json
    json_case "simulate, an ESM station code" ok "$station in o['input']" \
        "$rocking" simulate --record "$esm" --alpha 0.15 --p 2 --json
    json_case "collapse, an ESM file"        ok 'o["file"] == arg(2)' "$rocking" collapse "$esm" --alpha 0.15 --json
    json_case "assess, an ESM file"          ok 'o["records"][0]["file"] == arg(2)' "$rocking" assess "$esm" --alpha 0.15 --height 2 --json
fi

exit $fail
