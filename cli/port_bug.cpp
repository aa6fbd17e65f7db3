#include "port_bug.h"

#include "common.h"

#include <algorithm>
#include <iterator>

namespace fftess::cli {
namespace {

// A patch of each domain that every whole-patch bug applies to (pow2, triangles, a denormal factor).
Patch formSample(Domain d) {
  Patch p;
  p.domain = d;
  p.partitioning = Partitioning::Pow2;
  p.primitive = d == Domain::Isoline ? OutputPrimitive::Line : OutputPrimitive::TriangleCw;
  p.factors[0] = floatOf(1); // a denormal
  return p;
}

constexpr Domain kFormDomains[] = {Domain::Quad, Domain::Tri, Domain::Isoline};
const char* const kFormDomainNames[] = {"quad", "tri", "isoline"};

} // namespace

SimulatedPortBug::SimulatedPortBug(const std::string& value) {
  if (value.empty()) return;
  const size_t colon = value.find(':');
  const std::string name = value.substr(0, colon);
  std::string accepted;
  for (int b = 0; b < int(PortBug::Count); ++b)
    if (portBugTransformsPatch(PortBug(b)))
      accepted += std::string(accepted.empty() ? "" : ", ") + toString(PortBug(b));
  if (!parsePortBug(name.c_str(), bug_))
    throw UsageError("--port-bug " + quoteToken(name) + ": not a port bug; accepted: " + accepted);
  if (!portBugTransformsPatch(bug_))
    throw UsageError("--port-bug " + name + ": " + describe(bug_) +
                     " is a per-point arithmetic bug, not a change of a patch's input or output: it cannot be "
                     "simulated around a driver; accepted: " + accepted);
  if (colon != std::string::npos) {
    const std::string form = value.substr(colon + 1);
    const bool digits = !form.empty() && form.size() <= 2 && form.find_first_not_of("0123456789") == std::string::npos;
    int forms = 0;
    for (Domain d : kFormDomains) forms = std::max(forms, portBugVariants(bug_, formSample(d)));
    const int k = digits ? std::stoi(form) : 0;
    if (k < 1 || k > forms)
      throw UsageError("--port-bug " + quoteToken(value) + ": FORM after ':' must be a number from 1 to " +
                       std::to_string(forms) + " (the forms of " + name + ")");
    form_ = k - 1;
  }
  active_ = true;
}

std::string SimulatedPortBug::header() const {
  if (!active_) return "";
  std::string forms;
  for (size_t i = 0; i < std::size(kFormDomains); ++i) {
    const std::string f = portBugVariantName(bug_, formSample(kFormDomains[i]), form_);
    if (!f.empty()) forms += std::string(forms.empty() ? "" : "; ") + kFormDomainNames[i] + ": " + f;
  }
  return std::string("simulated port bug: ") + toString(bug_) + " (" + describe(bug_) + "), form " +
         std::to_string(form_ + 1) + (forms.empty() ? "" : " (" + forms + ")") +
         "; patches it does not apply to run as they are\n";
}

} // namespace fftess::cli
