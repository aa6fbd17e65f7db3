// fftess._fftess: the Python module (docs/python.md). The tessellator (tessellator/parallel.h: planBatch and
// tessellateBatch straight into NumPy arrays), and the check, sweep and compare reports (cli/report_api.h: the
// subcommands' own JSON text, parsed by Python's json module into the dict the --json file holds). A UsageError (the
// command line's exit 2) becomes ValueError with the same message; findings are in the dict, never an exception.
#include "report_api.h"

#include "common.h"

#include "base/threads.h"
#include "tessellator/names.h"
#include "tessellator/parallel.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace {

using namespace fftess;

static_assert(sizeof(DomainPoint) == 2 * sizeof(float), "DomainPoint is two floats: an (N, 2) float32 array");

// The factors each domain reads (tessellator.h, "Factor order").
int factorsOf(Domain d) { return d == Domain::Quad ? 6 : d == Domain::Tri ? 4 : 2; }

template <typename E>
E parseName(const std::string& what, const std::string& s, bool (*parse)(const char*, E&),
            const std::vector<std::string>& names) {
  E out{};
  if (!parse(s.c_str(), out))
    throw cli::UsageError(what + " " + cli::quoteToken(s) + ": expected " + joinNames(names, "|"));
  return out;
}

// The patches of one call: every row of factors with the same domain, partitioning, primitive and stage. factors:
// float32 (other dtypes cast by NumPy, as astype(np.float32)), shape (N, k) or (k,) with k the domain's factor count
// or 6 (the unused ones ignored).
std::vector<Patch> patchesOf(const std::string& domain, const std::string& partitioning, const std::string& primitive,
                             const std::string& stage, const py::array_t<float, py::array::c_style | py::array::forcecast>& f) {
  Patch proto;
  proto.domain = parseName("domain", domain, parseDomain, domainNames());
  proto.partitioning = parseName("partitioning", partitioning, parsePartitioning, partitioningNames());
  proto.primitive = parseName("primitive", primitive, parseOutputPrimitive, outputPrimitiveNames());
  proto.stage = parseName("stage", stage, parseStage, stageNames());
  if (proto.domain == Domain::Isoline && (proto.primitive == OutputPrimitive::TriangleCw ||
                                          proto.primitive == OutputPrimitive::TriangleCcw))
    throw cli::UsageError("primitive " + cli::quoteToken(primitive) + ": an isoline's output is point or line");
  const int need = factorsOf(proto.domain);
  const py::ssize_t rows = f.ndim() == 1 ? 1 : f.ndim() == 2 ? f.shape(0) : -1;
  const py::ssize_t cols = f.ndim() == 1 ? f.shape(0) : f.ndim() == 2 ? f.shape(1) : -1;
  if (rows < 0 || (cols != need && cols != 6))
    throw cli::UsageError("factors: expected an array of shape (N, " + std::to_string(need) + ")" +
                          (need == 6 ? "" : " or (N, 6)") + " for domain " + domain + " (or one row of " +
                          std::to_string(need) + "), got " + std::to_string(f.ndim()) + " dimensions" +
                          (f.ndim() >= 1 ? " with " + std::to_string(cols) + " columns" : ""));
  std::vector<Patch> patches(static_cast<size_t>(rows), proto);
  const float* data = f.data();
  for (size_t i = 0; i < patches.size(); ++i)
    for (int k = 0; k < cols && k < 6; ++k) patches[i].factors[k] = data[i * static_cast<size_t>(cols) + size_t(k)];
  return patches;
}

