#!/usr/bin/env bash
# fftess setup: installs the Debian 12 packages fftess needs (when missing), builds, and runs.
#   bash setup.sh run    install, build, run the main job (crack sweep of the bundled default scene, twice)
#   bash setup.sh test   install, build, run the whole test suite (ctest), then a second build with ASan+UBSan
#                        (build-sanitize/, without the GL/Vulkan modules: -DFFTESS_GPU=OFF) and the tests not labelled
#                        slow under it (SANITIZE=full: with the GL/Vulkan modules and their llvmpipe/lavapipe tests)
#   bash setup.sh build  install and build only
#   bash setup.sh fuzz   also install clang; build both libFuzzer targets (build-fuzz/) and run each on its seed
#                        corpus for FUZZ_RUNS inputs (default 100000). CI does not run this: its short fuzz run is
#                        the replay ctests (test_*_fuzz_replay: corpus + fixed mutations), which the sanitizer build of
#                        `test` runs under ASan+UBSan with g++.
# Environment: BUILD_DIR (default build), BUILD_TYPE (default Release), JOBS (default: all cores),
#   SANITIZE (default 1; 0 skips the sanitizer build of `test`; full: with the GL/Vulkan modules),
#   SANITIZE_DIR (default build-sanitize).
set -euo pipefail
cd "$(dirname "$0")"

mode=${1:-run}
BUILD_DIR=${BUILD_DIR:-build}
BUILD_TYPE=${BUILD_TYPE:-Release}
JOBS=${JOBS:-$(nproc)}
SANITIZE=${SANITIZE:-1}
SANITIZE_DIR=${SANITIZE_DIR:-build-sanitize}

packages=(
  g++ cmake ninja-build
  catch2 libcli11-dev libglm-dev libcgal-dev nlohmann-json3-dev libtomlplusplus-dev libbenchmark-dev libtinygltf-dev
  glslang-tools spirv-cross glslang-dev libspirv-cross-c-shared-dev
  libegl-dev libgl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri
  libvulkan-dev mesa-vulkan-drivers
  pybind11-dev python3-dev python3-numpy python3-pytest python3-pip python3-setuptools python3-wheel
  python3 python3-jsonschema
)

install_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all ${#packages[@]} packages present"
    return
  fi
  echo "setup: installing ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  # The Python module (python/) for Debian's python3, whose packages the list above installs (not a python3 that comes
  # first on PATH, e.g. pyenv's).
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE="$BUILD_TYPE" -DPython3_EXECUTABLE=/usr/bin/python3
  cmake --build "$BUILD_DIR" -j "$JOBS"
}

# The fast tests (ctest -LE slow) again, built with AddressSanitizer and UndefinedBehaviorSanitizer (any report fails
# the test: -fno-sanitize-recover=all). No benchmarks in this build.
sanitize_tests() {
  echo "setup: sanitizer build ($SANITIZE_DIR, address,undefined) and the tests not labelled slow"
  # -g1: line tables only (symbolised sanitizer stacks, a third less compile time for the CGAL files than -g).
  # -O1: a third less compile time than -O2 under ASan+UBSan (the build is most of this job; the tests are not).
  # The GL/Vulkan modules (gl/, gpu_lod/, vk/) and their tests on Mesa's software drivers are left out here
  # (SANITIZE=full keeps them): half of this build's compile time and of its test time, for the code that the
  # Release suite above already runs on llvmpipe and lavapipe. CI's time goal is 10 minutes on 2 cores.
  local gpu=OFF
  [ "$SANITIZE" = full ] && gpu=ON
  cmake -S . -B "$SANITIZE_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFFTESS_SANITIZE=address,undefined \
    -DFFTESS_BENCHMARKS=OFF -DFFTESS_GPU=$gpu "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
  cmake --build "$SANITIZE_DIR" -j "$JOBS"
  # A sanitizer report ends a program with exit status 1 by default, which is also fftess's "findings" status: 86
  # instead, so a test that runs the fftess binary and expects 1 fails on a report (tests/cli also reads the report).
  ASAN_OPTIONS=exitcode=86 UBSAN_OPTIONS=print_stacktrace=1:exitcode=86 \
    ctest --test-dir "$SANITIZE_DIR" --output-on-failure -j "$JOBS" -LE slow
}

fuzz() {
  packages+=(clang libclang-rt-14-dev)
  install_packages
  cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
    -DCMAKE_CXX_COMPILER=clang++ -DFFTESS_FUZZ=ON -DFFTESS_TESTS=OFF -DFFTESS_BENCHMARKS=OFF
  cmake --build build-fuzz -j "$JOBS" --target fuzz_tessellator fuzz_scene
  local runs=${FUZZ_RUNS:-100000} work
  work=$(mktemp -d)
  cp tessellator/fuzz_corpus/* "$work"/ 2>/dev/null || true
  build-fuzz/tessellator/fuzz_tessellator -runs="$runs" "$work"
  rm -rf "$work" && work=$(mktemp -d)
  cp verify/fuzz_corpus/* "$work"/
  build-fuzz/verify/fuzz_scene -runs="$runs" -timeout=20 -rss_limit_mb=4096 "$work"
  rm -rf "$work"
}

case "$mode" in
  fuzz)
    fuzz
    ;;
  build)
    install_packages
    build
    ;;
  run)
    install_packages
    build
    scene=docs/examples/terrain.toml
    echo
    echo "== fftess sweep $scene  (NVIDIA terrain sample setup, power-of-two workaround on) =="
    set +e
    "$BUILD_DIR/fftess" sweep "$scene"
    on=$?
    echo
    echo "== fftess sweep $scene --set lod.adjacency_clamp=none  (workaround off) =="
    "$BUILD_DIR/fftess" sweep "$scene" --set lod.adjacency_clamp=none
    off=$?
    set -e
    echo
    echo "exit status: workaround on = $on (0 = watertight), workaround off = $off (1 = cracks found)"
    [ "$on" -le 1 ] && [ "$off" -le 1 ]
    ;;
  test)
    install_packages
    build
    ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS"
    if [ "$SANITIZE" != 0 ]; then sanitize_tests; fi
    ;;
  *)
    echo "usage: bash setup.sh [run|test|build|fuzz]" >&2
    exit 2
    ;;
esac
