// fftess lod: the one field list per LOD scheme. Every other spelling of a scheme's parameters is produced from
// these lists, by field name:
//   * lod.h's *Params structs (the C++ member, its type and its default: FFTESS_LOD_DECLARE_PARAM);
//   * the float build (lod/glsl_cpp.h) and the double build (lod/lod_double.cpp): *Params -> the shaders'
//     *Settings structs (lod/shader_convert.h, detail::ShaderValue);
//   * the GLSL text that sets a *Settings variable field by field (lod/glsl_settings.h, lod::glslSettings), used by
//     the GPU LOD provider (gpu_lod/), tests/lod/test_glsl.cpp and tests/tools/lod_gpu_drift;
//   * the enum codes: the shaders take ints (kInsideMin, kClampPow2, ...): the C++ enumerator, the GLSL constant's
//     name and its value are listed once below (shaderCode, glslCodeName, the HLSL wrapper's constants).
// The *Settings structs themselves stay declared by hand in lod/shaders/*.glsl (the .glsl files are the one source
// of the functions and must stay valid GLSL on their own); tests/lod/test_glsl.cpp checks that each declaration
// has exactly these fields, with these types and names, in this order, and glsl_cpp.h checks the codes at compile
// time.
//
// Adding a field (docs/lod.md, "Adding a field"): one X(...) line here, the field in the .glsl struct and its use
// there, and the scene key in verify/scene.cpp. Nothing else spells the field.
//
// Entry: X(cppType, cppName, cppDefault, shaderType, shaderName)
//   cppType, cppName, cppDefault: the *Params member in lod.h (cppDefault in parentheses when it has a comma);
//   shaderType, shaderName: the member of the .glsl *Settings struct (GLSL spelling: float, int, bool, vec3, or
//   another *Settings struct). An enum member's shaderType is int (its code, below). Per-field documentation is the
//   /* */ comment before the entry (a // comment would swallow the line continuation).
#pragma once

// 1. Screen-space sphere (lod.h screenSphere, patchCenter; lod/shaders/screen_sphere.glsl ScreenSphereSettings).
#define FFTESS_LOD_SCREEN_SPHERE_FIELDS(X)                                                                        \
  /* target triangle width in pixels (> 0); sample: 3 at 1920x1200, a game: 6 */                                  \
  X(float, tessellatedTriWidth, 3.0f, float, triWidth)                                                            \
  /* <= maxFactor */                                                                                              \
  X(float, minFactor, 1.0f, float, minFactor)                                                                     \
  X(float, maxFactor, 64.0f, float, maxFactor)                                                                    \
  X(InsideRule, inside, InsideRule::Average, int, insideRule)                                                     \
  X(bool, frustumCull, true, bool, frustumCull)                                                                   \
  /* the sample writes -1 */                                                                                      \
  X(float, culledFactor, -1.0f, float, culledFactor)                                                              \
  /* the edge midpoint (HalfSum) or the --gpu-float negative control (AroundQuadScaled) */                         \
  X(SphereCentre, sphereCentre, SphereCentre::HalfSum, int, sphereCentre)

// 2. Tile rings (lod.h nvidiaTile; lod/shaders/nvidia_tile.glsl TileSettings).
#define FFTESS_LOD_NVIDIA_TILE_FIELDS(X)                                                                          \
  /* the per-edge factor (the sample's own settings by default) */                                                \
  X(ScreenSphereParams, sphere, ScreenSphereParams{}, ScreenSphereSettings, sphere)                               \
  /* the sample ships the power-of-two workaround */                                                              \
  X(AdjacencyClamp, clamp, AdjacencyClamp::Pow2, int, clampMode)                                                  \
  X(Reconstruction, reconstruction, Reconstruction::EdgeVector, int, rebuild)                                     \
  /* Inside factors from the edge factors after the neighbour rule (the sample: Inside[1] = 0.5 * (Edges[0] +      \
     Edges[2]), Inside[0] = 0.5 * (Edges[1] + Edges[3]) with sphere.inside = Average) instead of the patch's own  \
     edges before it. Changes interiors only, never an edge. */                                                   \
  X(bool, insideFromFixedEdges, false, bool, insideFromFixedEdges)

