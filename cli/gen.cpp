// fftess gen: seeded random patches as a batch file (placeholder of the scaffold; the gen worktree implements it).
#include "common.h"

#include <CLI/CLI.hpp>

namespace fftess::cli {

CLI::App* addGen(CLI::App& app, GenArgs& a) {
  CLI::App* sub = app.add_subcommand("gen", "Write seeded random patches as a batch file");
  sub->add_option("--random", a.random, "Number of random patches")->check(CLI::Range(0, 100000000));
  sub->add_option("--seed", a.seed, "Seed (default 1)");
  sub->add_flag("--sweep", a.sweep, "The systematic sweep first");
  sub->add_option("-o,--output", a.output, "Output file (default stdout)");
  return sub;
}

int runGen(const GenArgs&) { throw UsageError("gen: not built yet"); }

} // namespace fftess::cli
