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
import hashlib
import multiprocessing
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
    # Identical reports (a test that runs the same command twice) are validated once; the rest on every core.
    by_content = {}
    for path in files:
        with open(path, "rb") as f:
            by_content.setdefault(hashlib.sha1(f.read()).hexdigest(), []).append(path)
    unique = [paths[0] for paths in by_content.values()]
    with multiprocessing.Pool(min(len(unique), os.cpu_count() or 1), initializer=load, initargs=(schema_dir,)) as pool:
        results = pool.map(check, unique)
    bad, kinds = 0, {}
    for (errors, kind), paths in zip(results, by_content.values()):
        kinds[kind] = kinds.get(kind, 0) + len(paths)
        if not errors:
            continue
        bad += len(paths)
        for path in paths:
            cmd = path[: -len(".json")] + ".cmd"
            print("INVALID %s (%s)" % (path, open(cmd).read().strip() if os.path.exists(cmd) else "?"))
        for ptr, message in errors[:10]:
            print("  %s: %s" % (ptr or "/", message))
    print("kinds: " + ", ".join("%s %d" % (k, n) for k, n in sorted(kinds.items(), key=lambda x: str(x[0]))))
    print("%d of %d reports invalid (%d different reports validated)" % (bad, len(files), len(unique)))
    return 1 if bad else 0


_schemas = None


def load(schema_dir):
    global _schemas
    _schemas = validate_json.load_schemas(schema_dir)


def check(path):
    """(errors, kind) of one file."""
    schemas, store = _schemas
    try:
        reports = validate_json.reports_of(path)
    except ValueError as e:
        return [("", "not JSON: %s" % e)], None
    errors, kind = [], None
    for where, report in reports:
        errors += validate_json.validate(schemas, store, where, report)
        kind = report.get("kind") if isinstance(report, dict) else None
    return errors, kind


if __name__ == "__main__":
    sys.exit(main(sys.argv))
