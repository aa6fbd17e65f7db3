#!/bin/bash
# `fftess driver-check --hardware` on a machine with a GPU driver but no compiler (docs/compare.md "fftess
# driver-check", docs/oracle.md "Real hardware"): the order-free capture on the GPU (random patches, the reference
# with denormals kept), the same with --flush-denormals, and --strict-order (expected: exit 3 with the reason on a
# driver with its own order). The binary and the shared libraries the host lacks come prebuilt in DIST:
#   mkdir -p build-dc/dist/lib && cp build/fftess build-dc/dist/
#   cp -L /usr/lib/x86_64-linux-gnu/{libEGL.so.1,libGLdispatch.so.0,libmpfr.so.6,libgmp.so.10,libtomlplusplus.so.3,libspirv-cross-c-shared.so.0,libtinygltf.so.2d,libstb.so.0} \
#     build-dc/dist/lib/          (check with `ldd build/fftess`)
#   tests/tools/driver_check_device.sh OUTDIR [DIST [PATCHES [SEED [EXTRA fftess options, e.g. --api vulkan]]]]
# NVIDIA's EGL vendor only (glvnd), whatever else is installed; FFTESS_EGL_VENDOR overrides the vendor file. The
# report's first line names the renderer: it must be the GPU's, not llvmpipe.
set -u
out=${1:?OUTDIR}; dist=${2:-build-dc/dist}; n=${3:-20000}; seed=${4:-1}; shift 4 || shift $#
extra=("$@")
mkdir -p "$out"
export LD_LIBRARY_PATH=$PWD/$dist/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export __EGL_VENDOR_LIBRARY_FILENAMES=${FFTESS_EGL_VENDOR:-/usr/share/glvnd/egl_vendor.d/10_nvidia.json}
{ nvidia-smi --query-gpu=name,driver_version --format=csv 2>/dev/null; uname -r; grep PRETTY /etc/os-release; nproc; } > "$out/env.txt" 2>&1
run() { # NAME ARGS...
  local name=$1; shift
  { time "$dist/fftess" driver-check --hardware --random "$n" --seed "$seed" "$@" "${extra[@]}" \
      > "$out/$name.txt" 2> "$out/$name.err"; } 2> "$out/$name.time"
  echo "exit $?" >> "$out/$name.time"
}
run reference --show 5
run reference_json --json
run flush_denormals --flush-denormals --show 5
run strict_order --strict-order --show 5
