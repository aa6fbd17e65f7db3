// The scene bound to the user's hull shader: control points, uniforms, blocks, samplers. See hull_bind.h.
#include "gpu_lod/hull_bind.h"

#include "base/bits.h"
#include "verify/internal.h" // buildMipChain

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace fftess::gpulod::hull {

// ---------------------------------------------------------------------------------------------------------------
// Camera values.

namespace {

glm::vec4 row(const glm::mat4& m, int r) { return glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]); }

std::array<glm::vec4, 6> gribbHartmann(const glm::mat4& vp, bool d3d) {
  const glm::vec4 r0 = row(vp, 0), r1 = row(vp, 1), r2 = row(vp, 2), r3 = row(vp, 3);
  return {r3 + r0, r3 - r0, r3 + r1, r3 - r1, d3d ? r2 : r3 + r2, r3 - r2};
}

} // namespace

CameraValues cameraValues(const lod::Camera& camera) {
  CameraValues v;
  v.view = camera.view;
  v.projection = camera.projection;
  v.viewProjection = camera.projection * camera.view;
  v.projectionD3d = camera.projection;
  if (!camera.depthZeroToOne)
    for (int c = 0; c < 4; ++c)
      v.projectionD3d[c][2] = 0.5f * camera.projection[c][2] + 0.5f * camera.projection[c][3];
  v.viewProjectionD3d = v.projectionD3d * camera.view;
  v.projectionVulkan = v.projectionD3d;
  for (int c = 0; c < 4; ++c) v.projectionVulkan[c][1] = -v.projectionD3d[c][1]; // y down in Vulkan's clip space
  v.viewProjectionVulkan = v.projectionVulkan * camera.view;
  v.eye = camera.eye;
  v.viewport = camera.viewport;
  // The GL planes of a camera whose projection is already 0..1 (camera.convention = "d3d") come from its depth
  // [-w, w] twin: third row 2 * row2 - row3 (the inverse of the D3D map above).
  glm::mat4 projectionGl = camera.projection;
  if (camera.depthZeroToOne)
    for (int c = 0; c < 4; ++c) projectionGl[c][2] = 2.0f * camera.projection[c][2] - camera.projection[c][3];
  v.planesGl = gribbHartmann(camera.depthZeroToOne ? projectionGl * camera.view : v.viewProjection, false);
  v.planesD3d = gribbHartmann(v.viewProjectionD3d, true);
  v.planes = camera.depthZeroToOne ? v.planesD3d : v.planesGl;
  for (glm::vec4& p : v.planes) {
    const float len = std::sqrt((p.x * p.x + p.y * p.y) + p.z * p.z);
    p = glm::vec4(p.x / len, p.y / len, p.z / len, p.w / len);
  }
  const glm::mat4& P = camera.projection;
  v.fovY = 2.0f * std::atan(1.0f / P[1][1]);
  // s = P[2][3]: -1 for a right-handed view (w = -z_view), +1 for a left-handed one (D3D, w = z_view). Depth 0..1:
  // near = -s * P[3][2] / P[2][2], far = s * P[3][2] / (s - P[2][2]); depth -1..1: near = -s * P[3][2] /
  // (P[2][2] + s), far = -s * P[3][2] / (P[2][2] - s) (for s = -1 the same bits as P[3][2] / P[2][2] etc.).
  const float s = P[2][3] > 0.0f ? 1.0f : -1.0f;
  v.nearPlane = camera.depthZeroToOne ? -s * P[3][2] / P[2][2] : -s * P[3][2] / (P[2][2] + s);
  v.farPlane = camera.depthZeroToOne ? s * P[3][2] / (s - P[2][2]) : -s * P[3][2] / (P[2][2] - s);
  return v;
}

} // namespace fftess::gpulod::hull

// ---------------------------------------------------------------------------------------------------------------
// Uniforms, blocks, samplers.

