#!/usr/bin/env bash
# Installs everything hslam needs to build, test and run on Debian 12
# (bookworm), from Debian packages only. Safe to run again.
set -euo pipefail

packages=(
  build-essential cmake
  libmrpt-dev mrpt-apps mrpt-common   # MRPT 2.5: libraries, rawlog-edit/icp-slam, sample datasets
  libmrpt-nav-dev                     # MRPT reactive navigation: the peer of hslam-bench nav
  libopencv-dev libeigen3-dev zlib1g-dev
  libgtest-dev libbenchmark-dev
  python3                             # scripts/compare_slam.py and its test (standard library only), batch summary
  chromium                            # tests/packaging: report.html in a real (headless) browser
  help2man                            # man pages of the apps, generated from --help
  parallel                            # scripts/batch-process.sh (falls back to xargs -P without it)
  dpkg-dev file                       # cpack -G DEB: dpkg-shlibdeps computes Depends:
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
