// Paths and files named on the command line (issue 18): a path the user gave is printed whole in every message, at
// any length; outputs are compared with each other and with the inputs by the file they finally name; negative
// counts are refused; input that cannot be read is never taken for an empty input.
#include "run.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

using clitest::run;

namespace {

const std::string kScene = clitest::source("docs/examples/rings_small.toml");

// A directory under the system's temporary directory (not the checkout or the build tree, so the test is the same
// wherever the project is cloned), nested until its path is over 200 bytes. Removed with its files at the end.
struct LongDir {
  std::string root, path;
  explicit LongDir(size_t minLength = 200) {
    const char* t = std::getenv("TMPDIR");
    std::string tmpl = std::string(t && *t ? t : "/tmp") + "/fftess-long-path-XXXXXX";
    REQUIRE(::mkdtemp(tmpl.data()) != nullptr);
    root = path = tmpl;
    for (char c = 'a'; path.size() <= minLength; ++c) {
      path += "/" + std::string(60, c);
      REQUIRE(::mkdir(path.c_str(), 0755) == 0);
    }
  }
  ~LongDir() {
    for (std::string p = path; p.size() >= root.size(); p.erase(p.find_last_of('/'))) {
      for (const std::string& f : clitest::listDir(p)) ::unlink((p + "/" + f).c_str());
      ::rmdir(p.c_str());
      if (p == root) break;
    }
  }
};

} // namespace

TEST_CASE("paths: a path over 200 bytes is named whole in every message", "[cli][paths]") {
  const LongDir dir;
  REQUIRE(dir.path.size() > 200);
  const std::string missing = dir.path + "/missing-dir";
  struct Case {
    std::vector<std::string> args;
    std::string path; // must appear whole, quoted or not
  } cases[] = {
      {{"check", kScene, "-q", "--json", missing + "/r.json"}, missing + "/r.json"},
      {{"check", kScene, "-q", "--svg", missing + "/r.svg"}, missing + "/r.svg"},
      {{"sweep", kScene, "--orbit", "1", "-q", "--json", missing + "/s.json"}, missing + "/s.json"},
      {{"tessellate", "-e", "quad integer point hw 1 1 1 1 1 1", "-o", missing + "/t.txt"}, missing + "/t.txt"},
      {{"tessellate", dir.path + "/no-such-input.txt"}, dir.path + "/no-such-input.txt"},
      {{"merge", dir.path + "/no-such-report.json"}, dir.path + "/no-such-report.json"},
      {{"check", dir.path + "/no-such-scene.toml"}, dir.path + "/no-such-scene.toml"},
  };
  for (const Case& c : cases) {
    INFO(c.args[0] << " " << c.path);
    const auto r = run(c.args);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find(c.path) != std::string::npos);
    CHECK(r.err.find("bytes)") == std::string::npos); // nothing cut
  }
  // And a long path works: the report is written there.
  const auto ok = run({"check", kScene, "-q", "--json", dir.path + "/r.json"});
  CHECK(ok.status == 0);
  CHECK(clitest::fileExists(dir.path + "/r.json"));
}

// The reports name the scene (SVG titles, merge's messages): a scene path of any length is written whole, and the
// documents stay well formed. (A 512-byte buffer once cut the SVG titles of checkouts under long paths mid-tag.)
TEST_CASE("paths: reports about a scene under a path over 600 bytes are whole and well formed", "[cli][paths]") {
  const LongDir dir(600);
  const std::string scene = dir.path + "/scene.toml";
  clitest::writeFile(scene, clitest::readFile(kScene));
  struct Case {
    std::vector<std::string> args;
    std::string svg;
  } cases[] = {
      {{"check", scene, "-q", "--svg", dir.path + "/c.svg"}, dir.path + "/c.svg"},
      {{"sweep", scene, "--orbit", "2", "-q", "--svg", dir.path + "/s.svg"}, dir.path + "/s.svg"},
      {{"bench", "--scene", scene, "--cameras", "1", "--mesh-cameras", "1", "--svg", dir.path + "/b.svg"},
       dir.path + "/b.svg"},
  };
  for (const Case& c : cases) {
    INFO(c.args[0]);
    const auto r = run(c.args);
    INFO(r.err);
    REQUIRE(r.status <= 1);
    const std::string text = clitest::readFile(c.svg);
    std::string why;
    CHECK(clitest::wellFormedXml(text, why));
    INFO(why);
    CHECK(text.find(scene) != std::string::npos);
  }
  // merge names both shards whole when their scene contents differ.
  const std::string a = dir.path + "/shard1.json", b = dir.path + "/shard2.json";
  REQUIRE(run({"sweep", scene, "--orbit", "2", "--shard", "1/2", "-q", "--json", a}).status <= 1);
  clitest::writeFile(scene, clitest::readFile(kScene) + "\n# edited between the shards\n");
  REQUIRE(run({"sweep", scene, "--orbit", "2", "--shard", "2/2", "-q", "--json", b}).status <= 1);
  const auto m = run({"merge", a, b});
  INFO(m.err);
  CHECK(m.status == 2);
  CHECK(m.err.find("'" + b + "': scene_hash") != std::string::npos);
  CHECK(m.err.find("differs from '" + a + "'") != std::string::npos);
}

