#!/bin/bash
# Runs the NVIDIA comparison on a machine with an NVIDIA GPU and driver but no compiler and no libEGL.so.1 loader:
# the binaries and glvnd's libEGL.so.1 + libGLdispatch.so.0 come prebuilt in build-nv/dist (see README.md).
#   tests/tools/nvidia_compare/run_on_device.sh OUTDIR [RANDOM_PATCHES [SEED]]
# Writes OUTDIR/*.txt: the environment, the unchanged oracle's behaviour on NVIDIA, the comparisons.
set -u
out=${1:?OUTDIR}; big=${2:-1000000}; seed=${3:-1}
dist=build-nv/dist
mkdir -p "$out"
# NVIDIA's EGL vendor only (glvnd), whatever else is installed.
export LD_LIBRARY_PATH=$PWD/$dist/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export __EGL_VENDOR_LIBRARY_FILENAMES=${FFTESS_EGL_VENDOR:-/usr/share/glvnd/egl_vendor.d/10_nvidia.json}
{ nvidia-smi --query-gpu=name,driver_version --format=csv; uname -r; grep PRETTY /etc/os-release; } > "$out/env.txt" 2>&1

# 1. The llvmpipe oracle itself with --any-renderer: does its order-based harness accept the NVIDIA driver?
"$dist/fftess_gl_oracle" --any-renderer tests/oracle/data/example.batch > "$out/oracle_example.out" 2> "$out/oracle_example.err"
echo "exit $?" >> "$out/oracle_example.err"
"$dist/fftess_nvidia_compare" gen --no-sweep 2000 5 > "$out/gen2000.batch"
"$dist/fftess_gl_oracle" --any-renderer "$out/gen2000.batch" > /dev/null 2> "$out/oracle_gen2000.err"
echo "exit $?" >> "$out/oracle_gen2000.err"
grep -E ' point hw| line hw' "$out/gen2000.batch" | grep -v '^isoline [a-z0-9_]* line' > "$out/gen2000_pointonly.batch"
"$dist/fftess_gl_oracle" --any-renderer "$out/gen2000_pointonly.batch" > "$out/oracle_pointonly.out" 2> "$out/oracle_pointonly.err"
echo "exit $?" >> "$out/oracle_pointonly.err"
head -c 200000 "$out/oracle_pointonly.out" > "$out/oracle_pointonly_head.out"; rm -f "$out/oracle_pointonly.out"

# 2. The comparison: the llvmpipe ctest's patches (sweep + 30000, seed 20261122), then a large run.
{ time "$dist/fftess_nvidia_compare" run --diffs "$out/diffs_default.txt" 30000 20261122 \
  > "$out/compare_default.txt"; } 2> "$out/compare_default.err"
echo "exit $?" >> "$out/compare_default.err"
{ time "$dist/fftess_nvidia_compare" run --diffs "$out/diffs_big.txt" "$big" "$seed" \
  > "$out/compare_big.txt"; } 2> "$out/compare_big.err"
echo "exit $?" >> "$out/compare_big.err"
[ -f "$out/diffs_big.txt" ] && { echo "diff lines $(wc -l < "$out/diffs_big.txt")" >> "$out/compare_big.err"; head -c 2000000 "$out/diffs_big.txt" > "$out/diffs_big_head.txt"; rm -f "$out/diffs_big.txt"; }
rm -f "$out/gen2000.batch" "$out/gen2000_pointonly.batch"
# Few files come back: fold the oracle's results into one.
for f in oracle_example.err oracle_gen2000.err oracle_pointonly.err oracle_example.out oracle_pointonly_head.out; do
  echo "=== $f"; head -c 3000 "$out/$f"; echo
done > "$out/oracle.txt"
rm -f "$out"/oracle_*
