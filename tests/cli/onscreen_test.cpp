// On screen or not (docs/verify.md, "On screen"; docs/cli.md, --offscreen): check and sweep count what the camera
// sees; findings outside the view frustum are listed and counted apart; --offscreen counts them.
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <string>

using clitest::run;
using nlohmann::json;

namespace {

const std::string kScene = clitest::source("docs/examples/heightmap_offscreen.toml");

// The number after `key` in text (e.g. the pixels of "worst gap 1.22 world units, 8.09 pixels"); -1 if absent.
double numberAfter(const std::string& text, const std::string& key) {
  const size_t at = text.find(key);
  if (at == std::string::npos) return -1;
  return std::strtod(text.c_str() + at + key.size(), nullptr);
}

// The line of text that starts with `start` (after spaces), "" if none.
std::string lineOf(const std::string& text, const std::string& start) {
  size_t pos = 0;
  while (pos < text.size()) {
    const size_t end = text.find('\n', pos);
    const std::string line = text.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    if (line.find_first_not_of(' ') != std::string::npos && line.compare(line.find_first_not_of(' '), start.size(), start) == 0)
      return line;
    if (end == std::string::npos) break;
    pos = end + 1;
  }
  return "";
}

// The example scene with its camera path replaced by cameras that see none of the terrain's cracks.
std::string skyScene() {
  std::string text = clitest::readFile(kScene);
  const size_t path = text.find("[[camera_path]]");
  REQUIRE(path != std::string::npos);
  text = text.substr(0, path) +
         "[[camera_path]]\neye = [-250.0, 100.0, -250.0]\ntarget = [-400.0, 200.0, -400.0]\n\n"
         "[[camera_path]]\neye = [250.0, 100.0, 250.0]\ntarget = [400.0, 200.0, 400.0]\n";
  const std::string file = clitest::tmpDir() + "/sky.toml";
  clitest::writeFile(file, text);
  return file;
}

} // namespace

// The measured case: 112 cracks, 88 of them off screen; the farthest vertex of all (51 px) is off screen.
TEST_CASE("check: the worst gap is the worst on screen, off-screen cracks counted apart", "[cli][check][onscreen]") {
  const std::string js = clitest::tmpDir() + "/onscreen.json", svg = clitest::tmpDir() + "/onscreen.svg";
  auto r = run({"check", kScene, "--path-camera", "0", "--json", js, "--svg", svg});
  CHECK(r.status == 1);
  INFO(r.out);
  const std::string worst = lineOf(r.out, "worst gap");
  const double onScreenPixels = numberAfter(worst, "world units, ");
  CHECK(onScreenPixels > 0);
  CHECK(onScreenPixels < 10);
  CHECK(worst.find("(on screen)") != std::string::npos);
  CHECK(lineOf(r.out, "cracks").find("24 on screen (+ 88 off screen, not counted)") != std::string::npos);
  CHECK(lineOf(r.out, "off screen").find("the factors that made them belong to their camera") != std::string::npos);
  CHECK(lineOf(r.out, "verdict:") == "verdict: CRACKS (88 cracks off screen, not counted)");
  const json j = json::parse(clitest::readFile(js));
  CHECK(j.at("offscreen") == false);
  const json& st = j.at("stats");
  CHECK(st.at("cracks") == 112);
  CHECK(st.at("cracks_off_screen") == 88);
  CHECK(st.at("worst_gap_pixels_on_screen").get<double>() == Approx(onScreenPixels).epsilon(0.01));
  CHECK(st.at("worst_gap_pixels").get<double>() > 5 * onScreenPixels);
  int off = 0;
  for (const json& f : j.at("findings")) off += !f.at("on_screen").get<bool>();
  CHECK(off == 88);
  const std::string picture = clitest::readFile(svg);
  std::string why;
  CHECK(clitest::wellFormedXml(picture, why));
  CHECK(picture.find("class=\"off\"") != std::string::npos); // off-screen findings drawn apart
  CHECK(picture.find("88 off screen (grey, dashed: not counted)") != std::string::npos);

  // --offscreen: everything counts, the worst gap is the farthest vertex's.
  r = run({"check", kScene, "--path-camera", "0", "--offscreen", "--json", js});
  CHECK(r.status == 1);
  CHECK(numberAfter(lineOf(r.out, "worst gap"), "world units, ") == Approx(st.at("worst_gap_pixels").get<double>()).epsilon(0.01));
  CHECK(json::parse(clitest::readFile(js)).at("offscreen") == true);
}

