#!/bin/bash
# The compute port on an NVIDIA GPU (prebuilt build-port/dist, see CMakeLists.txt): bit-exact check of many random
# quad patches in-process (the comparison library of fftess compare), the float-division switch, and a CSV capture of
# 300 patches for `fftess compare` back home.   tests/tools/compute_port/run_on_device.sh OUTDIR [PATCHES]
set -u
out=${1:?OUTDIR}; n=${2:-200000}
dist=build-port/dist
mkdir -p "$out"
export LD_LIBRARY_PATH=$PWD/$dist/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export __EGL_VENDOR_LIBRARY_FILENAMES=${FFTESS_EGL_VENDOR:-/usr/share/glvnd/egl_vendor.d/10_nvidia.json}
{ nvidia-smi --query-gpu=name,driver_version --format=csv; uname -r; } > "$out/env.txt" 2>&1
p=$dist/fftess_compute_port
{ time $p --hardware --compare --csv none --random "$n" --seed 11; echo "exit $?"; } > "$out/port_big.txt" 2>&1
{ $p --hardware --compare --csv none --random 20000 --seed 12 --bug float-division; echo "exit $?"; } > "$out/port_bug.txt" 2>&1
$p --hardware --random 300 --seed 13 --batch-out "$out/nv.batch" --csv "$out/nv.csv" > "$out/port_csv.txt" 2>&1
$p --hardware --random 300 --seed 13 --bug no-mirroring --csv "$out/nv_no_mirroring.csv" >> "$out/port_csv.txt" 2>&1
tail -n 3 "$out"/*.txt
