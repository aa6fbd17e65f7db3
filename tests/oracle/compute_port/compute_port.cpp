// fftess_compute_port: a small GPU port of the D3D11 tessellator (quad_points.comp: quad-domain points for integer,
// pow2 and fractional_even) run through OpenGL compute on the local driver, writing its points as a CSV capture for
// `fftess compare`. docs/compare.md, "A port to prove it on".
//
//   fftess_compute_port [--bug none|float-division|no-mirroring] [--hardware] [--compare] [--csv FILE]
//                       (BATCH | --random N [--seed S] [--batch-out FILE])
//
// The port itself never calls the emulator. --compare additionally checks the capture in-process with the
// comparison library of `fftess compare` (compare/compare.h), for machines where the fftess binary is not
// available (the NVIDIA device run); it prints the summary and the patches/points/time figures.
#include "gl_capture.h" // oracle::Patch, parseBatch, batchLine
#include "gl_context.h"
#include "base/bits.h"
#include "base/splitmix64.h"

#include "compare/compare.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

#include "quad_points_comp.h" // kQuadPointsSource, generated from quad_points.comp by CMake

using namespace fftess;
constexpr size_t kSlot = 4225;  // points per patch slot (a quad at factor 64)
constexpr size_t kChunk = 1024; // patches per dispatch

int fail(const std::string& why, int status = 2) {
  std::fprintf(stderr, "fftess_compute_port: %s\n", why.c_str());
  return status;
}

// Quad patches for the port: integer, pow2, fractional_even; factors mostly in (0.5, 66), some exact integers.
std::vector<oracle::Patch> randomPatches(long n, uint64_t seed) {
  SplitMix64 rng{seed};
  const oracle::Partitioning parts[3] = {oracle::Partitioning::Integer, oracle::Partitioning::Pow2,
                                         oracle::Partitioning::FractionalEven};
  std::vector<oracle::Patch> out;
  for (long i = 0; i < n; ++i) {
    oracle::Patch p;
    p.domain = oracle::Domain::Quad;
    p.partitioning = parts[i % 3];
    p.topology = oracle::Topology::Point;
    const bool small = rng.below(2) == 0; // half the patches small, so that many fit
    for (uint32_t& b : p.factorBits) {
      const float hi = small ? 9.0f : 66.0f;
      float f = 0.5f + rng.unit() * (hi - 0.5f);
      if (rng.below(4) == 0) f = float(1 + rng.below(small ? 8 : 64));
      b = bitsOf(f);
    }
    out.push_back(p);
  }
  return out;
}

} // namespace

