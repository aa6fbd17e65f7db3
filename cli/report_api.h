// The JSON reports of check, sweep and compare as text, for callers that are not the command line (the Python module,
// python/fftess_module.cpp). Each runs the subcommand itself (runCheck, runSweep, runCompare: the same checks of the
// arguments, the same work, the same report functions), quietly, and returns the JSON text its --json writes, byte for
// byte: there is no second format. Errors as the subcommand's: UsageError (bad arguments, bad scene or capture; the
// command line's exit 2), anything else std::exception (exit 3). Findings are in the report, never an exception.
#pragma once

#include "commands.h"

#include <string>

namespace fftess::cli {

// `fftess check --json FILE` (a.json and a.quiet are ignored: the report goes to a private temporary file, removed
// afterwards; a.svg, a.gltf and a.view are written as the command line writes them).
std::string checkReportText(CheckArgs a);
// `fftess sweep --json FILE`, as checkReportText. A Ctrl-C (SIGINT) during the sweep stops it as on the command line
// (the report says "cancelled"); sweepInterrupted() then says so.
std::string sweepReportText(SweepArgs a);
bool sweepInterrupted();
// `fftess compare --json` (a.json is ignored: the report is returned instead of printed). a.format must be auto, hex or
// csv; a.show and a.details >= 0 (UsageError naming the option otherwise, as the command line's parser would).
std::string compareReportText(CompareArgs a);

} // namespace fftess::cli
