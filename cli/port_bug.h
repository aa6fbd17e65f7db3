// driver-check --port-bug NAME[:FORM]: the driver run as a port with a whole-patch bug would be (compare/compare.h
// portBugInput before the driver, portBugOutput after it), so that the report shows what the bug looks like on a
// real tessellator and that compare names it.
#pragma once

#include "compare/compare.h"

#include <string>

namespace fftess::cli {

class SimulatedPortBug {
public:
  // value: "" (no bug), NAME or NAME:FORM (FORM from 1, default 1; see portBugVariantName). UsageError naming
  // --port-bug for an unknown name, a per-point arithmetic bug (those cannot be simulated around a driver: the
  // accepted names are listed) or a bad form.
  explicit SimulatedPortBug(const std::string& value);
  bool active() const { return active_; }
  // The patch the driver gets (the patch itself when no bug, or the form does not apply to it).
  Patch input(const Patch& patch) const { return active_ ? portBugInput(bug_, form_, patch) : patch; }
  // The driver's capture of 'patch' as the port writes it.
  void output(const Patch& patch, CapturedPatch& capture) const {
    if (active_) portBugOutput(bug_, form_, patch, capture);
  }
  // The report's header line ("simulated port bug: NAME (...), form K: patches it does not apply to run as they
  // are\n"), "" when no bug.
  std::string header() const;
  PortBug bug() const { return bug_; }
  int form() const { return form_ + 1; } // 1-based, as on the command line

private:
  bool active_ = false;
  PortBug bug_{};
  int form_ = 0; // 0-based
};

} // namespace fftess::cli
