// The GLSL side: every lod/shaders/*.glsl file compiles as a GLSL 4.50 tessellation control shader with
// glslangValidator (with the files it needs in front), a TCS that calls every scheme compiles, the embedded copies
// (lod::glslSource) equal the files, and the files keep to the shared subset (f-suffixed float literals).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lod/glsl_settings.h"
#include "lod/lod.h"
#include "lod/lod_fields.h"

namespace fs = std::filesystem;

namespace {

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Writes `text` as NAME.tesc under the test's temp folder and runs glslangValidator on it; returns its exit
// status (0 = compiled) and puts its output in `log`.
int compileTcs(const std::string& name, const std::string& text, std::string& log) {
  const fs::path dir = FFTESS_LOD_TEST_TMP;
  fs::create_directories(dir);
  const fs::path src = dir / (name + ".tesc");
  const fs::path out = dir / (name + ".log");
  {
    std::ofstream f(src, std::ios::binary);
    f << text;
  }
  const std::string cmd =
      std::string("\"") + FFTESS_GLSLANG_VALIDATOR + "\" -S tesc \"" + src.string() + "\" > \"" + out.string() + "\" 2>&1";
  const int rc = std::system(cmd.c_str());
  log = readFile(out);
  return rc;
}

const char* const kHeader = "#version 450\nlayout(vertices = 4) out;\n";

std::string sourcesUpTo(int last) {
  std::string s;
  for (int i = 0; i <= last; ++i) {
    s += fftess::lod::glslSource(i);
    s += "\n";
  }
  return s;
}

// Removes // and /* */ comments.
std::string stripComments(const std::string& s) {
  std::string o;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s.compare(i, 2, "//") == 0) {
      while (i < s.size() && s[i] != '\n') {
        ++i;
      }
      o += '\n';
    } else if (s.compare(i, 2, "/*") == 0) {
      i = s.find("*/", i + 2);
      if (i == std::string::npos) {
        break;
      }
      ++i;
    } else {
      o += s[i];
    }
  }
  return o;
}

// One member of a GLSL struct: "TYPE NAME" (NAME with its [N] for an array).
struct Member {
  std::string type;
  std::string name;
  bool operator==(const Member& o) const { return type == o.type && name == o.name; }
};

// The members of `struct NAME { ... };` in GLSL text (comments already removed), in order; empty if absent.
std::vector<Member> structMembers(const std::string& code, const std::string& name) {
  std::vector<Member> out;
  const size_t at = code.find("struct " + name + " {");
  if (at == std::string::npos) {
    return out;
  }
  const size_t open = code.find('{', at);
  const size_t close = code.find("};", open);
  std::istringstream body(code.substr(open + 1, close - open - 1));
  std::string statement;
  while (std::getline(body, statement, ';')) {
    std::istringstream words(statement);
    Member m;
    if (words >> m.type >> m.name) {
      out.push_back(m);
    }
  }
  return out;
}

std::string describe(const std::vector<Member>& members) {
  std::string s;
  for (const Member& m : members) {
    s += m.type + " " + m.name + "; ";
  }
  return s;
}

} // namespace

TEST_CASE("glsl: the harness rejects a broken shader", "[lod][glsl]") {
  std::string log;
  CHECK(compileTcs("broken", std::string(kHeader) + "void main() { gl_TessLevelOuter[0] = undeclared; }\n", log) != 0);
  CHECK(log.find("undeclared") != std::string::npos);
  CHECK(compileTcs("minimal", std::string(kHeader) + "void main() { gl_TessLevelOuter[0] = 1.0f; }\n", log) == 0);
}

TEST_CASE("glsl: every shader file compiles as a tessellation control shader", "[lod][glsl]") {
  REQUIRE(fftess::lod::glslSourceCount() == 7);
  for (int i = 0; i < fftess::lod::glslSourceCount(); ++i) {
    const std::string name = fftess::lod::glslSourceName(i);
    std::string log;
    const std::string text =
        std::string(kHeader) + sourcesUpTo(i) + "void main() { gl_TessLevelOuter[0] = 1.0f; }\n";
    const int rc = compileTcs(name, text, log);
    INFO(name << ":\n" << log); // after the compile: the log is filled by then
    CHECK(rc == 0);
  }
}

