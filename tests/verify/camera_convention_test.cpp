// camera.convention (docs/verify.md): a "d3d" camera hands the LOD D3D's camera (LookAtLH, PerspectiveFovLH: depth in
// [0, w]) and so D3D's frustum planes, checked against planes built here from D3D's published matrix formulas (in
// double, not from lod/ or verify/); a "gl" camera keeps GL's. The verifier's own frustum does not change, so a
// scheme whose factors do not change with the convention gets the same report.
#include "verify_test_util.h"

#include "lod/lod.h"
#include "verify/internal.h"

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

using namespace fftess;
using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

using Plane = std::array<double, 4>; // inside: n . p + d >= 0
using Planes = std::array<Plane, 6>; // left right bottom top near far

glm::dvec3 dv(const glm::vec3& v) { return glm::dvec3(v.x, v.y, v.z); }

// D3DXMatrixLookAtLH and D3DXMatrixPerspectiveFovLH (row vectors: clip = p * View * Proj), in double:
//   zaxis = normalize(At - Eye), xaxis = normalize(cross(Up, zaxis)), yaxis = cross(zaxis, xaxis);
//   yScale = cot(fovY / 2), xScale = yScale / aspect, Q = zf / (zf - zn): Proj rows (xScale 0 0 0), (0 yScale 0 0),
//   (0 0 Q 1), (0 0 -zn Q 0).
// The planes from the columns c1..c4 of View * Proj (D3D's Gribb-Hartmann): c4 + c1, c4 - c1, c4 + c2, c4 - c2,
// near c3 (clip z >= 0), far c4 - c3.
Planes d3dPlanes(const Camera& c) {
  const glm::dvec3 eye = dv(c.eye), z = glm::normalize(dv(c.target) - eye);
  const glm::dvec3 x = glm::normalize(glm::cross(dv(c.up), z)), y = glm::cross(z, x);
  const double fov = double(c.fovY) * 3.14159265358979323846 / 180.0;
  const double ys = 1.0 / std::tan(fov / 2), xs = ys / (double(c.width) / double(c.height));
  const double zn = c.nearZ, zf = c.farZ, q = zf / (zf - zn);
  // View-space coordinates of a point p: (x . (p - eye), y . (p - eye), z . (p - eye)); clip = (xs vx, ys vy,
  // q vz - zn q, vz). Each clip coordinate as a plane (n, d) over world p.
  const Plane cx{xs * x.x, xs * x.y, xs * x.z, -xs * glm::dot(x, eye)};
  const Plane cy{ys * y.x, ys * y.y, ys * y.z, -ys * glm::dot(y, eye)};
  const Plane cz{q * z.x, q * z.y, q * z.z, -q * glm::dot(z, eye) - zn * q};
  const Plane cw{z.x, z.y, z.z, -glm::dot(z, eye)};
  auto add = [](const Plane& a, const Plane& b, double s) {
    return Plane{a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2], a[3] + s * b[3]};
  };
  return {add(cw, cx, 1), add(cw, cx, -1), add(cw, cy, 1), add(cw, cy, -1), cz, add(cw, cz, -1)};
}

// gluLookAt and gluPerspective (OpenGL, right-handed, depth in [-w, w]) the same way: f = normalize(target - eye),
// s = normalize(cross(f, up)), u = cross(s, f); view z = -f . (p - eye); w = -view z; clip z = A vz + B with
// A = -(zf + zn) / (zf - zn), B = -2 zf zn / (zf - zn); near plane w + z, far w - z.
Planes glPlanes(const Camera& c) {
  const glm::dvec3 eye = dv(c.eye), f = glm::normalize(dv(c.target) - eye);
  const glm::dvec3 s = glm::normalize(glm::cross(f, dv(c.up))), u = glm::cross(s, f);
  const double fov = double(c.fovY) * 3.14159265358979323846 / 180.0;
  const double ys = 1.0 / std::tan(fov / 2), xs = ys / (double(c.width) / double(c.height));
  const double zn = c.nearZ, zf = c.farZ, a = -(zf + zn) / (zf - zn), b = -2 * zf * zn / (zf - zn);
  const Plane cx{xs * s.x, xs * s.y, xs * s.z, -xs * glm::dot(s, eye)};
  const Plane cy{ys * u.x, ys * u.y, ys * u.z, -ys * glm::dot(u, eye)};
  // view z = -f . (p - eye)
  const Plane vz{-f.x, -f.y, -f.z, glm::dot(f, eye)};
  const Plane cz{a * vz[0], a * vz[1], a * vz[2], a * vz[3] + b};
  const Plane cw{-vz[0], -vz[1], -vz[2], -vz[3]};
  auto add = [](const Plane& p, const Plane& q, double k) {
    return Plane{p[0] + k * q[0], p[1] + k * q[1], p[2] + k * q[2], p[3] + k * q[3]};
  };
  return {add(cw, cx, 1), add(cw, cx, -1), add(cw, cy, 1), add(cw, cy, -1), add(cw, cz, 1), add(cw, cz, -1)};
}

