// A CiReport (ci_report.h) as SARIF 2.1.0 (OASIS; docs/ci.md, "SARIF"): one run of tool.driver "fftess" with one rule
// per cause (its fix as help.text), one result per CiResult (ruleId and ruleIndex of its cause, level, message.text,
// the file as an artifactLocation with region.startLine, patch and edge as logicalLocations), the run's notes as
// toolExecutionNotifications of its one invocation and its properties (verdict, what was checked). Files under the
// current directory are relative URIs against uriBaseId "%SRCROOT%" (run.originalUriBaseIds: the directory), others
// absolute file URIs; both percent-encoded (RFC 3986). Pure function (getcwd for the base).
#pragma once

#include "ci_report.h"

#include <string>

namespace fftess::cli {

// A path as a URI reference: each byte outside RFC 3986's unreserved set and '/' as %HH.
std::string percentEncodePath(const std::string& path);
// SARIF text ("\n"-terminated JSON). cwd: the directory relative paths are against ("" : getcwd()).
std::string sarifText(const CiReport& r, const std::string& cwd = "");

} // namespace fftess::cli
