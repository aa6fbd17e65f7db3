// The test suite's own checks of the CI files fftess writes (--sarif, --junit; docs/ci.md).
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace clitest {

// What a SARIF log violates of the properties SARIF 2.1.0 (OASIS, §3) requires: sarifLog version "2.1.0" and runs;
// run.tool.driver.name; reportingDescriptor.id (unique in rules); result.message with text or id; result.level and
// kind from their enums, and level "none" when kind is not "fail" (§3.27.9/10); ruleIndex within rules and
// rules[ruleIndex].id == ruleId (§3.27.6); physicalLocation with artifactLocation or address (§3.29.2); artifact uris
// as URI references (RFC 3986: no space, percent-encoding well formed), relative when a uriBaseId is given; region
// startLine >= 1 and endLine >= startLine; logicalLocation.kind from its list; invocation.executionSuccessful;
// notification.message; run.originalUriBaseIds' uris absolute and ending in '/'. Empty: none.
std::vector<std::string> sarifProblems(const nlohmann::json& log);

// The counts of a JUnit file: the first <testsuite>'s attributes and its child elements of each kind.
struct JunitCounts {
  long tests = -1, failures = -1, errors = -1, skipped = -1; // the attributes (-1: missing)
  long testcases = 0, failureElements = 0, errorElements = 0, skippedElements = 0;
};
JunitCounts junitCounts(const std::string& xml);

} // namespace clitest