namespace fftess::gpulod::hull {


namespace {

// A GL uniform type: base 'f' float, 'i' int, 'u' uint, 'b' bool, 's' sampler2D, 0 anything else; cols x rows
// (vectors: 1 x n).
struct TypeInfo {
  char base = 0;
  int cols = 1, rows = 1;
};

TypeInfo typeInfo(GLenum t) {
  switch (t) {
  case GL_FLOAT: return {'f', 1, 1};
  case GL_FLOAT_VEC2: return {'f', 1, 2};
  case GL_FLOAT_VEC3: return {'f', 1, 3};
  case GL_FLOAT_VEC4: return {'f', 1, 4};
  case GL_INT: return {'i', 1, 1};
  case GL_INT_VEC2: return {'i', 1, 2};
  case GL_INT_VEC3: return {'i', 1, 3};
  case GL_INT_VEC4: return {'i', 1, 4};
  case GL_UNSIGNED_INT: return {'u', 1, 1};
  case GL_UNSIGNED_INT_VEC2: return {'u', 1, 2};
  case GL_UNSIGNED_INT_VEC3: return {'u', 1, 3};
  case GL_UNSIGNED_INT_VEC4: return {'u', 1, 4};
  case GL_BOOL: return {'b', 1, 1};
  case GL_BOOL_VEC2: return {'b', 1, 2};
  case GL_BOOL_VEC3: return {'b', 1, 3};
  case GL_BOOL_VEC4: return {'b', 1, 4};
  case GL_FLOAT_MAT2: return {'f', 2, 2};
  case GL_FLOAT_MAT3: return {'f', 3, 3};
  case GL_FLOAT_MAT4: return {'f', 4, 4};
  case GL_FLOAT_MAT2x3: return {'f', 2, 3};
  case GL_FLOAT_MAT2x4: return {'f', 2, 4};
  case GL_FLOAT_MAT3x2: return {'f', 3, 2};
  case GL_FLOAT_MAT3x4: return {'f', 3, 4};
  case GL_FLOAT_MAT4x2: return {'f', 4, 2};
  case GL_FLOAT_MAT4x3: return {'f', 4, 3};
  case GL_SAMPLER_2D: return {'s', 1, 1};
  default: return {};
  }
}

bool isMatrixValue(const std::string& v) {
  return v == "view" || v == "projection" || v == "view_projection" || v == "projection_d3d" ||
         v == "view_projection_d3d" || v == "projection_vulkan" || v == "view_projection_vulkan" || v == "world";
}

const glm::mat4& matrixValue(const std::string& v, const CameraValues& c) {
  static const glm::mat4 identity(1.0f);
  return v == "view"                  ? c.view
         : v == "projection"          ? c.projection
         : v == "view_projection"     ? c.viewProjection
         : v == "projection_d3d"      ? c.projectionD3d
         : v == "view_projection_d3d" ? c.viewProjectionD3d
         : v == "projection_vulkan"   ? c.projectionVulkan
         : v == "view_projection_vulkan" ? c.viewProjectionVulkan
                                      : identity;
}

// The terrain's values: height scale, extent, the smallest patch's size.
struct TerrainValues {
  float heightScale = 0, patchSize = 0;
  verify::Extent extent{};
  glm::vec2 texSize{0.0f}; // the heightmap's texels across x and z
};

// A named value that is not a matrix: its elements (count x components) as floats. False when the name is unknown.
bool vectorValue(const std::string& v, const CameraValues& c, const TerrainValues& t, std::vector<float>& out,
                 int& components) {
  auto vec = [&](std::initializer_list<float> xs) {
    out.assign(xs);
    components = static_cast<int>(xs.size());
  };
  const std::array<glm::vec4, 6>* planes = v == "frustum_planes"      ? &c.planes
                                           : v == "frustum_planes_gl"  ? &c.planesGl
                                           : v == "frustum_planes_d3d" ? &c.planesD3d
                                                                       : nullptr;
  if (planes) {
    out.clear();
    for (const glm::vec4& p : *planes) out.insert(out.end(), {p.x, p.y, p.z, p.w});
    components = 4;
  } else if (v == "eye") vec({c.eye.x, c.eye.y, c.eye.z});
  else if (v == "viewport") vec({c.viewport.x, c.viewport.y});
  else if (v == "near") vec({c.nearPlane});
  else if (v == "far") vec({c.farPlane});
  else if (v == "fov_y") vec({c.fovY});
  else if (v == "height_scale") vec({t.heightScale});
  else if (v == "terrain_min") vec({t.extent.minX, t.extent.minZ});
  else if (v == "terrain_size") vec({t.extent.maxX - t.extent.minX, t.extent.maxZ - t.extent.minZ});
  else if (v == "patch_size") vec({t.patchSize});
  else if (v == "heightmap_size") vec({t.texSize.x, t.texSize.y});
  else if (v == "heightmap_texel") vec({1.0f / t.texSize.x, 1.0f / t.texSize.y}); // Luna's gTexelCellSpaceU/V
  else return false;
  return true;
}

std::string typeWords(const TypeInfo& t, GLint arraySize) {
  std::string s = t.cols > 1 ? "a " + std::to_string(t.cols) + "x" + std::to_string(t.rows) + " matrix"
                  : t.rows > 1 ? "a " + std::to_string(t.rows) + "-component vector"
                               : "a scalar";
  return arraySize > 1 ? "an array of " + std::to_string(arraySize) + " x " + s.substr(s.find(' ') + 1) : s;
}

// The binding's values for uniform `a` in the order the GLSL the driver compiles indexes them (a mat: column i, row j
// at i * rows + j), count = cols * rows * arraySize. Named matrices (clip = M * p): GLSL mat = M; an HLSL float4x4
// (after glslang + SPIRV-Cross a GLSL mat whose column i is the HLSL row i) gets M^T so that mul(M, p) is M * p;
// transpose(NAME) transposes once more.
bool valuesOf(const UniformBinder::Active& a, Language language, const CameraValues& c, const TerrainValues& t,
              std::vector<float>& out, std::string& error) {
  const verify::UniformBinding& b = *a.binding;
  const TypeInfo ti = typeInfo(a.type);
  const size_t comps = static_cast<size_t>(ti.cols * ti.rows), need = comps * static_cast<size_t>(a.arraySize);
  const std::string what = "[lod.uniforms] " + b.name + " (uniform '" + a.name + "', " + typeWords(ti, a.arraySize) +
                           ")";
  if (b.value.empty()) {
    if (b.numbers.size() < need || (!a.array && b.numbers.size() != need)) {
      error = what + ": " + std::to_string(b.numbers.size()) + " number(s) given, " + std::to_string(need) + " needed";
      return false;
    }
    out.assign(need, 0.0f);
    for (size_t k = 0; k < need; ++k) out[k] = static_cast<float>(b.numbers[k]);
    return true;
  }
  if (isMatrixValue(b.value)) {
    if (ti.cols != 4 || ti.rows != 4 || a.arraySize != 1) {
      error = what + ": " + b.value + " is a 4x4 matrix";
      return false;
    }
    glm::mat4 m = matrixValue(b.value, c);
    if (b.transpose != (language == Language::Hlsl)) m = glm::transpose(m);
    out.assign(&m[0][0], &m[0][0] + 16);
    return true;
  }
  int e = 0;
  if (!vectorValue(b.value, c, t, out, e)) {
    error = what + ": '" + b.value + "' is not a value for a uniform";
    return false;
  }
  // An array the driver reports shorter (its highest used element + 1) takes the value's first elements.
  const size_t count = std::max(out.size() / static_cast<size_t>(e), static_cast<size_t>(1));
  if (count > static_cast<size_t>(a.arraySize) && a.array) out.resize(static_cast<size_t>(a.arraySize * e));
  const size_t used = std::min(count, static_cast<size_t>(a.arraySize));
  if (ti.cols == 1 && (count == static_cast<size_t>(a.arraySize) || a.array) && e == 3 && comps == 4) {
    for (size_t k = used; k-- > 0;) out.insert(out.begin() + static_cast<long>(k * 3 + 3), 1.0f); // w = 1
    return true;
  }
  if (ti.cols != 1 || static_cast<size_t>(e) != comps || (count != static_cast<size_t>(a.arraySize) &&
                                                           (!a.array || count < static_cast<size_t>(a.arraySize)))) {
    error = what + ": " + b.value + " has " + std::to_string(count) + " element(s) of " + std::to_string(e) +
            " component(s)";
    return false;
  }
  return true;
}

uint32_t wordOf(char base, float v) {
  if (base == 'i') return static_cast<uint32_t>(static_cast<int32_t>(v));
  if (base == 'u') return static_cast<uint32_t>(v);
  if (base == 'b') return v != 0.0f ? 1u : 0u;
  return bitsOf(v);
}

} // namespace

UniformBinder::~UniformBinder() {
  if (!blockBuffers_.empty()) gl_.glDeleteBuffers(static_cast<GLsizei>(blockBuffers_.size()), blockBuffers_.data());
  if (heightmap_) gl_.glDeleteTextures(1, &heightmap_);
}

namespace {

// Every active uniform of the program (GL's uniform interface), block members with their block's name.
std::vector<UniformBinder::Active> activeUniforms(const gltest::GlFunctions& gl, GLuint program) {
  GLint count = 0;
  gl.glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  std::vector<UniformBinder::Active> out;
  const GLenum props[] = {GL_TYPE,         GL_ARRAY_SIZE,    GL_OFFSET,   GL_ARRAY_STRIDE,
                          GL_MATRIX_STRIDE, GL_IS_ROW_MAJOR, GL_LOCATION, GL_BLOCK_INDEX};
  for (GLint i = 0; i < count; ++i) {
    char name[512] = {};
    gl.glGetProgramResourceName(program, GL_UNIFORM, static_cast<GLuint>(i), sizeof name, nullptr, name);
    GLint v[8] = {};
    gl.glGetProgramResourceiv(program, GL_UNIFORM, static_cast<GLuint>(i), 8, props, 8, nullptr, v);
    UniformBinder::Active a;
    a.name = name;
    if (a.name.compare(0, 3, "gl_") == 0 || a.name.compare(0, 6, "fftess") == 0) continue;
    if (a.name.size() > 3 && a.name.compare(a.name.size() - 3, 3, "[0]") == 0) {
      a.name.resize(a.name.size() - 3);
      a.array = true;
    }
    a.type = static_cast<GLenum>(v[0]);
    a.arraySize = std::max(1, v[1]);
    a.offset = v[2], a.arrayStride = v[3], a.matrixStride = v[4], a.rowMajor = v[5], a.location = v[6];
    a.blockIndex = v[7];
    a.member = a.name;
    if (a.blockIndex >= 0) {
      char block[512] = {};
      gl.glGetProgramResourceName(program, GL_UNIFORM_BLOCK, static_cast<GLuint>(a.blockIndex), sizeof block, nullptr,
                                  block);
      a.block = block;
      if (a.name.compare(0, a.block.size() + 1, a.block + ".") == 0) a.member = a.name.substr(a.block.size() + 1);
    }
    out.push_back(a);
  }
  return out;
}

const verify::UniformBinding* findUniform(const verify::Lod& lod, const UniformBinder::Active& a) {
  for (const verify::UniformBinding& b : lod.uniforms)
    if (b.name == a.member || b.name == a.name || (!a.block.empty() && b.name == a.block + "." + a.member) ||
        ((a.block == "_Global" || a.block == "$Global") && b.name == "$Global." + a.member)) // HLSL globals
      return &b;
  return nullptr;
}

// Where the program's resource list declares `a` (line 0 when it does not list it).
SourcePos declaredAt(const HullProgram& hull, const UniformBinder::Active& a) {
  for (const Resource& r : hull.resources)
    if (r.name == a.member && (a.block.empty() || r.block.empty() || r.block == a.block)) return r.declared;
  return {};
}

std::string unboundMessage(const UniformBinder::Active& a, bool sampler) {
  if (sampler)
    return "sampler '" + a.member + "' is not bound: add " + a.member + " = \"heightmap\" to [lod.uniforms]";
  std::string values;
  for (const char* v : verify::kLodUniformValues)
    if (std::string(v) != "heightmap") values += std::string(values.empty() ? "" : ", ") + v;
  const std::string what = a.block.empty() ? "uniform '" + a.member + "'"
                                           : "member '" + a.member + "' of uniform block '" + a.block + "'";
  return what + " is not bound: add it to [lod.uniforms] (a number, an array, or one of: " + values + ")";
}

// The R32F heightmap with its mip chain (level 0 = displacement.texels, row 0 = z min), trilinear, clamped.
GLuint heightmapTexture(const gltest::GlFunctions& gl, const verify::Displacement& d) {
  std::vector<verify::MipLevel> built;
  const std::vector<verify::MipLevel>* mips = d.mips.get();
  if (!mips) {
    built = verify::detail::buildMipChain(*d.texels, d.texWidth, d.texHeight, d.format);
    mips = &built;
  }
  GLuint tex = 0;
  gl.glGenTextures(1, &tex);
  gl.glBindTexture(GL_TEXTURE_2D, tex);
  gl.glTexStorage2D(GL_TEXTURE_2D, static_cast<GLsizei>(mips->size() + 1), GL_R32F, d.texWidth, d.texHeight);
  gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl.glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, d.texWidth, d.texHeight, GL_RED, GL_FLOAT, d.texels->data());
  for (size_t k = 0; k < mips->size(); ++k) {
    const verify::MipLevel& m = (*mips)[k];
    gl.glTexSubImage2D(GL_TEXTURE_2D, static_cast<GLint>(k + 1), 0, 0, m.width, m.height, GL_RED, GL_FLOAT,
                       m.texels.data());
  }
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mips->empty() ? GL_LINEAR : GL_LINEAR_MIPMAP_LINEAR);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return tex;
}

