"""Shared pieces of the Python tests (run by ctest with PYTHONPATH=<build>/python, python/CMakeLists.txt)."""

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

SOURCE = Path(os.environ.get("FFTESS_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EXAMPLES = SOURCE / "docs" / "examples"
GOLDEN = Path(os.environ.get("FFTESS_GOLDEN_DIR", SOURCE.parent / "shared" / "golden"))
FFTESS_BIN = os.environ.get("FFTESS_BIN", str(Path(os.environ.get("FFTESS_BUILD_DIR", SOURCE / "build")) / "fftess"))


def run_cli(*args, expect=None):
    """Runs the fftess binary; returns (exit status, stdout). expect: the exit statuses allowed."""
    p = subprocess.run([FFTESS_BIN, *map(str, args)], capture_output=True, text=True)
    if expect is not None:
        assert p.returncode in expect, f"fftess {' '.join(map(str, args))}: exit {p.returncode}\n{p.stderr}"
    return p.returncode, p.stdout


def cli_json_report(*args, expect=(0, 1)):
    """`fftess ARGS --json FILE`: the report the command line writes, as Python's json module reads it."""
    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "report.json"
        run_cli(*args, "--json", out, "--quiet", expect=expect)
        return json.loads(out.read_text())


def without_process_counts(report):
    """The report without work.terrain_builds, which counts every terrain build of the process (docs/cli.md): 1 in a
    fresh fftess process, growing in a Python session."""
    r = json.loads(json.dumps(report))
    for part in ("work", "terrain_work"):
        r.get(part, {}).pop("terrain_builds", None)
    return r


def validate_against_schema(report):
    """Validates a report against docs/schema/<kind>.schema.json when the schemas and jsonschema are there; returns
    whether it did (the schemas arrive with the schema part of issue 25)."""
    schema_dir = SOURCE / "docs" / "schema"
    try:
        import jsonschema  # noqa: F401
    except ImportError:
        return False
    kind = report.get("kind")
    if not schema_dir.is_dir() or kind is None:
        return False
    schema_file = schema_dir / f"{kind}.schema.json"
    if not schema_file.exists():
        schema_file = schema_dir / f"{kind.replace('-', '_')}.schema.json"
    assert schema_file.exists(), f"no schema for kind {kind!r} in {schema_dir}"
    validator = SOURCE / "tests" / "tools" / "validate_json.py"
    with tempfile.TemporaryDirectory() as d:
        f = Path(d) / "report.json"
        f.write_text(json.dumps(report))
        if validator.exists():
            p = subprocess.run([sys.executable, str(validator), str(schema_dir), str(f)], capture_output=True, text=True)
            assert p.returncode == 0, p.stdout + p.stderr
            return True
    import jsonschema
    from jsonschema import Draft202012Validator, RefResolver

    schema = json.loads(schema_file.read_text())
    resolver = RefResolver(base_uri=schema_file.resolve().as_uri(), referrer=schema)
    Draft202012Validator(schema, resolver=resolver).validate(report)
    return True
