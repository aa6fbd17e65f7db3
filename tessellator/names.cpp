// The name tables of names.h: one per enum, read by toString, the parse functions and the *Names() lists.
#include "names.h"

#include <cstring>

namespace fftess {
namespace {

template <class T>
struct Named {
  T value;
  const char* name;
};

// Table order is the order of help texts and error messages (not necessarily the enum's order).
constexpr Named<Domain> kDomains[] = {
    {Domain::Quad, "quad"},
    {Domain::Tri, "tri"},
    {Domain::Isoline, "isoline"},
};
constexpr Named<Partitioning> kPartitionings[] = {
    {Partitioning::Integer, "integer"},
    {Partitioning::Pow2, "pow2"},
    {Partitioning::FractionalEven, "fractional_even"},
    {Partitioning::FractionalOdd, "fractional_odd"},
};
constexpr Named<OutputPrimitive> kOutputPrimitives[] = {
    {OutputPrimitive::Point, "point"},
    {OutputPrimitive::Line, "line"},
    {OutputPrimitive::TriangleCw, "triangle_cw"},
    {OutputPrimitive::TriangleCcw, "triangle_ccw"},
};
constexpr Named<Stage> kStages[] = {
    {{false, Reduction::Average, ReductionAxes::TwoAxis}, "hw"},
    {{true, Reduction::Average, ReductionAxes::TwoAxis}, "hlsl-avg"},
    {{true, Reduction::Min, ReductionAxes::TwoAxis}, "hlsl-min"},
    {{true, Reduction::Max, ReductionAxes::TwoAxis}, "hlsl-max"},
    {{true, Reduction::Average, ReductionAxes::OneAxis}, "hlsl-avg-1axis"},
    {{true, Reduction::Min, ReductionAxes::OneAxis}, "hlsl-min-1axis"},
    {{true, Reduction::Max, ReductionAxes::OneAxis}, "hlsl-max-1axis"},
};

// Stages are equal as names: every hw stage is "hw", whatever its (unused) reduction and axes.
bool sameName(const Stage& a, const Stage& b) {
  if (!a.hlsl || !b.hlsl) return a.hlsl == b.hlsl;
  return a.reduction == b.reduction && a.axes == b.axes;
}
template <class T>
bool sameName(T a, T b) {
  return a == b;
}

template <class T, size_t N>
const char* nameOf(const Named<T> (&table)[N], const T& value) {
  for (const Named<T>& n : table)
    if (sameName(n.value, value)) return n.name;
  return "?";
}

template <class T, size_t N>
bool parse(const Named<T> (&table)[N], const char* s, T& out) {
  for (const Named<T>& n : table)
    if (std::strcmp(s, n.name) == 0) return out = n.value, true;
  return false;
}

template <class T, size_t N>
std::vector<std::string> namesOf(const Named<T> (&table)[N]) {
  std::vector<std::string> v;
  for (const Named<T>& n : table) v.push_back(n.name);
  return v;
}

} // namespace

const char* toString(Domain d) { return nameOf(kDomains, d); }
const char* toString(Partitioning p) { return nameOf(kPartitionings, p); }
const char* toString(OutputPrimitive p) { return nameOf(kOutputPrimitives, p); }
const char* toString(const Stage& s) { return nameOf(kStages, s); }

bool parseDomain(const char* s, Domain& out) { return parse(kDomains, s, out); }
bool parsePartitioning(const char* s, Partitioning& out) { return parse(kPartitionings, s, out); }
bool parseOutputPrimitive(const char* s, OutputPrimitive& out) { return parse(kOutputPrimitives, s, out); }
bool parseStage(const char* s, Stage& out) { return parse(kStages, s, out); }

const std::vector<std::string>& domainNames() {
  static const std::vector<std::string> v = namesOf(kDomains);
  return v;
}
const std::vector<std::string>& partitioningNames() {
  static const std::vector<std::string> v = namesOf(kPartitionings);
  return v;
}
const std::vector<std::string>& outputPrimitiveNames() {
  static const std::vector<std::string> v = namesOf(kOutputPrimitives);
  return v;
}
const std::vector<std::string>& stageNames() {
  static const std::vector<std::string> v = namesOf(kStages);
  return v;
}

std::string joinNames(const std::vector<std::string>& names, const std::string& separator) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i) s += (i ? separator : "") + names[i];
  return s;
}

} // namespace fftess
