#!/usr/bin/env bash
# Installs the Debian 12 packages Elastic Lab needs to build, test and run (skips when present).
# help2man makes the man pages; dpkg-dev (dpkg-shlibdeps), desktop-file-utils and appstream are
# for the .deb and its test (packaging/); shared-mime-info compiles the scene files' MIME type there.
# universal-ctags reads the function lengths for the test long_functions (scripts/long-functions.sh).
# --cross also installs the AArch64 cross compiler and the user-mode emulator that
# scripts/check-aarch64.sh needs (not for the build, the tests or CI).
set -euo pipefail
packaging=(help2man dpkg-dev desktop-file-utils appstream shared-mime-info)
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
          pkgconf libxlsxwriter-dev python3-openpyxl
          qt6-tools-dev qt6-l10n-tools qt6-translations-l10n
          python3-pandas python3-dask python3-distributed python3-tqdm python3-venv python3-setuptools python3-wheel
          libbullet-dev qt6-svg-dev universal-ctags)
missing=()
for p in "${packages[@]}" "${packaging[@]}" "${optional[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  # A package lock held by another apt (a desktop's automatic updates, often right after the
  # first login) is waited for, up to 15 minutes, instead of failing at once.
  lock_wait=(-o DPkg::Lock::Timeout=900)
  held() { fuser /var/lib/dpkg/lock-frontend /var/lib/dpkg/lock /var/lib/apt/lists/lock >/dev/null 2>&1; }
  if command -v fuser >/dev/null && held; then echo "install-deps.sh: waiting for another package manager to finish..." >&2; fi
  $sudo apt-get "${lock_wait[@]}" update -qq
  # With recommends, as the packages were installed where this was tested.
  DEBIAN_FRONTEND=noninteractive $sudo apt-get "${lock_wait[@]}" install -y -qq "${missing[@]}"
fi
