// Internal: the shared lod/shaders/*.glsl compiled as C++ through GLM.
//
// The shim: the .glsl files are included inside an unnamed namespace in fftess::lod (so each .cpp gets its own
// internal copy and nothing clashes at link time), in namespace glsl with `using namespace glm;`, so vec3, mat4,
// min, max, floor, ceil, exp2, sqrt, acos and abs resolve to GLM's (single precision; GLM's scalar functions call
// the float overloads of <cmath>). Nothing else is needed: the files avoid every construct the two languages spell
// differently (array constructors, out/inout, multi-component swizzle writes, unsuffixed float literals).
// Compile with -ffp-contract=off (lod/CMakeLists.txt and the top level do) so no FMA is formed.
#pragma once

#include <glm/glm.hpp>

#include "lod/lod.h"

namespace fftess::lod {
namespace {

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace glsl {
using namespace glm;
#include "shaders/common.glsl"
#include "shaders/screen_sphere.glsl"
#include "shaders/nvidia_tile.glsl"
#include "shaders/distance_pow2.glsl"
#include "shaders/bonaventura.glsl"
#include "shaders/clip_diameter.glsl"
#include "shaders/geomorph.glsl"
} // namespace glsl

// The shader's fix bits are the public enum's.
static_assert(glsl::kFixClampedMin == FixClampedMin && glsl::kFixClampedMax == FixClampedMax &&
                  glsl::kFixCulled == FixCulled && glsl::kFixLargerNeighbour == FixLargerNeighbour &&
                  glsl::kFixSmallerNeighbour == FixSmallerNeighbour && glsl::kFixIntegerClamp == FixIntegerClamp &&
                  glsl::kFixPow2Clamp == FixPow2Clamp && glsl::kFixAngleCorrection == FixAngleCorrection &&
                  glsl::kFixRoundedExponent == FixRoundedExponent &&
                  glsl::kFixCoarserNeighbour == FixCoarserNeighbour && glsl::kFixLiteralSource == FixLiteralSource,
              "lod/shaders/common.glsl fix bits must equal fftess::lod::Fix");

namespace detail {

// Public structs -> shader structs, and the shader result -> PatchLod: the one place where lod.h's parameter structs
// become the shaders' settings structs. They cannot be one type: a GLSL struct has no default member initialisers
// and no constructors (lod.h documents each default in the struct), GLSL has no enums (the shaders take int codes;
// lod.h takes InsideRule, AdjacencyClamp, Reconstruction), and the shader structs are compiled per translation unit
// inside an unnamed namespace, so they cannot appear in a public header.
glsl::LodCamera toGlsl(const Camera& camera) {
  glsl::LodCamera c;
  c.view = camera.view;
  c.proj = camera.projection;
  c.viewport = camera.viewport;
  c.eye = camera.eye;
  c.depthZeroToOne = camera.depthZeroToOne;
  return c;
}

int clampCode(AdjacencyClamp clamp) {
  return clamp == AdjacencyClamp::Integer ? glsl::kClampInteger
         : clamp == AdjacencyClamp::Pow2  ? glsl::kClampPow2
                                          : glsl::kClampNone;
}

int rebuildCode(Reconstruction reconstruction) {
  return reconstruction == Reconstruction::FarCorner   ? glsl::kRebuildFarCorner
         : reconstruction == Reconstruction::Resampled ? glsl::kRebuildResampled
                                                       : glsl::kRebuildEdgeVector;
}

int insideRuleCode(InsideRule rule) {
  switch (rule) {
  case InsideRule::Min:
    return glsl::kInsideMin;
  case InsideRule::Max:
    return glsl::kInsideMax;
  case InsideRule::Average:
    break;
  }
  return glsl::kInsideAverage;
}

glsl::ScreenSphereSettings toGlsl(const ScreenSphereParams& p) {
  glsl::ScreenSphereSettings s;
  s.triWidth = p.tessellatedTriWidth;
  s.minFactor = p.minFactor;
  s.maxFactor = p.maxFactor;
  s.insideRule = insideRuleCode(p.inside);
  s.frustumCull = p.frustumCull;
  s.culledFactor = p.culledFactor;
  return s;
}

glsl::TileSettings toGlsl(const NvidiaTileParams& p) {
  glsl::TileSettings s;
  s.sphere = toGlsl(p.sphere);
  s.clampMode = clampCode(p.clamp);
  s.rebuild = rebuildCode(p.reconstruction);
  s.insideFromFixedEdges = p.insideFromFixedEdges;
  return s;
}

glsl::AdjacencySettings toGlsl(const TileAdjacency& p) {
  glsl::AdjacencySettings s;
  s.clampMode = clampCode(p.clamp);
  s.rebuild = rebuildCode(p.reconstruction);
  return s;
}

glsl::TileNeighbourInfo toGlsl(const TileNeighbours& t) {
  glsl::TileNeighbourInfo n;
  for (int i = 0; i < 4; ++i) {
    n.size[i] = t.size[i];
    n.farCorner[i] = t.farCorner[i];
    n.rebuiltHeight[i] = t.rebuiltHeight[i];
  }
  n.oddU = t.oddU;
  n.oddV = t.oddV;
  return n;
}

glsl::DistancePow2Settings toGlsl(const DistancePow2Params& p) {
  glsl::DistancePow2Settings s;
  s.minDistance = p.minDistance;
  s.maxDistance = p.maxDistance;
  s.minExponent = p.minTessExponent;
  s.maxExponent = p.maxTessExponent;
  s.frustumCull = p.frustumCull;
  return s;
}

glsl::BonaventuraSettings toGlsl(const BonaventuraParams& p) {
  glsl::BonaventuraSettings s;
  s.minDistance = p.minDistance;
  s.maxDistance = p.maxDistance;
  s.minExponent = p.minExponent;
  s.maxExponent = p.maxExponent;
  s.angleCorrection = p.angleCorrection;
  s.rank = p.rank;
  s.up = p.up;
  s.minFactor = p.minFactor;
  s.maxFactor = p.maxFactor;
  s.frustumCull = p.frustumCull;
  s.culledFactor = p.culledFactor;
  s.literalFourthCornerAngle = p.literalFourthCornerAngle;
  return s;
}

glsl::ClipDiameterSettings toGlsl(const ClipDiameterParams& p) {
  glsl::ClipDiameterSettings s;
  s.edgesPerScreenHeight = p.edgesPerScreenHeight;
  s.minFactor = p.minFactor;
  s.maxFactor = p.maxFactor;
  s.insideRule = insideRuleCode(p.inside);
  s.frustumCull = p.frustumCull;
  s.culledFactor = p.culledFactor;
  return s;
}

glsl::GeomorphSettings toGlsl(const GeomorphParams& p) {
  glsl::GeomorphSettings s;
  s.minDistance = p.minDistance;
  s.maxDistance = p.maxDistance;
  s.finestLevel = p.finestLevel;
  s.coarsestLevel = p.coarsestLevel;
  s.literalArticleWeight = p.literalArticleWeight;
  return s;
}

PatchLod fromGlsl(const glsl::LodResult& result, Scheme scheme) {
  PatchLod out;
  out.why.scheme = scheme;
  out.why.culled = result.culled;
  for (int i = 0; i < 6; ++i) {
    const glsl::EdgeLod& e = result.e[i];
    out.factors[i] = e.factor;
    out.why.factor[i].metric = e.metric;
    out.why.factor[i].unclamped = e.unclamped;
    out.why.factor[i].exponent = e.exponent;
    out.why.factor[i].fixes = static_cast<uint32_t>(e.fixes);
  }
  for (int i = 0; i < 4; ++i) {
    out.why.cornerLevel[i] = result.cornerLevel[i];
  }
  return out;
}

} // namespace detail
#pragma GCC diagnostic pop

} // namespace
} // namespace fftess::lod
