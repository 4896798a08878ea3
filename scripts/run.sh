#!/usr/bin/env bash
# Installs what is needed, builds (Release) and starts Elastic Lab on its default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
if [ -x build/release/app/gui/elastic-lab ]; then
  exec build/release/app/gui/elastic-lab "$@"
fi
exec build/release/app/cli/elastic-lab-cli run --scene ring2d "$@"
