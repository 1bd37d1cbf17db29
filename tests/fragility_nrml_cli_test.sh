#!/usr/bin/env bash
# rocking fragility --nrml XML (issue 40, item 6): each block's fit as an OpenQuake NRML 0.5 continuous
# fragility function, read back by Python's own XML parser (xml.etree) and checked against an independent
# computation from the --json's median and beta (math): theta = median alpha in g, mean = theta e^(beta^2/2),
# stddev = mean sqrt(e^(beta^2) - 1), to 1e-12 relative, and back (the engine's sigma = sqrt(ln(1 + c^2)),
# scale = mean^2 / sqrt(mean^2 + stddev^2)) to the median and beta; minIML, maxIML and noDamageLimit from
# the grid; the refine method's file naming the first overturning's fit, the grid's the first collapse; a
# block without a fit a comment and a line on stderr; a record named with & < > " ' and -- escaped, the
# file ASCII; the Python module's nrml=True the same bytes; --nrml over an input refused.
#
#   tests/fragility_nrml_cli_test.sh ROCKING
set -u
rocking=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
py=/usr/bin/python3
source "$here/check_lib.sh"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

odd="$tmp/a&b <c> \"d\" 'e' --f.txt"
"$rocking" record synth --stochastic 1 --dt 0.01 --duration 20 --output "$tmp/s1.txt" >/dev/null || exit 1
"$rocking" record synth --stochastic 2 --dt 0.01 --duration 20 --output "$tmp/s2.txt" >/dev/null || exit 1
"$rocking" record synth --stochastic 3 --dt 0.01 --duration 20 --output "$odd" >/dev/null || exit 1
files=("$tmp/s1.txt" "$tmp/s2.txt" "$odd")
# p = 0.5 rad/s: no record overturns the block below q = 2.5, so that block has no fit.
base=(--unit m/s2 --alpha 0.1,0.2 --p 3,0.5 --q-max 2.5 --points 20 --quiet)
refine=(--method refine --width 1e-3 --bootstrap 20 --seed 4)
"$rocking" fragility "${files[@]}" "${base[@]}" "${refine[@]}" --json --nrml "$tmp/refine.xml" \
    >"$tmp/refine.json" 2>"$tmp/refine.err" || { echo "FAIL: the refine run"; fail=1; }
"$rocking" fragility "${files[@]}" "${base[@]}" --json --nrml "$tmp/grid.xml" >"$tmp/grid.json" 2>/dev/null \
    || { echo "FAIL: the grid run"; fail=1; }
check "stderr names the block without a fit" \
    "--nrml $tmp/refine.xml: alpha 0.1, p 0.5 rad/s: no fit: no record overturned" cat "$tmp/refine.err"

$py - "$tmp" "$odd" <<'PY' && echo "ok: the NRML files against their independent reading" || fail=1
import json, math, sys
import xml.etree.ElementTree as ET
tmp, odd = sys.argv[1], sys.argv[2]
NS = "{http://openquake.org/xmlns/nrml/0.5}"
def close(a, b, what, rel=1e-12):
    assert abs(a - b) <= rel * abs(b), (what, a, b, abs(a - b) / abs(b))
