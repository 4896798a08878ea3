#!/usr/bin/env bash
# Installs what is needed, builds (Release) what it starts and starts Elastic Lab on its default
# scene: the GUI and the libraries it links (with the CLI when the GUI is not built), not the
# tests, fuzzers or benchmarks (scripts/test.sh builds those). Arguments go to the program.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release
if grep -q '^ELASTIC_LAB_BUILD_GUI:BOOL=ON' build/release/CMakeCache.txt; then
  cmake --build --preset release --target elastic-lab
  exec build/release/app/gui/elastic-lab "$@"
fi
cmake --build --preset release --target elastic-lab-cli
exec build/release/app/cli/elastic-lab-cli run --scene ring2d "$@"
