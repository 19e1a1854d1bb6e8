#!/usr/bin/env bash
# tetglow set-up on Debian: installs the missing packages, builds, then runs one job.
#   ./setup.sh demo   render the glowing fish (scenes/fish.json) into out/
#   ./setup.sh test   run the whole test suite
#   ./setup.sh build  only install and build
set -euo pipefail
cd "$(dirname "$0")"
job=${1:-build}
case "$job" in demo|test|build) ;; *) echo "usage: $0 demo|test|build" >&2; exit 2 ;; esac

packages=(g++ cmake make pkg-config libtet1.5-dev libembree-dev libopenexr-dev libglm-dev libtbb-dev nlohmann-json3-dev
          libcli11-dev libnanoflann-dev libpng-dev libcpp-httplib-dev libgtest-dev libbenchmark-dev gnuplot-nox python3)
# Only the tests need these: tetglow preview's page is tested in headless Chromium, tetglow farm
# through a real Slurm on localhost (tests/slurm).
test_packages=(chromium chromium-driver python3-selenium slurmctld slurmd slurm-client munge)
[ "$job" = test ] && packages+=("${test_packages[@]}")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

jobs=$(nproc)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$jobs"

case "$job" in
  demo)
    build/tetglow render scenes/fish.json -o out/fish.exr
    echo "demo: out/fish.exr (linear HDR) and out/fish.png (preview)"
    ;;
  test)
    ctest --test-dir build --output-on-failure -j "$jobs"
    ;;
esac