for name, capacity in (("refine", "first overturns the block, every island of overturning wider than 0.001 in ln q "
                                  "found (the refine method's fit on the first overturning, the conservative one of "
                                  "its three fits"),
                       ("grid", "on the IDA's grid (its first collapse")):
    raw = open("%s/%s.xml" % (tmp, name), "rb").read()
    assert all(b < 0x80 for b in raw), name + ": a byte beyond ASCII"
    doc = json.load(open("%s/%s.json" % (tmp, name)))
    root = ET.fromstring(raw, parser=ET.XMLParser(target=ET.TreeBuilder(insert_comments=True)))
    assert root.tag == NS + "nrml", root.tag
    (model,) = root.findall(NS + "fragilityModel")
    assert (model.get("id"), model.get("assetCategory"), model.get("lossCategory")) == \
        ("rocking-q_overturning", "buildings", "structural"), model.attrib
    assert model.find(NS + "limitStates").text == "overturning"
    description = model.find(NS + "description").text
    assert capacity in description, (name, description)
    assert description.endswith("Records: %s/s1.txt; %s/s2.txt; %s." % (tmp, tmp, odd)), description[-300:]
    functions = {f.get("id"): f for f in model.findall(NS + "fragilityFunction")}
    comments = [c.text for c in model if c.tag is ET.Comment]
    g = doc["grid"]
    fitted = 0
    for block in doc["blocks"]:
        a, p = block["alpha"], block["p"]
        label = "alpha %g, p %g rad/s" % (a, p)
        fid = ("rocking_alpha_%r_p_%r" % (a, p)).replace(".", "_")
        if block["fit"] is None:
            assert fid not in functions, fid
            assert any(c.startswith(" %s: no fit: %s" % (label, block["no_fit"])) for c in comments), (label, comments)
            continue
        fitted += 1
        f = functions[fid]
        assert (f.get("format"), f.get("shape")) == ("continuous", "logncdf"), f.attrib
        imls, params = f.find(NS + "imls"), f.findall(NS + "params")
        assert imls.get("imt") == "PGA" and len(params) == 1 and params[0].get("ls") == "overturning"
        close(float(imls.get("minIML")), a * g["q_min"], fid + " minIML")
        close(float(imls.get("noDamageLimit")), a * g["q_min"], fid + " noDamageLimit")
        close(float(imls.get("maxIML")), a * g["q_max"], fid + " maxIML")
        median, beta = block["fit"]["median"], block["fit"]["beta"]
        theta = median * a  # PGA = q alpha g: the median in g
        mean, stddev = float(params[0].get("mean")), float(params[0].get("stddev"))
        close(mean, theta * math.exp(beta * beta / 2), fid + " mean")
        close(stddev, theta * math.exp(beta * beta / 2) * math.sqrt(math.exp(beta * beta) - 1), fid + " stddev")
        # Back, as the engine reads a continuous function: sigma and scale of the lognormal.
        close(math.sqrt(math.log(1 + (stddev / mean) ** 2)), beta, fid + " beta back")
        close(mean ** 2 / math.sqrt(mean ** 2 + stddev ** 2), theta, fid + " theta back")
        # The comment before it states the fit and its bootstrap.
        assert any(c.startswith(" %s: median q %.6g, beta %.6g" % (label, median, beta)) for c in comments), label
    assert fitted == len(functions) >= 2, (fitted, sorted(functions))
    assert any(b["fit"] is None for b in doc["blocks"]), "a block without a fit"
PY

# The Python module gives the same bytes.
PYTHONPATH="$here/../build/python${PYTHONPATH:+:$PYTHONPATH}" $py - "$tmp" "${files[@]}" <<'PY' \
    && echo "ok: rq.fragility(nrml=True) is --nrml's file" || fail=1
import sys, warnings
import rocking_q as rq
tmp, paths = sys.argv[1], sys.argv[2:]
records = [rq.read_record(p, unit="m/s2") for p in paths]
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    got = rq.fragility(records, alpha=[0.1, 0.2], p=[3, 0.5], q_max=2.5, points=20, method="refine", width=1e-3,
                       bootstrap=20, seed=4, nrml=True)
assert got.nrml == open(tmp + "/refine.xml").read()
assert any("alpha 0.1, p 0.5 rad/s: no fit" in str(x.message) for x in w), [str(x.message) for x in w]
assert "nrml" not in rq.fragility(records[:2], alpha=0.1, p=3, q_max=2.5, points=20)
PY

status "--nrml over an input is refused" 2 "$rocking" fragility "${files[@]}" "${base[@]}" --nrml "$tmp/s1.txt"
check "--nrml over an input: the message names it" "--nrml" \
    "$rocking" fragility "${files[@]}" "${base[@]}" --nrml "$tmp/s1.txt"
status "--nrml into a missing folder is refused before the work" 1 \
    "$rocking" fragility "${files[@]}" "${base[@]}" --nrml "$tmp/none/x.xml"
check "fragility's usage names --nrml" "[--nrml XML]" "$rocking" fragility
exit $fail
