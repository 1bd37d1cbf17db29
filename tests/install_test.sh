#!/usr/bin/env bash
# The installable package (docs/package.md): cmake --install into a temporary
# prefix; the layout (public headers in, internal ones out); a project outside
# the tree (tests/consumer) configured with find_package(rocking_q), built
# against the prefix alone and run, its values equal to the installed
# command's --json; the installed Python module imported from the prefix.
#
#   tests/install_test.sh CMAKE BUILD_DIR CONSUMER_SOURCE CXX PYTHON_MODULE(ON|OFF) LIBDIR PYTHON_DIR
set -u
cmake="$1" build="$2" consumer="$3" cxx="$4" python_module="$5" libdir="$6" pydir="$7"
py=/usr/bin/python3
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
prefix="$tmp/prefix"

fail() {
    echo "install_test: $1" >&2
    [ -n "${2:-}" ] && tail -30 "$2" >&2
    exit 1
}

"$cmake" --install "$build" --prefix "$prefix" >"$tmp/install.log" 2>&1 || fail "cmake --install failed" "$tmp/install.log"

for f in bin/rocking "$libdir/librocking_core.a" "$libdir/cmake/rocking_q/rocking_qConfig.cmake" \
         "$libdir/cmake/rocking_q/rocking_qTargets.cmake" include/rocking_q/qfactor/closed_forms.hpp \
         include/rocking_q/dynamics/simulate.hpp include/rocking_q/studies/eq27_at_scale.hpp \
         include/rocking_q/records/collapse.hpp; do
    [ -f "$prefix/$f" ] || fail "not installed: $f"
done
for f in dynamics/closed_piece.hpp dynamics/run_rules.hpp dynamics/exact_record.hpp numerics/roots.hpp \
         records/cwt.hpp records/fft.hpp studies/scaled_input.hpp harness/table.hpp batch/pool.hpp cli/options.hpp; do
    [ ! -e "$prefix/include/rocking_q/$f" ] || fail "an internal header is installed: $f"
done

# The consumer sees only the prefix: no source tree, no build tree.
"$cmake" -S "$consumer" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_BUILD_TYPE=Release >"$tmp/configure.log" 2>&1 || fail "the consumer does not configure" "$tmp/configure.log"
grep -q "installed headers, each compiled alone" "$tmp/configure.log" || fail "the consumer's header check did not run" "$tmp/configure.log"
"$cmake" --build "$tmp/consumer" -j 2 >"$tmp/build.log" 2>&1 || fail "the consumer does not build" "$tmp/build.log"
"$tmp/consumer/consumer" >"$tmp/consumer.txt" || fail "the consumer failed" "$tmp/consumer.txt"

"$prefix/bin/rocking" q --case 2 --pulses 6 --x 0.5 --json >"$tmp/q.json" || fail "the installed rocking q failed"
"$prefix/bin/rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --json >"$tmp/simulate.json" ||
    fail "the installed rocking simulate failed"

# The consumer's values against the command's: the same code, so the same doubles.
"$py" - "$tmp/consumer.txt" "$tmp/q.json" "$tmp/simulate.json" <<'PY' || fail "the consumer's values differ" "$tmp/consumer.txt"
import json, sys
got = dict(line.split(" ", 1) for line in open(sys.argv[1]).read().splitlines())
q = json.load(open(sys.argv[2]))
sim = json.load(open(sys.argv[3]))
checks = [("q", float(got["q"]), q["q"]),
          ("theta_tfin_over_alpha", float(got["theta_tfin_over_alpha"]), sim["theta_tfin_over_alpha"]),
          ("max_theta_input_over_alpha", float(got["max_theta_input_over_alpha"]), sim["max_theta_input_over_alpha"]),
          ("t_overturn", float(got["t_overturn"]), sim["t_overturn"]),
          ("impacts", int(got["impacts"]), sim["impacts"]),
          ("collapse_overturning", got["collapse_overturning"] == "true", sim["collapse_overturning"])]
bad = [c for c in checks if c[1] != c[2]]
# Eq. 27 in closed form against the engine: another formula, 1e-13 relative.
if abs(float(got["q2_n6"]) - q["q"]) > 1e-13 * q["q"]:
    bad.append(("q2_n6", float(got["q2_n6"]), q["q"]))
for name, a, e in bad:
    print("consumer %s = %r, rocking --json %r" % (name, a, e))
sys.exit(1 if bad or len(checks) != 6 else 0)
PY

if [ "$python_module" = ON ]; then
    PYTHONPATH="$prefix/$pydir" PYTHONDONTWRITEBYTECODE=1 "$py" - "$prefix" "$tmp/q.json" "$tmp/simulate.json" <<'PY' ||
import json, os, sys
import rocking_q
prefix = os.path.realpath(sys.argv[1])
assert os.path.realpath(rocking_q.__file__).startswith(prefix + os.sep), rocking_q.__file__
q = json.load(open(sys.argv[2]))
sim = json.load(open(sys.argv[3]))
assert rocking_q.q(0.5, case=2, pulses=6) == q["q"], (rocking_q.q(0.5, case=2, pulses=6), q["q"])
r = rocking_q.simulate(case=2, x=0.5, rd=0.9, alpha=0.15, p=2, dt=None)
for key, value in sim.items():
    assert r[key] == value, (key, r[key], value)
print("the installed module %s agrees with the installed rocking" % rocking_q.__file__)
PY
        fail "the installed Python module does not import from the prefix or differs"
else
    echo "install_test: the Python module was not built (no pybind11): its installation is not checked"
fi
echo "install_test: installed into a prefix, the consumer built and ran, its values are rocking's"
