#!/usr/bin/env bash
# Builds the whole suite twice more, with AddressSanitizer + UndefinedBehaviorSanitizer and with
# ThreadSanitizer (CMake presets asan and tsan), and runs it under CTest. scripts/test.sh runs
# this after the Release suite; docs/reliability.md says what the sanitizers found and which
# reports are suppressed (only Qt's own, see tests/tsan.supp).
set -euo pipefail
cd "$(dirname "$0")/.."
for preset in asan tsan; do
  cmake --preset "$preset" -DELASTIC_LAB_BUILD_BENCH=OFF
  cmake --build --preset "$preset"
  # --timeout is a hang guard per test (the slowest takes about 1 min under TSan, idle).
  ctest --preset "$preset" --timeout 1800 -j2
done