TEST_CASE("glsl: a TCS that calls every scheme compiles", "[lod][glsl]") {
  using namespace fftess::lod;
  // The settings as the GPU LOD provider writes them (lod::glslSettings: every field by name, exact bits).
  ClipDiameterParams clip;
  clip.inside = InsideRule::Max;
  TileAdjacency adjacency;
  adjacency.clamp = AdjacencyClamp::Integer;
  adjacency.reconstruction = Reconstruction::Resampled;
  const std::string main = R"glsl(
layout(std140, binding = 0) uniform Lod {
  mat4 uView;
  mat4 uProj;
  vec4 uViewportEye;  // xy viewport; z unused
  vec4 uEye;
  vec4 uNeighbours;   // per-edge sizes
  vec4 uLevels;       // geomorph neighbour levels
};
layout(location = 0) in vec3 inPos[];
layout(location = 0) out vec3 outPos[];

void main() {
  outPos[gl_InvocationID] = inPos[gl_InvocationID];
  LodCamera cam;
  cam.view = uView;
  cam.proj = uProj;
  cam.viewport = uViewportEye.xy;
  cam.eye = uEye.xyz;
  cam.depthZeroToOne = false;
)glsl" + glslSettings("ss", ScreenSphereParams{}) + R"glsl(
  LodResult r = screenSphereLod(inPos[0], inPos[1], inPos[2], inPos[3], false, 0.0f, 0.0f, cam, ss);
  LodResult pc = patchCenterLod(inPos[0], inPos[1], inPos[2], inPos[3], false, 0.0f, 0.0f, cam, ss);
)glsl" + glslSettings("ts", NvidiaTileParams{}) + R"glsl(
  TileNeighbourInfo tn;
  tn.size[0] = uNeighbours.x; tn.size[1] = uNeighbours.y; tn.size[2] = uNeighbours.z; tn.size[3] = uNeighbours.w;
  tn.oddU = false;
  tn.oddV = true;
  for (int i = 0; i < 4; ++i) {
    tn.farCorner[i] = vec3(0.0f);
    tn.rebuiltHeight[i] = 0.0f;
  }
  LodResult t = nvidiaTileLod(inPos[0], inPos[1], inPos[2], inPos[3], false, 0.0f, 0.0f, tn, cam, ts);
)glsl" + glslSettings("ds", DistancePow2Params{}) + R"glsl(
  LodResult d = distancePow2Lod(inPos[0], inPos[1], inPos[2], inPos[3], true, -10.0f, 10.0f, cam, ds);
)glsl" + glslSettings("bs", BonaventuraParams{}) + R"glsl(
  LodResult b = bonaventuraLod(inPos[0], inPos[1], inPos[2], inPos[3], false, 0.0f, 0.0f, cam, bs);
)glsl" + glslSettings("cs", clip) + R"glsl(
  LodResult c = clipDiameterLod(inPos[0], inPos[1], inPos[2], inPos[3], false, 0.0f, 0.0f, cam, cs);
  // The neighbour rule for the other schemes (and the constant factor).
)glsl" + glslSettings("adj", adjacency) + R"glsl(
  LodResult dt = distancePow2TileLod(inPos[0], inPos[1], inPos[2], inPos[3], true, -10.0f, 10.0f, tn, cam, ds, adj);
  LodResult bt = bonaventuraTileLod(inPos[0], inPos[1], inPos[2], inPos[3], false, 0.0f, 0.0f, tn, cam, bs, adj);
  LodResult ct = clipDiameterTileLod(inPos[0], inPos[1], inPos[2], inPos[3], false, 0.0f, 0.0f, tn, cam, cs, adj);
  LodResult kt = constantTileLod(8.0f, tn, adj);
  vec3 rebuilt = rebuiltCorner(inPos[0], inPos[2], tn.oddV);
)glsl" + glslSettings("gs", GeomorphParams{}) + R"glsl(
  float level = geomorphLevelAt(patchCentre(inPos[0], inPos[1], inPos[2], inPos[3]), cam, gs);
  LodResult g = geomorphLod(level, uLevels.x, uLevels.y, uLevels.z, uLevels.w);
  float fine[65];
  for (int i = 0; i < 65; ++i) {
    fine[i] = float(i);
  }
  GeomorphBorder border = geomorphBorderHeights(level, uLevels.x, fine, gs);
  if (gl_InvocationID == 0) {
    // D3D Ueq0 Veq0 Ueq1 Veq1 = GL outer[0..3]; insideU insideV = inner[0..1].
    for (int i = 0; i < 4; ++i) {
      gl_TessLevelOuter[i] = max(max(r.e[i].factor, t.e[i].factor), max(d.e[i].factor, b.e[i].factor)) +
                             c.e[i].factor * 0.0f + g.e[i].factor * 0.0f + pc.e[i].factor * 0.0f + border.heights[i] * 0.0f +
                             (dt.e[i].factor + bt.e[i].factor + ct.e[i].factor + kt.e[i].factor + rebuilt.x) * 0.0f;
    }
    gl_TessLevelInner[0] = r.e[4].factor;
    gl_TessLevelInner[1] = r.e[5].factor;
  }
}
)glsl";
  std::string log;
  const int rc = compileTcs("all_schemes", std::string(kHeader) + sourcesUpTo(6) + main, log);
  INFO(log);
  CHECK(rc == 0);
}