bool isUsedMember(const HullProgram& hull, const UniformBinder::Active& a) {
  for (const Resource& r : hull.resources)
    if (r.kind == Resource::Kind::BlockMember && r.name == a.member) return true;
  return false;
}

// Checks one active uniform against its binding: false with a diagnostic when unbound or of the wrong kind.
bool checkBinding(const HullProgram& hull, const UniformBinder::Active& a, std::vector<Diagnostic>& errors) {
  const bool sampler = typeInfo(a.type).base == 's';
  if (!a.binding) {
    errors.push_back(diagnostic(declaredAt(hull, a), unboundMessage(a, sampler)));
    return false;
  }
  const std::string where = "[lod.uniforms] " + a.binding->name + " (scene line " + std::to_string(a.binding->line) +
                            ")";
  std::string problem;
  if (sampler != (a.binding->value == "heightmap"))
    problem = sampler ? "a sampler2D binds only \"heightmap\"" : "\"heightmap\" binds only a sampler2D";
  else if (typeInfo(a.type).base == 0)
    problem = "uniform '" + a.name + "' has a type fftess cannot set (GL type " + std::to_string(a.type) + ")";
  if (problem.empty()) return true;
  errors.push_back(diagnostic(declaredAt(hull, a), where + ": " + problem));
  return false;
}

} // namespace

