// Ctrl-C (SIGINT) on sweep at several points (issues 13, 18): from the start, mid-sweep and while a report waits for a
// FIFO's reader; other fatal signals. Each is answered at once (bounded by a 10 s watchdog, not timed) with a summary of
// what was done, the report says how many cameras were not done (without listing them), the documented status (130
// when no crack was found), no partial or temporary file.
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <csignal>
#include <fcntl.h>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

using clitest::runWith;
using nlohmann::json;

namespace {

const std::string kRings = clitest::source("docs/examples/rings_small.toml");

std::string scratch(const std::string& name) {
  const std::string d = clitest::tmpDir() + "/" + name;
  ::mkdir(d.c_str(), 0755);
  return d;
}

bool noTempFiles(const std::string& dir) {
  for (const std::string& f : clitest::listDir(dir))
    if (f.find(".tmp.") != std::string::npos) return false;
  return true;
}

// The report of an interrupted sweep: cancelled, the undone cameras counted, only done cameras listed.
void checkInterruptedReport(const std::string& path, size_t requested) {
  REQUIRE(clitest::fileExists(path));
  const json j = json::parse(clitest::readFile(path));
  CHECK(j.at("cancelled") == true);
  CHECK(j.at("cameras_total") == requested);
  const size_t done = j.at("cameras_done");
  CHECK(done < requested);
  CHECK(j.at("cameras_not_done") == requested - done);
  CHECK(j.at("cameras").size() == done);
}

} // namespace

TEST_CASE("interrupt: Ctrl-C early in a 10^8-camera sweep stops at once, with a summary and a report",
          "[cli][interrupt]") {
  const std::string d = scratch("sigint-gen");
  const std::string js = d + "/x.json";
  clitest::RunOptions o;
  o.sigintAfter = 0.4; // the terrain loads in far less; the cameras are made one by one as they are checked
  const auto r = runWith({"sweep", kRings, "--random", "100000000", "--json", js}, o);
  REQUIRE(r.interrupted);
  INFO("exit " << r.exitAfterSigint << " s after SIGINT");
  CHECK_FALSE(r.watchdogFired);
  CHECK(r.status == 130);
  CHECK(r.out.find("(interrupted)") != std::string::npos);
  CHECK(r.out.find("of 100000000") != std::string::npos);
  checkInterruptedReport(js, 100000000);
  CHECK(noTempFiles(d));
}

TEST_CASE("interrupt: Ctrl-C mid-sweep stops within a second, the report counts the cameras not done",
          "[cli][interrupt]") {
  const std::string d = scratch("sigint-mid");
  const std::string js = d + "/y.json", svg = d + "/y.svg";
  clitest::RunOptions o;
  o.sigintWhenErr = "fftess sweep "; // the header: the cameras exist, the sweep starts
  o.sigintAfter = 0.3;
  const auto r = runWith({"sweep", kRings, "--random", "200000", "--threads", "2", "--json", js, "--svg", svg}, o);
  REQUIRE(r.interrupted);
  INFO("exit " << r.exitAfterSigint << " s after SIGINT");
  CHECK_FALSE(r.watchdogFired);
  CHECK(r.status == 130);
  CHECK(r.out.find("of 200000 (interrupted)") != std::string::npos);
  checkInterruptedReport(js, 200000);
  CHECK(clitest::readFile(svg).find("</svg>") != std::string::npos);
  CHECK(noTempFiles(d));
}

