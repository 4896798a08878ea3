#!/usr/bin/env bash
# Installs what is needed, builds (Release) and runs the whole test suite under CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
ctest --preset release --timeout 600 -j2