bool UniformBinder::create(const HullProgram& hull, const verify::LodPatches& patches,
                           std::vector<Diagnostic>& errors) {
  scene_ = &patches.scene();
  language_ = hull.language;
  heightScale_ = scene_->displacement.heightScale;
  texSize_ = glm::vec2(static_cast<float>(scene_->displacement.texWidth), static_cast<float>(scene_->displacement.texHeight));
  extent_ = patches.extent();
  patchSize_ = 0;
  for (size_t i = 0; i < patches.size(); ++i) {
    const float s = patches.corner(i, 1).flat.x - patches.corner(i, 0).flat.x;
    if (i == 0 || s < patchSize_) patchSize_ = s;
  }
  active_ = activeUniforms(gl_, program_);
  int units = 0;
  bool ok = true;
  for (Active& a : active_) {
    a.binding = findUniform(scene_->lod, a);
    // GL lists every member of a std140 / shared block as active: a member the front end did not find used
    // (HullProgram::resources) may stay unbound (zero).
    if (!a.binding && a.blockIndex >= 0 && !isUsedMember(hull, a)) continue;
    ok = checkBinding(hull, a, errors) && ok;
    if (typeInfo(a.type).base == 's') a.unit = units++;
  }
  if (!ok) return false;
  GLint blocks = 0;
  gl_.glGetProgramInterfaceiv(program_, GL_UNIFORM_BLOCK, GL_ACTIVE_RESOURCES, &blocks);
  blockBuffers_.assign(static_cast<size_t>(blocks), 0);
  blockBytes_.assign(static_cast<size_t>(blocks), {});
  if (blocks > 0) gl_.glGenBuffers(blocks, blockBuffers_.data());
  for (GLint b = 0; b < blocks; ++b) {
    const GLenum prop = GL_BUFFER_DATA_SIZE;
    GLint size = 0;
    gl_.glGetProgramResourceiv(program_, GL_UNIFORM_BLOCK, static_cast<GLuint>(b), 1, &prop, 1, nullptr, &size);
    blockBytes_[b].assign(static_cast<size_t>(size), 0);
    gl_.glBindBuffer(GL_UNIFORM_BUFFER, blockBuffers_[b]);
    gl_.glBufferData(GL_UNIFORM_BUFFER, size, nullptr, GL_DYNAMIC_DRAW);
    gl_.glUniformBlockBinding(program_, static_cast<GLuint>(b), static_cast<GLuint>(b));
  }
  if (units > 0 && !scene_->displacement.texels) {
    errors.push_back(diagnostic({}, "[lod.uniforms] binds \"heightmap\" but the scene has no displacement texture"));
    return false;
  }
  if (units > 0) heightmap_ = heightmapTexture(gl_, scene_->displacement);
  // Every value checked once against its uniform's type (any camera: the shapes do not depend on it).
  std::string error;
  gl_.glUseProgram(program_);
  if (!bind(lod::Camera{}, error)) {
    errors.push_back(diagnostic({}, error));
    return false;
  }
  return true;
}