TEST_CASE("check and sweep: cracks only off screen are not counted, --offscreen counts them", "[cli][sweep][onscreen]") {
  const std::string sky = skyScene();
  auto r = run({"check", sky, "--path-camera", "0"});
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK(lineOf(r.out, "verdict:").rfind("verdict: watertight (", 0) == 0);
  CHECK(lineOf(r.out, "verdict:").find("cracks off screen, not counted") != std::string::npos);
  CHECK(run({"check", sky, "--path-camera", "0", "--offscreen"}).status == 1);

  const std::string sweepSvg = clitest::tmpDir() + "/sky-sweep.svg";
  // --no-visible-first: the off-screen cracks are found (visible first would not look for them: the default run below).
  r = run({"sweep", sky, "-j", "1", "--svg", sweepSvg, "--no-visible-first"});
  CHECK(r.status == 0);
  std::string why;
  const std::string picture = clitest::readFile(sweepSvg);
  CHECK(clitest::wellFormedXml(picture, why));
  CHECK(picture.find("class=\"ok\"") != std::string::npos); // both cameras green: nothing they see is cracked
  CHECK(picture.find("class=\"bad\"") == std::string::npos);
  CHECK(lineOf(r.out, "verdict:").rfind("verdict: WATERTIGHT from all 2 cameras (", 0) == 0);
  CHECK(run({"sweep", sky, "-j", "1", "--offscreen"}).status == 1);
  // Visible first (the default): both cameras see no shared edge, so nothing they see was checked. The full check's
  // WATERTIGHT above rests on pairs proven off screen; visible first does not classify those and says so.
  r = run({"sweep", sky, "-j", "1"});
  CHECK(r.status == 1);
  CHECK(lineOf(r.out, "verdict:").find("NOTHING CHECKED") != std::string::npos);

  // Shards merge with the choice they were run with (the report's "offscreen").
  const std::string dir = clitest::tmpDir();
  for (const char* mode : {"", "--offscreen"}) {
    std::vector<std::string> merge{"merge"};
    for (const char* k : {"1/2", "2/2"}) {
      const std::string part = dir + "/sky_" + std::string(k).substr(0, 1) + (*mode ? "_all" : "") + ".json";
      // --no-visible-first: the shards classify the off-screen pairs (visible first would find nothing in view).
      std::vector<std::string> args{"sweep", sky, "-q", "--shard", k, "--json", part, "--no-visible-first"};
      if (*mode) args.push_back(mode);
      run(args);
      merge.push_back(part);
    }
    const auto m = run(merge);
    INFO(m.out);
    CHECK(m.status == (*mode ? 1 : 0));
  }
}

// The sweep headline was a vertex near the eye plane (thousands of pixels) that no camera sees.
TEST_CASE("sweep: the headline's worst gap is the worst on screen", "[cli][sweep][onscreen]") {
  const std::string js = clitest::tmpDir() + "/onscreen-sweep.json";
  // --no-visible-first: visible first does not look for the findings no camera sees, and this compares with them.
  const auto r = run({"sweep", kScene, "--random", "200", "--seed", "3", "-j", "2", "--json", js, "--no-visible-first"});
  CHECK(r.status == 1);
  const std::string verdict = lineOf(r.out, "verdict:");
  INFO(verdict);
  const double pixels = numberAfter(verdict, "world units, ");
  CHECK(pixels > 0);
  CHECK(pixels < 100);
  CHECK(verdict.find("worst gap on screen") != std::string::npos);
  const json j = json::parse(clitest::readFile(js));
  const json& st = j.at("stats");
  CHECK(st.at("worst_gap_pixels_on_screen").get<double>() == Approx(pixels).epsilon(0.01));
  CHECK(st.at("worst_gap_pixels").get<double>() > 1000); // the farthest vertex of all: off screen
  // Each camera's worst is a finding it sees.
  for (const json& c : j.at("cameras"))
    if (!c.at("worst").is_null()) CHECK(c.at("worst").at("on_screen") == true);
}
