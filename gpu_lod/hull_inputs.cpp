// The control points of the user's hull shader: each patch's corners as the scene's [lod.inputs] say, and the vertex
// shader that feeds them to the TCS. See hull_bind.h.
#include "gpu_lod/hull_bind.h"

#include <cstdio>
#include <cstring>
#include <regex>
#include <sstream>

namespace fftess::gpulod::hull {

namespace {

constexpr const char* kVertexAttribute = "fftessAttribute";

const char* glslType(int components) {
  static const char* const names[] = {"float", "float", "vec2", "vec3", "vec4"};
  return names[std::clamp(components, 1, 4)];
}

const verify::InputBinding* findInput(const verify::Lod& lod, const Input& in) {
  for (const verify::InputBinding& b : lod.inputs)
    if (b.name == in.name || b.name == in.glslName || (!in.semantic.empty() && b.name == in.semantic)) return &b;
  return nullptr;
}

const verify::InputBinding* findInputKey(const verify::Lod& lod, const std::string& key) {
  for (const verify::InputBinding& b : lod.inputs)
    if (b.name == key) return &b;
  return nullptr;
}

// A constant input ([lod.inputs] NAME = [0, 1, 0]) as the value string inputValue reads back: "=" and its numbers.
std::string constantKey(const std::vector<double>& numbers) {
  std::string s = "=";
  char b[32];
  for (double d : numbers) {
    std::snprintf(b, sizeof b, " %.9g", static_cast<double>(static_cast<float>(d))); // the float, exactly
    s += b;
  }
  return s;
}

// Control point value `value` (kLodInputValues, or constantKey's) of fftess corner c of patch i, as a vec4 (position
// types w = 1; a constant's missing components 0).
glm::vec4 inputValue(const std::string& value, const verify::LodPatches& patches, size_t i, int c,
                     const verify::LodInput& in) {
  if (!value.empty() && value[0] == '=') {
    glm::vec4 x(0.0f);
    std::istringstream n(value.substr(1));
    for (int k = 0; k < 4 && (n >> x[k]); ++k) {
    }
    return x;
  }
  if (value == "position") return glm::vec4(in.patch.corners[c], 1.0f);
  const verify::LodPatches::Corner corner = patches.corner(i, c);
  if (value == "position_flat") return glm::vec4(corner.flat, 1.0f);
  if (value == "position_xz") return glm::vec4(corner.flat.x, corner.flat.z, 0.0f, 0.0f);
  if (value == "uv") return glm::vec4(corner.tex, 0.0f, 0.0f);
  if (value == "bounds_y") return glm::vec4(in.patch.minHeight, in.patch.maxHeight, 0.0f, 0.0f);
  // patch_size: the flat patch's world size along x
  return glm::vec4(patches.corner(i, 1).flat.x - patches.corner(i, 0).flat.x, 0.0f, 0.0f, 0.0f);
}

} // namespace

bool controlPointData(const HullProgram& program, const verify::LodPatches& patches, std::vector<float>& data,
                      int& slots, std::vector<Diagnostic>& errors) {
  const verify::Lod& lod = patches.scene().lod;
  std::vector<std::string> values(1);
  const verify::InputBinding* position = findInputKey(lod, "gl_Position");
  values[0] = position ? position->value : "position";
  for (const Input& in : program.inputs) {
    if (in.builtin) continue;
    const verify::InputBinding* b = findInput(lod, in);
    if (!b) {
      errors.push_back(diagnostic(in.declared, "input '" + in.name + "' is not bound: add it to [lod.inputs] (one of: "
                                         "position, position_flat, position_xz, uv, bounds_y, patch_size, or a constant)"));
      continue;
    }
    values.push_back(b->value.empty() ? constantKey(b->numbers) : b->value);
  }
  if (!errors.empty()) return false;
  slots = static_cast<int>(values.size());
  const int n = lod.controlPoints;
  data.assign(patches.size() * n * slots * 4, 0.0f);
  float* p = data.data();
  for (size_t i = 0; i < patches.size(); ++i) {
    const verify::LodInput in = patches[i];
    for (int k = 0; k < n; ++k) {
      const int c = lod.cornerOrder[k];
      for (const std::string& v : values) {
        const glm::vec4 x = inputValue(v, patches, i, c, in);
        std::memcpy(p, &x[0], sizeof x);
        p += 4;
      }
    }
  }
  return true;
}

std::string generatedVersion(const HullProgram& program, bool tessellation) {
  std::smatch m;
  static const std::regex es(R"((?:^|\n)[ \t]*#[ \t]*version[ \t]+(\d+)[ \t]+es\b)");
  if (program.language != Language::Glsl || !std::regex_search(program.glsl, m, es)) return "#version 450\n";
  const int version = std::stoi(m[1]);
  return "#version " + m[1].str() + " es\n" +
         (tessellation && version < 320 ? "#extension GL_EXT_tessellation_shader : require\n" : "");
}

std::string vertexShaderSource(const HullProgram& program) {
  std::string decl, body = "  gl_Position = " + std::string(kVertexAttribute) + "0;\n";
  std::string block, blockName;
  int slot = 1;
  auto closeBlock = [&] {
    if (!blockName.empty()) decl += "out " + blockName + " {\n" + block + "} fftessOut" + blockName + ";\n";
    block.clear();
    blockName.clear();
  };
  for (const Input& in : program.inputs) {
    if (in.builtin) continue;
    const std::string attr = kVertexAttribute + std::to_string(slot);
    decl += "layout(location = " + std::to_string(slot) + ") in vec4 " + attr + ";\n";
    static const char* const swizzle[] = {".x", ".x", ".xy", ".xyz", ""};
    const std::string value = attr + swizzle[std::clamp(in.components, 1, 4)];
    const size_t dot = in.glslName.find('.');
    if (dot != std::string::npos) {
      const std::string name = in.glslName.substr(0, dot), member = in.glslName.substr(dot + 1);
      if (name != blockName) closeBlock();
      blockName = name;
      block += "  " + std::string(glslType(in.components)) + " " + member + ";\n";
      body += "  fftessOut" + name + "." + member + " = " + value + ";\n";
    } else {
      closeBlock();
      const std::string loc = in.location >= 0 ? "layout(location = " + std::to_string(in.location) + ") " : "";
      decl += loc + "out " + glslType(in.components) + " " + in.glslName + ";\n";
      body += "  " + in.glslName + " = " + value + ";\n";
    }
    ++slot;
  }
  closeBlock();
  // Attribute location k = controlPointData's slot k (0: gl_Position).
  const std::string pos = "layout(location = 0) in vec4 " + std::string(kVertexAttribute) + "0;\n";
  return generatedVersion(program, false) + pos + decl + "void main() {\n" + body + "}\n";
}

} // namespace fftess::gpulod::hull