Plane unit(const Plane& p) {
  const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  return {p[0] / n, p[1] / n, p[2] / n, p[3] / n};
}

Plane planeOf(const glm::vec4& p) { return {p.x, p.y, p.z, p.w}; }

double distance(const Plane& p, const glm::dvec3& x) { return p[0] * x.x + p[1] * x.y + p[2] * x.z + p[3]; }

// Unit normals within tol, offsets within tol times the scene's size (float matrices against double formulas). The
// far plane w - z is a difference of rows that agree to about 2 near / far: float keeps far / near times less.
void checkSame(const Plane& got, const Plane& want, double scale, double tol = 2e-6) {
  const Plane g = unit(got), w = unit(want);
  for (int k = 0; k < 3; ++k) CHECK(std::fabs(g[k] - w[k]) < tol);
  CHECK(std::fabs(g[3] - w[3]) < tol * scale);
}

double tolerance(const Camera& c, int plane) { return plane == 5 ? 2e-6 * double(c.farZ) / double(c.nearZ) : 2e-6; }

const std::vector<std::string> kCamera{"camera.eye=[13.5, 21.0, -64.0]", "camera.target=[2.0, -1.5, 3.0]",
                                       "camera.up=[0.1, 1.0, 0.05]", "camera.fov_y=52.0", "camera.near=0.75",
                                       "camera.far=900.0", "camera.width=1600", "camera.height=900"};

Scene sceneWith(const char* convention, std::vector<std::string> extra = {}) {
  std::vector<std::string> o = kCamera;
  o.push_back(std::string("camera.convention=") + convention);
  o.insert(o.end(), extra.begin(), extra.end());
  return loadExample("rings_small.toml", o);
}

} // namespace

TEST_CASE("camera: a d3d camera gives the D3D frustum planes of LookAtLH and PerspectiveFovLH", "[verify][camera]") {
  const Scene s = sceneWith("d3d");
  REQUIRE(s.camera.convention == CameraConvention::D3d);
  const lod::Camera cam = detail::toLodCamera(s.camera);
  CHECK(cam.depthZeroToOne);
  const lod::FrustumPlanes got = lod::frustumPlanes(cam);
  const Planes want = d3dPlanes(s.camera);
  for (int k = 0; k < 6; ++k) {
    INFO("plane " << k);
    checkSame(planeOf(got.planes[k]), want[k], 100.0, tolerance(s.camera, k));
  }
  // The near plane is clip z >= 0 (D3D's depth range): 0 at the near distance along the view axis, positive beyond.
  const glm::dvec3 eye = dv(s.camera.eye), axis = glm::normalize(dv(s.camera.target) - eye);
  const Plane nearPlane = planeOf(got.planes[4]);
  CHECK(std::fabs(distance(unit(nearPlane), eye + axis * double(s.camera.nearZ))) < 1e-5);
  CHECK(distance(nearPlane, eye + axis * (s.camera.nearZ * 1.01)) > 0);
  CHECK(distance(nearPlane, eye + axis * (s.camera.nearZ * 0.99)) < 0);
  CHECK(distance(nearPlane, eye) < 0); // GL's w + z of a [0, w] matrix would pass the eye itself
  // D3D's clip z of the near plane's row is the projection's third row: the raw plane is q * (z . p) - q * z.eye - zn q.
  const double q = double(s.camera.farZ) / (double(s.camera.farZ) - s.camera.nearZ);
  CHECK(std::fabs(nearPlane[0] - q * axis.x) < 1e-5);
}

TEST_CASE("camera: a gl camera keeps the GL frustum planes, the same frustum as d3d's with left and right swapped",
          "[verify][camera]") {
  const Scene s = sceneWith("gl");
  const lod::Camera cam = detail::toLodCamera(s.camera);
  CHECK_FALSE(cam.depthZeroToOne);
  const lod::FrustumPlanes gl = lod::frustumPlanes(cam);
  const Planes want = glPlanes(s.camera);
  for (int k = 0; k < 6; ++k) {
    INFO("plane " << k);
    checkSame(planeOf(gl.planes[k]), want[k], 100.0, tolerance(s.camera, k));
  }
  // The same camera as before the convention existed: lod::makeCamera, bit for bit.
  const lod::Camera before = lodCameraOf(s.camera);
  CHECK(std::memcmp(&cam.view, &before.view, sizeof cam.view) == 0);
  CHECK(std::memcmp(&cam.projection, &before.projection, sizeof cam.projection) == 0);
  // D3D's left-handed view mirrors x: its left plane is GL's right one; the set of points inside is the same.
  const lod::FrustumPlanes d3d = lod::frustumPlanes(detail::toLodCamera(sceneWith("d3d").camera));
  const int mirror[6] = {1, 0, 2, 3, 4, 5};
  for (int k = 0; k < 6; ++k) {
    INFO("plane " << k);
    checkSame(planeOf(d3d.planes[k]), planeOf(gl.planes[mirror[k]]), 100.0, tolerance(s.camera, k));
  }
  // The verifier's own camera is GL's whatever the convention (its frustum, on-screen and pixel decisions).
  const lod::Camera view = detail::viewCamera(sceneWith("d3d").camera);
  CHECK(std::memcmp(&view.view, &before.view, sizeof view.view) == 0);
  CHECK(std::memcmp(&view.projection, &before.projection, sizeof view.projection) == 0);
}