// 2b. The neighbour rule for the other schemes (lod.h TileAdjacency; nvidia_tile.glsl AdjacencySettings).
#define FFTESS_LOD_TILE_ADJACENCY_FIELDS(X)                                                                       \
  /* the sample's workaround by default */                                                                        \
  X(AdjacencyClamp, clamp, AdjacencyClamp::Pow2, int, clampMode)                                                  \
  /* Resampled needs TileNeighbours::rebuiltHeight */                                                             \
  X(Reconstruction, reconstruction, Reconstruction::EdgeVector, int, rebuild)

// 3. Distance-based power of two (lod.h distancePow2; lod/shaders/distance_pow2.glsl DistancePow2Settings).
#define FFTESS_LOD_DISTANCE_POW2_FIELDS(X)                                                                        \
  /* < maxDistance */                                                                                             \
  X(float, minDistance, 20.0f, float, minDistance)                                                                \
  X(float, maxDistance, 500.0f, float, maxDistance)                                                               \
  /* at maxDistance and beyond */                                                                                 \
  X(float, minTessExponent, 0.0f, float, minExponent)                                                             \
  /* at minDistance and nearer */                                                                                 \
  X(float, maxTessExponent, 6.0f, float, maxExponent)                                                             \
  X(bool, frustumCull, true, bool, frustumCull)

// 4. Bonaventura (lod.h bonaventura; lod/shaders/bonaventura.glsl BonaventuraSettings).
#define FFTESS_LOD_BONAVENTURA_FIELDS(X)                                                                          \
  X(float, minDistance, 20.0f, float, minDistance)                                                                \
  X(float, maxDistance, 500.0f, float, maxDistance)                                                               \
  X(float, minExponent, 0.0f, float, minExponent)                                                                 \
  X(float, maxExponent, 6.0f, float, maxExponent)                                                                 \
  X(bool, angleCorrection, true, bool, angleCorrection)                                                           \
  /* in [0, 2]: how far the correction moves the exponent (factor 1 +- rank/2) */                                 \
  X(float, rank, 0.5f, float, rank)                                                                               \
  /* terrain normal; unit length */                                                                               \
  X(glm::vec3, up, (glm::vec3(0.0f, 1.0f, 0.0f)), vec3, up)                                                       \
  X(float, minFactor, 1.0f, float, minFactor)                                                                     \
  X(float, maxFactor, 64.0f, float, maxFactor)                                                                    \
  X(bool, frustumCull, true, bool, frustumCull)                                                                   \
  X(float, culledFactor, 0.0f, float, culledFactor)                                                               \
  /* corner 3: (pi/2 - |c.e|)/(pi/2), as printed */                                                               \
  X(bool, literalFourthCornerAngle, false, bool, literalFourthCornerAngle)

// 5. Clip-space sphere diameter (lod.h clipDiameter; lod/shaders/clip_diameter.glsl ClipDiameterSettings).
#define FFTESS_LOD_CLIP_DIAMETER_FIELDS(X)                                                                        \
  /* target edge count over the screen height (> 0) */                                                            \
  X(float, edgesPerScreenHeight, 16.0f, float, edgesPerScreenHeight)                                              \
  X(float, minFactor, 1.0f, float, minFactor)                                                                     \
  X(float, maxFactor, 64.0f, float, maxFactor)                                                                    \
  X(InsideRule, inside, InsideRule::Average, int, insideRule)                                                     \
  /* the article does not cull */                                                                                 \
  X(bool, frustumCull, false, bool, frustumCull)                                                                  \
  X(float, culledFactor, 0.0f, float, culledFactor)

