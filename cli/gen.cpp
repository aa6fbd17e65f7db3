// fftess gen: seeded random patches (driver-check's generator, gl/random_patches.h) as a batch file with hex factors,
// so a random run can be kept, re-run (driver-check FILE) and fed to a port (compare PATCHES CAPTURE).
#include "commands.h"
#include "common.h"
#include "options.h"
#include "random_batch.h"

#include <CLI/CLI.hpp>

namespace fftess::cli {

CLI::App* addGen(CLI::App& app, GenArgs& a) {
  CLI::App* sub = app.add_subcommand("gen", "Write seeded random patches (driver-check's) as a batch file");
  sub->add_option("--random", a.random, "Number of random patches (default 1000)")->check(CLI::Range(0, 100000000));
  addSeedOption(sub, a.seed, "Seed of the random patches");
  sub->add_flag("--sweep", a.sweep, "The systematic sweep first (6348 uniform patches)");
  sub->add_option("-o,--output", a.output, "Output file (default stdout), written all or nothing");
  sub->footer("Example:\n  fftess gen --random 3000 --seed 7 -o random7.batch\n  fftess driver-check random7.batch\n"
              "Line 1 names the command; patch N (0-based) is on line N + 2. The same patches as\n"
              "driver-check --random N --seed S (and its --write-batch file, byte for byte).\n"
              "Exit status: 0 written, 2 bad usage, 3 the file could not be written.");
  return sub;
}

int runGen(const GenArgs& a) {
  BatchFileWriter out(a.output.empty() ? "-" : a.output);
  const GenSpec spec{a.random, a.seed, a.sweep};
  out.text(genHeader(spec));
  forEachGenPatch(spec, [&](int64_t, const Patch& p) { out.add(p); });
  out.commit();
  return kExitClean;
}

} // namespace fftess::cli
