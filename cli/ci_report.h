// What a CI system shows of a check, sweep, compare or driver-check (docs/ci.md): the findings of one command as a
// list of results, each with its cause (a rule), its fix, where it is (a file and line, patch and edge) and what it
// is in JUnit terms, grouped into JUnit test cases. report_sarif.h writes it as SARIF 2.1.0, report_junit.h as JUnit
// XML; ci_scene.h and ci_compare.h build it from verify's and compare's reports. Pure data: no I/O.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace fftess::cli {

// A logical location (SARIF logicalLocation): a patch ("patch[12]", kind "object"), an edge ("patch[12].Ueq0", kind
// "member") or a scene key ("lod.adjacency_clamp", kind "variable").
struct CiLogical {
  std::string name, fullyQualifiedName, kind;
};

// What a result is in JUnit: a <failure> (a finding that fails the command: a crack, a hole, a difference), an
// <error> (something not decided or not checked: undecided patches, an invalid camera, nothing checked, an
// interrupted run) or nothing of its own (a finding that does not count: a T-junction without --fail-on-tjunctions,
// an off-screen finding without --offscreen; its test case is <skipped> with the reason, and it is in system-out).
enum class CiOutcome { Failure, Error, NotCounted };

struct CiResult {
  std::string rule;        // the cause key: one SARIF rule per distinct key
  std::string kind;        // crack, t_junction, hole, undecided, gpu_float, nothing_checked, camera_invalid, ...
  std::string level;       // SARIF level: "error", "warning" or "note"
  CiOutcome outcome = CiOutcome::Failure;
  std::string where;       // short place in words ("ring 0 tile 1 patch 2 Ueq1 | ring 0 tile 1 patch 3 Veq0")
  std::string message;     // the cause in words, with this finding's numbers
  std::string fix;         // what removes the cause (SARIF rule help and result property; JUnit failure text)
  std::string file;        // the artifact: the scene or batch file as given on the command line ("": none)
  int line = 0;            // its line (1-based; 0: the file as a whole)
  std::string lineWhy;     // what the line is ("the line of lod.adjacency_clamp", "the patch's batch line")
  std::vector<CiLogical> logical;
  nlohmann::ordered_json properties = nlohmann::ordered_json::object(); // SARIF result properties
};

// One JUnit test case: its results (indices into CiReport::results) become its children; skipped: the reason it is
// <skipped> ("" for none; set when it has only results that do not count, or nothing was checked); out: system-out.
struct CiCase {
  std::string name;
  std::vector<size_t> results;
  std::string skipped;
  std::string out;
};

struct CiReport {
  std::string command;       // "check", "sweep", "compare", "driver-check"
  std::string suite;         // the JUnit test suite's name and the SARIF run's description: "fftess check FILE"
  std::vector<std::string> commandLine; // what was run (SARIF invocation)
  std::vector<CiResult> results;
  std::vector<CiCase> cases;
  // Run-level notes (SARIF toolExecutionNotifications): what was checked, truncations; level "note" or "warning".
  std::vector<std::pair<std::string, std::string>> notes;
  nlohmann::ordered_json properties = nlohmann::ordered_json::object(); // SARIF run properties: verdict, counts
  int exitStatus = 0;
};

// The results of a case that are JUnit <failure>s / <error>s, and the totals over the report (JUnit's counts).
struct CiCounts {
  size_t tests = 0, failures = 0, errors = 0, skipped = 0;
};
CiCounts ciCounts(const CiReport& r);

} // namespace fftess::cli
