#include "gpu_lod/hull.h"
#include "verify/scene.h"
#include <catch2/catch.hpp>
#include <iostream>
using namespace fftess::gpulod::hull;
static const std::string kData = FFTESS_HULL_DATA;
TEST_CASE("dump") {
  for (const char* f : {"include.hlsl", "include_error.tesc"}) {
    HullProgram p; std::vector<Diagnostic> e;
    bool ok = compileHull(kData + "/" + f, "", p, e);
    std::cout << "=== " << f << " ok=" << ok << "\n" << formatDiagnostics(e) << "\n";
    for (auto& r : p.resources) std::cout << "R " << int(r.kind) << " " << r.name << " [" << r.block << "] " << r.declared.file << ":" << r.declared.line << ":" << r.declared.column << "\n";
    for (auto& i : p.inputs) std::cout << "I " << i.name << " " << i.semantic << " " << i.glslName << " loc=" << i.location << " c=" << i.components << " b=" << i.builtin << " " << i.declared.file << i.declared.line << ":" << i.declared.column << "\n";
  }
  fftess::verify::Scene s;
  for (const char* f : {"uniforms.tesc", "hull.hlsl", "unbound_uniform.tesc"}) {
    HullProgram p; std::vector<Diagnostic> e;
    compileHull(kData + "/" + f, "", p, e);
    readEvaluationShader(kData + "/quad_odd.tese", p, e);
    checkAgainstScene(p, s, e);
    std::cout << "=== " << f << "\n" << formatDiagnostics(e) << "\n";
  }
}
