// The JSON reports of check, sweep and compare as text (report_api.h): the subcommands run quietly into a private file.
#include "report_api.h"

#include "common.h"
#include "progress.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace fftess::cli {

namespace {

// A private directory ($TMPDIR or /tmp) for one report file; removed with the file when done.
class TempReport {
public:
  TempReport() {
    const char* env = std::getenv("TMPDIR");
    std::string tmpl = std::string(env && *env ? env : "/tmp") + "/fftess-report.XXXXXX";
    if (!::mkdtemp(tmpl.data()))
      throw std::runtime_error("cannot create a temporary directory in " + tmpl.substr(0, tmpl.rfind('/')) + ": " +
                               std::strerror(errno));
    dir_ = tmpl;
  }
  ~TempReport() {
    ::unlink(path().c_str());
    ::rmdir(dir_.c_str());
  }
  TempReport(const TempReport&) = delete;
  TempReport& operator=(const TempReport&) = delete;
  std::string path() const { return dir_ + "/report.json"; }
  std::string read() const {
    std::ifstream in(path(), std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    if (!in) throw std::runtime_error("reading the report " + path() + " failed");
    return s.str();
  }

private:
  std::string dir_;
};

} // namespace

std::string checkReportText(CheckArgs a) {
  TempReport t;
  a.json = t.path();
  a.quiet = true;
  runCheck(a); // the exit status is the report's verdict
  return t.read();
}

std::string sweepReportText(SweepArgs a) {
  TempReport t;
  a.json = t.path();
  a.quiet = true;
  runSweep(a);
  return t.read();
}

bool sweepInterrupted() { return InterruptGuard::flag()->load(); }

std::string compareReportText(CompareArgs a) {
  if (a.format != "auto" && a.format != "hex" && a.format != "csv")
    throw UsageError("--format " + quoteToken(a.format) + ": expected auto|hex|csv");
  if (a.show < 0) throw UsageError("--show " + std::to_string(a.show) + ": must be >= 0");
  if (a.details < 0) throw UsageError("--details " + std::to_string(a.details) + ": must be >= 0");
  std::string out;
  a.json = true;
  a.jsonOut = &out;
  runCompare(a);
  return out;
}

} // namespace fftess::cli
