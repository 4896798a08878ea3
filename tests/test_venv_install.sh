#!/usr/bin/env bash
# The Python package installs into a virtual environment the way docs/python.md says
# (issue 29): `python3 -m venv --system-site-packages` and `pip install --no-build-isolation`,
# nothing downloaded (--no-index), then imported and run from the environment, its stubs and
# marker installed beside it. The compiled part is the module this build made
# (ELASTIC_LAB_PREBUILT_CORE, setup.py), so the test costs seconds; building it through
# setup.py from scratch is the same CMake build as the project's (docs/python.md: measured).
#   test_venv_install.sh SOURCE_DIR PYTHON CORE_SO
set -euo pipefail
src=$1 python=$2 core=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# A copy of what the package is built from (pip builds in the source tree: keep it clean).
mkdir -p "$work/src"
cp "$src/pyproject.toml" "$src/setup.py" "$src/README.md" "$src/CMakeLists.txt" "$work/src/"
cp -r "$src/python" "$work/src/python"
"$python" -m venv --system-site-packages "$work/venv"
ELASTIC_LAB_PREBUILT_CORE=$core "$work/venv/bin/pip" install --quiet --no-build-isolation --no-index "$work/src"
cd "$work"
"$work/venv/bin/python" - "$work/venv" <<'PY'
import inspect, pathlib, sys
import elasticlab as el
venv = pathlib.Path(sys.argv[1]).resolve()
here = pathlib.Path(el.__file__).resolve().parent
assert venv in here.parents, f"imported from {here}, not from the environment {venv}"
for name in ("py.typed", "_core.pyi"):
    assert (here / name).exists(), f"{name} not installed"
assert list(here.glob("_core*.so")), "the compiled module is not installed"
sim = el.Simulation("ring2d")
rows = sim.run(duration=0.3)
assert abs(sim.time - 0.3) < 1e-9 and len(rows) > 0, (sim.time, len(rows))
assert "duration" in inspect.signature(el.sweep).parameters
print("installed into", venv, "and ran ring2d to t =", sim.time)
PY
