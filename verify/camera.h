// fftess verify, stage 3: cameras for sweeps (the scene's own camera is Scene::camera, scene.h). Generators of
// camera lists (path, orbit, flyover, random) and CameraSet, the same cameras by index without storing them. None
// builds a layout: they read the prepared terrain's extent (terrain.h). Every camera is checked later by checkScene
// (check.h) or sweep (sweep.h).
#pragma once

#include "verify/scene.h"
#include "verify/terrain.h"

#include <glm/glm.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fftess::verify {

// ---------------------------------------------------------------------------------------------------------------
// Cameras for sweeps. All return cameras with the scene camera's fov, near, far and viewport; none builds a layout
// (they read terrain.extent()).

// The scene's camera path, or just the scene camera when it has none.
std::vector<Camera> pathCameras(const Terrain& terrain);
// count (>= 0) cameras on a circle around the terrain centre, looking at the centre. radius <= 0: half the extent;
// height <= 0: a quarter of the radius.
// cancel (all generators): when it becomes true, generation stops and the cameras made so far are returned.
std::vector<Camera> orbitCameras(const Terrain& terrain, int count, float radius = 0, float height = 0,
                                 const std::atomic<bool>* cancel = nullptr);
// count cameras on a straight line across the terrain (diagonal, -x-z to +x+z) at `height` above it (<= 0: 2% of
// the extent plus the displacement scale), looking along the flight direction and slightly down.
std::vector<Camera> flyoverCameras(const Terrain& terrain, int count, float height = 0,
                                   const std::atomic<bool>* cancel = nullptr);
// count cameras at uniform random positions over the extent, heights in (0, 25% of extent], random yaw, pitch
// in [-60, 0] degrees. Deterministic for a seed (splitmix64, same on every platform).
std::vector<Camera> randomCameras(const Terrain& terrain, int count, uint64_t seed,
                                  const std::atomic<bool>* cancel = nullptr);

// The same cameras by index: CameraSet::at(i) is camera i of the generator above with the same arguments (the same
// floats), computed when asked for (a random camera from (seed, i): splitmix64 is counter-based), so a set of any
// size costs the same memory; path() keeps the scene's list. at(i) needs i < size(); safe to call from several
// threads at once.
class CameraSet {
public:
  // pathCameras (the scene's list is copied); terrain: built (not empty).
  static CameraSet path(const Terrain& terrain);
  // A list of cameras as given (e.g. read from a camera file; each already valid or reported per camera by the
  // check): at(i) = cameras[i]. Holds the list (about 64 bytes a camera). terrain: built (not empty).
  static CameraSet list(const Terrain& terrain, std::vector<Camera> cameras);
  // orbitCameras: radius, height as there (<= 0: the defaults).
  static CameraSet orbit(const Terrain& terrain, size_t count, float radius = 0, float height = 0);
  // flyoverCameras: height as there (<= 0: the default).
  static CameraSet flyover(const Terrain& terrain, size_t count, float height = 0);
  // randomCameras: the same seed gives the same cameras.
  static CameraSet random(const Terrain& terrain, size_t count, uint64_t seed);
  // Cameras in the set.
  size_t size() const { return count_; }
  // Camera i (i < size()).
  Camera at(size_t i) const;

private:
  enum class Kind : uint8_t { List, Orbit, Flyover, Random };
  CameraSet(Kind kind, const Terrain& terrain, size_t count);
  Camera looking(glm::vec3 eye, glm::vec3 target) const;
  Kind kind_;
  size_t count_;
  Camera base_;                 // the scene camera (fov, near, far, viewport), up = +y
  double cx_ = 0, cz_ = 0, size_ = 0; // the extent's centre and larger side
  double radius_ = 0, height_ = 0;    // orbit radius; orbit / flyover height
  uint64_t seed_ = 0;
  std::vector<Camera> list_;    // path(), list()
};

} // namespace fftess::verify