void UniformBinder::store(const Active& a, const std::vector<float>& v) {
  const TypeInfo t = typeInfo(a.type);
  const int comps = t.cols * t.rows;
  if (a.blockIndex >= 0) {
    std::vector<unsigned char>& bytes = blockBytes_[static_cast<size_t>(a.blockIndex)];
    for (int e = 0; e < a.arraySize; ++e)
      for (int i = 0; i < t.cols; ++i)
        for (int j = 0; j < t.rows; ++j) {
          const size_t at = static_cast<size_t>(a.offset + e * a.arrayStride) +
                            static_cast<size_t>(t.cols == 1 ? j * 4
                                                : a.rowMajor ? j * a.matrixStride + i * 4
                                                             : i * a.matrixStride + j * 4);
          const uint32_t w = wordOf(t.base, v[static_cast<size_t>(e * comps + i * t.rows + j)]);
          if (at + 4 <= bytes.size()) std::memcpy(bytes.data() + at, &w, 4);
        }
    return;
  }
  const GLint loc = a.location;
  const GLsizei n = a.arraySize;
  if (t.base == 's') {
    gl_.glUniform1i(loc, a.unit);
  } else if (t.base == 'f' && t.cols == 1) {
    const decltype(gl_.glUniform1fv) fs[] = {gl_.glUniform1fv, gl_.glUniform2fv, gl_.glUniform3fv, gl_.glUniform4fv};
    fs[t.rows - 1](loc, n, v.data());
  } else if (t.base == 'f') {
    const decltype(gl_.glUniformMatrix2fv) ms[3][3] = {
        {gl_.glUniformMatrix2fv, gl_.glUniformMatrix2x3fv, gl_.glUniformMatrix2x4fv},
        {gl_.glUniformMatrix3x2fv, gl_.glUniformMatrix3fv, gl_.glUniformMatrix3x4fv},
        {gl_.glUniformMatrix4x2fv, gl_.glUniformMatrix4x3fv, gl_.glUniformMatrix4fv}};
    ms[t.cols - 2][t.rows - 2](loc, n, GL_FALSE, v.data());
  } else {
    std::vector<uint32_t> w(v.size());
    for (size_t k = 0; k < v.size(); ++k) w[k] = wordOf(t.base, v[k]);
    if (t.base == 'u') {
      const decltype(gl_.glUniform1uiv) us[] = {gl_.glUniform1uiv, gl_.glUniform2uiv, gl_.glUniform3uiv,
                                                gl_.glUniform4uiv};
      us[t.rows - 1](loc, n, w.data());
    } else {
      const decltype(gl_.glUniform1iv) is[] = {gl_.glUniform1iv, gl_.glUniform2iv, gl_.glUniform3iv, gl_.glUniform4iv};
      is[t.rows - 1](loc, n, reinterpret_cast<const GLint*>(w.data()));
    }
  }
}

