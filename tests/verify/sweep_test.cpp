// Sweep driver and camera generators: deterministic cameras, threads give the same results as one thread,
// progress is reported per camera, cancel stops early.
#include "verify_test_util.h"

#include <atomic>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

using namespace fftess::verify;
using namespace fftess::verify::test;

TEST_CASE("camera generators are deterministic and sized", "[verify][sweep]") {
  Scene s = loadExample("rings_small.toml");
  const Terrain terrain = prepared(s);
  CHECK(randomCameras(terrain, 17, 5).size() == 17);
  CHECK(orbitCameras(terrain, 9).size() == 9);
  CHECK(flyoverCameras(terrain, 4).size() == 4);
  CHECK(pathCameras(terrain).size() == 1);
  auto a = randomCameras(terrain, 10, 42), b = randomCameras(terrain, 10, 42), c = randomCameras(terrain, 10, 43);
  for (size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].eye.x == b[i].eye.x);
    CHECK(a[i].target.z == b[i].target.z);
    CHECK(a[i].width == s.camera.width);
  }
  CHECK(a[0].eye.x != c[0].eye.x);
  const Extent e = terrain.extent();
  for (const Camera& cam : randomCameras(terrain, 200, 7)) {
    CHECK(cam.eye.x >= e.minX);
    CHECK(cam.eye.x <= e.maxX);
    CHECK(cam.eye.y > 0);
  }
}

namespace {

// FNV-1a over the bits of each camera's eye, target, up, fov, near and far.
uint64_t cameraHash(const std::vector<Camera>& cams) {
  uint64_t h = 1469598103934665603ull;
  for (const Camera& c : cams) {
    const float f[] = {c.eye.x, c.eye.y, c.eye.z, c.target.x, c.target.y, c.target.z,
                       c.up.x,  c.up.y,  c.up.z,  c.fovY,     c.nearZ,    c.farZ};
    unsigned char b[sizeof f];
    std::memcpy(b, f, sizeof f);
    for (unsigned char x : b) h = (h ^ x) * 1099511628211ull;
  }
  return h;
}

std::vector<Camera> all(const CameraSet& set) {
  std::vector<Camera> out;
  for (size_t i = 0; i < set.size(); ++i) out.push_back(set.at(i));
  return out;
}

} // namespace

// Golden: the hashes are those of the cameras the generators made before CameraSet (every camera generated in one
// loop, the random ones from one running splitmix64 state), so sweeps, shards and golden reports keep their cameras.
TEST_CASE("camera sets by index are the cameras the generators always made", "[verify][sweep]") {
  const Terrain terrain = prepared(loadExample("rings_small.toml"));
  CHECK(cameraHash(all(CameraSet::random(terrain, 1000, 7))) == 0xcffe029e8ff9356dull);
  CHECK(cameraHash(all(CameraSet::orbit(terrain, 100))) == 0x6a68f00765d32d09ull);
  CHECK(cameraHash(all(CameraSet::flyover(terrain, 100))) == 0x982323460fb32557ull);
  // Far into a huge set without making the cameras before it: camera 2999999 of seed 20260611.
  const CameraSet huge = CameraSet::random(terrain, 100000000, 20260611);
  CHECK(huge.size() == 100000000);
  CHECK(cameraHash({huge.at(2999999)}) == 0x71f23a4796add795ull);
  // The vector generators are the sets, camera for camera.
  CHECK(cameraHash(randomCameras(terrain, 1000, 7)) == 0xcffe029e8ff9356dull);
  CHECK(cameraHash(orbitCameras(terrain, 7, 30.0f, 12.0f)) == cameraHash(all(CameraSet::orbit(terrain, 7, 30.0f, 12.0f))));
  CHECK(cameraHash(flyoverCameras(terrain, 1)) == cameraHash(all(CameraSet::flyover(terrain, 1))));
  CHECK(cameraHash(pathCameras(terrain)) == cameraHash(all(CameraSet::path(terrain))));
}

TEST_CASE("sweep over cameras by index makes only the cameras it checks", "[verify][sweep]") {
  const Terrain terrain = prepared(loadExample("rings_small.toml"));
  const CameraSet set = CameraSet::random(terrain, 100000000, 1);
  std::atomic<bool> cancel{false};
  std::atomic<size_t> made{0};
  SweepOptions so;
  so.threads = 2;
  so.cancel = &cancel;
  so.keepCameras = false;
  so.progress = [&](size_t done, size_t total) {
    CHECK(total == set.size());
    if (done >= 5) cancel = true;
  };
  const SweepResult r = sweep(terrain, set.size(), [&](size_t i) { return ++made, set.at(i); }, {}, so);
  CHECK(r.cancelled);
  CHECK(r.camerasDone >= 5);
  CHECK(made.load() <= r.camerasDone + 2); // one more per thread at most
  CHECK(r.cameras.empty());
}