// tessellate(...) -> (points float32 (P, 2), indices uint32 (I,), point_offsets int64 (N + 1,), index_offsets int64
// (N + 1,)): patch i's points are points[point_offsets[i]:point_offsets[i + 1]], its indices (counting from its own
// first point, as Tessellator::tessellate) indices[index_offsets[i]:index_offsets[i + 1]].
py::tuple tessellate(const std::string& domain, const std::string& partitioning, const std::string& primitive,
                     const py::array_t<float, py::array::c_style | py::array::forcecast>& factors,
                     const std::string& stage, bool flushDenormals, int threads) {
  if (threads < 0 || threads > kMaxThreads)
    throw cli::UsageError("threads " + std::to_string(threads) + ": must be 0 (one per hardware thread) to " +
                          std::to_string(kMaxThreads));
  const std::vector<Patch> patches = patchesOf(domain, partitioning, primitive, stage, factors);
  Options opt;
  opt.flushDenormals = flushDenormals;
  std::vector<BatchSlot> slots(patches.size());
  const BatchTotals totals = planBatch(patches.data(), patches.size(), slots.data(), opt);
  py::array_t<float> points({static_cast<py::ssize_t>(totals.points), py::ssize_t(2)});
  py::array_t<uint32_t> indices(static_cast<py::ssize_t>(totals.indices));
  py::array_t<int64_t> pointOffsets(static_cast<py::ssize_t>(patches.size() + 1));
  py::array_t<int64_t> indexOffsets(static_cast<py::ssize_t>(patches.size() + 1));
  int64_t* po = pointOffsets.mutable_data();
  int64_t* io = indexOffsets.mutable_data();
  for (size_t i = 0; i < slots.size(); ++i) po[i] = slots[i].firstPoint, io[i] = slots[i].firstIndex;
  po[slots.size()] = totals.points;
  io[slots.size()] = totals.indices;
  // The indices are never negative: the int32 the tessellator writes and the uint32 NumPy reads have the same bits.
  auto* pts = reinterpret_cast<DomainPoint*>(points.mutable_data());
  auto* idx = reinterpret_cast<int32_t*>(indices.mutable_data());
  {
    py::gil_scoped_release release;
    tessellateBatch(patches.data(), patches.size(), slots.data(), pts, idx, threads, opt);
  }
  return py::make_tuple(points, indices, pointOffsets, indexOffsets);
}

// check, sweep and compare run one at a time: they share the command line's process-wide state (the temporary report
// files a signal removes, sweep's Ctrl-C flag). Taken with the GIL released, so other Python threads run meanwhile.
std::mutex gCommandMutex;

// The report text as the dict Python's json module reads from the --json file.
py::object dictOf(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

// A Python str may hold NUL characters; a path or a word of the command line cannot (the C library ends it there:
// fftess.check("rings_small.toml\0other") checked rings_small.toml). Refused, naming the argument and the position.
const std::string& noNul(const char* what, const std::string& s) {
  const size_t at = s.find('\0');
  if (at != std::string::npos)
    throw cli::UsageError(std::string(what) + ": a NUL character at position " + std::to_string(at) +
                          " (a path or a command-line word cannot hold one)");
  return s;
}

std::vector<std::string> strings(const py::object& o, const char* what) {
  std::vector<std::string> out;
  if (o.is_none()) return out;
  if (py::isinstance<py::str>(o)) throw cli::UsageError(std::string(what) + ": expected a dict or a list of KEY=VALUE");
  if (py::isinstance<py::dict>(o)) {
    for (auto kv : py::reinterpret_borrow<py::dict>(o)) {
      py::object v = py::reinterpret_borrow<py::object>(kv.second);
      std::string value;
      if (py::isinstance<py::bool_>(v)) value = v.cast<bool>() ? "true" : "false"; // TOML's spelling
      else if (py::isinstance<py::str>(v)) value = v.cast<std::string>();          // a bare word or a TOML value
      else value = py::str(v).cast<std::string>(); // numbers; lists as [a, b, c] (TOML arrays of numbers)
      out.push_back(noNul(what, py::str(kv.first).cast<std::string>() + "=" + value));
    }
    return out;
  }
  for (auto item : o) out.push_back(noNul(what, py::str(item).cast<std::string>()));
  return out;
}

void sceneArgs(cli::SceneArgs& a, const std::string& scene, const py::object& overrides, const std::string& kernel,
               const std::string& flushDenormals, bool offscreen, const std::string& gpuFloat, const std::string& cameras,
               const std::string& svg, const std::string& gltf) {
  a.scene = noNul("scene", scene);
  a.overrides = strings(overrides, "overrides");
  a.kernel = noNul("kernel", kernel);
  a.flushDenormals = noNul("flush_denormals", flushDenormals);
  a.offscreen = offscreen;
  a.gpuFloat = noNul("gpu_float", gpuFloat);
  a.cameras = noNul("cameras", cameras);
  a.svg = noNul("svg", svg);
  a.gltf = noNul("gltf", gltf);
}

py::object check(const std::string& scene, const py::object& overrides, const std::string& kernel,
                 const std::string& flushDenormals, bool offscreen, const std::string& gpuFloat,
                 const std::string& cameras, std::optional<int> cameraIndex, std::optional<int> pathCamera,
                 const std::string& svg, const std::string& gltf, const std::string& view) {
  cli::CheckArgs a;
  sceneArgs(a, scene, overrides, kernel, flushDenormals, offscreen, gpuFloat, cameras, svg, gltf);
  a.view = noNul("view", view);
  if (cameraIndex) a.cameraIndex = *cameraIndex, a.cameraIndexGiven = true;
  if (pathCamera) a.pathCamera = *pathCamera, a.pathCameraGiven = true;
  std::string text;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(gCommandMutex);
    text = cli::checkReportText(a);
  }
  return dictOf(text);
}

