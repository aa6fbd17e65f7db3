// --cameras FILE (check and sweep): the CSV and JSON examples of docs/cli.md give the report of the equivalent
// [[camera_path]] scene; each refusal of a bad file names FILE:LINE:FIELD, exits 2 and writes nothing; shards of a
// sweep over a camera file merge, shards over different files do not.
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>

using clitest::run;
using json = nlohmann::ordered_json;

namespace {

const std::string kRings = clitest::source("docs/examples/rings_small.toml");
const std::string kCsv = clitest::source("docs/examples/cameras.csv");
const std::string kJson = clitest::source("docs/examples/cameras.json");

// The cameras of docs/examples/cameras.csv / .json as a scene's [[camera_path]] (missing keys from [camera]).
const char* const kPath = R"(
[[camera_path]]
eye = [10.0, 25.0, -70.0]
target = [0.0, 0.0, 0.0]
fov_y = 60.0
convention = "gl"

[[camera_path]]
eye = [-40.0, 18.0, -30.0]
target = [0.0, 0.0, 0.0]
convention = "d3d"

[[camera_path]]
eye = [30.0, 12.0, 40.0]
target = [5.0, 0.0, 5.0]
fov_y = 45.0

[[camera_path]]
eye = [0.0, 60.0, -5.0]
target = [0.0, -2.0, 0.0]
fov_y = 70.0
)";

// A report without what names the cameras' source or the scene's file (the path scene is another file), and without
// what the result cache's timing on two threads decides (which camera's check found a pair in the cache first: the
// work counters and the cache's; the findings and stats do not depend on it).
json withoutSource(json j) {
  for (const char* k : {"cameras_source", "cameras_source_text", "cameras_file", "scene", "scene_hash", "work",
                        "result_cache"})
    j.erase(k);
  return j;
}

json sweepReport(const std::vector<std::string>& extra, const std::string& scene, const std::string& out) {
  std::vector<std::string> args{"sweep", scene, "--set", "lod.adjacency_clamp=none", "-q", "--threads", "2",
                                "--json", out};
  args.insert(args.end(), extra.begin(), extra.end());
  const clitest::Result r = run(args);
  INFO(r.err);
  REQUIRE(r.status <= 1);
  return json::parse(clitest::readFile(out));
}

} // namespace

TEST_CASE("sweep --cameras with the CSV and the JSON example gives the report of the equivalent camera path",
          "[cli][cameras]") {
  const std::string dir = clitest::tmpDir();
  const std::string pathScene = dir + "/rings_path.toml";
  clitest::writeFile(pathScene, clitest::readFile(kRings) + kPath);
  const json path = sweepReport({}, pathScene, dir + "/path.json");
  const json csv = sweepReport({"--cameras", kCsv}, kRings, dir + "/csv.json");
  const json js = sweepReport({"--cameras", kJson}, kRings, dir + "/js.json");
  REQUIRE(path.at("cameras").size() == 4);
  REQUIRE(path.at("stats").at("cracks").get<int64_t>() > 0); // findings take part in the comparison
  CHECK(csv.at("cameras_source") == "file");
  CHECK(csv.at("cameras_source_text").get<std::string>().find("cameras.csv") != std::string::npos);
  CHECK(csv.at("cameras_file").at("cameras") == 4);
  CHECK(js.at("cameras_file").at("path") == kJson);
  CHECK(withoutSource(csv) == withoutSource(path));
  CHECK(withoutSource(js) == withoutSource(path));
  // docs/cli.md shows these very files.
  const std::string docs = clitest::readFile(clitest::source("docs/cli.md"));
  CHECK(docs.find(clitest::readFile(kCsv)) != std::string::npos);
  CHECK(docs.find(clitest::readFile(kJson)) != std::string::npos);
}

