// Cameras for sweeps: the scene's path, an orbit, a flyover and seeded random positions, each computed from its
// index when needed (CameraSet), so that memory does not depend on the camera count.
#include "verify/camera.h"
#include "verify/internal.h"

#include "base/splitmix64.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace fftess::verify {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr uint64_t kDrawsPerRandomCamera = 5;

// splitmix64 (base/splitmix64.h): the same sequence on every platform. Counter-based: the state after k draws is
// seed + k * kIncrement, so random camera i (draws 5i+1 .. 5i+5) is computed from (seed, i) alone.
using Rng = SplitMix64;

// Checked every 4096 cameras: cheap, and a Ctrl-C is seen within milliseconds.
bool cancelled(const std::atomic<bool>* cancel, size_t i) { return cancel && (i & 4095) == 0 && cancel->load(); }

std::vector<Camera> materialise(const CameraSet& set, const std::atomic<bool>* cancel) {
  std::vector<Camera> out;
  for (size_t i = 0; i < set.size() && !cancelled(cancel, i); ++i) out.push_back(set.at(i));
  return out;
}

} // namespace

CameraSet::CameraSet(Kind kind, const Terrain& terrain, size_t count) : kind_(kind), count_(count) {
  base_ = terrain.scene().camera;
  base_.up = glm::vec3{0, 1, 0};
  const Extent& e = terrain.extent();
  cx_ = 0.5 * (double(e.minX) + e.maxX);
  cz_ = 0.5 * (double(e.minZ) + e.maxZ);
  size_ = std::fmax(double(e.maxX) - e.minX, double(e.maxZ) - e.minZ);
}

CameraSet CameraSet::path(const Terrain& terrain) {
  CameraSet s(Kind::List, terrain, 0);
  const Scene& scene = terrain.scene();
  s.list_ = scene.cameraPath.empty() ? std::vector<Camera>{scene.camera} : scene.cameraPath;
  s.count_ = s.list_.size();
  return s;
}

CameraSet CameraSet::list(const Terrain& terrain, std::vector<Camera> cameras) {
  CameraSet s(Kind::List, terrain, cameras.size());
  s.list_ = std::move(cameras);
  return s;
}

CameraSet CameraSet::orbit(const Terrain& terrain, size_t count, float radius, float height) {
  CameraSet s(Kind::Orbit, terrain, count);
  s.radius_ = radius > 0 ? radius : 0.5 * s.size_;
  s.height_ = height > 0 ? height : 0.25 * s.radius_;
  return s;
}

CameraSet CameraSet::flyover(const Terrain& terrain, size_t count, float height) {
  CameraSet s(Kind::Flyover, terrain, count);
  s.height_ = height > 0 ? height : 0.02 * s.size_ + std::fabs(double(terrain.scene().displacement.heightScale));
  return s;
}

CameraSet CameraSet::random(const Terrain& terrain, size_t count, uint64_t seed) {
  CameraSet s(Kind::Random, terrain, count);
  s.seed_ = seed;
  return s;
}

Camera CameraSet::looking(glm::vec3 eye, glm::vec3 target) const {
  Camera c = base_;
  c.eye = eye;
  c.target = target;
  return c;
}

// Each formula is the one the generators used when they made all cameras in a loop (same operations, same order).
Camera CameraSet::at(size_t i) const {
  const double cx = cx_, cz = cz_, size = size_;
  switch (kind_) {
  case Kind::List: return list_.at(i);
  case Kind::Orbit: {
    const double a = 2 * kPi * double(i) / double(std::max<size_t>(count_, 1));
    return looking(glm::vec3{float(cx + radius_ * std::cos(a)), float(height_), float(cz + radius_ * std::sin(a))},
                   glm::vec3{float(cx), 0.0f, float(cz)});
  }
  case Kind::Flyover: {
    const double half = 0.5 * size, step = 0.05 * size, h = height_;
    const double s = count_ > 1 ? double(i) / double(count_ - 1) : 0.5;
    const double x = cx - half + s * size, z = cz - half + s * size;
    return looking(glm::vec3{float(x), float(h), float(z)},
                   glm::vec3{float(x + step), float(h - 0.3 * step), float(z + step)});
  }
  case Kind::Random: {
    Rng rng{seed_ + uint64_t(i) * kDrawsPerRandomCamera * SplitMix64::kIncrement}; // wraps mod 2^64 like the sequential state
    const double x = cx + (rng.unitDouble() - 0.5) * size;
    const double z = cz + (rng.unitDouble() - 0.5) * size;
    const double h = (1.0 - rng.unitDouble()) * 0.25 * size; // (0, 25%]
    const double yaw = rng.unitDouble() * 2 * kPi;
    const double pitch = -rng.unitDouble() * kPi / 3;
    const double d = 0.05 * size;
    return looking(glm::vec3{float(x), float(h), float(z)},
                   glm::vec3{float(x + d * std::cos(pitch) * std::cos(yaw)), float(h + d * std::sin(pitch)),
                             float(z + d * std::cos(pitch) * std::sin(yaw))});
  }
  }
  return base_;
}

