// fftess: the command-line tool. Subcommands: tessellate, explain, check, sweep, compare, driver-check, bench,
// merge, layout, gen, prove (docs/cli.md).
// Exit statuses: 0 clean, 1 cracks found, 2 bad usage or input, 3 internal error. Errors go to stderr.
#include "commands.h"
#include "common.h"
#include "options.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <unistd.h>
#include <algorithm>
#include <string>
#include <vector>
#include <exception>
#include <new>


// A standard stream the caller closed (`<&-`, `>&-`) is opened on /dev/null the wrong way round: reading a closed stdin
// or writing a closed stdout then fails with EBADF and is reported (never read as empty input or written to
// nowhere), and no file this process opens (a report, a temporary file) can take descriptor 0, 1 or 2.
static void occupyClosedStdStreams() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int got = ::open("/dev/null", fd == 0 ? O_WRONLY : O_RDONLY);
    if (got >= 0 && got != fd) {
      ::dup2(got, fd);
      ::close(got);
    }
  }
}

// --help, -h, --version, --help-all: what the top level takes before a subcommand.
static bool isTopLevelOption(const CLI::App& app, const std::string& arg) {
  for (const CLI::Option* o : app.get_options())
    if (o->check_name(arg.substr(0, arg.find('=')))) return true;
  return false;
}

int main(int argc, char** argv) {
  using namespace fftess::cli;
  occupyClosedStdStreams();
  CLI::App app{"fftess " FFTESS_VERSION
               ": bit-exact D3D11 tessellator emulator and terrain crack checker.\n"
               "Run 'fftess SUBCOMMAND --help' for details and an example."};
  app.set_version_flag("--version", std::string("fftess ") + FFTESS_VERSION);
  app.require_subcommand(1);
  app.footer("Examples:\n"
             "  fftess tessellate -e 'quad integer triangle_cw hw 4 4 4 4 4 4'\n"
             "  fftess explain --why-pow2\n"
             "  fftess sweep docs/examples/terrain.toml\n"
             "Exit status: 0 clean, 1 cracks found, 2 bad usage or input, 3 internal error.");

  TessellateArgs tessArgs;
  ExplainArgs explainArgs;
  BenchArgs benchArgs;
  CLI::App* tess = addTessellate(app, tessArgs);
  CLI::App* explain = addExplain(app, explainArgs);
  CheckArgs checkArgs;
  SweepArgs sweepArgs;
  CLI::App* check = addCheck(app, checkArgs);
  CLI::App* sweep = addSweep(app, sweepArgs);
  MergeArgs mergeArgs;
  CLI::App* merge = addMerge(app, mergeArgs);
  CLI::App* bench = addBench(app, benchArgs);
  CompareArgs compareArgs;
  CLI::App* compare = addCompare(app, compareArgs);
  DriverCheckArgs driverArgs;
  CLI::App* driver = addDriverCheck(app, driverArgs);
  LayoutArgs layoutArgs;
  CLI::App* layout = addLayout(app, layoutArgs);
  GenArgs genArgs;
  CLI::App* gen = addGen(app, genArgs);
  ProveArgs proveArgs;
  CLI::App* prove = addProve(app, proveArgs);

  const std::vector<std::string> names = subcommandNames(app);
  const char* first = argc > 1 ? argv[1] : "";
  const bool known = std::find(names.begin(), names.end(), first) != names.end();
  std::string expected;
  for (const std::string& n : names) expected += (expected.empty() ? "" : "|") + n;
  if (argc > 1 && first[0] != '-' && !known) {
    std::fprintf(stderr, "fftess: error: unknown subcommand %s%s (expected %s; see fftess --help)\n",
                 quoteToken(first).c_str(), didYouMeanText(first, names).c_str(), expected.c_str());
    return kExitUsage;
  }
  if (argc > 1 && first[0] == '-' && !isTopLevelOption(app, first)) { // before CLI11's "a subcommand is required"
    std::fprintf(stderr, "fftess: error: unknown option %s%s (see fftess --help)\n", quoteToken(first).c_str(),
                 didYouMeanText(first, {"--help", "--version"}).c_str());
    return kExitUsage;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // The subcommand being parsed (CLI11 lists it as soon as it starts on its arguments): its own help is named.
    const std::vector<CLI::App*> started = app.get_subcommands();
    const CLI::App* sub = started.empty() ? nullptr : started.back();
    std::fprintf(stderr, "fftess: error: %s\n", parseErrorText(app, sub, e).c_str());
    return kExitUsage;
  }

  try {
    if (tess->parsed()) return runTessellate(tessArgs);
    if (explain->parsed()) return runExplain(explainArgs);
    if (check->parsed()) return runCheck(checkArgs);
    if (sweep->parsed()) return runSweep(sweepArgs);
    if (merge->parsed()) return runMerge(mergeArgs);
    if (compare->parsed()) return runCompare(compareArgs);
    if (driver->parsed()) return runDriverCheck(driverArgs);
    if (layout->parsed()) return runLayout(layoutArgs);
    if (gen->parsed()) return runGen(genArgs);
    if (prove->parsed()) return runProve(proveArgs);
    if (bench->parsed()) {
      benchArgs.passThrough = bench->remaining();
      return runBench(benchArgs, argv[0]);
    }
    std::fprintf(stderr, "fftess: error: no subcommand (see fftess --help)\n");
    return kExitUsage;
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "fftess: %s\n", e.what());
    return 130;
  } catch (const UsageError& e) {
    std::fputs(e.details.c_str(), stderr);
    std::fprintf(stderr, "fftess: error: %s\n", e.what());
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "fftess: internal error: out of memory\n");
    return kExitInternal;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fftess: internal error: %s\n", e.what());
    return kExitInternal;
  }
}
