#!/bin/bash
# The GPU LOD path (docs/gpu_lod.md) on a machine with a GPU driver but no compiler: `fftess sweep` with
# --gpu-hardware for every built-in scheme (lod.evaluate = "gpu": the GPU build's factors checked, compared with the
# C++ build) and for the two example shaders (GLSL, HLSL), with and without the pow2 clamp. The binaries and the
# shared libraries the host lacks come prebuilt in DIST (fftess, glslangValidator, spirv-cross, lib/):
#   mkdir -p build-gpudev/dist/lib && cp build/fftess /usr/bin/glslangValidator /usr/bin/spirv-cross build-gpudev/dist/
#   cp -L /usr/lib/x86_64-linux-gnu/{libEGL.so.1,libGLdispatch.so.0,libmpfr.so.6,libgmp.so.10,libtomlplusplus.so.3,libspirv-cross-c-shared.so.0} \
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
if [ -z "${HULL_ONLY:-}" ]; then # HULL_ONLY=1: only the hull shaders' part below
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
fi
# Hull shaders as written (docs/examples/hull; docs/gpu_lod.md "Your hull shader as written"): each example's verdict
# on 200 flyover cameras, and with the nearest built-in scheme as the C++ reference (the factor drift); the TCS /
# lodMain twin; the negative fixtures' diagnostics on this driver (the columns come from its compiler).
near() { # EXAMPLE LAYOUT: the --set arguments of the nearest built-in scheme (docs/examples/hull/README.md)
  local far=120; [ "$2" = rings ] && far=200
  case $1 in
    distance) echo "--set lod.scheme=distance_pow2 --set lod.min_distance=4 --set lod.max_distance=$far" ;;
    terrain_hs) echo "--set lod.scheme=distance_pow2 --set lod.min_distance=4 --set lod.max_distance=$far --set lod.min_tess=0 --set lod.max_tess=6 --set lod.frustum_cull=true" ;;
    *) echo "--set lod.scheme=screen_sphere --set lod.target_pixels=8 --set lod.min_factor=1 --set lod.max_factor=64" ;;
  esac
}
for ex in distance frustum_heightmap tile_point terrain_hs; do
  for layout in grid rings; do
    run "hull_${ex}_${layout}" "docs/examples/hull/${ex}_${layout}.toml"
    # shellcheck disable=SC2046
    run "hull_${ex}_${layout}_near" "docs/examples/hull/${ex}_${layout}.toml" $(near $ex $layout)
  done
done
run hull_twin_tcs tests/oracle/data/hull/twin_tcs.toml --flyover 40
run hull_twin_lodmain tests/oracle/data/hull/twin_lodmain.toml --flyover 40
for bad in unbound_uniform missing_sampler partitioning_contradicts wrong_entry syntax_error include_error include_missing; do
  "$dist/fftess" check "tests/oracle/data/hull/$bad.toml" "${extra[@]}" > "$out/hull_bad_$bad.txt" 2>&1
  echo "exit $?" >> "$out/hull_bad_$bad.txt"
done
