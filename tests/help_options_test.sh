#!/usr/bin/env bash
# Every option a command takes is named in its help, and every option its
# help lists is one it takes (issue 40, item 7).
#
# Which options a command takes is asked of the command itself, not read from
# a copy of its parse() list: each option-like literal ("--word") of the
# command line's sources is given to each command with a value, and the
# command takes it unless it answers "unknown option '--word'" (a run never
# starts: the FILE does not exist and the other options are missing).  So an
# option added to any parse() list, or handled before it (--paper, --resume),
# is found with no table to keep in step, and fails here until its command's
# help names it.  A made-up option must be refused, or the probe proves
# nothing.
#
#   tests/help_options_test.sh ROCKING SOURCE_DIR
set -u
rocking=$(realpath "$1")
src=$(realpath "$2")
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1

mapfile -t candidates < <(grep -ohE '"--[a-z][a-z0-9-]*"' "$src"/src/cli/*.cpp "$src"/src/cli/*.hpp | tr -d '"' |
                          grep -vx -e --help | sort -u)
if (( ${#candidates[@]} < 40 )); then
    echo "FAIL: only ${#candidates[@]} option literals found in $src/src/cli"; exit 1
fi

# Each command with the arguments before its options.
declare -A before=(
    [q]="q" [response]="response" [simulate]="simulate"
    [record info]="record info nosuch.txt" [record synth]="record synth" [record floor]="record floor nosuch.txt"
    [collapse]="collapse nosuch.txt" [assess]="assess nosuch.txt" [spectrum]="spectrum nosuch.txt"
    [fragility]="fragility nosuch.txt" [eq27]="eq27 nosuch.txt" [batch]="batch nosuch.csv"
)
# The topics the overview lists must all be probed.
for t in q response simulate "record info" "record synth" "record floor" collapse assess spectrum fragility eq27 batch; do
    [[ -n ${before[$t]+set} ]] || { echo "FAIL: no probe for $t"; fail=1; }
done

# Whether `words` is a whole option in text: --p is not --p-min, --dt not --record-dt.
names() { grep -qE -- "(^|[^A-Za-z0-9-])$2([^A-Za-z0-9-]|\$)" <<<"$1"; }

for topic in "${!before[@]}"; do
    read -r -a args <<<"${before[$topic]}"
    help=$("$rocking" $topic --help 2>&1)
    out=$("$rocking" "${args[@]}" --no-such-option 1 2>&1)
    if [[ $out != *"unknown option '--no-such-option'"* ]]; then
        echo "FAIL: $topic does not refuse a made-up option: $out"; fail=1; continue
    fi
    taken=()
    for opt in "${candidates[@]}"; do
        out=$("$rocking" "${args[@]}" "$opt" 1 2>&1)
        [[ $out == *"unknown option '$opt'"* ]] && continue
        taken+=("$opt")
        names "$help" "$opt" || { echo "FAIL: rocking $topic takes $opt; its help does not name it"; fail=1; }
    done
    echo "ok: rocking $topic takes ${#taken[@]} options: ${taken[*]}"
    # The options its help lists, one a line, each one it takes.
    while read -r opt; do
        out=$("$rocking" "${args[@]}" "$opt" 1 2>&1)
        if [[ $out == *"unknown option '$opt'"* ]]; then
            echo "FAIL: rocking $topic's help lists $opt, which it refuses"; fail=1
        fi
    done < <(grep -oE '^  --[a-z][a-z0-9-]*' <<<"$help" | sed 's/^ *//' | sort -u)
done
exit $fail