TEST_CASE("outputs: the same file twice, or an input, is refused naming both", "[cli][paths]") {
  const std::string d = clitest::tmpDir() + "/same-files";
  ::mkdir(d.c_str(), 0755);
  const std::string scene = d + "/scene.toml", target = d + "/target.json", link = d + "/link.json";
  clitest::writeFile(scene, clitest::readFile(kScene));
  clitest::writeFile(target, "{\"keep\": true}\n");
  ::unlink(link.c_str());
  REQUIRE(::symlink("target.json", link.c_str()) == 0);
  const std::string sceneText = clitest::readFile(scene);
  const std::string batch = d + "/in.txt";
  clitest::writeFile(batch, "quad integer point hw 1 1 1 1 1 1\n");
  struct Case {
    std::vector<std::string> args;
    std::vector<std::string> mentions;
  } cases[] = {
      {{"check", scene, "-q", "--json", link, "--svg", target}, {"--json '" + link + "'", "--svg '" + target + "'"}},
      {{"sweep", scene, "--orbit", "1", "-q", "--json", link, "--svg", target}, {"--json", "--svg", "same file"}},
      {{"check", scene, "-q", "--json", d + "/../same-files/new.json", "--svg", d + "/new.json"}, {"--json", "--svg"}},
      {{"check", scene, "-q", "--json", scene}, {"--json '" + scene + "'", "SCENE"}},
      {{"sweep", scene, "--orbit", "1", "-q", "--svg", d + "/./scene.toml"}, {"--svg", "SCENE"}},
      {{"tessellate", batch, "-o", batch}, {"-o", "INPUT"}},
      {{"merge", target, "--json", link}, {"--json", "REPORT"}},
  };
  for (const Case& c : cases) {
    std::string joined;
    for (const auto& a : c.args) joined += a + " ";
    INFO(joined);
    const auto r = run(c.args);
    INFO(r.err);
    CHECK(r.status == 2);
    for (const std::string& m : c.mentions) CHECK(r.err.find(m) != std::string::npos);
    CHECK(clitest::readFile(target) == "{\"keep\": true}\n");
    CHECK(clitest::readFile(scene) == sceneText);
    CHECK(clitest::readFile(batch) == "quad integer point hw 1 1 1 1 1 1\n");
    CHECK_FALSE(clitest::fileExists(d + "/new.json"));
  }
  for (const std::string& f : clitest::listDir(d)) CHECK(f.find(".tmp.") == std::string::npos);
  // Several outputs to /dev/null are fine (a device is never replaced).
  CHECK(run({"check", scene, "-q", "--json", "/dev/null", "--svg", "/dev/null"}).status == 0);
}

TEST_CASE("counts: negative camera counts and camera numbers are refused, naming the option", "[cli][paths]") {
  struct Case {
    std::vector<std::string> args;
    const char* mention;
  } cases[] = {
      {{"sweep", kScene, "--random", "-1"}, "--random -1"},
      {{"sweep", kScene, "--flyover", "-1"}, "--flyover -1"},
      {{"sweep", kScene, "--orbit", "-1"}, "--orbit -1"},
      {{"sweep", kScene, "--random", "-5"}, "--random -5"},
      {{"check", kScene, "--path-camera", "-1"}, "--path-camera -1"},
  };
  for (const Case& c : cases) {
    INFO(c.mention);
    const auto r = run(c.args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(c.mention) != std::string::npos);
  }
}

TEST_CASE("tessellate: input that cannot be read is an error naming it, never an empty input", "[cli][paths]") {
  // /dev/zero: one endless line (it once grew until memory ran out, then ended as if the input were empty).
  auto r = run({"tessellate", "/dev/zero"});
  CHECK(r.status == 2);
  CHECK(r.err.find("'/dev/zero':1: line longer than") != std::string::npos);
  CHECK(r.out.empty());
  // Standard input closed (`<&-`): once read as an empty batch, exit 0.
  clitest::RunOptions o;
  o.closeStdin = true;
  r = clitest::runWith({"tessellate"}, o);
  CHECK(r.status == 2);
  CHECK(r.err.find("cannot read standard input") != std::string::npos);
  r = clitest::runWith({"tessellate", "-", "-o", clitest::tmpDir() + "/never.txt"}, o);
  CHECK(r.status == 2);
  CHECK_FALSE(clitest::fileExists(clitest::tmpDir() + "/never.txt"));
}