TEST_CASE("glsl: embedded sources equal the files, files keep to the shared subset", "[lod][glsl]") {
  for (int i = 0; i < fftess::lod::glslSourceCount(); ++i) {
    const std::string name = fftess::lod::glslSourceName(i);
    const std::string file = readFile(fs::path(FFTESS_LOD_SHADER_DIR) / name);
    INFO(name);
    CHECK(file == fftess::lod::glslSource(i));
    const std::string code = stripComments(file);
    // Every float literal ends in f (else C++ computes in double); no out / inout parameters; no uniforms.
    for (size_t k = 0; k < code.size(); ++k) {
      const bool startsNumber = std::isdigit(static_cast<unsigned char>(code[k])) &&
                                (k == 0 || !(std::isalnum(static_cast<unsigned char>(code[k - 1])) ||
                                             code[k - 1] == '_' || code[k - 1] == '.'));
      if (!startsNumber) {
        continue;
      }
      size_t e = k;
      while (e < code.size() && std::isdigit(static_cast<unsigned char>(code[e]))) {
        ++e;
      }
      if (e < code.size() && code[e] == '.') {
        ++e;
        while (e < code.size() && std::isdigit(static_cast<unsigned char>(code[e]))) {
          ++e;
        }
        INFO("literal at offset " << k << ": " << code.substr(k, e - k + 1));
        CHECK((e < code.size() && code[e] == 'f'));
      }
      k = e;
    }
    CHECK(code.find(" inout ") == std::string::npos);
    CHECK(code.find("(out ") == std::string::npos);
    CHECK(code.find(", out ") == std::string::npos);
    CHECK(code.find("uniform") == std::string::npos);
  }
}

// The *Settings structs stay hand-written in lod/shaders/*.glsl (the .glsl files are the one source and valid GLSL on
// their own); everything else is produced from lod/lod_fields.h. So the two must agree, field by field, in order:
// a field only in the .glsl would be left unset by the generated GLSL and zero in the C++ builds.
TEST_CASE("glsl: every settings struct in lod/shaders has the fields of lod/lod_fields.h, in order", "[lod][glsl]") {
#define FFTESS_TEST_MEMBER(cppType, cppName, cppDefault, shaderType, shaderName) Member{#shaderType, #shaderName},
#define FFTESS_TEST_SCHEME(Params, Settings, file, FIELDS) {#Settings, file, {FIELDS(FFTESS_TEST_MEMBER)}},
  struct List {
    const char* settings;
    const char* file;
    std::vector<Member> members;
  };
  const List lists[] = {FFTESS_LOD_SCHEMES(FFTESS_TEST_SCHEME)};
#undef FFTESS_TEST_SCHEME
#undef FFTESS_TEST_MEMBER
  REQUIRE(sizeof lists / sizeof lists[0] == 7);
  for (const List& list : lists) {
    std::string code;
    for (int i = 0; i < fftess::lod::glslSourceCount(); ++i) {
      if (std::string(fftess::lod::glslSourceName(i)) == list.file) {
        code = stripComments(fftess::lod::glslSource(i));
      }
    }
    const std::vector<Member> glsl = structMembers(code, list.settings);
    INFO(list.file << " struct " << list.settings << ": " << describe(glsl) << "\nlod_fields.h: "
                   << describe(list.members));
    CHECK(!glsl.empty());
    CHECK(glsl == list.members);
  }
}

