// A CiReport (ci_report.h) as JUnit XML (docs/ci.md, "JUnit"): <testsuites> with one <testsuite> (the command) whose
// <testcase>s are the report's cases; each result of a case is a <failure> (a finding that fails the command) or an
// <error> (undecided, not checked), with message = where and the cause, type = its kind, and the cause, the fix and
// the file:line as text; a case with results that do not count or nothing checked is <skipped message=reason>. The
// tests / failures / errors / skipped attributes count those elements. Pure function.
#pragma once

#include "ci_report.h"

#include <string>

namespace fftess::cli {

std::string junitText(const CiReport& r);

} // namespace fftess::cli
