#!/usr/bin/env bash
# The fftess step of the CI jobs in docs/ci.md: sweep a scene and write the reports a CI system shows, SARIF 2.1.0
# (code scanning) and JUnit XML (test reports), next to the JSON report. Run from the repository root after
# `bash setup.sh build`; ctest runs it too (tests/cli/CMakeLists.txt, "cli:docs/ci.md's sweep step"), so every command
# here is one that works.
#   docs/examples/ci_sweep.sh [SCENE [OUT_DIR [MORE SWEEP OPTIONS...]]]
#   SCENE    default docs/examples/terrain.toml;  OUT_DIR  default fftess-reports
#   FFTESS   the binary (default build/fftess);   CAMERAS  sweep's camera option (default "--orbit 16")
# Writes OUT_DIR/sweep.json, OUT_DIR/fftess.sarif, OUT_DIR/fftess-junit.xml. Exit status: fftess sweep's (0
# watertight, 1 cracks, holes, undecided or nothing checked, 2 bad usage or scene, 3 internal error); the reports are
# written for 0 and 1, so a CI job uploads them with "always" and fails on the status.
set -u
fftess=${FFTESS:-build/fftess}
scene=${1:-docs/examples/terrain.toml}
out=${2:-fftess-reports}
shift $(($# > 2 ? 2 : $#))
mkdir -p "$out"
# shellcheck disable=SC2086 # CAMERAS is an option and its value
"$fftess" sweep "$scene" ${CAMERAS:---orbit 16} --threads 0 \
  --json "$out/sweep.json" --sarif "$out/fftess.sarif" --junit "$out/fftess-junit.xml" "$@"
status=$?
echo "ci_sweep: fftess sweep $scene exited $status; reports in $out/"
exit $status
