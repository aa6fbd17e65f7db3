// fftess lod: the built-in schemes (lod/shaders/*.glsl) compiled with Bound (lod/bound.h) as their float: the same
// source and order of operations as lod.h's float build, evaluated over sets of inputs. For proofs over regions of
// cameras (verify/prove.h) and for the float freedom of GPU compilers (--gpu-float conformant).
//
// Each function runs its shader once, so it must run inside BoundContext::forEachPath (each run is one combination
// of answers to the undecided comparisons; the union over the runs covers every input in the sets and every choice
// of the context's model). Geomorphing is not compiled with Bound (its integer levels convert floats to int).
#pragma once

#include <glm/glm.hpp>

#include "lod/bound.h"
#include "lod/lod.h"

namespace fftess::lod {

using BoundVec2 = glm::vec<2, Bound>;
using BoundVec3 = glm::vec<3, Bound>;
using BoundVec4 = glm::vec<4, Bound>;
using BoundMat4 = glm::mat<4, 4, Bound>;

// lod::Camera with Bound entries.
struct BoundCamera {
  BoundMat4 view{Bound(1.0f)};
  BoundMat4 projection{Bound(1.0f)};
  BoundVec2 viewport{Bound(1920.0f), Bound(1200.0f)};
  BoundVec3 eye{Bound(0.0f)};
  bool depthZeroToOne = false;
};

// One camera as constants (every entry a point): for --gpu-float on one camera.
BoundCamera boundCamera(const Camera& camera);

// Every camera makeCamera (d3d false) or makeCameraD3d (d3d true) builds for an eye in [eyeLo, eyeHi] and a target in
// [targetLo, targetHi] (per component, lo <= hi, finite), the other arguments fixed: view is glm::lookAt (lookAtRH;
// lookAtLH for d3d) evaluated with Bound in GLM's order of operations (normalize = v * inversesqrt(dot(v, v)),
// inversesqrt = 1 / sqrt, dot = (x + y) + z, cross as GLM writes it) under FloatModel::Cpp semantics (the camera is
// built on the CPU); projection is the float build's, as constants. The eye and target coordinates are inputs with
// symbols 1..6 (eye x, y, z, target x, y, z). Must be called with a BoundContext active (forEachPath or Scope): an
// undecided comparison inside lookAt is not expected (GLM's lookAt has none).
BoundCamera boundCameraRegion(glm::vec3 eyeLo, glm::vec3 eyeHi, glm::vec3 targetLo, glm::vec3 targetHi, glm::vec3 up,
                              float fovyRadians, float zNear, float zFar, glm::vec2 viewport, bool d3d);

// A patch's factors as Bounds: one run's answer. factors in PatchLod order (Ueq0 Veq0 Ueq1 Veq1 insideU insideV);
// culled: this run culled the patch (every factor is then the cull value).
struct BoundPatchLod {
  Bound factors[6]{};
  bool culled = false;
};

// lod.h's functions, one to one (same parameters, the camera as Bounds). A patch's corners are constants (the
// same bits give the same trace on both sides of an edge).
BoundPatchLod screenSphereBound(const Patch& patch, const BoundCamera& camera, const ScreenSphereParams& params);
BoundPatchLod patchCenterBound(const Patch& patch, const BoundCamera& camera, const ScreenSphereParams& params);
BoundPatchLod nvidiaTileBound(const Patch& patch, const TileNeighbours& neighbours, const BoundCamera& camera,
                              const NvidiaTileParams& params);
BoundPatchLod distancePow2Bound(const Patch& patch, const BoundCamera& camera, const DistancePow2Params& params);
BoundPatchLod distancePow2TileBound(const Patch& patch, const TileNeighbours& neighbours, const BoundCamera& camera,
                                    const DistancePow2Params& params, const TileAdjacency& adjacency);
BoundPatchLod bonaventuraBound(const Patch& patch, const BoundCamera& camera, const BonaventuraParams& params);
BoundPatchLod bonaventuraTileBound(const Patch& patch, const TileNeighbours& neighbours, const BoundCamera& camera,
                                   const BonaventuraParams& params, const TileAdjacency& adjacency);
BoundPatchLod clipDiameterBound(const Patch& patch, const BoundCamera& camera, const ClipDiameterParams& params);
BoundPatchLod clipDiameterTileBound(const Patch& patch, const TileNeighbours& neighbours, const BoundCamera& camera,
                                    const ClipDiameterParams& params, const TileAdjacency& adjacency);
BoundPatchLod constantTileBound(float factor, const TileNeighbours& neighbours, const TileAdjacency& adjacency);

} // namespace fftess::lod
