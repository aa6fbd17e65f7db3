// Silent defaults and wrong counts (issue 13, item 6): every bad argument is an error (exit 2, one line naming it),
// directories are called directories, and bad bytes or huge tokens never reach the terminal raw.
#include "run.h"
#include "usage_error.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <sys/stat.h>

using clitest::run;

namespace {

const std::string kScene = clitest::source("docs/examples/terrain.toml");
const std::string kLuna = clitest::source("docs/examples/luna.toml");
const std::string kLine = "quad integer triangle_cw hw 4 4 4 4 4 4";

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

// No byte outside printable ASCII, newline and valid UTF-8 (here: no byte >= 0x80 at all, the inputs are ASCII
// apart from the bad bytes).
bool clean(const std::string& s) {
  for (unsigned char c : s)
    if ((c < 0x20 && c != '\n') || c >= 0x7f) return false;
  return true;
}

} // namespace

TEST_CASE("input: counts, seeds and --show are checked, not silently replaced", "[cli][input]") {
  struct Case {
    std::vector<std::string> args;
    const char* mention;
  } cases[] = {
      {{"sweep", kScene, "--random", "0"}, "--random"},
      {{"sweep", kScene, "--orbit", "0"}, "--orbit"},
      {{"sweep", kScene, "--flyover", "0"}, "--flyover"},
      {{"sweep", kScene, "--random", "-3"}, "--random"},
      {{"sweep", kScene, "--random", "2", "--seed", "-1"}, "--seed"},
      {{"sweep", kScene, "--random", "2", "--seed", "18446744073709551616"}, "--seed"},
      {{"sweep", kScene, "--random", "2", "--seed", "99999999999999999999999"}, "--seed"},
      {{"sweep", kScene, "--random", "2", "--seed", "12x"}, "--seed"},
      {{"check", kScene, "--show", "-1"}, "--show"},
  };
  for (const Case& c : cases) clitest::checkUsageError(c.args, c.mention);
  // The largest seed is a seed.
  const auto r = run({"sweep", kScene, "--random", "1", "--seed", "18446744073709551615", "-q"});
  CHECK(r.status == 0);
  CHECK(r.err.empty());
}

TEST_CASE("input: tessellate -e LINE FILE says INPUT and --patch exclude each other", "[cli][input]") {
  const std::string file = clitest::tmpDir() + "/batch.txt";
  clitest::writeFile(file, kLine + "\n");
  const auto r = run({"tessellate", "-e", kLine, file});
  CHECK(r.status == 2);
  CHECK(r.err.find("either INPUT or --patch") != std::string::npos);
  CHECK(r.err.find("token") == std::string::npos);
  CHECK(run({"tessellate", "-e", kLine, "-e", kLine}).status == 0); // -e stays repeatable
}

TEST_CASE("input: directories are called directories", "[cli][input]") {
  const std::string dir = clitest::tmpDir() + "/a-directory";
  ::mkdir(dir.c_str(), 0755);
  auto r = run({"check", dir});
  CHECK(r.status == 2);
  CHECK(r.err.find("directory") != std::string::npos);
  CHECK(r.err.find("missing table") == std::string::npos);
  r = run({"check", kLuna, "--set", "displacement.file=\"" + dir + "\""});
  CHECK(r.status == 2);
  CHECK(r.err.find("is a directory") != std::string::npos);
  CHECK(r.err.find("9223372036854775807") == std::string::npos);
}

TEST_CASE("input: a wrong factor count names a token", "[cli][input]") {
  const auto r = run({"tessellate"}, "quad integer triangle_cw hw 4 4 4 4 4\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("token 9 '4': expected 6 factors") != std::string::npos);
}

TEST_CASE("input: raw bytes are escaped and huge tokens cut on stderr", "[cli][input]") {
  const std::string bad = "lod.\xff\xfe\x01\x1b[31m=1";
  auto r = run({"check", kScene, "--set", bad});
  CHECK(r.status == 2);
  CHECK(clean(r.err));
  CHECK(r.err.find("\\xff") != std::string::npos);
  r = run({"tessellate", "-e", "quad\xff\x1b integer triangle_cw hw 4 4 4 4 4 4"});
  CHECK(r.status == 2);
  CHECK(clean(r.err));
  const std::string huge(100000, 'k');
  r = run({"check", kScene, "--set", "lod." + huge + "=1"});
  CHECK(r.status == 2);
  CHECK(r.err.size() < 2000);
  CHECK(lines(r.err) == 1);
  r = run({"tessellate", "-e", "quad integer triangle_cw hw 4 4 " + huge + " 4 4 4"});
  CHECK(r.status == 2);
  CHECK(r.err.size() < 2000);
  const std::string scene = clitest::tmpDir() + "/bytes.toml";
  clitest::writeFile(scene, "name = \"x\"\n[layout]\nkind = \"\xc3\x28\xff" + huge + "\"\n");
  r = run({"check", scene});
  CHECK(r.status == 2);
  CHECK(clean(r.err));
  CHECK(r.err.size() < 2000);
}
