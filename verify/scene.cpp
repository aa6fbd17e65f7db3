// Scene files: TOML (toml++) -> Scene, with every error naming the key and the file position, unknown keys
// rejected, and `KEY=VALUE` overrides validated exactly like the file. The steps of a parse (parseImpl): the TOML
// text parsed, the overrides applied to the document (applyOverride), the sections read and validated in order
// (readScene; each section in scene_sections.cpp), the content hash (scene_content.cpp), errors made one line.
#include "verify/scene.h"
#include "verify/internal.h"
#include "verify/scene_reader.h"

#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace fftess::verify {

namespace {

using detail::kClamps;
using detail::kDisplacementKinds;
using detail::kEvaluates;
using detail::kFormulas;
using detail::kHeightBounds;
using detail::kLayoutKinds;
using detail::kMipModes;
using detail::kReconstructions;
using detail::kSchemes;
using detail::kTexelFormats;

const detail::Enum kKernels[] = {
    {"epick", int(Kernel::Epick)}, {"epeck", int(Kernel::Epeck)}, {"float", int(Kernel::FloatNaive)}};

// The sections in order; the first bad key throws detail::Failed with r.error set.
void readScene(detail::Reader& r, const toml::table& root, Scene& s, const std::string& baseDir) {
  r.unknownKeys(root, "", {"name", "layout", "displacement", "lod", "tessellation", "domain", "camera", "camera_path"});
  r.string(root, "", "name", s.name);
  detail::readLayout(r, root, s, baseDir);
  detail::readDisplacement(r, root, s, baseDir);
  detail::readLod(r, root, s, baseDir);
  detail::readTessellation(r, root, s);
  detail::checkSchemeEffects(r, root, s);
  detail::readDomain(r, root, s);
  detail::readCameras(r, root, s);
}

// Applies "KEY=VALUE" to the document.
bool applyOverride(toml::table& root, const std::string& ov, std::map<std::string, std::string>& overridden,
                   std::string& error) {
  const size_t eq = ov.find('=');
  if (eq == std::string::npos || eq == 0) {
    error = "--set " + ov + ": expected KEY=VALUE";
    return false;
  }
  std::string key = ov.substr(0, eq), value = ov.substr(eq + 1);
  while (!key.empty() && key.back() == ' ') key.pop_back();
  while (!value.empty() && value.front() == ' ') value.erase(0, 1);
  std::vector<std::string> parts;
  {
    std::string cur;
    for (char c : key) {
      if (c == '.') {
        parts.push_back(cur);
        cur.clear();
      } else {
        cur += c;
      }
    }
    parts.push_back(cur);
  }
  for (const std::string& part : parts)
    if (part.empty()) {
      error = "--set " + key + ": empty key component";
      return false;
    }
  toml::table* t = &root;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* n = t->get(parts[i]);
    if (!n) {
      t->insert(parts[i], toml::table{});
      n = t->get(parts[i]);
    }
    if (!n->is_table()) {
      error = "--set " + key + ": '" + parts[i] + "' is not a table";
      return false;
    }
    t = n->as_table();
  }
  toml::node* existing = t->get(parts.back());
  if (existing && existing->is_table()) {
    error = "--set " + key + ": is a table, expected a key";
    return false;
  }
  try {
    toml::table v = toml::parse("v = " + value);
    t->insert_or_assign(parts.back(), *v.get("v"));
  } catch (const toml::parse_error&) {
    t->insert_or_assign(parts.back(), value); // a bare word: a string
  }
  overridden[key] = ov;
  return true;
}

// Scene::keyLines: every key of a table (recursively, not into arrays) with the line toml++ recorded for it.
void recordKeyLines(const toml::table& t, const std::string& prefix, std::map<std::string, int>& lines) {
  for (const auto& [k, node] : t) {
    const std::string key = prefix + std::string(k.str());
    if (k.source().begin) lines[key] = static_cast<int>(k.source().begin.line);
    else if (node.source().begin) lines[key] = static_cast<int>(node.source().begin.line);
    if (const toml::table* sub = node.as_table()) recordKeyLines(*sub, key + ".", lines);
  }
}

