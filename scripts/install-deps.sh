#!/usr/bin/env bash
# Installs everything hslam needs to build, test and run on Debian 12
# (bookworm), from Debian packages only. Safe to run again.
set -euo pipefail

packages=(
  build-essential cmake
  libmrpt-dev mrpt-apps mrpt-common   # MRPT 2.5: libraries, rawlog-edit/icp-slam, sample datasets
  libopencv-dev libeigen3-dev zlib1g-dev
  libgtest-dev libbenchmark-dev
  python3                             # scripts/compare-carmen.sh (rawlog rewriting for rbpf-slam)
  clang-14 libfuzzer-14-dev           # scripts/sanitize-and-fuzz.sh: ASan/UBSan build and libFuzzer targets
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -q
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
