#!/bin/bash
# The GPU float model (lod/bound.h, FloatModel::Conformant) against a real GPU: `fftess sweep --gpu-float conformant`
# with lod.evaluate = "gpu" for every built-in scheme, on the tile rings and the default terrain. Every factor the GPU
# returns is checked against the conformant model's set for its patch and camera (the sweep's `gpu model` line; JSON
# stats gpu_model_factors / gpu_model_outside), and every matching pair is analysed for compiler freedom (gpu float).
# The binaries and the shared libraries the host lacks come prebuilt in DIST, as for tests/tools/gpu_lod_device.sh:
#   tests/tools/gpu_float_device.sh OUTDIR [DIST] [EXTRA fftess options, e.g. --gpu-hardware]
set -u
out=${1:?OUTDIR}; dist=${2:-build-gpudev/dist}; shift 2 || shift $#
extra=("$@")
mkdir -p "$out"
export LD_LIBRARY_PATH=$PWD/$dist/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
{ nvidia-smi --query-gpu=name,driver_version --format=csv 2>/dev/null; uname -r; nproc; } > "$out/env.txt" 2>&1
cameras=${CAMERAS:-300}
for scheme in screen_sphere distance_pow2 bonaventura clip_diameter constant; do
  for scene in rings_small terrain; do
    name="${scheme}_${scene}"
    { time "$dist/fftess" sweep "docs/examples/$scene.toml" --set lod.evaluate=gpu --set lod.scheme=$scheme \
        --random "$cameras" --gpu-float conformant --json "$out/$name.json" "${extra[@]}" > "$out/$name.txt" 2>&1; } \
      2> "$out/$name.time"
    echo "exit $?" >> "$out/$name.txt"
  done
done
# The summary: per run, the model line and the gpu float line of the sweep's text.
grep -H "gpu model\|gpu float  \|factors differ\|verdict" "$out"/*.txt > "$out/summary.txt"
