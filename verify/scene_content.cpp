// Scene contents: files read with a size limit, and Scene::contentHash (FNV-1a 64 of what the verdict depends on).
// docs/verify.md, Scene format (Limits, Scene::contentHash).
#include "verify/scene.h"
#include "verify/internal.h"

#include <cstring>
#include <fstream>

namespace fftess::verify::detail {

namespace {

// FNV-1a 64 (offset basis 0xcbf29ce484222325, prime 0x100000001b3), byte by byte.
struct Fnv1a64 {
  uint64_t h = 0xcbf29ce484222325ull;
  void add(const void* data, size_t n) {
    const unsigned char* b = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
  }
  void add(const std::string& s) { add(s.data(), s.size()); }
  void tag(unsigned char t, uint64_t size) { // a separator: the tag byte, then the part's size (8 bytes, little endian)
    add(&t, 1);
    for (int i = 0; i < 8; ++i) {
      const unsigned char c = static_cast<unsigned char>(size >> (8 * i));
      add(&c, 1);
    }
  }
};

} // namespace

// Reads path whole when it holds at most limit bytes (any kind of file: a FIFO or /dev/zero is read only up to the
// limit). 1: read; 0: cannot open or read; -1: larger than limit.
int readBounded(const std::string& path, size_t limit, std::string& out) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return 0;
  out.clear();
  char buf[65536];
  while (f) {
    f.read(buf, sizeof buf);
    const size_t got = static_cast<size_t>(f.gcount());
    if (out.size() + got > limit) return -1;
    out.append(buf, got);
  }
  return f.bad() ? 0 : 1;
}

// Scene::contentHash: the text, each override, the raw heightmap's texels (after displacement.format), the
// lod.shader file and (layout.kind = "patches") layout.file, each part after a tag byte and its size (Fnv1a64::tag). False with error: the shader cannot be
// read (it was there when the key was read) or is larger than kMaxSceneBytes.
// The files a shader #includes ("..." and <...>, relative to the including file), depth first, each hashed with
// its name as written; one that cannot be read is left to the shader's compiler to report.
static void hashIncludes(Fnv1a64& h, const std::string& file, const std::string& text, int depth) {
  if (depth > 16) return;
  const size_t slash = file.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : file.substr(0, slash);
  size_t at = 0;
  while ((at = text.find("#include", at)) != std::string::npos) {
    at += 8;
    const size_t open = text.find_first_of("\"<\n", at);
    if (open == std::string::npos || text[open] == '\n') continue;
    const size_t close = text.find_first_of(text[open] == '"' ? "\"\n" : ">\n", open + 1);
    if (close == std::string::npos || text[close] == '\n') continue;
    const std::string name = text.substr(open + 1, close - open - 1);
    const std::string path = !name.empty() && name[0] == '/' ? name : dir + "/" + name;
    std::string bytes;
    if (readBounded(path, kMaxSceneBytes, bytes) <= 0) continue;
    h.tag(5, name.size());
    h.add(name);
    h.tag(6, bytes.size());
    h.add(bytes);
    hashIncludes(h, path, bytes, depth + 1);
  }
}

// One file the scene names: its bytes after the tag and their size. False with error "KEY: PATH: why" when it cannot
// be read (`unreadable`) or holds more than kMaxSceneBytes.
static bool hashFile(Fnv1a64& h, unsigned char tag, const char* key, const std::string& path, const char* unreadable,
                     std::string& bytes, std::string& error) {
  const int rc = readBounded(path, kMaxSceneBytes, bytes);
  if (rc <= 0) {
    error = std::string(key) + ": " + path +
            (rc < 0 ? ": larger than " + std::to_string(kMaxSceneBytes) + " bytes" : ": " + std::string(unreadable));
    return false;
  }
  h.tag(tag, bytes.size());
  h.add(bytes);
  return true;
}

bool hashSceneContent(const std::string& text, const std::vector<std::string>& overrides, Scene& s, std::string& error) {
  Fnv1a64 h;
  h.tag(0, text.size());
  h.add(text);
  for (const std::string& o : overrides) {
    h.tag(1, o.size());
    h.add(o);
  }
  if (s.displacement.kind == DisplacementKind::Raw && s.displacement.texels) {
    const std::vector<float>& t = *s.displacement.texels;
    h.tag(2, t.size() * sizeof(float));
    for (float x : t) {
      uint32_t b;
      std::memcpy(&b, &x, sizeof b);
      h.add(&b, sizeof b); // host order (little endian on every target fftess builds for)
    }
  }
  std::string bytes;
  if (!s.lod.shader.empty()) {
    if (!hashFile(h, 3, "lod.shader", s.lod.shader, "cannot read the shader", bytes, error)) return false;
    hashIncludes(h, s.lod.shader, bytes, 0);
  }
  if (!s.lod.evaluationShader.empty()) {
    if (!hashFile(h, 4, "lod.evaluation_shader", s.lod.evaluationShader, "cannot read it", bytes, error)) return false;
    hashIncludes(h, s.lod.evaluationShader, bytes, 0);
  }
  if (s.layout.kind == LayoutKind::Patches && !s.layout.file.empty() && // layout.file's bytes, as read
      !hashFile(h, 7, "layout.file", s.layout.file, "cannot read it", bytes, error))
    return false;
  s.contentHash = h.h;
  return true;
}

} // namespace fftess::verify::detail
