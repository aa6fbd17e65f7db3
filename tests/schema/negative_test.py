#!/usr/bin/env python3
"""ctest "schema:the validator rejects reports that break their schema": a check and a sweep report fftess writes
validate; each mutation of them is rejected (exit 1, naming the file and the JSON pointer): a verdict that is no
verdict, a missing stats member, a member the envelope does not know, a wrong type, a cause key as prose (version 9's
cameras_source), an unknown kind, a report that is no object, a file that is no JSON. Usage errors exit 2.

    negative_test.py FFTESS SCHEMA_DIR SOURCE_ROOT WORK_DIR
"""
import copy
import json
import os
import shutil
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
validator = os.path.join(here, "..", "tools", "validate_json.py")
sys.path.insert(0, os.path.join(here, "..", "tools"))
import validate_json  # noqa: E402


def validate(schema_dir, *files):
    """validate_json.py SCHEMA_DIR FILE... as a program: its exit status and output."""
    r = subprocess.run([sys.executable, validator, schema_dir] + list(files), capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def main(argv):
    fftess, schema_dir, root, work = argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    rings = os.path.join(root, "docs", "examples", "rings_small.toml")
    check, sweep = os.path.join(work, "check.json"), os.path.join(work, "sweep.json")
    for args in (["check", rings, "-q", "--json", check],
                 ["sweep", rings, "--random", "1", "--seed", "1", "-j", "1", "-q", "--json", sweep]):
        r = subprocess.run([fftess] + args, capture_output=True, text=True)
        if r.returncode not in (0, 1):
            print("FAIL fftess %s: exit %d\n%s" % (" ".join(args), r.returncode, r.stderr))
            return 1
    failures = []
    rc, out = validate(schema_dir, check, sweep)
    if rc != 0:
        failures.append("the reports fftess wrote do not validate (exit %d):\n%s" % (rc, out))
    base = {"check": json.load(open(check)), "sweep": json.load(open(sweep))}

    def drop(path):
        def f(j):
            *parents, last = path
            for p in parents:
                j = j[p]
            del j[last]
        return f

    def put(path, value):
        def f(j):
            *parents, last = path
            for p in parents:
                j = j[p]
            j[last] = value
        return f

    # (name, report, mutation, the JSON pointer the message must name)
    cases = [
        ("wrong verdict enum", "check", put(["verdict"], "mostly_fine"), "/verdict"),
        ("missing stats member", "check", drop(["stats", "cracks"]), "/stats"),
        ("missing envelope member", "check", drop(["fftess_version"]), "/:"),
        ("unknown envelope member", "check", put(["verdict_words"], "CRACKS"), "/:"),
        ("wrong type", "check", put(["version"], "10"), "/version"),
        ("old schema version", "check", put(["version"], 9), "/version"),
        ("wrong camera convention enum", "check", put(["camera", "convention"], "opengl"), "/camera/convention"),
        ("prose in a key", "sweep", put(["cameras_source"], "1 random, seed 1"), "/cameras_source"),
        ("wrong off_reason enum", "sweep", put(["result_cache", "off_reason"], "--no-result-cache"),
         "/result_cache/off_reason"),
        ("missing camera stats", "sweep", drop(["cameras", 0, "stats"]), "/cameras/0"),
        ("unknown kind", "check", put(["kind"], "chek"), "/kind"),
    ]
    schemas, store = validate_json.load_schemas(schema_dir)
    for name, kind, mutate, pointer in cases:
        j = copy.deepcopy(base[kind])
        mutate(j)
        errors = validate_json.validate(schemas, store, "", j)
        if not any((p or "/") + ":" == pointer or (p or "/") == pointer for p, _ in errors):
            failures.append("%s: not rejected at %s: %s" % (name, pointer, errors))
        else:
            print("rejected as expected: %s: %s" % (name, "; ".join("%s: %s" % (p or "/", m) for p, m in errors)))
    # As a program: an invalid report exits 1 naming the file and the pointer.
    bad = os.path.join(work, "wrong_verdict.json")
    j = copy.deepcopy(base["check"])
    j["verdict"] = "mostly_fine"
    with open(bad, "w") as f:
        json.dump(j, f, indent=2)
    rc, out = validate(schema_dir, bad)
    if rc != 1 or bad + ": /verdict: " not in out:
        failures.append("%s: exit %d (expected 1), output does not name %s: /verdict:\n%s" % (bad, rc, bad, out))
    not_object = os.path.join(work, "array.json")
    not_json = os.path.join(work, "truncated.json")
    with open(not_object, "w") as f:
        f.write("[1, 2]\n")
    with open(not_json, "w") as f:
        f.write(open(check).read()[:100])
    # One invalid file among valid ones: still exit 1, naming only that file.
    rc, out = validate(schema_dir, check, not_json, not_object, sweep)
    if rc != 1 or check in out or sweep in out or not_json not in out or not_object not in out:
        failures.append("valid and invalid files: exit %d (expected 1), naming only the invalid ones:\n%s" % (rc, out))
    for args in ([], [schema_dir], [os.path.join(work, "no-such-dir"), check]):
        r = subprocess.run([sys.executable, validator] + args, capture_output=True, text=True)
        if r.returncode != 2:
            failures.append("usage %s: exit %d (expected 2)" % (args, r.returncode))
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
