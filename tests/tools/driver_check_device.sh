#!/bin/bash
# `fftess driver-check --hardware` through GL and Vulkan on a machine with a GPU driver but no compiler (docs/compare.md
# "fftess driver-check", "Vulkan", "--port-bug"): for each API the order-free capture of N random patches against the
# reference (denormals kept), the same JSON, then a run per simulated port bug (each must be named), and GL
# --strict-order (expected on a driver with its own order: exit 3 with the reason). The binary and the shared
# libraries the host lacks come prebuilt in DIST:
#   mkdir -p build-dc/dist/lib && cp build/fftess build-dc/dist/
#   cp -L /usr/lib/x86_64-linux-gnu/{libEGL.so.1,libGLdispatch.so.0,libvulkan.so.1,libmpfr.so.6,libgmp.so.10,libtomlplusplus.so.3,libspirv-cross-c-shared.so.0,libtinygltf.so.2d,libstb.so.0} \
#     build-dc/dist/lib/          (check with `ldd build/fftess`; libvulkan.so.1 is opened at run time)
#   tests/tools/driver_check_device.sh OUTDIR [DIST [N [SEED [BUG_PATCHES]]]]
# NVIDIA's EGL vendor and Vulkan ICD files are looked for in the usual places (FFTESS_EGL_VENDOR, VK_DRIVER_FILES
# override). Every report's first line names the renderer: it must be the GPU's, not llvmpipe / lavapipe.
set -u
out=${1:?OUTDIR}; dist=${2:-build-dc/dist}; n=${3:-20000}; seed=${4:-1}; nbug=${5:-2000}
mkdir -p "$out"
export LD_LIBRARY_PATH=$PWD/$dist/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
for f in /usr/share/glvnd/egl_vendor.d/10_nvidia.json /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json; do
  [ -f "$f" ] && : "${FFTESS_EGL_VENDOR:=$f}"
done
export __EGL_VENDOR_LIBRARY_FILENAMES=${FFTESS_EGL_VENDOR:-/usr/share/glvnd/egl_vendor.d/10_nvidia.json}
if [ -z "${VK_DRIVER_FILES:-}" ] && [ -f /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json ] &&
   [ ! -f /usr/share/vulkan/icd.d/nvidia_icd.json ] && [ ! -f /etc/vulkan/icd.d/nvidia_icd.json ]; then
  export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
fi
{ nvidia-smi --query-gpu=name,driver_version --format=csv 2>/dev/null; uname -r; grep PRETTY /etc/os-release; nproc
  echo "EGL vendor: $__EGL_VENDOR_LIBRARY_FILENAMES; VK_DRIVER_FILES=${VK_DRIVER_FILES:-}"; } > "$out/env.txt" 2>&1
dc() { # API NAME ARGS...: one driver-check, its stdout in NAME.txt, stderr + time + exit status in NAME.err
  local api=$1 name=$2; shift 2
  { time "$dist/fftess" driver-check --api "$api" --hardware "$@" > "$out/$name.txt" 2> "$out/$name.err"; } \
    2>> "$out/$name.err"
  echo "exit $?" >> "$out/$name.err"
}
bugs=(outer_factors_rotated:1 outer_factors_rotated:3 outer_factors_mirrored:1 outer_factors_mirrored:2
      outer_factors_v_flipped domain_v_flipped uv_swapped inside_factors_swapped tri_barycentrics_permuted:1
      winding_swapped pow2_as_fractional_even denormals_flushed isoline_factors_swapped)
for api in gl vulkan; do
  dc "$api" "$api" --random "$n" --seed "$seed" --show 3
  dc "$api" "${api}_json" --random "$n" --seed "$seed" --json
  for b in "${bugs[@]}"; do
    dc "$api" "bug_${api}_${b/:/_}" --random "$nbug" --seed "$seed" --show 0 --port-bug "$b"
  done
done
dc gl strict --random 300 --seed "$seed" --strict-order --show 1
# Few files come back: the port-bug runs and the strict run folded into one file, each with its last lines.
for f in "$out"/bug_*.txt "$out"/strict.txt; do
  echo "=== $(basename "$f" .txt)"; head -2 "$f"; tail -4 "$f"; tail -2 "${f%.txt}.err"
done > "$out/bugs.txt"
for f in gl vulkan gl_json vulkan_json; do cat "$out/$f.err"; done > "$out/runs.err"
rm -f "$out"/bug_*.txt "$out"/bug_*.err "$out"/strict.txt "$out"/strict.err "$out"/*.err.tmp
rm -f "$out"/gl.err "$out"/vulkan.err "$out"/gl_json.err "$out"/vulkan_json.err
