#!/usr/bin/env bash
# Installs the Debian 12 packages Elastic Lab needs to build, test and run (skips when present).
# help2man makes the man pages; dpkg-dev (dpkg-shlibdeps), desktop-file-utils and appstream are
# for the .deb and its test (packaging/).
# --cross also installs the AArch64 cross compiler and the user-mode emulator that
# scripts/check-aarch64.sh needs (not for the build, the tests or CI).
set -euo pipefail
packaging=(help2man dpkg-dev desktop-file-utils appstream)
cross=(g++-aarch64-linux-gnu qemu-user)
optional=()
for arg in "$@"; do
  case "$arg" in
    --cross) optional+=("${cross[@]}") ;;
    *) echo "usage: $0 [--cross]" >&2; exit 2 ;;
  esac
done
packages=(g++ cmake ninja-build qt6-base-dev libqt6opengl6-dev libeigen3-dev libqcustomplot-dev
          xvfb xauth libbenchmark-dev nlohmann-json3-dev libcli11-dev stress-ng ccache
          pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib libsundials-dev
          python3-pandas python3-dask python3-distributed python3-tqdm python3-venv python3-setuptools python3-wheel)
missing=()
for p in "${packages[@]}" "${packaging[@]}" "${optional[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  # With recommends, as the packages were installed where this was tested.
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
fi
