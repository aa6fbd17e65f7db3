// Internal to gpu_lod/: what HullCapture (hull_capture.cpp) binds from the scene (hull_bind.cpp): the control points'
// vertex data from [lod.inputs], the uniforms / uniform-block members / samplers from [lod.uniforms] (numbers or the
// named values of docs/gpu_lod.md "The driver half"), the heightmap texture with its mip chain.
#pragma once

#include "gpu_lod/hull.h"

#include <glm/glm.hpp>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace fftess::gpulod::hull {

// A diagnostic built member by member (GCC 12 warns on the aggregate's brace form).
inline Diagnostic diagnostic(SourcePos at, std::string message) {
  Diagnostic d;
  d.at = std::move(at);
  d.message = std::move(message);
  return d;
}

// The per-camera named values of [lod.uniforms], as fftess computes them (float, glm's mat4 products).
//   viewProjection = projection * view; projectionD3d = projection when camera.depthZeroToOne, else the projection's
//   third row replaced by 0.5f * row2 + 0.5f * row3 (clip z' = (z + w) / 2, each product and the sum rounded);
//   viewProjectionD3d = projectionD3d * view.
//   planesGl / planesD3d (left right bottom top near far; Gribb-Hartmann, inward): with r0..r3 the rows of the GL /
//   D3D view-projection: r3 + r0, r3 - r0, r3 + r1, r3 - r1, near r3 + r2 (GL) / r2 (D3D), far r3 - r2; component
//   by component, not normalised. The GL view-projection of a camera with depthZeroToOne (camera.convention =
//   "d3d"): the projection's third row replaced by 2.0f * row2 - row3, times view.
//   planes: the camera's own convention (planesD3d when depthZeroToOne, else planesGl), each divided component-wise
//   by its normal's length sqrt((x * x + y * y) + z * z) (float).
//   fovY = 2 * atan(1 / P[1][1]); with s = P[2][3] (-1: right-handed view, +1: left-handed, D3D): near =
//   -s * P[3][2] / (P[2][2] + s), far = -s * P[3][2] / (P[2][2] - s) (GL depth) or near = -s * P[3][2] / P[2][2],
//   far = s * P[3][2] / (s - P[2][2]) (depth 0..1); P = the projection, glm's [column][row]. The named values
//   view, projection, view_projection and frustum_planes are the camera's own convention (lod::Camera as toLodCamera
//   builds it); the *_d3d, *_vulkan and *_gl values have their fixed clip space, from the camera's own view.
struct CameraValues {
  glm::mat4 view{1.0f}, projection{1.0f}, viewProjection{1.0f}, projectionD3d{1.0f}, viewProjectionD3d{1.0f};
  glm::mat4 projectionVulkan{1.0f}, viewProjectionVulkan{1.0f}; // D3D's depth range and y flipped (Vulkan clip space)
  glm::vec3 eye{0.0f};
  glm::vec2 viewport{0.0f};
  std::array<glm::vec4, 6> planes{}, planesGl{}, planesD3d{};
  float nearPlane = 0, farPlane = 0, fovY = 0;
};
CameraValues cameraValues(const lod::Camera& camera);

// The control points of every patch as vertex attributes: per vertex `slots` vec4s; slot 0 = the vertex shader's
// gl_Position (the input bound to "gl_Position" if any, else the value "position", w = 1), slot k + 1 = the k-th
// non-builtin entry of program.inputs. Vertex k of patch i is fftess corner lod.corner_order[k]. False with a
// diagnostic naming an input the scene does not bind.
bool controlPointData(const HullProgram& program, const verify::LodPatches& patches, std::vector<float>& data,
                      int& slots, std::vector<Diagnostic>& errors);

// The generated vertex shader for controlPointData's attributes: one output per non-builtin input (at its location,
// or by its name; glslName "Block.member" declares an output block Block with the members in program.inputs' order).
std::string vertexShaderSource(const HullProgram& program);

// The #version line fftess's vertex and evaluation shaders take: "#version 450", or the TCS's own "#version N es"
// (GLSL ES: every stage of a program must say the same version). tessellation: for the evaluation shader (ES 3.10
// needs GL_EXT_tessellation_shader).
std::string generatedVersion(const HullProgram& program, bool tessellation);

// The uniforms of a linked program bound from [lod.uniforms]: found by GL program introspection (every active
// uniform, block member and sampler; names "x", "Block.x", arrays "x[0]"), each matched to its binding by name.
class UniformBinder {
public:
  UniformBinder(const gltest::GlFunctions& gl, GLuint program) : gl_(gl), program_(program) {}
  ~UniformBinder();
  // Introspects the program, creates the uniform buffers and the heightmap texture; false with one diagnostic per
  // unbound uniform / member / sampler or a value that does not fit its type.
  bool create(const HullProgram& hull, const verify::LodPatches& patches, std::vector<Diagnostic>& errors);
  // Writes every bound value for this camera (glUniform*, the blocks' buffers) and binds buffers and textures. The
  // program must be current. False with error on a value that does not fit.
  bool bind(const lod::Camera& camera, std::string& error);

  // An active uniform of the program (GL introspection) and its binding.
  struct Active {
    std::string name;   // GL's name without a trailing "[0]"
    std::string member; // without its "Block." prefix
    std::string block;  // the block's GL name ("" in the default block)
    GLenum type = 0;
    GLint arraySize = 1, offset = -1, arrayStride = 0, matrixStride = 0, rowMajor = 0, location = -1, blockIndex = -1;
    const verify::UniformBinding* binding = nullptr;
    int unit = -1; // sampler: its texture unit
    bool array = false; // GL named it "x[0]" (its arraySize may be the highest used element + 1)
  };

private:
  void store(const Active& a, const std::vector<float>& values);

  const gltest::GlFunctions& gl_;
  GLuint program_;
  Language language_ = Language::Glsl;
  std::vector<Active> active_;
  std::vector<GLuint> blockBuffers_;
  std::vector<std::vector<unsigned char>> blockBytes_;
  GLuint heightmap_ = 0;
  float heightScale_ = 0, patchSize_ = 0;
  glm::vec2 texSize_{0.0f}; // the heightmap's texels across x and z
  verify::Extent extent_{};
  const verify::Scene* scene_ = nullptr;
};

} // namespace fftess::gpulod::hull