int main(int argc, char** argv) {
  std::string batchPath, csvPath = "-", batchOut, bugName = "none";
  long random = 0;
  uint64_t seed = 1;
  bool hardware = false, compare = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* what) -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(std::string(what) + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--bug")
        bugName = value("--bug");
      else if (a == "--hardware")
        hardware = true;
      else if (a == "--compare")
        compare = true;
      else if (a == "--csv")
        csvPath = value("--csv");
      else if (a == "--random")
        random = std::stol(value("--random"));
      else if (a == "--seed")
        seed = std::stoull(value("--seed"));
      else if (a == "--batch-out")
        batchOut = value("--batch-out");
      else if (!a.empty() && a[0] != '-' && batchPath.empty())
        batchPath = a;
      else
        return fail("unknown argument '" + a + "' (see the comment at the top of compute_port.cpp)");
    } catch (const std::exception& e) {
      return fail(e.what());
    }
  }
  const uint32_t bug = bugName == "none" ? 0u : bugName == "float-division" ? 1u : bugName == "no-mirroring" ? 2u : 9u;
  if (bug == 9u) return fail("--bug: expected none, float-division or no-mirroring");
  if (batchPath.empty() == (random == 0)) return fail("give a BATCH file or --random N");

  std::vector<oracle::Patch> patches;
  if (!batchPath.empty()) {
    std::ifstream in(batchPath);
    if (!in) return fail("cannot open '" + batchPath + "'");
    std::stringstream text;
    text << in.rdbuf();
    std::vector<oracle::BatchLine> lines;
    std::string error;
    if (!oracle::parseBatch(text.str(), lines, error)) return fail(batchPath + ": " + error);
    for (const auto& l : lines) {
      const auto& p = l.patch;
      if (p.domain != oracle::Domain::Quad || p.partitioning == oracle::Partitioning::FractionalOdd)
        return fail(batchPath + ":" + std::to_string(l.lineNumber) +
                    ": the port does quad integer, pow2 and "
                    "fractional_even only");
      patches.push_back(p);
    }
  } else {
    patches = randomPatches(random, seed);
  }
  if (!batchOut.empty()) {
    std::ofstream out(batchOut);
    for (const auto& p : patches) out << oracle::batchLine(p) << "\n";
    if (!out) return fail("cannot write '" + batchOut + "'");
  }

  gltest::GlContext ctx;
  gltest::ContextOptions opt;
  opt.order = hardware ? gltest::DeviceOrder::HardwareFirst : gltest::DeviceOrder::SoftwareFirst;
  std::string error;
  if (!ctx.create(opt, error)) return fail("no OpenGL 4.5 context: " + error, 3);
  const auto& gl = ctx.gl;
  std::fprintf(stderr, "fftess_compute_port: %s, bug %s, %zu patches\n", ctx.renderer().c_str(), bugName.c_str(),
               patches.size());
  GLuint shader = gl.glCreateShader(GL_COMPUTE_SHADER);
  if (!gltest::compileShader(gl, shader, kQuadPointsSource, error)) return fail(error, 3);
  GLuint program = gl.glCreateProgram();
  gl.glAttachShader(program, shader);
  if (!gltest::linkProgram(gl, program, error)) return fail(error, 3);
  gl.glUseProgram(program);
  gl.glUniform1ui(gl.glGetUniformLocation(program, "bug"), bug);
  GLuint bufs[3];
  gl.glGenBuffers(3, bufs);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, bufs[1]);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(kChunk * kSlot * 8), nullptr, GL_DYNAMIC_READ);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, bufs[2]);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(kChunk * 4), nullptr, GL_DYNAMIC_READ);
  for (int b = 0; b < 3; ++b) gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(b), bufs[b]);

  std::FILE* csv = csvPath == "-" ? stdout : csvPath == "none" ? nullptr : std::fopen(csvPath.c_str(), "w");
  if (csvPath != "-" && csvPath != "none" && !csv) return fail("cannot write '" + csvPath + "'");
  std::vector<uint32_t> words, pts(kChunk * kSlot * 2), counts(kChunk);
  CompareSummary summary;
  Tessellator tess;
  double gpuSeconds = 0;
  long long totalPoints = 0;
  for (size_t begin = 0; begin < patches.size(); begin += kChunk) {
    const size_t n = std::min(kChunk, patches.size() - begin);
    words.assign(n * 8, 0);
    for (size_t i = 0; i < n; ++i) {
      std::memcpy(&words[i * 8], patches[begin + i].factorBits, 24);
      words[i * 8 + 6] = uint32_t(patches[begin + i].partitioning);
    }
    const auto t0 = std::chrono::steady_clock::now();
    gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, bufs[0]);
    gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(words.size() * 4), words.data(), GL_STATIC_DRAW);
    gl.glUniform1ui(gl.glGetUniformLocation(program, "patchCount"), GLuint(n));
    gl.glDispatchCompute(GLuint((n + 63) / 64), 1, 1);
    gl.glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, bufs[2]);
    gl.glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(n * 4), counts.data());
    size_t maxCount = 0;
    for (size_t i = 0; i < n; ++i) maxCount = std::max<size_t>(maxCount, counts[i]);
    gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, bufs[1]);
    gl.glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(n * kSlot * 8), pts.data());
    gpuSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!gltest::checkGl(gl, "the compute dispatch", error)) return fail(error, 3);
    if (maxCount > kSlot) return fail("a patch reported more than 4225 points", 3);
    for (size_t i = 0; i < n; ++i) {
      CapturedPatch c;
      c.patch = int64_t(begin + i);
      c.verticesPerPrimitive = counts[i] ? 1 : 0;
      for (uint32_t k = 0; k < counts[i]; ++k)
        c.vertices.push_back(CapturedVertex{pts[(i * kSlot + k) * 2], pts[(i * kSlot + k) * 2 + 1]});
      totalPoints += counts[i];
      if (csv) {
        std::string rows;
        appendCsv(rows, c);
        std::fwrite(rows.data(), 1, rows.size(), csv);
      }
      if (compare) {
        Patch p;
        p.domain = Domain::Quad;
        p.partitioning = static_cast<Partitioning>(static_cast<uint8_t>(patches[begin + i].partitioning));
        p.primitive = OutputPrimitive::Point;
        std::memcpy(p.factors, patches[begin + i].factorBits, 24);
        const PatchComparison r = comparePatch(p, &c, CompareOptions{}, tess);
        summary.add(r, int(c.vertices.size()));
      }
    }
  }
  if (csv && csv != stdout) std::fclose(csv);
  std::fprintf(stderr, "fftess_compute_port: %zu patches, %lld points, %.3f s dispatch + readback (%.0f patches/s)\n",
               patches.size(), totalPoints, gpuSeconds, double(patches.size()) / gpuSeconds);
  if (compare) {
    std::fprintf(stderr, "compare: %lld patches, %lld same, %lld differ", (long long)summary.patches,
                 (long long)summary.same, (long long)summary.differing);
    for (PortBug b : summary.explainingAll()) std::fprintf(stderr, "; every difference is %s", toString(b));
    std::fprintf(stderr, "\n");
    return summary.differing ? 1 : 0;
  }
  return 0;
}
