// fftess verify: terrain scenes, domain-shader emulation and the exact crack verifier.
//
// The umbrella header: the public contract of the module is the stage headers below, included in data-flow order.
// Each is self-contained; include the one you use, or this one for all of them. They speak plain structs; CGAL and
// toml++ stay inside verify's .cpp files. The fault-injection hook (verify/testing.h) is not included: tests only.
//
// Once per scene:
//   scene.h       parse and validate a scene file (loadScene / parseScene -> Scene); bad input is an error value
//                 naming the key and the file position, no exception escapes.
//   terrain.h     prepare (prepareTerrain -> Terrain): everything that does not depend on the camera: the layout's
//                 patches, their neighbours, corners and corner heights, the LOD's height bounds, neighbour sizes and
//                 far corners, the extent; and the work counters (WorkStats).
// Per camera (each stage consumes only the previous stage's plain data, and is skipped when the scene does not call
// for it):
//   camera.h      the cameras of a sweep (path, orbit, flyover, random; CameraSet).
//   lod_bridge.h  per patch the four outer factors as the hull shader computes them (fftess::lod, or a
//                 FactorProvider on the GPU path) and lod's record of why (EdgeLod), including the clamp at
//                 different-sized neighbours (tile rings only; a uniform grid never runs adjacency code);
//   edges.h       tessellate the 16.16 points of each outer edge (fftess::edgePoints), position them as a domain
//                 shader does (float, stated order) and classify each shared edge (match | T-junction | crack,
//                 CGAL exact predicates): Finding;
//   visibility.h  a patch that is not drawn but on screen: Hole (decided by splitting its domain);
//   check.h       one camera: CheckOptions, checkScene -> Report with its Stats (the stages above in order; see
//                 docs/architecture.md, "verify: the stages of a check");
//   mesh_check.h  the independent whole-mesh check of one camera (checkSceneMesh);
//   view_mesh.h   the terrain as one camera draws it, fully tessellated and positioned (viewMesh; pictures);
//   sweep.h       many cameras on worker threads (sweep -> SweepResult);
//   report.h      the verdict of a report or a sweep (verdictOf) and how stats add up (accumulate).
//
// Findings are reports, not exceptions: nothing here turns a report into an exit status.
#pragma once

#include "verify/scene.h"
#include "verify/terrain.h"
#include "verify/camera.h"
#include "verify/lod_bridge.h"
#include "verify/edges.h"
#include "verify/visibility.h"
#include "verify/check.h"
#include "verify/mesh_check.h"
#include "verify/view_mesh.h"
#include "verify/sweep.h"
#include "verify/report.h"
