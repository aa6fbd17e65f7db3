// fftess_bench's main: Google Benchmark's own main, with a console reporter whose context says how fftess was built.
// Debian's libbenchmark is compiled without NDEBUG, so its reporter prints "Library was built as DEBUG. Timings may be
// affected." above every run of fftess_bench, although the code timed is fftess's (Release: -O3, NDEBUG) and the
// timing loop (State's iterator, benchmark.h) is inlined into it; only the library's own bookkeeping keeps its
// asserts. FftessReporter prints the same context (date, CPUs, caches, load, CPU scaling) with that said instead.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <ctime>
#include <cstring>
#include <ostream>
#include <string>
#include <unistd.h>

namespace {

class FftessReporter : public benchmark::ConsoleReporter {
public:
  using benchmark::ConsoleReporter::ConsoleReporter;

  bool ReportContext(const Context& context) override {
    name_field_width_ = context.name_field_width;
    printed_header_ = false;
    prev_counters_.clear();
    std::ostream& out = GetErrorStream();
    char date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%S%z", std::localtime(&now));
    out << date << "\n";
    if (context.executable_name) out << "Running " << context.executable_name << "\n";
    const benchmark::CPUInfo& info = context.cpu_info;
    out << "Run on (" << info.num_cpus << " X " << (info.cycles_per_second / 1e6) << " MHz CPU"
        << (info.num_cpus > 1 ? "s" : "") << ")\n";
    if (!info.caches.empty()) out << "CPU Caches:\n";
    for (const auto& c : info.caches) {
      out << "  L" << c.level << " " << c.type << " " << (c.size / 1024) << " KiB";
      if (c.num_sharing != 0) out << " (x" << (info.num_cpus / c.num_sharing) << ")";
      out << "\n";
    }
    if (!info.load_avg.empty()) {
      char buf[32];
      out << "Load Average: ";
      for (size_t i = 0; i < info.load_avg.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%.2f", info.load_avg[i]);
        out << (i ? ", " : "") << buf;
      }
      out << "\n";
    }
    if (info.scaling == benchmark::CPUInfo::Scaling::ENABLED)
      out << "***WARNING*** CPU scaling is enabled, the benchmark real time measurements may be noisy and will incur "
             "extra overhead.\n";
    out << buildLine() << "\n";
    return true;
  }

private:
  static std::string buildLine() {
#ifdef NDEBUG
    const char* asserts = "NDEBUG, asserts off";
#else
    const char* asserts = "asserts ON: timings are not Release timings";
#endif
    return std::string("fftess_bench: fftess built as ") + FFTESS_BUILD_TYPE + " (" + asserts +
           "); the Google Benchmark library as Debian packages it (its own asserts on; the timed loops are "
           "compiled into fftess_bench)";
  }
};

// The value of --NAME=VALUE among the arguments ("" when not given).
std::string flagValue(int argc, char** argv, const char* name) {
  const std::string prefix = std::string("--") + name + "=";
  std::string value;
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], prefix.c_str(), prefix.size()) == 0) value = argv[i] + prefix.size();
  return value;
}

bool isFalse(const std::string& v) { return v == "false" || v == "0" || v == "no" || v == "off"; }

} // namespace

int main(int argc, char** argv) {
  // The flags the console reporter's look depends on, read as the library reads them (--benchmark_format=console is
  // the default; json and csv keep the library's own reporter, whose context line is data, not a warning).
  const std::string format = flagValue(argc, argv, "benchmark_format");
  const std::string color = flagValue(argc, argv, "benchmark_color");
  const std::string tabular = flagValue(argc, argv, "benchmark_counters_tabular");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  int options = benchmark::ConsoleReporter::OO_None;
  if (color.empty() || color == "auto" ? ::isatty(STDOUT_FILENO) != 0 : !isFalse(color))
    options |= benchmark::ConsoleReporter::OO_Color;
  if (!tabular.empty() && !isFalse(tabular)) options |= benchmark::ConsoleReporter::OO_Tabular;
  FftessReporter console(static_cast<benchmark::ConsoleReporter::OutputOptions>(options));
  if (format.empty() || format == "console") benchmark::RunSpecifiedBenchmarks(&console);
  else benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
