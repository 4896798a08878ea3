#!/usr/bin/env bash
# Installs what is needed, builds (Release) and runs the whole test suite under CTest, then the
# same suite under AddressSanitizer + UBSan and under ThreadSanitizer (scripts/sanitize.sh).
# ELASTIC_LAB_SKIP_SANITIZERS=1 stops after the Release suite (a quicker local check).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
ctest --preset release --timeout 600 -j2
if [ "${ELASTIC_LAB_SKIP_SANITIZERS:-0}" != 1 ]; then
  scripts/sanitize.sh
fi
