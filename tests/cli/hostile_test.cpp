// Hostile input, I/O faults and interrupts (issue 13): no crash, no lost or clobbered file, the documented exit
// status. Fault injection uses only nodes this test makes in its own scratch directory: a FIFO (mkfifo), a character
// device like /dev/full (mknod c 1 7, written to as a device: it must never be replaced), symlinks, and a path under
// a regular file (FILE/x: fails for root too, unlike permission bits). Nothing here ever names a node under /dev.
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

using clitest::run;
using clitest::runWith;
using nlohmann::json;

namespace {

const std::string kScene = clitest::source("docs/examples/terrain.toml");
const std::string kRings = clitest::source("docs/examples/rings_small.toml");
const std::string kGrid = clitest::source("docs/examples/grid.toml");
const std::string kLine = "quad integer triangle_cw hw 4 4 4 4 4 4";

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

// A fresh directory for one test case.
std::string scratch(const std::string& name) {
  const std::string d = clitest::tmpDir() + "/" + name;
  ::mkdir(d.c_str(), 0755);
  return d;
}

// Our own full device (major 1, minor 7, like /dev/full) inside dir; "" if this process may not make one.
std::string fullDevice(const std::string& dir) {
  const std::string p = dir + "/full";
  ::unlink(p.c_str());
  if (::mknod(p.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) return "";
  return p;
}

bool isCharDevice(const std::string& p) {
  struct stat st;
  return ::lstat(p.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

bool noTempFiles(const std::string& dir) {
  for (const std::string& f : clitest::listDir(dir))
    if (f.find(".tmp.") != std::string::npos) return false;
  return true;
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

TEST_CASE("hostile: patch sizes that vanish or overflow in float are rejected before CGAL (check and sweep)",
          "[cli][hostile]") {
  struct Case {
    std::vector<std::string> args;
    const char* key;
  } cases[] = {
      {{"check", kScene, "--set", "layout.base_patch_size=1e-45"}, "layout.base_patch_size"},
      {{"check", kScene, "--set", "layout.base_patch_size=1e-40"}, "layout.base_patch_size"},
      {{"check", kScene, "--set", "layout.base_patch_size=1e37"}, "layout.base_patch_size"},
      {{"sweep", kScene, "--set", "layout.base_patch_size=1e-45", "--orbit", "2"}, "layout.base_patch_size"},
      {{"check", kGrid, "--set", "layout.patch_size=1e-45"}, "layout.patch_size"},
      {{"check", kGrid, "--set", "layout.patch_size=3e38"}, "layout.patch_size"},
  };
  for (const Case& c : cases) {
    INFO(c.args[0] + " " + c.args[3]);
    const auto r = run(c.args);
    CHECK(r.status == 2);
    CHECK(r.err.find(c.key) != std::string::npos);
    CHECK(lines(r.err) == 1);
    CHECK(r.out.empty());
  }
}

TEST_CASE("hostile: a stdout that cannot be written exits 3 (check, sweep, explain)", "[cli][hostile]") {
  const std::string full = fullDevice(scratch("stdout-full"));
  if (full.empty()) {
    WARN("skipped: cannot mknod a full device here (" << std::strerror(errno) << ")");
    return;
  }
  const std::vector<std::vector<std::string>> cmds = {
      {"check", kScene}, {"sweep", kScene, "--orbit", "2"}, {"explain", "--why-pow2"}, {"explain", "7", "3"},
      {"check", kScene, "--json", "-"}};
  for (const auto& args : cmds) {
    INFO(args[0] + " " + args[1]);
    clitest::RunOptions o;
    o.stdoutPath = full;
    const auto r = runWith(args, o);
    CHECK(r.status == 3);
    CHECK(r.err.find("stdout") != std::string::npos);
  }
  CHECK(isCharDevice(full));
}

TEST_CASE("hostile: unusable output paths exit 2 before the work and name the path, reports are all or nothing",
          "[cli][hostile]") {
  const std::string d = scratch("paths");
  const std::string file = d + "/plain";
  clitest::writeFile(file, "x");
  const std::string ok = d + "/ok.json", under = file + "/x.svg"; // a path under a regular file fails for root too
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"check", kScene, "--json", ok, "--svg", under},
           {"sweep", kRings, "--random", "20000", "--json", ok, "--svg", under},
           {"check", kScene, "--json", d},
           {"sweep", kScene, "--orbit", "2", "--json", ok, "--svg", d + "/missing/x.svg"}}) {
    INFO(args.back());
    const auto r = run(args);
    CHECK(r.status == 2);
    CHECK(lines(r.err) == 1); // nothing else: the work never started
    CHECK(r.err.find(args.back()) != std::string::npos);
    CHECK_FALSE(clitest::fileExists(ok));
    CHECK(noTempFiles(d));
  }
  const auto r = run({"check", kScene, "--json", d});
  CHECK(r.err.find("is a directory") != std::string::npos);

  // A write that fails later (the SVG goes to a full device): exit 3, the JSON written first is removed again.
  const std::string full = fullDevice(d);
  if (full.empty()) {
    WARN("skipped the full-device part: cannot mknod here");
    return;
  }
  const auto w = run({"check", kScene, "-q", "--json", ok, "--svg", full});
  CHECK(w.status == 3);
  CHECK(w.err.find(full) != std::string::npos);
  CHECK_FALSE(clitest::fileExists(ok));
  CHECK(isCharDevice(full));
  CHECK(noTempFiles(d));
}

TEST_CASE("hostile: outputs to symlinks, FIFOs and devices are followed or written straight, never replaced",
          "[cli][hostile]") {
  const std::string d = scratch("nodes");
  // A symlink: its target is replaced atomically, the link stays a link.
  const std::string target = d + "/target.json", link = d + "/link.json";
  clitest::writeFile(target, "old");
  ::unlink(link.c_str());
  REQUIRE(::symlink("target.json", link.c_str()) == 0);
  auto r = run({"check", kScene, "-q", "--json", link});
  CHECK(r.status == 0);
  struct stat st;
  REQUIRE(::lstat(link.c_str(), &st) == 0);
  CHECK(S_ISLNK(st.st_mode));
  CHECK(json::parse(clitest::readFile(target)).at("kind") == "check");
  // A dangling symlink names the file to create.
  const std::string dangling = d + "/dangling.svg";
  ::unlink(dangling.c_str());
  REQUIRE(::symlink("made.svg", dangling.c_str()) == 0);
  r = run({"check", kScene, "-q", "--svg", dangling});
  CHECK(r.status == 0);
  CHECK(clitest::readFile(d + "/made.svg").find("<svg") != std::string::npos);
  REQUIRE(::lstat(dangling.c_str(), &st) == 0);
  CHECK(S_ISLNK(st.st_mode));
  // tessellate -o through a symlink.
  const std::string tlink = d + "/t.txt";
  ::unlink(tlink.c_str());
  REQUIRE(::symlink("t-target.txt", tlink.c_str()) == 0);
  r = run({"tessellate", "-e", kLine, "-o", tlink});
  CHECK(r.status == 0);
  REQUIRE(::lstat(tlink.c_str(), &st) == 0);
  CHECK(S_ISLNK(st.st_mode));
  CHECK_FALSE(clitest::readFile(d + "/t-target.txt").empty());

  // A FIFO: written straight, a reader gets the bytes, the FIFO stays a FIFO.
  const std::string fifo = d + "/fifo";
  ::unlink(fifo.c_str());
  REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  std::string got;
  clitest::RunOptions o;
  o.whileRunning = [&](pid_t) {
    got = readFifo(fifo);
  };
  r = runWith({"check", kScene, "-q", "--json", fifo}, o);
  CHECK(r.status == 0);
  CHECK(json::parse(got).at("kind") == "check");
  REQUIRE(::lstat(fifo.c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));

  // A device: written straight (here it fails: a full device, exit 3), never replaced by a regular file.
  const std::string full = fullDevice(d);
  if (full.empty()) {
    WARN("skipped the device part: cannot mknod here");
    return;
  }
  for (const auto& args : std::vector<std::vector<std::string>>{{"check", kScene, "-q", "--json", full},
                                                                 {"tessellate", "-e", kLine, "-o", full}}) {
    INFO(args[0]);
    r = run(args);
    CHECK(r.status == 3);
    CHECK(r.err.find(full) != std::string::npos);
    CHECK(isCharDevice(full));
  }
  CHECK(noTempFiles(d));
}

TEST_CASE("hostile: a disk that fills up while reports are written: exit 3, the path named, nothing left behind",
          "[cli][hostile]") {
  // A 4 KiB tmpfs of our own; skipped where this process may not mount one.
  const std::string d = scratch("diskfull");
  if (::mount("tmpfs", d.c_str(), "tmpfs", 0, "size=4k") != 0) {
    WARN("skipped: cannot mount a small tmpfs here (" << std::strerror(errno) << ")");
    return;
  }
  const std::string js = d + "/r.json", svg = d + "/r.svg", out = d + "/t.txt";
  // Many findings: the JSON is far larger than the disk.
  auto r = run({"check", kScene, "-q", "--set", "lod.adjacency_clamp=integer", "--json", js, "--svg", svg});
  CHECK(r.status == 3);
  CHECK(r.err.find(js) != std::string::npos);
  CHECK(clitest::listDir(d).empty()); // no partial JSON, no SVG either (all or nothing), no temporary file
  r = run({"sweep", kScene, "--orbit", "4", "-q", "--set", "lod.adjacency_clamp=integer", "--json", js});
  CHECK(r.status == 3);
  CHECK(clitest::listDir(d).empty());
  r = run({"tessellate", "-e", "quad integer triangle_cw hw 64 64 64 64 64 64", "--format", "hex", "-o", out});
  CHECK(r.status == 3);
  CHECK(r.err.find(out) != std::string::npos);
  CHECK(clitest::listDir(d).empty());
  ::umount(d.c_str());
}