TEST_CASE("scene camera path", "[verify][sweep]") {
  SceneResult r = parseScene(R"([layout]
kind = "grid"
[lod]
scheme = "constant"
[tessellation]
partitioning = "integer"
[camera]
eye = [0.0, 5.0, -5.0]
target = [0.0, 0.0, 0.0]
[[camera_path]]
eye = [1.0, 5.0, -5.0]
[[camera_path]]
eye = [2.0, 5.0, -5.0]
fov_y = 45.0
)",
                             "path.toml");
  INFO(r.error);
  REQUIRE(r.ok);
  auto cams = pathCameras(prepared(r.scene));
  REQUIRE(cams.size() == 2);
  CHECK(cams[1].eye.x == 2.0f);
  CHECK(cams[1].fovY == 45.0f);
  CHECK(cams[0].fovY == 60.0f);
  CHECK(cams[0].target.z == 0.0f);
}

TEST_CASE("sweep on threads equals one thread, with progress", "[verify][sweep]") {
  Scene s = loadExample("rings_small.toml", {"lod.adjacency_clamp=integer"});
  const Terrain terrain = prepared(s);
  auto cams = randomCameras(terrain, 24, 99);
  SweepOptions one, two;
  one.threads = 1;
  two.threads = 2;
  std::vector<size_t> seen;
  two.progress = [&](size_t done, size_t total) {
    CHECK(total == cams.size());
    seen.push_back(done);
  };
  SweepResult a = sweep(terrain, cams, {}, one), b = sweep(terrain, cams, {}, two);
  CheckOptions all;
  all.countOffScreen = true; // every finding counts, on screen or not
  SweepResult c = sweep(terrain, cams, all, one);
  REQUIRE(seen.size() == cams.size());
  for (size_t i = 0; i < seen.size(); ++i) CHECK(seen[i] == i + 1);
  CHECK(a.camerasDone == cams.size());
  CHECK(b.camerasDone == cams.size());
  CHECK_FALSE(b.cancelled);
  CHECK(a.total.cracks == b.total.cracks);
  CHECK(a.total.edgesChecked == b.total.edgesChecked);
  CHECK(a.total.worstGapWorld == b.total.worstGapWorld);
  CHECK(a.total.cracks > 0);
  for (size_t i = 0; i < cams.size(); ++i) {
    CHECK(a.cameras[i].stats.cracks == b.cameras[i].stats.cracks);
    // A camera's worst is chosen among the findings that count: by default those on screen (the expectation was
    // stats.cracks > 0 before findings knew whether they are on screen; with countOffScreen it still is).
    CHECK(a.cameras[i].hasFinding == (a.cameras[i].stats.cracksOnScreen() + a.cameras[i].stats.tJunctionsOnScreen() > 0));
    CHECK(c.cameras[i].hasFinding == (c.cameras[i].stats.cracks > 0));
    CHECK(c.cameras[i].stats.cracks == a.cameras[i].stats.cracks); // the report is the same either way
    // The same as checking the camera alone.
    if (i < 3) CHECK(checkScene(terrain, cams[i]).stats.cracks == a.cameras[i].stats.cracks);
  }
}

TEST_CASE("sweep cancel stops early", "[verify][sweep]") {
  Scene s = loadExample("rings_small.toml");
  const Terrain terrain = prepared(s);
  auto cams = randomCameras(terrain, 200, 1);
  std::atomic<bool> cancel{false};
  SweepOptions so;
  so.threads = 2;
  so.cancel = &cancel;
  so.progress = [&](size_t done, size_t) {
    if (done >= 3) cancel = true;
  };
  SweepResult r = sweep(terrain, cams, {}, so);
  CHECK(r.cancelled);
  CHECK(r.camerasDone >= 3);
  CHECK(r.camerasDone < cams.size());
  size_t done = 0;
  for (const CameraResult& c : r.cameras) done += c.done;
  CHECK(done == r.camerasDone);
}

namespace {

// What a test keeps of one camera's report: its stats and every finding's sides, verdict and gap.
struct ReportDigest {
  int calls = 0;
  std::string error;
  int64_t edgesChecked = -1, cracks = -1, tJunctions = -1;
  std::vector<std::tuple<int, int, int, int, int, double>> findings;
};

std::vector<ReportDigest> reportsOf(const Scene& s, const std::vector<Camera>& cams, int threads, int& maxConcurrent,
                                    SweepResult& result) {
  std::vector<ReportDigest> got(cams.size());
  std::atomic<int> active{0};
  std::atomic<int> most{0};
  SweepOptions so;
  so.threads = threads;
  so.keepReports = true;
  // No Catch2 assertions in here: the callback runs on worker threads.
  so.onReport = [&](size_t i, const Report& r) {
    const int now = ++active;
    if (now > most) most = now;
    if (i < got.size()) {
      ReportDigest& d = got[i];
      ++d.calls;
      d.error = r.error;
      d.edgesChecked = r.stats.edgesChecked;
      d.cracks = r.stats.cracks;
      d.tJunctions = r.stats.tJunctions;
      for (const Finding& f : r.findings)
        d.findings.emplace_back(static_cast<int>(f.classification), f.a.patch.index, f.a.edge, f.b.patch.index, f.b.edge,
                                f.gapWorld);
    }
    --active;
  };
  result = sweep(prepared(s), cams, {}, so);
  maxConcurrent = most;
  return got;
}

} // namespace

