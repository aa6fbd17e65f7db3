#include "gpu_lod/hull.h"
#include <catch2/catch.hpp>
#include <iostream>
using namespace fftess::gpulod::hull;
static const std::string kData = FFTESS_HULL_DATA;
TEST_CASE("dump") {
  for (const char* f : {"uniforms.tesc", "syntax_error.tesc", "include_missing.tesc", "unbound_uniform.tesc", "hull.hlsl", "partitioning_contradicts.hlsl"}) {
    HullProgram p; std::vector<Diagnostic> e;
    bool ok = compileHull(kData + "/" + f, "", p, e);
    std::cout << "=== " << f << " ok=" << ok << "\n" << formatDiagnostics(e) << "\n";
    for (auto& r : p.resources) std::cout << "R " << int(r.kind) << " " << r.name << " [" << r.block << "] " << r.declared.file << ":" << r.declared.line << ":" << r.declared.column << "\n";
    for (auto& i : p.inputs) std::cout << "I " << i.name << " " << i.semantic << " " << i.glslName << " loc=" << i.location << " c=" << i.components << " b=" << i.builtin << " " << i.declared.line << ":" << i.declared.column << "\n";
    std::cout << "ocp " << p.outputControlPoints << " icp " << p.inputControlPoints << " files " << p.sourceFiles.size() << "\n";
    if (std::string(f) == "hull.hlsl" || std::string(f) == "uniforms.tesc") std::cout << p.glsl << "\n";
  }
}
