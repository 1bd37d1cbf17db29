# The checks the command-line test scripts share; each sets fail=1 on a failure.
# Sourced by the command-line test scripts (tests/*_test.sh).
fail=0
check() {  # description, expected substring, command...
    local what="$1" want="$2"; shift 2
    local out; out=$("$@" 2>&1)
    if [[ "$out" != *"$want"* ]]; then echo "FAIL: $what: wanted '$want' in: $out"; fail=1; else echo "ok: $what"; fi
}
check_not() {  # description, substring that must be absent, command...
    local what="$1" unwanted="$2"; shift 2
    local out; out=$("$@" 2>&1)
    if [[ "$out" == *"$unwanted"* ]]; then echo "FAIL: $what: '$unwanted' should not be in: $out"; fail=1; else echo "ok: $what"; fi
}
status() {  # description, expected exit status, command...
    local what="$1" want="$2"; shift 2
    "$@" >/dev/null 2>&1; local got=$?
    if [[ $got != "$want" ]]; then echo "FAIL: $what: exit $got, wanted $want"; fail=1; else echo "ok: $what (exit $got)"; fi
}
same() {  # description, file, reference: the same bytes, the first lines of the difference where not
    if cmp -s "$2" "$3"; then echo "ok: $1"; else echo "FAIL: $1: differs from $3"; diff "$2" "$3" | head -5; fail=1; fi
}
