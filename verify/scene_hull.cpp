// The scene keys of a hull shader as written (docs/gpu_lod.md "Your hull shader as written"): lod.entry,
// lod.evaluation_shader, [lod.uniforms], [lod.inputs], lod.control_points, lod.corner_order, lod.domain_u,
// lod.domain_v. What the shader itself declares is checked against them by gpu_lod (hull::checkAgainstScene): here
// only what the scene alone can get wrong.
#include "verify/scene_reader.h"

#include <sys/stat.h>

#include <cstring>
#include <iterator>
#include <vector>

namespace fftess::verify::detail {

namespace {

const Enum kAxes[] = {{"+x", int(DomainAxis::PlusX)},
                      {"-x", int(DomainAxis::MinusX)},
                      {"+z", int(DomainAxis::PlusZ)},
                      {"-z", int(DomainAxis::MinusZ)}};

// The named matrices of kLodUniformValues ("transpose(NAME)" takes one of these).
bool isMatrixValue(const std::string& v) {
  for (const char* m : {"view", "projection", "view_projection", "projection_d3d", "view_projection_d3d", "world"})
    if (v == m) return true;
  return false;
}

template <size_t N>
bool oneOf(const char* const (&names)[N], const std::string& v) {
  for (const char* n : names)
    if (v == n) return true;
  return false;
}

template <size_t N>
std::string nearest(const char* const (&names)[N], const std::string& v) {
  return Reader::didYouMean(v, std::vector<std::string>(std::begin(names), std::end(names)));
}

template <size_t N>
std::string choices(const char* const (&names)[N]) {
  std::string s;
  for (const char* n : names) s += std::string(s.empty() ? "" : ", ") + n;
  return s;
}

void position(const toml::node& n, int& line, int& column) {
  line = n.source().begin ? static_cast<int>(n.source().begin.line) : 0;
  column = n.source().begin ? static_cast<int>(n.source().begin.column) : 0;
}

// A number or boolean, or an array of them (nested arrays flattened in reading order) into `out`.
void numbers(Reader& r, const std::string& key, const toml::node& n, std::vector<double>& out) {
  if (n.is_boolean()) {
    out.push_back(n.as_boolean()->get() ? 1.0 : 0.0);
  } else if (n.is_integer()) {
    out.push_back(static_cast<double>(n.as_integer()->get()));
  } else if (n.is_floating_point()) {
    const double d = n.as_floating_point()->get();
    if (!std::isfinite(d)) r.fail(key, &n, "must be finite (a NaN or infinity goes in as bits: use the shader)");
    out.push_back(d);
  } else if (const toml::array* a = n.as_array()) {
    if (a->empty()) r.fail(key, &n, "an empty array binds nothing");
    for (const toml::node& e : *a) numbers(r, key, e, out);
  } else {
    r.fail(key, &n, std::string("expected a number, a boolean, an array of them or a named value, got ") +
                        Reader::typeName(n));
  }
  if (out.size() > 4096) r.fail(key, &n, "more than 4096 numbers");
}

void readUniforms(Reader& r, const toml::table& lod, Lod& L) {
  const toml::table* t = r.table(lod, "lod.", "uniforms", false);
  if (!t) return;
  for (auto&& [k, v] : *t) {
    UniformBinding b;
    b.name = std::string(k.str());
    const std::string key = "lod.uniforms." + b.name;
    position(v, b.line, b.column);
    if (v.is_string()) {
      std::string s = v.as_string()->get();
      if (s.rfind("transpose(", 0) == 0 && s.size() > 11 && s.back() == ')') {
        s = s.substr(10, s.size() - 11);
        if (!isMatrixValue(s))
          r.fail(key, &v, "transpose() takes a named matrix (view, projection, view_projection, projection_d3d, "
                          "view_projection_d3d, world), got \"" + s + "\"");
        b.transpose = true;
      }
      if (!oneOf(kLodUniformValues, s))
        r.fail(key, &v, "unknown value \"" + s + "\" (expected a number, an array, or one of: " +
                            choices(kLodUniformValues) + ", or transpose(MATRIX)" + nearest(kLodUniformValues, s) + ")");
      b.value = s;
    } else {
      numbers(r, key, v, b.numbers);
    }
    L.uniforms.push_back(std::move(b));
  }
}

void readInputs(Reader& r, const toml::table& lod, Lod& L) {
  const toml::table* t = r.table(lod, "lod.", "inputs", false);
  if (!t) return;
  for (auto&& [k, v] : *t) {
    InputBinding b;
    b.name = std::string(k.str());
    const std::string key = "lod.inputs." + b.name;
    position(v, b.line, b.column);
    if (v.is_string()) {
      b.value = v.as_string()->get();
      if (!oneOf(kLodInputValues, b.value))
        r.fail(key, &v, "unknown value \"" + b.value + "\" (expected one of: " + choices(kLodInputValues) +
                            ", or a constant: a number or an array of up to 4" + nearest(kLodInputValues, b.value) + ")");
    } else {
      numbers(r, key, v, b.numbers);
      if (b.numbers.size() > 4) r.fail(key, &v, "a constant input has at most 4 components");
    }
    L.inputs.push_back(std::move(b));
  }
}

void readControlPoints(Reader& r, const toml::table& t, Lod& L) {
  const std::string p = "lod.";
  r.integer(t, p, "control_points", L.controlPoints, 1, 4);
  if (L.controlPoints != 1 && L.controlPoints != 4)
    r.fail(p + "control_points", t.get("control_points"), "must be 4 (a patch's corners) or 1 (one point per patch)");
  // Default order for one point: corner 0.
  if (const toml::node* n = t.get("corner_order")) {
    const toml::array* a = n->as_array();
    if (!a || a->size() != static_cast<size_t>(L.controlPoints))
      r.fail(p + "corner_order", n, "expected an array of " + std::to_string(L.controlPoints) +
                                        " corner indices (lod.control_points), each 0..3 (u + 2v: 0 (-x,-z), 1 (+x,-z), "
                                        "2 (-x,+z), 3 (+x,+z))");
    bool seen[4] = {false, false, false, false};
    for (size_t i = 0; i < a->size(); ++i) {
      const toml::node& e = *a->get(i);
      if (!e.is_integer() || e.as_integer()->get() < 0 || e.as_integer()->get() > 3)
        r.fail(p + "corner_order", &e, "element " + std::to_string(i) + ": expected a corner index 0..3 (u + 2v)");
      const int c = static_cast<int>(e.as_integer()->get());
      if (seen[c]) r.fail(p + "corner_order", &e, "element " + std::to_string(i) + ": corner " + std::to_string(c) + " twice");
      seen[c] = true;
      L.cornerOrder[i] = c;
    }
  }
  r.enumeration(t, p, "domain_u", kAxes, L.domainU);
  r.enumeration(t, p, "domain_v", kAxes, L.domainV);
  const auto onX = [](DomainAxis a) { return a == DomainAxis::PlusX || a == DomainAxis::MinusX; };
  if (onX(L.domainU) == onX(L.domainV))
    r.fail(p + (t.get("domain_v") ? "domain_v" : "domain_u"), t.get("domain_v") ? t.get("domain_v") : t.get("domain_u"),
           std::string("lod.domain_u and lod.domain_v must lie on different axes (one on x, one on z), got \"") +
               nameOf(kAxes, int(L.domainU)) + "\" and \"" + nameOf(kAxes, int(L.domainV)) + "\"");
}

} // namespace

void readHullKeys(Reader& r, const toml::table& t, Lod& L, const std::string& baseDir) {
  const std::string p = "lod.";
  const char* keys[] = {"entry", "evaluation_shader", "uniforms", "inputs", "control_points", "corner_order",
                        "domain_u", "domain_v"};
  if (L.shader.empty()) {
    // lod.shader = "" (--set lod.shader='' switches a shader scene to the built-in scheme): the keys stay unread.
    if (t.get("shader")) return;
    for (const char* k : keys)
      if (const toml::node* n = t.get(k))
        r.fail(p + k, n, "needs lod.shader (a hull shader as written: a GLSL tessellation control shader or an HLSL "
                         "hull shader)");
    return;
  }
  if (r.string(t, p, "entry", L.entry)) {
    if (L.entry.empty()) r.fail(p + "entry", t.get("entry"), "must name the hull shader function");
    position(*t.get("entry"), L.entryLine, L.entryColumn);
  }
  if (r.string(t, p, "evaluation_shader", L.evaluationShader)) {
    const toml::node* at = t.get("evaluation_shader");
    if (L.evaluationShader.empty()) r.fail(p + "evaluation_shader", at, "must name a file");
    if (L.evaluationShader[0] != '/') L.evaluationShader = baseDir + "/" + L.evaluationShader;
    struct stat st;
    if (::stat(L.evaluationShader.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
      r.fail(p + "evaluation_shader", at,
             "cannot read \"" + L.evaluationShader + "\" (the path is relative to the scene file)");
  }
  readUniforms(r, t, L);
  readInputs(r, t, L);
  readControlPoints(r, t, L);
}

} // namespace fftess::verify::detail