SceneResult parseImpl(const std::string& text, const std::string& source, const std::vector<std::string>& overrides,
                      const std::string& baseDir) {
  SceneResult res;
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << source << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    res.error = os.str();
    return res;
  }
  std::map<std::string, int> keyLines;
  recordKeyLines(root, "", keyLines); // before the overrides: the file's own lines
  std::map<std::string, std::string> overridden;
  for (const std::string& ov : overrides)
    if (!applyOverride(root, ov, overridden, res.error)) return res;
  detail::Reader r(source, overridden);
  try {
    res.scene.source = source;
    readScene(r, root, res.scene, baseDir);
  } catch (const detail::Failed&) {
    res.error = r.error;
    return res;
  } catch (const std::exception& e) {
    res.error = source + ": " + e.what();
    return res;
  }
  res.scene.keyLines = std::move(keyLines);
  if (!detail::hashSceneContent(text, overrides, res.scene, res.error)) return res;
  res.ok = true;
  return res;
}

// Errors are one line: control bytes that came from the input (a key or an override with a newline) as \xHH.
SceneResult oneLine(SceneResult r) {
  std::string out;
  for (unsigned char c : r.error) {
    if (c >= 0x20 && c != 0x7f) {
      out += static_cast<char>(c);
      continue;
    }
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02x", c);
    out += buf;
  }
  r.error = out;
  return r;
}

} // namespace

SceneResult parseScene(const std::string& text, const std::string& sourceName,
                       const std::vector<std::string>& overrides, const std::string& baseDir) {
  return oneLine(parseImpl(text, sourceName, overrides, baseDir));
}

SceneResult loadScene(const std::string& path, const std::vector<std::string>& overrides) {
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    SceneResult r;
    r.error = path + ": is a directory, not a scene file";
    return r;
  }
  std::string text;
  const int rc = detail::readBounded(path, detail::kMaxSceneBytes, text);
  if (rc <= 0) {
    SceneResult r;
    r.error = path + (rc < 0 ? ": scene file larger than " + std::to_string(detail::kMaxSceneBytes) + " bytes (16 MiB, the limit)"
                             : std::string(": cannot open scene file"));
    return r;
  }
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash == 0 ? 1 : slash);
  return oneLine(parseImpl(text, path, overrides, dir));
}

const char* toString(Classification c) {
  switch (c) {
  case Classification::Match: return "match";
  case Classification::TJunction: return "t_junction";
  case Classification::Crack: return "crack";
  }
  return "?";
}
const char* toString(LayoutKind k) { return detail::nameOf(kLayoutKinds, int(k)); }
const char* toString(QuadtreeSplit s) { return detail::nameOf(detail::kQuadtreeSplits, int(s)); }
const char* toString(QuadtreeBalance b) { return detail::nameOf(detail::kQuadtreeBalances, int(b)); }
const char* toString(CameraConvention c) { return detail::nameOf(detail::kCameraConventions, int(c)); }
const char* toString(DisplacementKind k) { return detail::nameOf(kDisplacementKinds, int(k)); }
const char* toString(LodScheme s) { return detail::nameOf(kSchemes, int(s)); }
const char* toString(AdjacencyClamp c) { return detail::nameOf(kClamps, int(c)); }
const char* toString(lod::Reconstruction r) { return detail::nameOf(kReconstructions, int(r)); }
const char* toString(LerpFormula f) { return detail::nameOf(kFormulas, int(f)); }
const char* toString(Kernel k) { return detail::nameOf(kKernels, int(k)); }
const char* toString(MipMode m) { return detail::nameOf(kMipModes, int(m)); }
const char* toString(TexelFormat f) { return detail::nameOf(kTexelFormats, int(f)); }
const char* toString(HeightBounds b) { return detail::nameOf(kHeightBounds, int(b)); }
const char* toString(LodEvaluate e) { return detail::nameOf(kEvaluates, int(e)); }
bool parseKernel(const char* s, Kernel& out) {
  for (const detail::Enum& e : kKernels)
    if (std::strcmp(s, e.name) == 0) {
      out = static_cast<Kernel>(e.value);
      return true;
    }
  return false;
}

} // namespace fftess::verify