TEST_CASE("interrupt: the first Ctrl-C while a report waits for a FIFO's reader ends the wait", "[cli][interrupt]") {
  // The JSON goes to a FIFO nobody reads: the 3-camera sweep is done and the process waits for a reader. The first
  // Ctrl-C is answered there (it was once swallowed by the blocking open): exit 130, the FIFO named, no report at all
  // (the SVG, published after the JSON, is not written either) and no temporary file.
  const std::string d = scratch("sigint-report");
  const std::string fifo = d + "/fifo", svg = d + "/z.svg";
  ::unlink(fifo.c_str());
  REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  clitest::RunOptions o;
  o.sigintWhenErr = "3/3 cameras"; // the last progress line: the sweep is done, the reports are being written
  o.sigintAfter = 0.5;
  const auto r = runWith({"sweep", kRings, "--orbit", "3", "--json", fifo, "--svg", svg}, o);
  REQUIRE(r.interrupted);
  INFO("exit " << r.exitAfterSigint << " s after SIGINT; stderr: " << r.err);
  CHECK_FALSE(r.watchdogFired);
  CHECK(r.status == 130);
  CHECK(r.err.find("interrupted while waiting for a reader of '" + fifo + "'") != std::string::npos);
  CHECK_FALSE(clitest::fileExists(svg));
  CHECK(noTempFiles(d));
}

TEST_CASE("interrupt: Ctrl-C at any moment of a 10^8-camera sweep, memory bounded", "[cli][interrupt]") {
  // Cameras are made by index: no setup that outlasts a Ctrl-C, and memory does not grow with the count (it was GBs
  // after seconds when every camera was generated first). From the start (scene loading, before the sweep's
  // handler: the default action, temporary files removed) to the middle of the sweep: each Ctrl-C ends the process,
  // long before the watchdog, with no temporary file, and a report is either whole or absent.
  for (const double at : {0.0, 0.02, 0.1, 0.3, 1.0, 2.5}) {
    const std::string d = scratch("sigint-any-" + std::to_string(static_cast<int>(at * 1000)));
    const std::string js = d + "/x.json";
    clitest::RunOptions o;
    o.sigintAfter = at;
    const auto r = runWith({"sweep", kRings, "--random", "100000000", "--json", js}, o);
    INFO("SIGINT at " << at << " s: exit " << r.exitAfterSigint << " s later, peak RSS " << r.maxRssKb << " kB; stderr: " << r.err);
    REQUIRE(r.interrupted);
    CHECK_FALSE(r.watchdogFired);
    CHECK(r.status == 130);
    CHECK(r.maxRssKb < 1024 * 1024);
    CHECK(noTempFiles(d));
    if (clitest::fileExists(js)) checkInterruptedReport(js, 100000000);
  }
}

TEST_CASE("interrupt: every fatal signal removes the temporary report files", "[cli][interrupt]") {
  const std::string scene = clitest::source("docs/examples/terrain.toml");
  for (const int sig : {SIGQUIT, SIGUSR1, SIGALRM, SIGPIPE, SIGTERM, SIGHUP, SIGUSR2, SIGXCPU, SIGRTMIN + 1}) {
    const std::string d = scratch("signal-" + std::to_string(sig));
    clitest::RunOptions o;
    o.signal = sig;
    bool temps = false; // the reports' temporary files exist when the signal is sent (check --mesh takes seconds)
    o.whileRunning = [&](pid_t) {
      for (int waited = 0; !temps && waited < 20000; waited += 5, ::usleep(5000)) temps = !noTempFiles(d);
    };
    o.sigintAfter = 0;
    const auto r = runWith({"check", scene, "--mesh", "--json", d + "/c.json", "--svg", d + "/c.svg"}, o);
    INFO("signal " << sig << ", stderr: " << r.err);
    REQUIRE(temps);
    REQUIRE(r.interrupted);
    CHECK_FALSE(r.watchdogFired);
    CHECK(r.status == 128 + sig); // the default action, after the cleanup
    CHECK(clitest::listDir(d).empty());
  }
}

TEST_CASE("interrupt: Ctrl-C kills check without leaving temporary files",
          "[cli][interrupt]") {
  // The report paths are claimed (temporary files made) before the work, so a signal must remove them.
  const std::string d = scratch("sigint-kill");
  const std::string scene = clitest::source("docs/examples/terrain.toml");
  clitest::RunOptions o;
  o.sigintAfter = 0.15;
  const auto r = runWith({"check", scene, "--mesh", "--json", d + "/c.json", "--svg", d + "/c.svg"}, o);
  REQUIRE(r.interrupted);
  CHECK(r.status == 130);
  CHECK(clitest::listDir(d).empty());
}
