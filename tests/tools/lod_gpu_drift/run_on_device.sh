#!/bin/bash
# Runs the GLSL-versus-C++ LOD drift measurement on a machine with an NVIDIA GPU and driver but no compiler and no
# libEGL.so.1 loader: the binary and glvnd's libEGL.so.1 + libGLdispatch.so.0 come prebuilt in build-lodgpu/dist
# (see README.md).
#   tests/tools/lod_gpu_drift/run_on_device.sh OUTDIR [CASES [SEED]]
# Writes OUTDIR/env.txt and one OUTDIR/<variant>.txt per shader variant.
set -u
out=${1:?OUTDIR}; cases=${2:-1000000}; seed=${3:-1}
dist=build-lodgpu/dist
mkdir -p "$out"
# NVIDIA's EGL vendor only (glvnd), whatever else is installed.
export LD_LIBRARY_PATH=$PWD/$dist/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export __EGL_VENDOR_LIBRARY_FILENAMES=${FFTESS_EGL_VENDOR:-/usr/share/glvnd/egl_vendor.d/10_nvidia.json}
{ nvidia-smi --query-gpu=name,driver_version --format=csv; uname -r; grep PRETTY /etc/os-release; ldd --version | head -1; } > "$out/env.txt" 2>&1
run() { # NAME ARGS...
  local name=$1; shift
  { time "$dist/fftess_lod_gpu_drift" "$@" > "$out/$name.txt"; } 2> "$out/$name.err"
  echo "exit $?" >> "$out/$name.err"
}
run plain --examples 6 "$cases" "$seed"
run precise --examples 6 --precise "$cases" "$seed"
run precise_nvpragmas --examples 6 --precise --nv-pragmas "$cases" "$seed"
run plain_seed2 --examples 0 "$cases" 2
