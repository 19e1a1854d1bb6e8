#!/usr/bin/env bash
# tetglow set-up on Debian: installs the missing packages, builds, then runs one job.
#   ./setup.sh demo   render the glowing fish (scenes/fish.json) into out/
#   ./setup.sh test   run the whole test suite
#   ./setup.sh build  only install and build
#   ./setup.sh sanitizers  only install, adding clang with its sanitizer and libFuzzer runtimes
#                          (for .ci/sanitize.sh and fuzz/run.sh, which build in their own folders)
set -euo pipefail
cd "$(dirname "$0")"
job=${1:-build}
case "$job" in demo|test|build|sanitizers) ;; *) echo "usage: $0 demo|test|build|sanitizers" >&2; exit 2 ;; esac

packages=(g++ cmake make pkg-config libtet1.5-dev libcgal-dev libboost-dev libembree-dev libopenexr-dev libglm-dev libtbb-dev nlohmann-json3-dev
          libcli11-dev libnanoflann-dev libpng-dev libassimp-dev libdraco-dev libcpp-httplib-dev libgtest-dev libbenchmark-dev gnuplot-nox pngquant python3)
# Only the tests need these: tetglow preview's page is tested in headless Chromium, tetglow farm
# through a real Slurm on localhost (tests/slurm); the sanitized suite and the fuzzers need clang,
# and ccache keeps the sanitized build that CI compiles from each clean clone. Blender is tested
# itself: the add-on renders its scenes (tests/blender, numpy for the image comparisons), and its
# glTF exporter writes a scene that tetglow reads (tests/test_gltf_blender.cpp).
test_packages=(chromium chromium-driver python3-selenium slurmctld slurmd slurm-client munge clang-format
               blender python3-numpy)
case "$job" in
  test) packages+=("${test_packages[@]}") ;;
  sanitizers) packages+=("${test_packages[@]}" clang libclang-rt-14-dev ccache) ;;
esac
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
[ "$job" = sanitizers ] && exit 0  # the sanitizer build has its own folder (.ci/sanitize.sh)

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