py::object sweep(const std::string& scene, const py::object& overrides, std::optional<int> orbit,
                 std::optional<int> flyover, std::optional<int> random, const py::object& seed, int threads,
                 const std::string& kernel, const std::string& flushDenormals, bool offscreen,
                 const std::string& gpuFloat, const std::string& cameras, const std::string& label,
                 const std::string& shard, bool visibleFirst, bool resultCache, const std::string& svg,
                 const std::string& gltf) {
  cli::SweepArgs a;
  sceneArgs(a, scene, overrides, kernel, flushDenormals, offscreen, gpuFloat, cameras, svg, gltf);
  if (orbit) a.orbit = *orbit, a.orbitGiven = true;
  if (flyover) a.flyover = *flyover, a.flyoverGiven = true;
  if (random) a.random = *random, a.randomGiven = true;
  a.seed = py::str(seed).cast<std::string>(); // checked by runSweep: 0 .. 2^64-1
  a.threads = threads;
  a.label = noNul("label", label);
  a.shard = noNul("shard", shard);
  a.noVisibleFirst = !visibleFirst;
  a.noResultCache = !resultCache;
  std::string text;
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(gCommandMutex);
    text = cli::sweepReportText(a);
    interrupted = cli::sweepInterrupted();
  }
  if (interrupted) { // Ctrl-C stopped the sweep: Python's answer to it
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  return dictOf(text);
}

py::object compare(const std::string& patches, const std::string& capture, const std::string& format,
                   bool strictOrder, bool flushDenormals, int show, int details, const std::string& svg) {
  cli::CompareArgs a;
  a.patches = noNul("patches", patches);
  a.capture = noNul("capture", capture);
  a.format = noNul("format", format);
  a.strictOrder = strictOrder;
  a.flushDenormals = flushDenormals;
  a.show = show;
  a.details = details;
  a.svg = noNul("svg", svg);
  if (patches == "-" || capture == "-") throw cli::UsageError("compare: give file paths ('-', stdin, is the command line's)");
  std::string text;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(gCommandMutex);
    text = cli::compareReportText(a);
  }
  return dictOf(text);
}

} // namespace

PYBIND11_MODULE(_fftess, m) {
  m.doc() = "fftess: the D3D11 tessellator emulator and the crack checker (docs/python.md)";
  m.attr("__version__") = FFTESS_VERSION;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const cli::UsageError& e) { // the command line's exit 2: the same message
      const std::string msg = e.details.empty() ? e.what() : e.details + e.what();
      PyErr_SetString(PyExc_ValueError, msg.c_str());
    } catch (const cli::Interrupted& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });
  using namespace py::literals;
  m.def("tessellate", &tessellate, "domain"_a, "partitioning"_a, "primitive"_a, "factors"_a, "stage"_a = "hw",
        "flush_denormals"_a = false, "threads"_a = 0);
  m.def("check", &check, "scene"_a, "overrides"_a = py::none(), "kernel"_a = "epick", "flush_denormals"_a = "auto",
        "offscreen"_a = false, "gpu_float"_a = "off", "cameras"_a = "", "camera_index"_a = py::none(),
        "path_camera"_a = py::none(), "svg"_a = "", "gltf"_a = "", "view"_a = "");
  m.def("sweep", &sweep, "scene"_a, "overrides"_a = py::none(), "orbit"_a = py::none(), "flyover"_a = py::none(),
        "random"_a = py::none(), "seed"_a = 1, "threads"_a = 0, "kernel"_a = "epick", "flush_denormals"_a = "auto",
        "offscreen"_a = false, "gpu_float"_a = "off", "cameras"_a = "", "label"_a = "", "shard"_a = "",
        "visible_first"_a = true, "result_cache"_a = true, "svg"_a = "", "gltf"_a = "");
  m.def("compare", &compare, "patches"_a, "capture"_a, "format"_a = "auto", "strict_order"_a = false,
        "flush_denormals"_a = false, "show"_a = 20, "details"_a = 4, "svg"_a = "");
}
