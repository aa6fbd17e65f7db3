// The seam proof (verify/seam_proof.h; docs/verify.md, "Sweep shortcuts", "Seam proof") judged by brute force:
// wherever proveSeam says Identical, the domain emulation (evalDomain) gives the same point (sameBits) on both sides
// of the edge at every parameter k / 65536 and at random floats in [0, 1] (-0, the smallest subnormal and the float
// just below 1 among them), on the example scenes and variants of every domain option; the degenerate cases are
// fixtures with their expected answers.
#include "verify_test_util.h"

#include "verify/internal.h"
#include "verify/seam_proof.h"

#include <sys/stat.h>

#include <cfloat>
#include <cstdio>
#include <fstream>
#include <random>

using namespace fftess;
using namespace fftess::verify;
using namespace fftess::verify::test;
using detail::SeamProof;
using detail::TerrainData;
using detail::TerrainPatch;

namespace {

struct SeamPair {
  int a = 0, e = 0, b = 0; // edge e of patch a; b is across it
};

// Every shared edge between two patches of the same size, once (from the patch with the lower index).
std::vector<SeamPair> sameSizePairs(const TerrainData& t) {
  std::vector<SeamPair> out;
  for (size_t i = 0; i < t.patches.size(); ++i) {
    const TerrainPatch& p = t.patches[i];
    for (int e = 0; e < 4; ++e) {
      if (p.nbCount[e] != 1) continue;
      const int j = *t.neighboursBegin(p, e);
      const TerrainPatch& q = t.patches[static_cast<size_t>(j)];
      if (j <= static_cast<int>(i) || q.size != p.size) continue;
      const int back = detail::kOpposite[e];
      if (q.nbCount[back] != 1 || *t.neighboursBegin(q, back) != static_cast<int>(i)) FAIL("neighbours not mutual");
      out.push_back({static_cast<int>(i), e, j});
    }
  }
  return out;
}

// The parameters the brute force tries: k / 65536 for every k (all = true) or k / 256, and the awkward ones.
std::vector<float> parameters(bool all) {
  std::vector<float> out;
  const int n = all ? 65536 : 256;
  for (int k = 0; k <= n; ++k) out.push_back(static_cast<float>(k) / static_cast<float>(n));
  for (float v : {-0.0f, std::numeric_limits<float>::denorm_min(), FLT_MIN, std::nextafter(1.0f, 0.0f), 0.1f,
                  1.0f / 3.0f, 0.7f})
    out.push_back(v);
  std::mt19937 rng(22);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::uniform_int_distribution<uint32_t> bits(0, 0x3f800000u); // every float in [+0, 1] equally
  for (int i = 0; i < (all ? 512 : 32); ++i) {
    out.push_back(uniform(rng));
    const uint32_t b = bits(rng);
    float v;
    std::memcpy(&v, &b, sizeof v);
    out.push_back(v);
  }
  return out;
}

// How many of the parameters give different points (sameBits) on the two sides.
int disagreements(const TerrainData& t, const TerrainPatch& a, int e, const TerrainPatch& b,
                  const std::vector<float>& params) {
  WorkStats work;
  int n = 0;
  for (float s : params) {
    const DomainPoint pa = detail::edgeDomain(e, s), pb = detail::edgeDomain(detail::kOpposite[e], s);
    const glm::vec3 qa = detail::evalDomain(t, a, pa.u, pa.v, nullptr, work);
    const glm::vec3 qb = detail::evalDomain(t, b, pb.u, pb.v, nullptr, work);
    if (!detail::sameBits(qa, qb)) ++n;
  }
  return n;
}

struct SeamFigures {
  size_t pairs = 0, identical = 0;
  int sampledNotProven = 0, sampledNotProvenAgreeing = 0; // brute force: the same at every parameter, yet no proof
};

// The soundness check of one prepared terrain: every Identical pair (at most ~500, by stride) at the few parameters;
// a sample of one pair per (edge along u or v, answer) at all of them. Fails on any Identical pair that
// disagrees anywhere.
SeamFigures checkSoundness(const TerrainData& t) {
  static const std::vector<float> few = parameters(false), all = parameters(true);
  SeamFigures f;
  const std::vector<SeamPair> pairs = sameSizePairs(t);
  f.pairs = pairs.size();
  std::vector<SeamProof> proof(pairs.size());
  std::vector<size_t> groups[2][2]; // [along u][identical]
  for (size_t i = 0; i < pairs.size(); ++i) {
    const SeamPair& p = pairs[i];
    proof[i] = detail::proveSeam(t, t.patches[p.a], p.e, t.patches[p.b]);
    REQUIRE(proof[i] != SeamProof::Unknown);
    const bool identical = proof[i] == SeamProof::Identical;
    f.identical += identical;
    groups[p.e == Veq0 || p.e == Veq1][identical].push_back(i);
  }
  const size_t stride = f.identical / 500 + 1;
  size_t seen = 0;
  for (size_t i = 0; i < pairs.size(); ++i) {
    if (proof[i] != SeamProof::Identical || seen++ % stride != 0) continue;
    const SeamPair& p = pairs[i];
    const int n = disagreements(t, t.patches[p.a], p.e, t.patches[p.b], few);
    if (n == 0) continue;
    INFO("patch " << p.a << " edge " << p.e << " patch " << p.b << " (few parameters)");
    REQUIRE(n == 0);
  }
  for (auto& byAxis : groups)
    for (int identical = 0; identical < 2; ++identical) {
      const std::vector<size_t>& g = byAxis[identical];
      if (!g.empty()) {
        const SeamPair& p = pairs[g[g.size() / 2]];
        const int n = disagreements(t, t.patches[p.a], p.e, t.patches[p.b], all);
        INFO("patch " << p.a << " edge " << p.e << " patch " << p.b << " (all parameters)");
        if (identical) REQUIRE(n == 0);
        else {
          ++f.sampledNotProven;
          f.sampledNotProvenAgreeing += n == 0;
        }
      }
    }
  return f;
}

// A scene as prepared once, and the domain shaders (domain.formula, order, height_uv) checked on it: the domain
// keys change nothing of the preparation, so each is a copy of the prepared terrain with scene.domain set.
struct Variant {
  const char* file;
  std::vector<std::string> overrides;
  std::vector<DomainShader> domains;
  bool cameraDependent = false; // the domain reads camera state: never proven
};

DomainShader domainOf(LerpFormula f, LerpOrder o, HeightUv uv) {
  DomainShader d;
  d.formula = f;
  d.order = o;
  d.heightUv = uv;
  return d;
}

std::vector<DomainShader> everyDomain() {
  std::vector<DomainShader> out;
  for (LerpFormula f : {LerpFormula::Nvidia, LerpFormula::Lerp, LerpFormula::LerpFma, LerpFormula::Blend,
                        LerpFormula::BlendFma})
    for (LerpOrder o : {LerpOrder::UFirst, LerpOrder::VFirst})
      for (HeightUv uv : {HeightUv::World, HeightUv::Interpolated}) out.push_back(domainOf(f, o, uv));
  return out;
}

// The k-th and (k + 10)-th of everyDomain(): the variants (k = 0..18, each also with the scene's own domain)
// together check every formula, order and height_uv.
std::vector<DomainShader> someDomains(int k) {
  const std::vector<DomainShader> all = everyDomain();
  return {all[static_cast<size_t>(k) % all.size()], all[static_cast<size_t>(k + 10) % all.size()]};
}

std::string describe(const Variant& v, const DomainShader& d) {
  std::string s = v.file;
  for (const std::string& o : v.overrides) s += " --set " + o;
  return s + " (domain " + toString(d.formula) + (d.order == LerpOrder::UFirst ? ", u_first" : ", v_first") +
         (d.heightUv == HeightUv::World ? ", world)" : ", interpolated)");
}

std::string tmpFile(const std::string& name) {
  ::mkdir(FFTESS_TEST_TMP_DIR, 0755);
  return std::string(FFTESS_TEST_TMP_DIR) + "/" + name;
}

// A 6 x 6 patches layout of side 0.25 from (-0.7, -0.95), its last 2 x 2 patches one of side 0.5 (floats; every
// coordinate exact, none a short dyadic, the terrain straddling x = 0 and z = 0), written with round-trip precision.
std::string nonDyadicPatchesFile() {
  const std::string path = tmpFile("seam_non_dyadic.csv");
  std::ofstream out(path, std::ios::binary);
  out << "x0,z0,x1,z1,x2,z2,x3,z3\n";
  auto x = [](int i) { return -0.7f + 0.25f * static_cast<float>(i); };
  auto z = [](int j) { return -0.95f + 0.25f * static_cast<float>(j); };
  auto row = [&](int i0, int j0, int n) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", x(i0), z(j0), x(i0 + n), z(j0),
                  x(i0), z(j0 + n), x(i0 + n), z(j0 + n));
    out << buf;
  };
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i)
      if (i < 4 || j < 4) row(i, j, 1);
  row(4, 4, 2);
  return path;
}

