// fftess_gl_oracle: tessellates batch patches on a real OpenGL tessellator (Mesa llvmpipe, headless EGL) and prints
// them in the golden .out format. See docs/oracle.md.
//
//   fftess_gl_oracle [--any-renderer] [FILE | -]
//
// Exit status: 0 done; 1 usage; 2 bad input (nothing printed); 3 no OpenGL 4.5 context, or not llvmpipe without
// --any-renderer; 4 the driver did something the harness cannot trust (message names the patch).
#include "gl_capture.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

using namespace fftess::oracle;

int main(int argc, char** argv) {
  bool anyRenderer = false;
  const char* file = nullptr;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--any-renderer") anyRenderer = true;
    else if (a == "-h" || a == "--help") {
      std::printf("usage: %s [--any-renderer] [FILE | -]\n"
                  "Reads batch lines 'DOMAIN PARTITIONING TOPOLOGY hw f0 .. f5' (stdin by default), tessellates them\n"
                  "on Mesa's llvmpipe through OpenGL 4.5 (headless EGL) and prints the golden .out format.\n"
                  "--any-renderer: accept a GL implementation other than llvmpipe (its point/primitive order may\n"
                  "differ from the D3D reference; vertex-id checks may then fail).\n",
                  argv[0]);
      return 0;
    } else if (!file && (a == "-" || a[0] != '-')) file = argv[i];
    else {
      std::fprintf(stderr, "fftess_gl_oracle: unknown argument '%s' (see --help)\n", argv[i]);
      return 1;
    }
  }
  std::string text;
  if (!file || std::string(file) == "-") {
    text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
  } else {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "fftess_gl_oracle: cannot read '%s'\n", file);
      return 2;
    }
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::vector<BatchLine> lines;
  std::string error;
  if (!parseBatch(text, lines, error)) {
    std::fprintf(stderr, "fftess_gl_oracle: %s: %s\n", file ? file : "<stdin>", error.c_str());
    return 2;
  }
  auto oracle = GlOracle::create(error);
  if (!oracle) {
    std::fprintf(stderr, "fftess_gl_oracle: %s\n", error.c_str());
    return 3;
  }
  if (!oracle->isLlvmpipe() && !anyRenderer) {
    std::fprintf(stderr,
                 "fftess_gl_oracle: the GL renderer is '%s', not llvmpipe; set GALLIUM_DRIVER=llvmpipe "
                 "LIBGL_ALWAYS_SOFTWARE=1 __EGL_VENDOR_LIBRARY_FILENAMES=/usr/share/glvnd/egl_vendor.d/50_mesa.json "
                 "or pass --any-renderer\n",
                 oracle->renderer().c_str());
    return 3;
  }
  std::vector<Patch> patches;
  patches.reserve(lines.size());
  for (const BatchLine& b : lines) patches.push_back(b.patch);
  std::vector<Result> results;
  const auto t0 = std::chrono::steady_clock::now();
  if (!oracle->run(patches, results, error)) {
    std::fprintf(stderr, "fftess_gl_oracle: %s\n", error.c_str());
    return 4;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::string out;
  for (size_t i = 0; i < patches.size(); ++i) {
    writePatchBlock(out, static_cast<int>(i), patches[i], results[i]);
    if (out.size() > (1u << 20)) {
      std::fwrite(out.data(), 1, out.size(), stdout);
      out.clear();
    }
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  std::fprintf(stderr, "fftess_gl_oracle: %zu patches on %s in %.2f s (%d draw calls)\n", patches.size(),
               oracle->renderer().c_str(), seconds, oracle->drawCalls());
  return std::fflush(stdout) == 0 ? 0 : 4;
}