// 6. Geomorphing (lod.h geomorphLevel, geomorphEdgeHeights, geomorphWeight; geomorph.glsl GeomorphSettings).
#define FFTESS_LOD_GEOMORPH_FIELDS(X)                                                                             \
  X(float, minDistance, 20.0f, float, minDistance)                                                                \
  X(float, maxDistance, 500.0f, float, maxDistance)                                                               \
  /* <= 5 (2^6 = 64 segments) */                                                                                  \
  X(float, finestLevel, 5.0f, float, finestLevel)                                                                 \
  /* >= 0 */                                                                                                      \
  X(float, coarsestLevel, 0.0f, float, coarsestLevel)                                                             \
  /* The article's inserted-vertex weight (1 - tweenNeighbour) * tweenSelf instead of the shared border tween.    \
     Not symmetric: the two sides of a border disagree unless a tween is 0. Kept so the verifier can show it. */  \
  X(bool, literalArticleWeight, false, bool, literalArticleWeight)

// Every scheme: X(Params (lod.h), Settings (the .glsl struct), the .glsl file that declares it, FIELDS).
#define FFTESS_LOD_SCHEMES(X)                                                                                     \
  X(ScreenSphereParams, ScreenSphereSettings, "screen_sphere.glsl", FFTESS_LOD_SCREEN_SPHERE_FIELDS)              \
  X(NvidiaTileParams, TileSettings, "nvidia_tile.glsl", FFTESS_LOD_NVIDIA_TILE_FIELDS)                            \
  X(TileAdjacency, AdjacencySettings, "nvidia_tile.glsl", FFTESS_LOD_TILE_ADJACENCY_FIELDS)                       \
  X(DistancePow2Params, DistancePow2Settings, "distance_pow2.glsl", FFTESS_LOD_DISTANCE_POW2_FIELDS)              \
  X(BonaventuraParams, BonaventuraSettings, "bonaventura.glsl", FFTESS_LOD_BONAVENTURA_FIELDS)                    \
  X(ClipDiameterParams, ClipDiameterSettings, "clip_diameter.glsl", FFTESS_LOD_CLIP_DIAMETER_FIELDS)              \
  X(GeomorphParams, GeomorphSettings, "geomorph.glsl", FFTESS_LOD_GEOMORPH_FIELDS)

// The enum codes the shaders take: X(Enum, Enumerator, glslConstant, code). The first entry of each enum is also
// the code of any value outside the enum. The GLSL constants are declared in common.glsl (InsideRule),
// screen_sphere.glsl (SphereCentre) and nvidia_tile.glsl (the other two); glsl_cpp.h static_asserts that they equal
// these codes.
#define FFTESS_LOD_INSIDE_RULE_CODES(X)                                                                           \
  X(InsideRule, Average, kInsideAverage, 0)                                                                       \
  X(InsideRule, Min, kInsideMin, 1)                                                                               \
  X(InsideRule, Max, kInsideMax, 2)
#define FFTESS_LOD_ADJACENCY_CLAMP_CODES(X)                                                                       \
  X(AdjacencyClamp, None, kClampNone, 0)                                                                          \
  X(AdjacencyClamp, Integer, kClampInteger, 1)                                                                    \
  X(AdjacencyClamp, Pow2, kClampPow2, 2)
#define FFTESS_LOD_RECONSTRUCTION_CODES(X)                                                                        \
  X(Reconstruction, EdgeVector, kRebuildEdgeVector, 0)                                                            \
  X(Reconstruction, FarCorner, kRebuildFarCorner, 1)                                                              \
  X(Reconstruction, Resampled, kRebuildResampled, 2)
#define FFTESS_LOD_SPHERE_CENTRE_CODES(X)                                                                         \
  X(SphereCentre, HalfSum, kCentreHalfSum, 0)                                                                     \
  X(SphereCentre, AroundQuadScaled, kCentreAroundQuadScaled, 1)
#define FFTESS_LOD_ENUM_CODES(X)                                                                                  \
  FFTESS_LOD_INSIDE_RULE_CODES(X) FFTESS_LOD_ADJACENCY_CLAMP_CODES(X) FFTESS_LOD_RECONSTRUCTION_CODES(X)          \
  FFTESS_LOD_SPHERE_CENTRE_CODES(X)

// lod.h's member declaration of one entry.
#define FFTESS_LOD_DECLARE_PARAM(cppType, cppName, cppDefault, shaderType, shaderName) cppType cppName = cppDefault;
