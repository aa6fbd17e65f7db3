// --cameras FILE (check and sweep): cameras from a CSV file with a header or a JSON array of objects (docs/cli.md,
// "Camera files"). Every camera starts from the scene's [camera] and is validated like it (verify's validateCamera);
// a bad file is a UsageError naming FILE:LINE:FIELD.
#pragma once

#include "verify/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fftess::cli {

struct CameraFile {
  std::string path;                   // as given
  std::vector<verify::Camera> cameras; // in file order (at least one)
  std::vector<int> lines;             // the line each camera starts on (one per camera: the count, also after the
                                      // cameras were moved away)
  uint64_t hash = 0;                  // FNV-1a 64 over the file's bytes (shards of one sweep must agree)
  std::string hashText() const;       // "fnv1a64:%016x"
};

// Reads FILE: JSON when the name ends in ".json" (any case), CSV otherwise. base: the scene's [camera] (the
// values of the columns / fields a camera leaves out). Throws UsageError "FILE:LINE:FIELD: what is wrong" (the
// field left out where the whole line or file is wrong), exit 2.
CameraFile readCameraFile(const std::string& path, const verify::Camera& base);

// The columns and JSON fields, in the order the docs list them: eye_x eye_y eye_z target_x target_y target_z (required)
// up_x up_y up_z fov_y near far width height convention (optional).
const std::vector<std::string>& cameraFields();

} // namespace fftess::cli