const std::vector<Variant>& variants() {
  const std::string nonDyadic = "layout.file=" + nonDyadicPatchesFile();
  static const std::vector<Variant> v = {
      {"terrain.toml", {}, someDomains(0)},
      {"terrain.toml", {"layout.corners=shared"}, someDomains(1)},
      {"terrain.toml", {"layout.base_patch_size=0.3", "layout.center=[0.1, -0.7]"}, someDomains(2)},
      {"grid.toml", {}, someDomains(3)},
      {"grid.toml", {"layout.patch_size=0.1", "layout.center=[0.37, -0.13]"}, someDomains(4)},
      {"grid.toml", {"layout.patch_size=0.1", "layout.center=[0.37, -0.13]", "layout.corners=reconstructed"},
       someDomains(5)},
      {"patches.toml", {}, someDomains(6)},
      {"patches.toml", {nonDyadic, "lod.scheme=distance_pow2"}, someDomains(7)},
      {"luna.toml", {}, someDomains(8)},
      {"luna_r16.toml", {}, someDomains(9)},
      {"heightmap_offscreen.toml", {}, someDomains(10)},
      {"rings_small.toml", {}, someDomains(11)},
      {"t_junction.toml", {}, someDomains(12)},
      {"quadtree_cdlod.toml", {}, someDomains(13)},
      {"quadtree_cdlod.toml", {"layout.corners=reconstructed", "layout.root_size=10.3", "layout.center=[0.3, -0.2]"},
       someDomains(17)},
      {"luna_r16.toml", {"layout.cell_size=0.3"}, someDomains(18)},
      {"broken_lod.toml", {}, someDomains(14)},
      {"geomorph.toml", {}, someDomains(15), true},
      {"bonaventura_mip.toml", {}, someDomains(16), true},
  };
  return v;
}

