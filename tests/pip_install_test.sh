#!/usr/bin/env bash
# `pip install .` (issue 42): into a virtual environment that sees Debian's packages,
# offline (--no-build-isolation --no-index: only setuptools and numpy from Debian), the
# module built by the project's CMake in BUILD (the tree ctest runs in, so that nothing
# is compiled twice), then imported from outside the sources: its file must be the
# environment's copy, and its numbers the build tree's.
#
#   tests/pip_install_test.sh SOURCE BUILD
set -u
source_dir="$1"
build_dir="$2"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$tmp/v" || { echo "FAIL: python3 -m venv (apt-get install python3-venv)"; exit 1; }
if ! ROCKING_BUILD_DIR="$build_dir" PIP_NO_CACHE_DIR=1 "$tmp/v/bin/pip" install -q --no-build-isolation --no-index \
        "$source_dir" >"$tmp/pip.log" 2>&1; then
    cat "$tmp/pip.log"
    echo "FAIL: pip install --no-build-isolation ."
    exit 1
fi
cd "$tmp" || exit 1
if "$tmp/v/bin/python" - "$tmp/v" "$build_dir/python" <<'PY'
import os, subprocess, sys
import rocking_q
venv, tree = sys.argv[1], sys.argv[2]
assert os.path.realpath(rocking_q.__file__).startswith(os.path.realpath(venv)), rocking_q.__file__
# The same numbers as the build tree's module, run by the system interpreter.
mine = repr((rocking_q.q2_n6(1.0), rocking_q.q(case=2, x=0.7)))
theirs = subprocess.run(["/usr/bin/python3", "-c", "import rocking_q as r; print(repr((r.q2_n6(1.0), r.q(case=2, x=0.7))))"],
                        env={**os.environ, "PYTHONPATH": tree}, capture_output=True, text=True, check=True).stdout.strip()
assert mine == theirs, (mine, theirs)
print("ok: import rocking_q from", rocking_q.__file__)
PY
then :; else echo "FAIL: import rocking_q in the environment"; exit 1; fi
"$tmp/v/bin/pip" show -q rocking_q >/dev/null || { echo "FAIL: pip does not list rocking_q"; exit 1; }
echo "ok: pip install . into a virtual environment"
