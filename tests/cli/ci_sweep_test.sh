#!/usr/bin/env bash
# ctest "cli:docs/ci.md's sweep step": docs/ci.md's CI jobs run docs/examples/ci_sweep.sh; run it as they do (from the
# repository root) on the scene as shipped (exit 0) and with the neighbour rule off (exit 1), and check that both
# write the three reports, and that docs/ci.md runs this script in both jobs (its only fftess commands).
# Usage: ci_sweep_test.sh SOURCE_ROOT FFTESS OUT_DIR
set -u
root=$1 fftess=$2 out=$3
cd "$root" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$out" && mkdir -p "$out"
FFTESS=$fftess CAMERAS="--orbit 4" docs/examples/ci_sweep.sh docs/examples/terrain.toml "$out/clean" -q
[ $? -eq 0 ] || fail "the shipped scene: expected exit 0"
FFTESS=$fftess CAMERAS="--orbit 4" docs/examples/ci_sweep.sh docs/examples/terrain.toml "$out/cracked" -q \
  --set lod.adjacency_clamp=none
[ $? -eq 1 ] || fail "lod.adjacency_clamp=none: expected exit 1"
for run in clean cracked; do
  for f in sweep.json fftess.sarif fftess-junit.xml; do
    [ -s "$out/$run/$f" ] || fail "$run: $f not written"
  done
  grep -q '"version": "2.1.0"' "$out/$run/fftess.sarif" || fail "$run: not SARIF 2.1.0"
done
grep -q '"level": "error"' "$out/cracked/fftess.sarif" || fail "cracked: no error result"
grep -q '"results": \[\]' "$out/clean/fftess.sarif" || fail "clean: results not empty"
grep -q 'failures="0"' "$out/clean/fftess-junit.xml" || fail "clean: JUnit failures"
grep -q '<failure ' "$out/cracked/fftess-junit.xml" || fail "cracked: no JUnit failure"
# docs/ci.md: both jobs run the script; no other fftess command line in it.
[ "$(grep -c 'docs/examples/ci_sweep.sh' docs/ci.md)" -ge 2 ] || fail "docs/ci.md does not run docs/examples/ci_sweep.sh in both jobs"
grep -nE '^\s*-?\s*(run:)?\s*(build/)?fftess ' docs/ci.md && fail "docs/ci.md runs fftess outside docs/examples/ci_sweep.sh"
echo "ci_sweep_test: ok"
