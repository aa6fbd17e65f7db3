// Ctrl-C (SIGINT) on sweep at several points (issue 13): during camera generation, mid-sweep and while the reports
// are written. Each is answered within a second with a summary of what was done, the report says how many cameras
// were not done (without listing them), the documented status (130 when no crack was found), no partial file.
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

// Reads a FIFO until its writer closes it (or 20 s pass without one: a binary that replaced the FIFO never writes).
std::string readFifo(const std::string& path) {
  std::string got;
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK);
  if (fd < 0) return got;
  char buf[65536];
  for (int waited = 0; waited < 20000;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n > 0) got.append(buf, static_cast<size_t>(n));
    else if (n == 0 && !got.empty()) break;
    else ::usleep(1000), ++waited;
  }
  ::close(fd);
  return got;
}

} // namespace

TEST_CASE("interrupt: Ctrl-C during camera generation stops within a second, with a summary and a report",
          "[cli][interrupt]") {
  const std::string d = scratch("sigint-gen");
  const std::string js = d + "/x.json";
  clitest::RunOptions o;
  o.sigintAfter = 0.4; // the terrain loads in far less; generating 10^8 cameras takes many seconds
  const auto r = runWith({"sweep", kRings, "--random", "100000000", "--json", js}, o);
  REQUIRE(r.interrupted);
  CHECK(r.exitAfterSigint < 1.0);
  CHECK(r.status == 130);
  CHECK(r.out.find("(interrupted)") != std::string::npos);
  CHECK(r.out.find("of 100000000") != std::string::npos);
  checkInterruptedReport(js, 100000000);
  CHECK(noTempFiles(d));
}

TEST_CASE("interrupt: Ctrl-C mid-sweep stops within a second; the report counts the cameras not done",
          "[cli][interrupt]") {
  const std::string d = scratch("sigint-mid");
  const std::string js = d + "/y.json", svg = d + "/y.svg";
  clitest::RunOptions o;
  o.sigintWhenErr = "fftess sweep "; // the header: the cameras exist, the sweep starts
  o.sigintAfter = 0.3;
  const auto r = runWith({"sweep", kRings, "--random", "200000", "--threads", "2", "--json", js, "--svg", svg}, o);
  REQUIRE(r.interrupted);
  CHECK(r.exitAfterSigint < 1.0);
  CHECK(r.status == 130);
  CHECK(r.out.find("of 200000 (interrupted)") != std::string::npos);
  checkInterruptedReport(js, 200000);
  CHECK(clitest::readFile(svg).find("</svg>") != std::string::npos);
  CHECK(noTempFiles(d));
}

TEST_CASE("interrupt: Ctrl-C while a report is written does not cut it short", "[cli][interrupt]") {
  // The JSON goes to a FIFO: the process blocks opening it until we read, and we send SIGINT while it waits there.
  const std::string d = scratch("sigint-report");
  const std::string fifo = d + "/fifo", svg = d + "/z.svg";
  ::unlink(fifo.c_str());
  REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  std::string got;
  clitest::RunOptions o;
  o.whileRunning = [&](pid_t pid) {
    ::usleep(1500 * 1000); // the 3-camera sweep is done by now; the process waits for a reader of the FIFO
    ::kill(pid, SIGINT);
    ::usleep(100 * 1000);
    got = readFifo(fifo);
  };
  const auto r = runWith({"sweep", kRings, "--orbit", "3", "-q", "--json", fifo, "--svg", svg}, o);
  CHECK(r.status == 0); // the sweep was complete: the interrupt came after the work
  const json j = json::parse(got);
  CHECK(j.at("cameras_done") == 3);
  CHECK(clitest::readFile(svg).find("</svg>") != std::string::npos);
  CHECK(noTempFiles(d));
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