std::vector<Camera> pathCameras(const Terrain& terrain) {
  const Scene& scene = terrain.scene();
  if (!scene.cameraPath.empty()) return scene.cameraPath;
  return {scene.camera};
}

std::vector<Camera> orbitCameras(const Terrain& terrain, int count, float radius, float height,
                                 const std::atomic<bool>* cancel) {
  return materialise(CameraSet::orbit(terrain, size_t(std::max(count, 0)), radius, height), cancel);
}

std::vector<Camera> flyoverCameras(const Terrain& terrain, int count, float height, const std::atomic<bool>* cancel) {
  return materialise(CameraSet::flyover(terrain, size_t(std::max(count, 0)), height), cancel);
}

std::vector<Camera> randomCameras(const Terrain& terrain, int count, uint64_t seed, const std::atomic<bool>* cancel) {
  return materialise(CameraSet::random(terrain, size_t(std::max(count, 0)), seed), cancel);
}

} // namespace fftess::verify

// ---------------------------------------------------------------------------------------------------------------
// The first stage of every check (checkTerrain) and of every scene camera (scene.cpp): is the camera usable?

namespace fftess::verify::detail {

namespace {

std::string vecText(const glm::vec3& v) {
  char b[96];
  std::snprintf(b, sizeof b, "(%g, %g, %g)", double(v.x), double(v.y), double(v.z));
  return b;
}

// glm::lookAt in float, as lod::makeCamera runs it: f = normalize(target - eye), s = normalize(cross(f, up)), with
// normalize(v) = v * inversesqrt(dot(v, v)). Each dot must be a finite normal float (>= 2^-126): below, it underflows
// (0 or a denormal with few bits) and the view matrix is NaN or meaningless (a view direction of float noise).
bool lookAtFits(const Camera& c, std::string& error) {
  const glm::vec3 d = c.target - c.eye;
  const float dd = glm::dot(d, d);
  if (!std::isfinite(dd) || !(dd >= FLT_MIN)) {
    char b[96];
    std::snprintf(b, sizeof b, "%g", double(dd));
    error = "camera.target: the view direction target - eye = " + vecText(d) + " (eye " + vecText(c.eye) +
            ", target " + vecText(c.target) + ") " +
            (std::isfinite(dd) ? "is too short for float: |target - eye|^2 = " + std::string(b) +
                                     " is below 2^-126; move camera.target away from camera.eye"
                               : std::string("overflows float: |target - eye|^2 is not finite"));
    return false;
  }
  const glm::vec3 f = d * (1.0f / std::sqrt(dd));
  const glm::vec3 x = glm::cross(f, c.up);
  const float xx = glm::dot(x, x);
  if (!std::isfinite(xx) || !(xx >= FLT_MIN)) {
    error = "camera.up: " + vecText(c.up) + " is (nearly) parallel to the view direction target - eye = " + vecText(d) +
            " in float (|cross|^2 below 2^-126 or not finite)";
    return false;
  }
  return true;
}

} // namespace

bool validateCamera(const Camera& c, std::string& error) {
  if (!finite(c.eye)) return error = "camera.eye: not finite", false;
  if (!finite(c.target)) return error = "camera.target: not finite", false;
  if (!finite(c.up)) return error = "camera.up: not finite", false;
  if (sameBits(c.eye, c.target)) return error = "camera.target: equals camera.eye", false;
  const double dx = double(c.target.x) - c.eye.x, dy = double(c.target.y) - c.eye.y, dz = double(c.target.z) - c.eye.z;
  const double cx = dy * c.up.z - dz * c.up.y, cy = dz * c.up.x - dx * c.up.z, cz = dx * c.up.y - dy * c.up.x;
  if (cx == 0 && cy == 0 && cz == 0) return error = "camera.up: parallel to the view direction", false;
  if (!lookAtFits(c, error)) return false;
  if (!(c.fovY > 0 && c.fovY < 180)) return error = "camera.fov_y: must be in (0, 180) degrees", false;
  if (!(c.nearZ > 0) || !std::isfinite(c.nearZ)) return error = "camera.near: must be > 0", false;
  if (!(c.farZ > c.nearZ) || !std::isfinite(c.farZ)) return error = "camera.far: must be > camera.near", false;
  if (c.width < 1) return error = "camera.width: must be >= 1", false;
  if (c.height < 1) return error = "camera.height: must be >= 1", false;
  return true;
}

} // namespace fftess::verify::detail
