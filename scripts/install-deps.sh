#!/usr/bin/env bash
# Installs the Debian 12 packages Elastic Lab needs to build, test and run (skips when present).
# help2man makes the man pages; dpkg-dev (dpkg-shlibdeps), desktop-file-utils and appstream are
# for the .deb and its test (packaging/).
set -euo pipefail
packaging=(help2man dpkg-dev desktop-file-utils appstream)
packages=(g++ cmake ninja-build qt6-base-dev libqt6opengl6-dev libeigen3-dev libqcustomplot-dev
          xvfb xauth libbenchmark-dev nlohmann-json3-dev libcli11-dev stress-ng ccache
          pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib libsundials-dev)
missing=()
for p in "${packages[@]}" "${packaging[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  # With recommends, as the packages were installed where this was tested.
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
fi