// A patch of hand-made corners (corners[u + 2v]), texture coordinates as every layout computes them.
TerrainPatch patchOf(const TerrainData& t, std::array<glm::vec2, 4> c, int64_t size = 1) {
  TerrainPatch p;
  p.size = size;
  for (int i = 0; i < 4; ++i) {
    p.corners[i] = glm::vec3(c[static_cast<size_t>(i)].x, 0.0f, c[static_cast<size_t>(i)].y);
    p.tex[i][0] = (p.corners[i].x - t.extent.minX) * t.invSizeX;
    p.tex[i][1] = (p.corners[i].z - t.extent.minZ) * t.invSizeZ;
  }
  return p;
}

// An axis-aligned square [x0, x1] x [z0, z1].
TerrainPatch squareOf(const TerrainData& t, float x0, float z0, float x1, float z1) {
  return patchOf(t, {glm::vec2(x0, z0), glm::vec2(x1, z0), glm::vec2(x0, z1), glm::vec2(x1, z1)});
}

// The fixture's answer, and the brute force's agreement with it: Identical pairs agree at every parameter;
// `differ`: the NotProven pair truly disagrees somewhere.
void expectSeam(const TerrainData& t, const TerrainPatch& a, int e, const TerrainPatch& b, SeamProof expected,
                bool differ) {
  static const std::vector<float> all = parameters(true);
  CHECK(detail::proveSeam(t, a, e, b) == expected);
  CHECK(detail::proveSeam(t, b, detail::kOpposite[e], a) == expected);
  const int n = disagreements(t, a, e, b, all);
  if (expected == SeamProof::Identical || !differ) CHECK(n == 0);
  else CHECK(n > 0);
}

} // namespace