bool UniformBinder::bind(const lod::Camera& camera, std::string& error) {
  const CameraValues c = cameraValues(camera);
  const TerrainValues t{heightScale_, patchSize_, extent_, texSize_};
  std::vector<float> v;
  for (const Active& a : active_) {
    if (!a.binding) continue; // an unused block member: zero
    if (a.unit < 0 && !valuesOf(a, language_, c, t, v, error)) return false;
    store(a, v);
  }
  for (size_t b = 0; b < blockBuffers_.size(); ++b) {
    gl_.glBindBuffer(GL_UNIFORM_BUFFER, blockBuffers_[b]);
    gl_.glBufferSubData(GL_UNIFORM_BUFFER, 0, static_cast<GLsizeiptr>(blockBytes_[b].size()), blockBytes_[b].data());
    gl_.glBindBufferBase(GL_UNIFORM_BUFFER, static_cast<GLuint>(b), blockBuffers_[b]);
  }
  if (heightmap_) {
    for (const Active& a : active_)
      if (a.unit >= 0) {
        gl_.glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(a.unit));
        gl_.glBindTexture(GL_TEXTURE_2D, heightmap_);
      }
    gl_.glActiveTexture(GL_TEXTURE0);
  }
  return true;
}

} // namespace fftess::gpulod::hull