TEST_CASE("a spreadsheet's CSV (byte order mark, CRLF, quotes, comments) gives the report of the plain file",
          "[cli][cameras]") {
  const std::string dir = clitest::tmpDir();
  // docs/examples/cameras.csv as a spreadsheet writes it, with a comment above the header and between rows.
  std::string sheet = "\xEF\xBB\xBF# exported cameras\r\n";
  const std::string plain = clitest::readFile(kCsv);
  size_t start = 0;
  for (int row = 0; start < plain.size(); ++row) {
    size_t end = plain.find('\n', start);
    if (end == std::string::npos) end = plain.size();
    std::string line = plain.substr(start, end - start), quoted;
    start = end + 1;
    if (line.empty()) continue;
    size_t f = 0;
    for (;;) { // every field in quotes, an empty one as ""
      const size_t comma = line.find(',', f);
      quoted += "\"" + line.substr(f, comma == std::string::npos ? std::string::npos : comma - f) + "\"";
      if (comma == std::string::npos) break;
      quoted += ", ";
      f = comma + 1;
    }
    sheet += quoted + "\r\n" + (row == 1 ? "# the d3d camera above\r\n\r\n" : "");
  }
  const std::string sheetPath = dir + "/sheet.csv";
  clitest::writeFile(sheetPath, sheet);
  const json csv = sweepReport({"--cameras", kCsv}, kRings, dir + "/plain.json");
  const json fromSheet = sweepReport({"--cameras", sheetPath}, kRings, dir + "/sheet.json");
  CHECK(fromSheet.at("cameras_file").at("cameras") == 4);
  CHECK(withoutSource(fromSheet) == withoutSource(csv));
}

TEST_CASE("check --cameras takes a file of one camera or the camera --camera-index names", "[cli][cameras]") {
  const std::string dir = clitest::tmpDir();
  const std::string pathScene = dir + "/rings_path1.toml";
  clitest::writeFile(pathScene, clitest::readFile(kRings) + kPath);
  // Camera 1 (the D3D one) of the file is camera 1 of the path.
  auto report = [&](std::vector<std::string> args, const std::string& out) {
    args.insert(args.end(), {"--set", "lod.adjacency_clamp=none", "-q", "--json", out});
    const clitest::Result r = run(args);
    INFO(r.err);
    REQUIRE(r.status <= 1);
    return json::parse(clitest::readFile(out));
  };
  const json byPath = report({"check", pathScene, "--path-camera", "1"}, dir + "/c_path.json");
  const json byFile = report({"check", kRings, "--cameras", kCsv, "--camera-index", "1"}, dir + "/c_csv.json");
  CHECK(byFile.at("camera").at("convention") == "d3d");
  CHECK(byFile.at("cameras_file").at("index") == 1);
  CHECK(byFile.at("cameras_file").at("line") == 3);
  CHECK(withoutSource(byFile) == withoutSource(byPath));
  // Several cameras without --camera-index, an index past the end, --camera-index alone: usage errors.
  clitest::Result r = run({"check", kRings, "--cameras", kCsv});
  CHECK(r.status == 2);
  CHECK(r.err.find("holds 4 cameras") != std::string::npos);
  CHECK(run({"check", kRings, "--cameras", kCsv, "--camera-index", "4"}).status == 2);
  CHECK(run({"check", kRings, "--camera-index", "0"}).status == 2);
  CHECK(run({"check", kRings, "--cameras", kCsv, "--path-camera", "0", "--camera-index", "0"}).status == 2);
  CHECK(run({"sweep", kRings, "--cameras", kCsv, "--orbit", "3"}).status == 2);
}

TEST_CASE("each bad camera file is refused with its file, line and field, exit 2 and nothing written",
          "[cli][cameras]") {
  const std::string dir = clitest::tmpDir();
  struct Case {
    const char* file;
    const char* where; // FILE:LINE[:FIELD] after the file's folder
    const char* what;
  };
  const Case cases[] = {
      {"missing_column.csv", "missing_column.csv:1:target_z: ", "missing column"},
      {"bad_number.csv", "bad_number.csv:3:eye_y: ", "\"2x5\" is not a number"},
      {"non_finite.csv", "non_finite.csv:4:eye_z: ", "\"inf\" is not a finite number"},
      {"eye_equals_target.csv", "eye_equals_target.csv:2:target: ", "equals camera.eye"},
      {"unknown_convention.csv", "unknown_convention.csv:3:convention: ", "unknown value \"vulkan\""},
      {"not_array.json", "not_array.json:1: ", "expected a JSON array of camera objects, got an object"},
      {"wrong_type.json", "wrong_type.json:4:target_y: ", "expected a number, got a string"},
  };
  for (const Case& c : cases) {
    INFO(c.file);
    const std::string file = clitest::source(std::string("tests/cli/data/cameras/") + c.file);
    for (const char* command : {"check", "sweep"}) {
      const std::string out = dir + "/bad_" + c.file + "_" + command + ".json";
      const clitest::Result r = run({command, kRings, "--cameras", file, "--json", out});
      INFO(command << ": " << r.err);
      CHECK(r.status == 2);
      CHECK(r.err.find(std::string(c.where) + c.what) != std::string::npos);
      CHECK_FALSE(clitest::fileExists(out));
    }
  }
}