TEST_CASE("seam proof: every Identical answer agrees point by point on the example scenes and their variants",
          "[seam]") {
  for (const Variant& v : variants()) {
    const Terrain terrain = prepared(loadExample(v.file, v.overrides));
    TerrainData t = terrain.data();
    std::vector<DomainShader> domains = v.domains;
    domains.insert(domains.begin(), t.scene.domain);
    for (const DomainShader& d : domains) {
      t.scene.domain = d;
      const std::string name = describe(v, d);
      INFO(name);
      const SeamFigures f = checkSoundness(t);
      if (v.cameraDependent) CHECK(f.identical == 0);
      WARN(name << ": " << f.identical << " of " << f.pairs << " same-size shared edges proven; sampled NotProven: "
                << f.sampledNotProvenAgreeing << " of " << f.sampledNotProven << " agree at every parameter");
    }
  }
}

TEST_CASE("seam proof: every same-size shared edge of the default scene is proven, in every lerp formula and order",
          "[seam]") {
  const Terrain terrain = prepared(loadExample("terrain.toml"));
  TerrainData t = terrain.data();
  const std::vector<SeamPair> pairs = sameSizePairs(t);
  CHECK(pairs.size() == 19968); // 10,240 patches; the 3 x 2 x 64 size jumps between rings excluded
  for (const DomainShader& d : everyDomain()) {
    t.scene.domain = d;
    size_t identical = 0;
    for (const SeamPair& p : pairs)
      identical += detail::proveSeam(t, t.patches[p.a], p.e, t.patches[p.b]) == SeamProof::Identical;
    INFO(toString(d.formula) << (d.order == LerpOrder::UFirst ? " u_first" : " v_first")
                             << (d.heightUv == HeightUv::World ? " world" : " interpolated"));
    CHECK(identical == pairs.size());
  }
}

TEST_CASE("seam proof: camera-dependent domains and patches of different sizes are never proven", "[seam]") {
  const Terrain terrain = prepared(loadExample("terrain.toml"));
  const TerrainData& t = terrain.data();
  const std::vector<SeamPair> pairs = sameSizePairs(t);
  REQUIRE(!pairs.empty());
  const SeamPair p = pairs.front();
  TerrainPatch b = t.patches[p.b];
  REQUIRE(detail::proveSeam(t, t.patches[p.a], p.e, b) == SeamProof::Identical);
  b.size *= 2;
  CHECK(detail::proveSeam(t, t.patches[p.a], p.e, b) == SeamProof::NotProven);
  for (const char* effect : {"lod.scheme=geomorph", "displacement.mip=per_patch"}) {
    TerrainData copy = t;
    if (effect[0] == 'l') copy.scene.lod.scheme = LodScheme::Geomorph;
    else copy.scene.displacement.mip = MipMode::PerPatch;
    INFO(effect);
    CHECK(detail::proveSeam(copy, t.patches[p.a], p.e, t.patches[p.b]) == SeamProof::NotProven);
  }
}

TEST_CASE("seam proof fixture: a negative-zero corner", "[seam]") {
  for (const char* displacement : {"none", "fbm"}) {
    INFO(displacement);
    const Terrain terrain = prepared(loadExample("grid.toml", {std::string("displacement.kind=") + displacement}));
    const TerrainData& t = terrain.data();
    const TerrainPatch a = squareOf(t, -1.0f, -1.0f, -0.0f, -0.0f);
    // x = -0 along a's +x edge, z = -0 along its +z edge (edges along v and along u).
    expectSeam(t, a, Ueq1, squareOf(t, -0.0f, -1.0f, 1.0f, -0.0f), SeamProof::Identical, false);
    expectSeam(t, a, Veq1, squareOf(t, -1.0f, -0.0f, -0.0f, 1.0f), SeamProof::Identical, false);
    for (const char* formula : {"blend", "lerp_fma", "blend_fma"}) {
      TerrainData copy = t;
      copy.scene.domain.formula = formula[0] == 'l' ? LerpFormula::LerpFma
                                  : formula[5] == 'f' ? LerpFormula::BlendFma : LerpFormula::Blend;
      INFO(formula);
      expectSeam(copy, a, Ueq1, squareOf(t, -0.0f, -1.0f, 1.0f, -0.0f), SeamProof::Identical, false);
      expectSeam(copy, a, Veq1, squareOf(t, -1.0f, -0.0f, -0.0f, 1.0f), SeamProof::Identical, false);
    }
  }
}

