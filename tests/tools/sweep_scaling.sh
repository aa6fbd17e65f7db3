#!/bin/bash
# The sweep shortcuts measured on a many-core machine without a compiler (docs/accuracy.md "Sweep shortcuts"): the
# default scene's random cameras with and without the shortcuts (and, when given, an older fftess for "today's
# main"), the thread scaling -j 1..N, and one long sweep (default 10^6 cameras) split over every core, each with its
# wall time and peak memory (the process's VmHWM, polled from /proc: no /usr/bin/time needed). The binary and the
# shared libraries the host lacks come prebuilt in DIST (see tests/tools/driver_check_device.sh).
#   tests/tools/sweep_scaling.sh OUTDIR [DIST [OLD_FFTESS [LONG [SEED]]]]
set -u
out=${1:?OUTDIR}; dist=${2:-build-dc/dist}; old=${3:-}; long=${4:-1000000}; seed=${5:-$(date +%s)}
mkdir -p "$out"
export LD_LIBRARY_PATH=$PWD/$dist/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
scene=docs/examples/terrain.toml
cores=$(nproc)
{ uname -r; grep PRETTY /etc/os-release; echo "cores $cores"; grep -m1 "model name" /proc/cpuinfo; echo "seed $seed"; } \
  > "$out/env.txt" 2>&1
# measure NAME CMD...: stdout+stderr in NAME.txt; a line "NAME wall_s peak_kb exit" in summary.txt.
measure() {
  local name=$1; shift
  local t0 t1 pid peak=0 kb
  t0=$(date +%s.%N)
  "$@" > "$out/$name.txt" 2>&1 &
  pid=$!
  while kill -0 "$pid" 2>/dev/null; do
    kb=$(awk '/VmHWM/ {print $2}' "/proc/$pid/status" 2>/dev/null)
    [ -n "$kb" ] && [ "$kb" -gt "$peak" ] && peak=$kb
    sleep 0.05
  done
  wait "$pid"; local rc=$?
  t1=$(date +%s.%N)
  awk -v n="$name" -v a="$t0" -v b="$t1" -v p="$peak" -v r="$rc" 'BEGIN { printf "%s %.2f s %d KB exit %d\n", n, b - a, p, r }' \
    | tee -a "$out/summary.txt"
}
# Side by side, one thread, 1,000 cameras: full check, each shortcut, both; clamp on and off; the older binary.
for clamp in pow2 none; do
  s=(--set lod.adjacency_clamp=$clamp)
  measure "j1_${clamp}_full" "$dist/fftess" sweep "$scene" --random 1000 --seed "$seed" -j 1 "${s[@]}" --no-visible-first --no-result-cache
  measure "j1_${clamp}_visible" "$dist/fftess" sweep "$scene" --random 1000 --seed "$seed" -j 1 "${s[@]}" --no-result-cache
  measure "j1_${clamp}_cache" "$dist/fftess" sweep "$scene" --random 1000 --seed "$seed" -j 1 "${s[@]}" --no-visible-first
  measure "j1_${clamp}_both" "$dist/fftess" sweep "$scene" --random 1000 --seed "$seed" -j 1 "${s[@]}"
  [ -n "$old" ] && measure "j1_${clamp}_old" "$old" sweep "$scene" --random 1000 --seed "$seed" -j 1 "${s[@]}"
done
# Scaling: 20,000 cameras on 1, 2, 4, 8, ..., all cores (clamp on), and the older binary on all cores.
n=20000
for j in 1 2 4 8 12 16 24 32 64 128; do
  [ "$j" -gt "$cores" ] && break
  measure "scale_j${j}" "$dist/fftess" sweep "$scene" --random $((j == 1 ? 4000 : n)) --seed "$seed" -j "$j" -q
done
[ -n "$old" ] && measure "scale_old_j${cores}" "$old" sweep "$scene" --random "$n" --seed "$seed" -j "$cores" -q
# The long sweep: every core, the cameras split over the threads, the totals merged in one report.
measure "long_${long}" "$dist/fftess" sweep "$scene" --random "$long" --seed "$seed" -j "$cores"
echo done >> "$out/summary.txt"
