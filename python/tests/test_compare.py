"""fftess.compare: the dict `fftess compare --json` prints, on a matching and on a differing capture."""

import json

import pytest

import fftess
from conftest import EXAMPLES, run_cli, validate_against_schema

BATCH = EXAMPLES / "compare_port.batch"


def cli_compare(*args):
    status, out = run_cli("compare", *args, "--json", expect=(0, 1))
    return status, json.loads(out)


def test_matching_capture_is_same(tmp_path):
    capture = tmp_path / "reference.hex"
    run_cli("tessellate", BATCH, "--format", "hex", "-o", capture, expect=(0,))
    report = fftess.compare(BATCH, capture)
    status, want = cli_compare(BATCH, capture)
    assert report == want and status == 0
    assert report["kind"] == "compare" and report["differing"] == 0 and report["same"] == report["patches"] == 3
    assert report["format"] == "hex" and report["listed"] == []
    validate_against_schema(report)


def test_differing_capture_lists_the_patches():
    capture = EXAMPLES / "compare_port_bug.csv"
    report = fftess.compare(str(BATCH), str(capture), show=1, details=2)
    status, want = cli_compare(BATCH, capture, "--show", "1", "--details", "2")
    assert report == want and status == 1
    assert report["differing"] > 0 and len(report["listed"]) == 1
    assert report["listed"][0]["batch_line"].startswith("quad ")
    validate_against_schema(report)


def test_bad_capture_path_raises_value_error_naming_it(tmp_path):
    missing = tmp_path / "no-such-capture.csv"
    with pytest.raises(ValueError, match="CAPTURE '" + str(missing) + "': cannot open"):
        fftess.compare(BATCH, missing)


def test_bad_options_raise_value_error():
    with pytest.raises(ValueError, match="--format 'xml': expected auto|hex|csv"):
        fftess.compare(BATCH, EXAMPLES / "compare_port_bug.csv", format="xml")
    with pytest.raises(ValueError, match="--show -1: must be >= 0"):
        fftess.compare(BATCH, EXAMPLES / "compare_port_bug.csv", show=-1)
