// Cameras for sweeps: the scene's path, an orbit, a flyover and seeded random positions.
#include "verify/internal.h"

#include <cmath>

namespace fftess::verify {

namespace {

constexpr double kPi = 3.14159265358979323846;

Camera like(const Terrain& t, glm::vec3 eye, glm::vec3 target) {
  Camera c = t.scene().camera;
  c.eye = eye;
  c.target = target;
  c.up = glm::vec3{0, 1, 0};
  return c;
}

struct Geometry {
  double cx, cz, size;
};

Geometry geometry(const Terrain& t) {
  const Extent& e = t.extent();
  return {0.5 * (double(e.minX) + e.maxX), 0.5 * (double(e.minZ) + e.maxZ),
          std::fmax(double(e.maxX) - e.minX, double(e.maxZ) - e.minZ)};
}

// splitmix64: the same sequence on every platform.
struct Rng {
  uint64_t s;
  uint64_t next() {
    uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); } // [0, 1)
};

// Checked every 4096 cameras: cheap, and a Ctrl-C is seen within milliseconds.
bool cancelled(const std::atomic<bool>* cancel, int i) { return cancel && (i & 4095) == 0 && cancel->load(); }

} // namespace

std::vector<Camera> pathCameras(const Terrain& terrain) {
  const Scene& scene = terrain.scene();
  if (!scene.cameraPath.empty()) return scene.cameraPath;
  return {scene.camera};
}

std::vector<Camera> orbitCameras(const Terrain& terrain, int count, float radius, float height,
                                 const std::atomic<bool>* cancel) {
  const Geometry g = geometry(terrain);
  const double r = radius > 0 ? radius : 0.5 * g.size;
  const double h = height > 0 ? height : 0.25 * r;
  std::vector<Camera> out;
  for (int i = 0; i < count && !cancelled(cancel, i); ++i) {
    const double a = 2 * kPi * i / std::max(count, 1);
    out.push_back(like(terrain, glm::vec3{float(g.cx + r * std::cos(a)), float(h), float(g.cz + r * std::sin(a))},
                       glm::vec3{float(g.cx), 0.0f, float(g.cz)}));
  }
  return out;
}

std::vector<Camera> flyoverCameras(const Terrain& terrain, int count, float height, const std::atomic<bool>* cancel) {
  const Geometry g = geometry(terrain);
  const double h = height > 0 ? height : 0.02 * g.size + std::fabs(double(terrain.scene().displacement.heightScale));
  std::vector<Camera> out;
  const double half = 0.5 * g.size, step = 0.05 * g.size;
  for (int i = 0; i < count && !cancelled(cancel, i); ++i) {
    const double s = count > 1 ? double(i) / (count - 1) : 0.5;
    const double x = g.cx - half + s * g.size, z = g.cz - half + s * g.size;
    out.push_back(like(terrain, glm::vec3{float(x), float(h), float(z)},
                       glm::vec3{float(x + step), float(h - 0.3 * step), float(z + step)}));
  }
  return out;
}

std::vector<Camera> randomCameras(const Terrain& terrain, int count, uint64_t seed, const std::atomic<bool>* cancel) {
  const Geometry g = geometry(terrain);
  Rng rng{seed};
  std::vector<Camera> out;
  for (int i = 0; i < count && !cancelled(cancel, i); ++i) {
    const double x = g.cx + (rng.uniform() - 0.5) * g.size;
    const double z = g.cz + (rng.uniform() - 0.5) * g.size;
    const double h = (1.0 - rng.uniform()) * 0.25 * g.size; // (0, 25%]
    const double yaw = rng.uniform() * 2 * kPi;
    const double pitch = -rng.uniform() * kPi / 3;
    const double d = 0.05 * g.size;
    const glm::vec3 eye{float(x), float(h), float(z)};
    glm::vec3 target{float(x + d * std::cos(pitch) * std::cos(yaw)), float(h + d * std::sin(pitch)),
                float(z + d * std::cos(pitch) * std::sin(yaw))};
    out.push_back(like(terrain, eye, target));
  }
  return out;
}

} // namespace fftess::verify