TEST_CASE("glsl: the generated settings set every field by name, floats as exact bits", "[lod][glsl]") {
  using namespace fftess::lod;
  NvidiaTileParams p;
  p.sphere.tessellatedTriWidth = 0.1f; // not exact in decimal
  p.sphere.inside = InsideRule::Min;
  p.sphere.frustumCull = false;
  p.clamp = AdjacencyClamp::Integer;
  p.reconstruction = Reconstruction::FarCorner;
  p.insideFromFixedEdges = true;
  const std::string ts = glslSettings("ts", p);
  INFO(ts);
  CHECK(ts.rfind("  TileSettings ts;\n", 0) == 0);
  for (const char* line : {"  ts.sphere.triWidth = uintBitsToFloat(0x3dcccccdu);\n",
                           "  ts.sphere.maxFactor = uintBitsToFloat(0x42800000u);\n",
                           "  ts.sphere.insideRule = kInsideMin;\n", "  ts.sphere.frustumCull = false;\n",
                           "  ts.sphere.culledFactor = uintBitsToFloat(0xbf800000u);\n",
                           "  ts.clampMode = kClampInteger;\n", "  ts.rebuild = kRebuildFarCorner;\n",
                           "  ts.insideFromFixedEdges = true;\n"}) {
    CHECK(ts.find(line) != std::string::npos);
  }
  BonaventuraParams b;
  b.up = glm::vec3(0.0f, -1.0f, 0.5f);
  CHECK(glslSettings("bs", b).find("  bs.up = vec3(uintBitsToFloat(0x00000000u), uintBitsToFloat(0xbf800000u), "
                                   "uintBitsToFloat(0x3f000000u));\n") != std::string::npos);
  // Every field of every list is set, once, by name (a nested struct field by field): one statement per line.
#define FFTESS_TEST_NAME(cppType, cppName, cppDefault, shaderType, shaderName) #shaderName,
#define FFTESS_TEST_SCHEME(Params, Settings, file, FIELDS)                                                       \
  {#Settings, glslSettings("v", Params{}), {FIELDS(FFTESS_TEST_NAME)}},
  struct Generated {
    const char* settings;
    std::string text;
    std::vector<std::string> fields;
  };
  const Generated generated[] = {FFTESS_LOD_SCHEMES(FFTESS_TEST_SCHEME)};
#undef FFTESS_TEST_SCHEME
#undef FFTESS_TEST_NAME
  for (const Generated& g : generated) {
    INFO(g.text);
    std::istringstream lines(g.text);
    std::string line;
    std::getline(lines, line);
    CHECK(line == std::string("  ") + g.settings + " v;");
    std::vector<std::string> set; // the left-hand sides
    while (std::getline(lines, line)) {
      CHECK(line.rfind("  v.", 0) == 0);
      CHECK(line.find(" = ") != std::string::npos);
      set.push_back(line.substr(4, line.find(" = ") - 4));
    }
    for (const std::string& field : g.fields) {
      size_t n = 0;
      for (const std::string& lhs : set) {
        n += lhs == field || lhs.rfind(field + ".", 0) == 0 ? 1 : 0;
      }
      INFO(g.settings << "." << field);
      CHECK(n >= 1);
    }
    std::vector<std::string> sorted = set;
    std::sort(sorted.begin(), sorted.end());
    CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
  }
  CHECK(shaderCode(InsideRule::Max) == 2);
  CHECK(shaderCode(AdjacencyClamp::Pow2) == 2);
  CHECK(shaderCode(Reconstruction::Resampled) == 2);
  CHECK(std::string(glslCodeName(Reconstruction::EdgeVector)) == "kRebuildEdgeVector");
}
