#!/usr/bin/env python3
"""ctest "schema:every JSON report of the cli tests validates" (FIXTURES_CLEANUP of cli_reports): every JSON report the
cli tests produced, collected by tests/cli/run.cpp as PID.N.json (its command line in PID.N.cmd, one PID.runs per test
process with a line per fftess run: "json" when its report was collected, "unread" when it went to a FIFO or a
device, "other" when the run asked for none or failed), validates against docs/schema. Fails on any invalid report,
and on an empty collection unless the cli tests that ran wrote no JSON report that could be collected (a single test
run with ctest -R); an empty collection with no run logged at all (the harness collects nothing) fails too.

    collected_test.py SCHEMA_DIR REPORTS_DIR
"""
import glob
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
import validate_json  # noqa: E402


def main(argv):
    schema_dir, reports = argv[1], argv[2]
    files = sorted(glob.glob(os.path.join(reports, "*.json")))
    runs = []
    for log in glob.glob(os.path.join(reports, "*.runs")):
        with open(log) as f:
            runs += f.read().split()
    wanted = runs.count("json")
    print("%d fftess runs logged by the cli tests: %d wrote a JSON report, %d wrote one to a FIFO or device (not "
          "collected); %d reports collected in %s" % (len(runs), wanted, runs.count("unread"), len(files), reports))
    if not files:
        if runs and wanted == 0:
            print("no cli test that ran wrote a JSON report that can be collected: nothing to validate")
            return 0
        print("FAIL: no JSON report collected (%s): tests/cli/run.cpp collects none" %
              ("no fftess run logged either" if not runs else "%d runs logged one" % wanted))
        return 1
    schemas, store = validate_json.load_schemas(schema_dir)
    bad = 0
    kinds = {}
    for path in files:
        try:
            reports_in = validate_json.reports_of(path)
        except ValueError as e:
            reports_in, errors = [], [("", "not JSON: %s" % e)]
        else:
            errors = []
        for where, report in reports_in:
            errors += validate_json.validate(schemas, store, where, report)
            if isinstance(report, dict):
                kinds[report.get("kind")] = kinds.get(report.get("kind"), 0) + 1
        if errors:
            bad += 1
            cmd = path[: -len(".json")] + ".cmd"
            print("INVALID %s (%s)" % (path, open(cmd).read().strip() if os.path.exists(cmd) else "?"))
            for ptr, message in errors[:10]:
                print("  %s: %s" % (ptr or "/", message))
    print("kinds: " + ", ".join("%s %d" % (k, n) for k, n in sorted(kinds.items(), key=lambda x: str(x[0]))))
    print("%d of %d reports invalid" % (bad, len(files)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