// Issue [8/8]: `--cameras /dev/zero` read gigabytes; a directory was called an "empty file".
TEST_CASE("a camera file that never ends, is too large or is a directory is refused at once, exit 2",
          "[cli][cameras]") {
  const std::string dir = clitest::tmpDir();
  const std::string big = dir + "/big_cameras.csv"; // a valid header, then more than 64 MiB of rows
  {
    std::FILE* f = std::fopen(big.c_str(), "wb");
    REQUIRE(f);
    std::fputs("eye_x,eye_y,eye_z,target_x,target_y,target_z\n", f);
    const std::string row = "10,25,-70,0,0,0\n";
    for (size_t n = 0; n < (size_t(64) << 20) / row.size() + 1; ++n) std::fputs(row.c_str(), f);
    std::fclose(f);
  }
  struct Case {
    std::string file, what;
  };
  const Case cases[] = {{"/dev/zero", "': larger than 67108864 bytes (64 MiB, the limit for a camera file)"},
                        {big, "': larger than 67108864 bytes (64 MiB, the limit for a camera file)"},
                        {dir, "': is a directory, not a camera file"}};
  for (const Case& c : cases)
    for (const char* command : {"check", "sweep"}) {
      const std::string out = dir + "/refused_" + command + ".json";
      const clitest::Result r = run({command, kRings, "--cameras", c.file, "--json", out});
      INFO(command << " " << c.file << ": " << r.err);
      CHECK(r.status == 2);
      CHECK(r.err.find("--cameras '") != std::string::npos);
      CHECK(r.err.find(c.what) != std::string::npos);
      CHECK_FALSE(clitest::fileExists(out));
    }
  std::remove(big.c_str());
}

TEST_CASE("shards of a sweep over a camera file merge into the single run, shards over other files are refused",
          "[cli][cameras][merge]") {
  const std::string dir = clitest::tmpDir();
  const std::string single = dir + "/m_single.json";
  // --no-result-cache: byte for byte (with the cache each shard's work counters are its own cache's).
  sweepReport({"--cameras", kCsv, "--no-result-cache"}, kRings, single);
  const std::string s1 = dir + "/m_s1.json", s2 = dir + "/m_s2.json", merged = dir + "/m_merged.json";
  sweepReport({"--cameras", kCsv, "--shard", "1/2", "--no-result-cache"}, kRings, s1);
  sweepReport({"--cameras", kCsv, "--shard", "2/2", "--no-result-cache"}, kRings, s2);
  CHECK(run({"merge", s1, s2, "--json", merged}).status == 1);
  CHECK(clitest::readFile(merged) == clitest::readFile(single));
  // The same path with other contents: the file's hash differs.
  const std::string copy = dir + "/cams.csv", other = dir + "/m_other.json";
  clitest::writeFile(copy, clitest::readFile(kCsv));
  const std::string c1 = dir + "/m_c1.json";
  sweepReport({"--cameras", copy, "--shard", "1/2"}, kRings, c1);
  // The same count of cameras (so the same cameras_source), one eye moved: only the hash tells them apart.
  std::string moved = clitest::readFile(kCsv);
  const size_t at = moved.find("0,0,0,10,25,-70");
  REQUIRE(at != std::string::npos);
  moved.replace(at, 15, "0,0,0,11,25,-70");
  clitest::writeFile(copy, moved);
  sweepReport({"--cameras", copy, "--shard", "2/2"}, kRings, other);
  const clitest::Result r = run({"merge", c1, other, "--json", dir + "/m_bad.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("\"cameras_file\" differs") != std::string::npos);
}
