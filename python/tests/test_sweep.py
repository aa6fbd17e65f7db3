"""fftess.sweep: the dict `fftess sweep --json` writes, with a few cameras."""

import pytest

import fftess
from conftest import EXAMPLES, cli_json_report, validate_against_schema, without_process_counts


def test_sweep_of_a_few_cameras_is_the_command_lines_report():
    scene = EXAMPLES / "broken_lod.toml"
    report = fftess.sweep(scene, orbit=3, threads=1)
    want = cli_json_report("sweep", scene, "--orbit", "3", "-j", "1", expect=(1,))
    assert without_process_counts(report) == without_process_counts(want)
    assert len(report["cameras"]) == 3 and [c["index"] for c in report["cameras"]] == [0, 1, 2]
    assert report["verdict"] == "cracks" and report["stats"]["cracks"] > 0
    assert report["causes"] and all(c["findings"] > 0 and c["fix"] for c in report["causes"])
    validate_against_schema(report)


def test_clean_sweep_and_random_cameras():
    report = fftess.sweep(EXAMPLES / "grid.toml", {"layout.patches_x": 8, "layout.patches_z": 8}, random=2, seed=5,
                          threads=1)
    assert report["verdict"] == "watertight" and report["cameras_total"] == 2
    validate_against_schema(report)


@pytest.mark.parametrize("kwargs, message", [
    ({"orbit": 2, "random": 2}, "sweep: give only one of --orbit, --flyover, --random"),
    ({"orbit": 0}, "--orbit 0: must be >= 1"),
    ({"random": 1, "seed": -1}, "--seed '-1': expected a whole number from 0 to 18446744073709551615"),
    ({"orbit": 1, "shard": "3/2"}, "--shard '3/2': expected K/N"),
])
def test_usage_errors_raise_value_error(kwargs, message):
    with pytest.raises(ValueError) as e:
        fftess.sweep(EXAMPLES / "grid.toml", **kwargs)
    assert message in str(e.value)