TEST_CASE("sweep onReport: every camera once, serialised, the same reports on 1 and 2 threads", "[verify][sweep]") {
  Scene s = loadExample("rings_small.toml", {"lod.adjacency_clamp=integer"});
  auto cams = randomCameras(prepared(s), 24, 99);
  int concurrentOne = 0, concurrentTwo = 0;
  SweepResult a, b;
  const std::vector<ReportDigest> one = reportsOf(s, cams, 1, concurrentOne, a);
  const std::vector<ReportDigest> two = reportsOf(s, cams, 2, concurrentTwo, b);
  CHECK(concurrentOne == 1);
  CHECK(concurrentTwo == 1); // serialised by sweep
  REQUIRE(one.size() == cams.size());
  int64_t findings = 0;
  for (size_t i = 0; i < cams.size(); ++i) {
    INFO("camera " << i);
    CHECK(one[i].calls == 1);
    CHECK(two[i].calls == 1);
    CHECK(one[i].error.empty());
    CHECK(one[i].edgesChecked == two[i].edgesChecked);
    CHECK(one[i].cracks == two[i].cracks);
    CHECK(one[i].tJunctions == two[i].tJunctions);
    CHECK(one[i].findings == two[i].findings);
    // The callback sees the report the sweep keeps and summarises.
    CHECK(one[i].cracks == a.cameras[i].stats.cracks);
    CHECK(one[i].findings.size() == a.reports[i].findings.size());
    if (!a.reports[i].truncated)
      CHECK(static_cast<int64_t>(one[i].findings.size()) == one[i].cracks + one[i].tJunctions);
    findings += static_cast<int64_t>(one[i].findings.size());
  }
  CHECK(findings > 0);
}

TEST_CASE("sweep onReport: cancelled sweeps report exactly the cameras done", "[verify][sweep]") {
  Scene s = loadExample("rings_small.toml");
  const Terrain terrain = prepared(s);
  auto cams = randomCameras(terrain, 200, 1);
  std::atomic<bool> cancel{false};
  std::vector<int> calls(cams.size(), 0);
  SweepOptions so;
  so.threads = 2;
  so.cancel = &cancel;
  so.onReport = [&](size_t i, const Report&) { ++calls[i]; };
  so.progress = [&](size_t done, size_t) {
    if (done >= 3) cancel = true;
  };
  SweepResult r = sweep(terrain, cams, {}, so);
  CHECK(r.cancelled);
  for (size_t i = 0; i < cams.size(); ++i) {
    INFO("camera " << i);
    CHECK(calls[i] == (r.cameras[i].done ? 1 : 0));
  }
}

TEST_CASE("sweep: an invalid camera is reported and the sweep is not clean", "[verify][sweep][verdict]") {
  const Scene s = loadExample("rings_small.toml");
  const Terrain t = prepared(s);
  std::vector<Camera> cams = randomCameras(t, 3, 7);
  Camera bad = cams[0];
  bad.target = bad.eye; // nothing to look at
  cams.insert(cams.begin() + 1, bad);
  const SweepResult r = sweep(t, cams);
  CHECK(r.camerasDone == 3);
  CHECK(r.camerasInvalid == 1);
  CHECK(!r.cameras[1].done);
  CHECK(r.cameras[1].error.find("camera.target") != std::string::npos);
  CHECK(verdictOf(r.total) == Verdict::Watertight); // what was checked is clean...
  CHECK(verdictOf(r) == Verdict::Unchecked);        // ...but the sweep is not
  // All cameras invalid: nothing checked at all.
  const SweepResult none = sweep(t, {bad, bad});
  CHECK(none.camerasDone == 0);
  CHECK(verdictOf(none) == Verdict::Unchecked);
}

TEST_CASE("sweep: cameras that classify no shared edge make a not-clean verdict", "[verify][sweep][verdict]") {
  const Scene s = loadExample("rings_small.toml");
  const Terrain t = prepared(s);
  Camera sky = s.camera;
  sky.eye = {0.0f, 200.0f, 0.0f};
  sky.target = {0.0f, 400.0f, 1.0f};
  const SweepResult r = sweep(t, {sky});
  CHECK(r.camerasDone == 1);
  CHECK(r.camerasNothingChecked == 1);
  CHECK(r.total.edgesChecked == 0);
  CHECK(verdictOf(r) == Verdict::NothingChecked);
  // One camera that sees the terrain makes the sweep watertight again; the other is counted.
  const SweepResult mixed = sweep(t, {sky, s.camera});
  CHECK(mixed.camerasNothingChecked == 1);
  CHECK(verdictOf(mixed) == Verdict::Watertight);
}
