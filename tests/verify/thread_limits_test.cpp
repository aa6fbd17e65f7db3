// A thread the system will not start (issue [8/8]: `sweep -j 100000` and `prove -j 100000` ended in std::terminate,
// exit 134, no message). The failure is made real, not mocked: the process's default thread stack is set to 2^47
// bytes (pthread_setattr_default_np, glibc), more than the user address space, so std::thread's constructor throws
// std::system_error for every new thread. Each pool must then stop what it started, join it and throw one
// std::runtime_error naming the thread, never terminate.
#include "verify_test_util.h"

#include "base/threads.h"
#include "tessellator/parallel.h"
#include "verify/prove.h"
#include "verify/sweep.h"

#include <pthread.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace fftess;
using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

// While alive, no new thread can start in this process (the previous default attributes come back after).
struct NoNewThreads {
  pthread_attr_t saved{};
  bool ok = false;
  NoNewThreads() {
    ok = pthread_getattr_default_np(&saved) == 0;
    pthread_attr_t huge;
    pthread_attr_init(&huge);
    ok = ok && pthread_attr_setstacksize(&huge, size_t(1) << 47) == 0 && pthread_setattr_default_np(&huge) == 0;
    pthread_attr_destroy(&huge);
  }
  ~NoNewThreads() {
    if (ok) pthread_setattr_default_np(&saved);
    pthread_attr_destroy(&saved);
  }
};

// What a pool's exception says, or "" when it threw nothing.
template <class F>
std::string failureOf(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

} // namespace

TEST_CASE("runOnThreads: every thread runs once, this one as 0", "[verify][threads]") {
  std::vector<std::atomic<int>> runs(7);
  bool stopped = false;
  runOnThreads(7, [&](int t) { ++runs[size_t(t)]; }, [&] { stopped = true; });
  for (const std::atomic<int>& r : runs) CHECK(r.load() == 1);
  CHECK_FALSE(stopped);
}

TEST_CASE("runOnThreads: a thread that cannot start stops the others and throws one message", "[verify][threads]") {
  NoNewThreads guard;
  REQUIRE(guard.ok);
  int ran = 0, stops = 0;
  const std::string why = failureOf([&] { runOnThreads(4, [&](int) { ++ran; }, [&] { ++stops; }); });
  CHECK(startsWith(why, "could not start thread 2 of 4: "));
  CHECK(ran == 0); // work(0) is not run when the pool is short
  CHECK(stops == 1);
  // One thread needs no new thread: it runs.
  CHECK(failureOf([&] { runOnThreads(1, [&](int) { ++ran; }, [&] { ++stops; }); }).empty());
  CHECK(ran == 1);
}

TEST_CASE("runOnThreads: an exception of this thread's work stops and joins the others first", "[verify][threads]") {
  std::atomic<bool> stop{false};
  std::atomic<int> joined{0};
  const std::string why = failureOf([&] {
    runOnThreads(
        3,
        [&](int t) {
          if (t == 0) throw std::runtime_error("work 0 failed");
          while (!stop.load()) std::this_thread::yield();
          ++joined;
        },
        [&] { stop = true; });
  });
  CHECK(why == "work 0 failed");
  CHECK(joined.load() == 2); // both others ended before the exception left runOnThreads
}

TEST_CASE("sweep, proveScene and tessellateBatch: a thread the system refuses is an exception, not std::terminate",
          "[verify][threads]") {
  const Terrain t = prepared(loadExample("grid.toml"));
  const std::vector<Camera> cams(8, t.scene().camera);
  NoNewThreads guard;
  REQUIRE(guard.ok);

  SweepOptions so;
  so.threads = 4;
  CHECK(startsWith(failureOf([&] { sweep(t, cams, {}, so); }), "could not start thread 2 of 4: "));
  so.threads = 1; // the calling thread alone: no thread to start, the sweep runs
  CHECK(sweep(t, cams, {}, so).camerasDone == cams.size());

  ProveOptions po;
  po.threads = 3;
  po.maxRegions = 4;
  CHECK(startsWith(failureOf([&] { proveScene(t, po); }), "could not start thread 2 of 3: "));

  std::vector<Patch> patches(16);
  for (Patch& p : patches)
    for (float& f : p.factors) f = 4;
  std::vector<BatchSlot> slots(patches.size());
  const BatchTotals totals = planBatch(patches.data(), patches.size(), slots.data());
  std::vector<DomainPoint> points(size_t(totals.points));
  std::vector<int32_t> indices(size_t(totals.indices));
  CHECK(startsWith(failureOf([&] {
                     tessellateBatch(patches.data(), patches.size(), slots.data(), points.data(), indices.data(), 4);
                   }),
                   "could not start thread 2 of 4: "));
}
