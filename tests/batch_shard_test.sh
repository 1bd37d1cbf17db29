#!/usr/bin/env bash
# rocking batch --shard I/N and rocking batch join (issue 42): the mixed manifest
# (batch_mixed_manifest.sh) cut into 1, 2, 3, 7 and more shards than jobs, each
# shard run on its own (threads 1 to 3), joined in a shuffled order: the same
# bytes as one run; a shard killed with SIGKILL and resumed, then joined: the
# same bytes; join's refusals (a shard missing or twice, another cut, another
# manifest, an unfinished shard, a damaged end line, the output a shard) and
# --shard's own (a bad I/N, no --output, a resume on another shard's file).
#
#   tests/batch_shard_test.sh ROCKING
set -u
rocking=$(realpath "$1")
source "$(dirname "$0")/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
"$(dirname "$0")/batch_mixed_manifest.sh" "$rocking" "$tmp" || exit 1
jobs=$(grep -vc -e '^#' -e '^$' "$tmp/m.csv"); jobs=$((jobs - 1))
"$rocking" batch "$tmp/m.csv" --jobs 2 --output "$tmp/one.csv" --quiet

for n in 1 2 3 7 $((jobs + 3)); do
    files=()
    for i in $(seq "$n"); do
        "$rocking" batch "$tmp/m.csv" --shard "$i/$n" --jobs $((i % 3 + 1)) --output "$tmp/s$n.$i.csv" --quiet
        files+=("$tmp/s$n.$i.csv")
    done
    shuffled=($(printf '%s\n' "${files[@]}" | sort -R))
    "$rocking" batch join "${shuffled[@]}" --output "$tmp/j$n.csv" --quiet
    if cmp -s "$tmp/j$n.csv" "$tmp/one.csv"; then echo "ok: $n shards joined: the bytes of one run"
    else echo "FAIL: $n shards joined differ from one run"; fail=1; fi
done
# Shard 1/N's file names its shard, and holds only its rows.
head -1 "$tmp/s3.1.csv" | grep -q " shard 1/3$" && echo "ok: a shard's first line names it" || { echo "FAIL: shard line"; fail=1; }

# SIGKILL in the middle of a shard, resumed (on other threads), joined.
export ROCKING_BATCH_FLUSH_SECONDS=0
out="$tmp/k.2.csv"
"$rocking" batch "$tmp/m.csv" --shard 2/2 --jobs 1 --output "$out" --quiet &
pid=$!
for _ in $(seq 300); do
    [[ -f $out.partial.state ]] && (( $(awk '{print $5}' "$out.partial.state") > 1 )) && break
    sleep 0.01
done
kill -KILL $pid 2>/dev/null; wait $pid 2>/dev/null
written=$(awk '{print $5}' "$out.partial.state" 2>/dev/null || echo 0)
check "a resume on another shard's file" "has changed since" \
    "$rocking" batch "$tmp/m.csv" --shard 1/2 --output "$out" --resume --quiet
"$rocking" batch "$tmp/m.csv" --shard 2/2 --jobs 3 --output "$out" --resume --quiet
"$rocking" batch join "$tmp/s2.1.csv" "$out" --output "$tmp/jk.csv" --quiet
if [[ $written -gt 0 ]] && cmp -s "$tmp/jk.csv" "$tmp/one.csv"; then
    echo "ok: a shard killed after $written jobs, resumed and joined: the bytes of one run"
else echo "FAIL: a killed shard (written $written) resumed and joined differs"; fail=1; fi

# The refusals.
check  "a bad shard"        "--shard: a shard is I/N, the I-th of N parts" "$rocking" batch "$tmp/m.csv" --shard 0/2 --output "$tmp/x.csv"
status "a bad shard"        2                                "$rocking" batch "$tmp/m.csv" --shard 3/2 --output "$tmp/x.csv"
check  "a shard to stdout"  "--shard needs --output FILE"    "$rocking" batch "$tmp/m.csv" --shard 1/2
check  "a shard missing"    "shard 2/3 is missing"           "$rocking" batch join "$tmp/s3.1.csv" "$tmp/s3.3.csv" --output "$tmp/x.csv"
status "a shard missing"    1                                "$rocking" batch join "$tmp/s3.1.csv" "$tmp/s3.3.csv" --output "$tmp/x.csv"
check  "a shard twice"      "shard 1 given twice"            "$rocking" batch join "$tmp/s3.1.csv" "$tmp/s3.1.csv" "$tmp/s3.2.csv" --output "$tmp/x.csv"
check  "another cut"        "of another cut"                 "$rocking" batch join "$tmp/s2.1.csv" "$tmp/s3.2.csv" --output "$tmp/x.csv"
check  "a whole run"        "not of a shard"                 "$rocking" batch join "$tmp/one.csv" --output "$tmp/x.csv"
check  "output is a shard"  "is the shard"                   "$rocking" batch join "$tmp/s2.1.csv" "$tmp/s2.2.csv" --output "$tmp/s2.2.csv"
check  "no output"          "--output FILE is required"      "$rocking" batch join "$tmp/s2.1.csv" "$tmp/s2.2.csv"
sed '1s/^\(# manifest sha256: \).\(.*\)$/\10\2/' "$tmp/s2.2.csv" >"$tmp/other.csv"
check  "another manifest"   "the results of another manifest" "$rocking" batch join "$tmp/s2.1.csv" "$tmp/other.csv" --output "$tmp/x.csv"
head -n -1 "$tmp/s2.2.csv" >"$tmp/open.csv"
check  "an unfinished shard" "has no '# end' line: the shard has not finished" \
    "$rocking" batch join "$tmp/s2.1.csv" "$tmp/open.csv" --output "$tmp/x.csv"
sed '$s/# end: \([0-9]*\) jobs/# end: 999 jobs/' "$tmp/s2.2.csv" >"$tmp/bad.csv"
check  "a damaged end line" "does not close its"             "$rocking" batch join "$tmp/s2.1.csv" "$tmp/bad.csv" --output "$tmp/x.csv"
[[ ! -e $tmp/x.csv && ! -e $tmp/x.csv.join.tmp ]] && echo "ok: a refused join leaves no file" || { echo "FAIL: a refused join left a file"; fail=1; }
exit $fail