TEST_CASE("seam proof fixture: corners that make b + (t - b) differ from t", "[seam]") {
  // Sheared quads: along u, a's top row is not its bottom row, so at v = 1 "lerp" computes
  // bottom + 1 * (top - bottom), which misses top (b's bottom row at v = 0) for some u: at u = 0,
  // -0.1 + (0.2 - -0.1) = 0.20000002.
  const Terrain terrain = prepared(loadExample("grid.toml", {"displacement.kind=none"}));
  const TerrainData& t = terrain.data();
  const TerrainPatch a = patchOf(t, {glm::vec2(-0.1f, 0), glm::vec2(0.9f, 0), glm::vec2(0.2f, 1), glm::vec2(1.2f, 1)});
  const TerrainPatch b = patchOf(t, {glm::vec2(0.2f, 1), glm::vec2(1.2f, 1), glm::vec2(0.5f, 2), glm::vec2(1.5f, 2)});
  expectSeam(t, a, Veq1, b, SeamProof::NotProven, true);
  // "blend" computes bottom * 0 + top * 1 = top there: proven.
  TerrainData blend = t;
  blend.scene.domain.formula = LerpFormula::Blend;
  expectSeam(blend, a, Veq1, b, SeamProof::Identical, false);
}

TEST_CASE("seam proof fixture: a huge coordinate near overflow", "[seam]") {
  const float big = 3.0e38f;
  for (const char* displacement : {"none", "fbm"}) {
    INFO(displacement);
    const bool flat = displacement[0] == 'n';
    const Terrain terrain = prepared(loadExample("grid.toml", {std::string("displacement.kind=") + displacement}));
    const TerrainData& t = terrain.data();
    // a is wider than the largest float: c1 - c0 overflows, a's edge at u = 1 is inf (then NaN along it).
    expectSeam(t, squareOf(t, -big, 0, big, 1), Ueq1, squareOf(t, big, 0, FLT_MAX, 1), SeamProof::NotProven, true);
    // Finite everywhere: flat, the same points; displaced, the texture coordinate x / extent times the texture
    // width overflows and the height is NaN on both sides (NaN is never sameBits).
    expectSeam(t, squareOf(t, 1e38f, 0, 2e38f, 1), Veq1, squareOf(t, 1e38f, 1, 2e38f, 2),
               flat ? SeamProof::Identical : SeamProof::NotProven, !flat);
  }
}

TEST_CASE("seam proof fixture: Blend formula", "[seam]") {
  // Corners whose difference rounds: "lerp" at u = 1 gives -0.1 + (0.2 - -0.1) = 0.20000002, not 0.2, so the
  // patches disagree at every point of the edge; "blend" gives -0.1 * 0 + 0.2 * 1 = 0.2 exactly on both sides.
  const Terrain terrain = prepared(loadExample("grid.toml"));
  TerrainData t = terrain.data();
  const TerrainPatch a = squareOf(t, -0.1f, 0.0f, 0.2f, 0.3f);
  const TerrainPatch b = patchOf(t, {glm::vec2(0.2f, 0.0f), glm::vec2(0.5f, 0.0f), glm::vec2(0.2f, 0.3f),
                                     glm::vec2(0.5f, 0.3f)});
  expectSeam(t, a, Ueq1, b, SeamProof::NotProven, true);
  for (LerpFormula f : {LerpFormula::Blend, LerpFormula::BlendFma}) {
    t.scene.domain.formula = f;
    expectSeam(t, a, Ueq1, b, SeamProof::Identical, false);
    // Straddling z = 0 along u: the zero products a * (1 - t) and b * t may have either sign.
    expectSeam(t, squareOf(t, -1, -1, 1, 0), Veq1, squareOf(t, -1, 0, 1, 1), SeamProof::Identical, false);
  }
}