TEST_CASE("camera: the d3d view's x and z rows are the gl view's negated bit for bit, its y row and w the same",
          "[verify][camera]") {
  const lod::Camera gl = detail::toLodCamera(sceneWith("gl").camera), d3d = detail::toLodCamera(sceneWith("d3d").camera);
  for (int c = 0; c < 4; ++c) {
    CHECK(d3d.view[c][0] == -gl.view[c][0]);
    CHECK(d3d.view[c][1] == gl.view[c][1]);
    CHECK(d3d.view[c][2] == -gl.view[c][2]);
  }
  CHECK(d3d.projection[0][0] == gl.projection[0][0]);
  CHECK(d3d.projection[1][1] == gl.projection[1][1]);
  CHECK(d3d.projection[2][3] == 1.0f);
  CHECK(gl.projection[2][3] == -1.0f);
}

TEST_CASE("camera: path cameras take the scene camera's convention unless they set their own, bad values are refused",
          "[verify][camera]") {
  // grid.toml's [camera] set to d3d by an override (applied before the path entries inherit it), two path entries.
  std::ifstream in(examplePath("grid.toml"));
  const std::string text = std::string(std::istreambuf_iterator<char>(in), {}) +
                           "\n[[camera_path]]\neye = [1.0, 10.0, -10.0]\n"
                           "\n[[camera_path]]\neye = [2.0, 10.0, -10.0]\nconvention = \"gl\"\n";
  SceneResult r = parseScene(text, "grid_path.toml", {"camera.convention=d3d"}, FFTESS_EXAMPLES_DIR);
  INFO(r.error);
  REQUIRE(r.ok);
  CHECK(r.scene.camera.convention == CameraConvention::D3d);
  REQUIRE(r.scene.cameraPath.size() == 2);
  CHECK(r.scene.cameraPath[0].convention == CameraConvention::D3d);
  CHECK(r.scene.cameraPath[1].convention == CameraConvention::Gl);
  SceneResult bad = parseScene(text, "grid_path.toml", {"camera.convention=vulkan"}, FFTESS_EXAMPLES_DIR);
  CHECK_FALSE(bad.ok);
  CHECK(bad.error.find("camera.convention") != std::string::npos);
  CHECK(bad.error.find("\"gl\" | \"d3d\"") != std::string::npos);
}

TEST_CASE("camera: where the LOD's factors do not change with the convention, neither does the report",
          "[verify][camera]") {
  // clip_diameter (clip w and the projection's y scale: the same bits in both) and the distance schemes (the eye
  // only), culling off; each from a few cameras.
  for (const char* scheme : {"clip_diameter", "distance_pow2", "bonaventura"}) {
    for (const char* eye : {"[10.0, 25.0, -70.0]", "[-40.0, 18.0, -30.0]", "[30.0, 6.0, 40.0]"}) {
      INFO(scheme << " from " << eye);
      const std::vector<std::string> o{std::string("lod.scheme=") + scheme, "lod.frustum_cull=false",
                                       "lod.adjacency_clamp=none", std::string("camera.eye=") + eye};
      std::vector<std::string> og = o, od = o;
      og.push_back("camera.convention=gl");
      od.push_back("camera.convention=d3d");
      const Terrain tg = prepared(loadExample("rings_small.toml", og));
      const Terrain td = prepared(loadExample("rings_small.toml", od));
      std::vector<lod::PatchLod> fg, fd;
      WorkStats w;
      detail::computeFactors(tg.data(), tg.scene().camera, fg, w);
      detail::computeFactors(td.data(), td.scene().camera, fd, w);
      REQUIRE(fg.size() == fd.size());
      size_t differ = 0;
      for (size_t i = 0; i < fg.size(); ++i) differ += std::memcmp(fg[i].factors, fd[i].factors, sizeof fg[i].factors) != 0;
      CHECK(differ == 0);
      const Report rg = checkScene(tg, tg.scene().camera), rd = checkScene(td, td.scene().camera);
      CHECK(rg.stats.cracks == rd.stats.cracks);
      CHECK(rg.stats.matches == rd.stats.matches);
      CHECK(rg.stats.edgesChecked == rd.stats.edgesChecked);
      CHECK(rg.stats.worstGapPixels == rd.stats.worstGapPixels);
      CHECK(rg.stats.cracksOnScreen() == rd.stats.cracksOnScreen());
    }
  }
}
