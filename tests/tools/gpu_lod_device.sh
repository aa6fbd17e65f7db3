#!/bin/bash
# The GPU LOD path (docs/gpu_lod.md) on a machine with a GPU driver but no compiler: `fftess sweep` with
# --gpu-hardware for every built-in scheme (lod.evaluate = "gpu": the GPU build's factors checked, compared with the
# C++ build) and for the two example shaders (GLSL, HLSL), with and without the pow2 clamp. The binaries and the
# shared libraries the host lacks come prebuilt in DIST (fftess, glslangValidator, spirv-cross, lib/):
#   mkdir -p build-gpudev/dist/lib && cp build/fftess /usr/bin/glslangValidator /usr/bin/spirv-cross build-gpudev/dist/
#   cp -L /usr/lib/x86_64-linux-gnu/{libEGL.so.1,libGLdispatch.so.0,libmpfr.so.6,libgmp.so.10,libtomlplusplus.so.3} \
#     build-gpudev/dist/lib/
#   tests/tools/gpu_lod_device.sh OUTDIR [DIST] [EXTRA fftess options, e.g. --gpu-hardware]
set -u
out=${1:?OUTDIR}; dist=${2:-build-gpudev/dist}; shift 2 || shift $#
extra=("$@")
mkdir -p "$out"
export LD_LIBRARY_PATH=$PWD/$dist/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export PATH=$PWD/$dist:$PATH
{ nvidia-smi --query-gpu=name,driver_version --format=csv 2>/dev/null; uname -r; grep PRETTY /etc/os-release; nproc; } > "$out/env.txt" 2>&1
run() { # NAME ARGS...
  local name=$1; shift
  { time "$dist/fftess" sweep "$@" "${extra[@]}" > "$out/$name.txt" 2>&1; } 2> "$out/$name.time"
}
for scheme in screen_sphere distance_pow2 bonaventura clip_diameter constant; do
  run "builtin_${scheme}_rings" docs/examples/rings_small.toml --set lod.evaluate=gpu --set lod.scheme=$scheme
  run "builtin_${scheme}_terrain" docs/examples/terrain.toml --set lod.evaluate=gpu --set lod.scheme=$scheme
done
run builtin_patch_center_grid docs/examples/grid.toml --set lod.evaluate=gpu --set lod.scheme=patch_center
for clamp in pow2 none; do
  run "glsl_$clamp" docs/examples/gpu_distance_glsl.toml --set lod.adjacency_clamp=$clamp
  run "hlsl_$clamp" docs/examples/gpu_sphere_hlsl.toml --set lod.adjacency_clamp=$clamp
done
run cpu_terrain docs/examples/terrain.toml
