// The 3D picture of one checked camera (`check --gltf`, `sweep --gltf`; docs/cli.md, "3D view"): the terrain as the
// camera draws it (verify/view_mesh.h), one mesh per patch size, each finding as coloured geometry and the camera as
// a glTF camera, written with tinygltf (Debian's libtinygltf). A pure function of the report: no I/O.
#pragma once

#include "verify/verify.h"

#include <string>

namespace fftess::cli {

namespace vf = fftess::verify;

// What the file says about where it came from (the glTF scene's name and the asset's extras).
struct GltfTitle {
  std::string command;  // e.g. "fftess check docs/examples/terrain.toml"
  std::string verdict;  // vf::toString(verdict)
  std::string camera;   // which camera, in words (e.g. "the scene's [camera]", "camera 17 of the sweep, the worst")
};

// The picture of report (checkScene(terrain, camera, options), its findings as kept) as binary glTF (.glb bytes), or
// with text as glTF JSON with the buffer embedded as a data URI. std::runtime_error when the camera cannot be
// tessellated (an invalid camera: the check refused it first) or the mesh exceeds a .glb's 4 GiB.
std::string checkGltf(const vf::Terrain& terrain, const vf::Camera& camera, const vf::CheckOptions& options,
                      const vf::Report& report, const GltfTitle& title, bool text);

// The path names a glTF JSON file (ends in .gltf, any case): checkGltf's text; anything else gets binary glTF.
bool gltfTextPath(const std::string& path);

} // namespace fftess::cli
