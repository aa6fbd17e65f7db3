"""fftess.check: the dict `fftess check --json` writes, on a clean and on a cracked scene; findings in the dict, usage
errors as ValueError with the command line's message."""

import pytest

import fftess
from conftest import EXAMPLES, cli_json_report, validate_against_schema, without_process_counts


def test_clean_scene_is_watertight():
    scene = EXAMPLES / "grid.toml"
    report = fftess.check(scene)
    assert report["verdict"] == "watertight"
    assert report["findings"] == [] or all(f["classification"] == "match" for f in report["findings"])
    assert report["stats"]["cracks"] == 0 and report["stats"]["edges_checked"] > 0
    assert without_process_counts(report) == without_process_counts(cli_json_report("check", scene, expect=(0,)))
    validate_against_schema(report)


def test_cracked_scene_has_its_findings_in_the_dict():
    scene = EXAMPLES / "broken_lod.toml"
    before = fftess.check(scene)["work"]["terrain_builds"]
    report = fftess.check(str(scene))  # findings are a report, never an exception
    assert report["work"]["terrain_builds"] == before + 1  # one terrain build per call
    assert report["verdict"] == "cracks" and report["stats"]["cracks"] > 0
    cracks = [f for f in report["findings"] if f["classification"] == "crack"]
    assert cracks and all("a" in f and "b" in f for f in cracks)
    assert without_process_counts(report) == without_process_counts(cli_json_report("check", scene, expect=(1,)))
    validate_against_schema(report)


def test_overrides_are_the_command_lines_set():
    scene = EXAMPLES / "broken_lod.toml"
    as_dict = fftess.check(scene, {"camera.eye": [0.0, 20.0, -45.0], "lod.target_pixels": 6.0})
    as_list = fftess.check(scene, ["camera.eye=[0.0, 20.0, -45.0]", "lod.target_pixels=6.0"])
    want = cli_json_report("check", scene, "--set", "camera.eye=[0.0, 20.0, -45.0]", "--set", "lod.target_pixels=6.0")
    assert without_process_counts(as_dict) == without_process_counts(as_list) == without_process_counts(want)
    assert as_dict["scene"]["overrides"] == ["camera.eye=[0.0, 20.0, -45.0]", "lod.target_pixels=6.0"]


def test_bad_scene_path_raises_value_error_naming_it(tmp_path):
    missing = tmp_path / "no-such-scene.toml"
    with pytest.raises(ValueError) as e:
        fftess.check(missing)
    assert str(missing) in str(e.value)


@pytest.mark.parametrize("kwargs, message", [
    ({"overrides": {"lod.no_such_key": 1}}, "lod.no_such_key"),
    ({"overrides": ["lod.scheme"]}, "--set 'lod.scheme': expected KEY=VALUE"),
    ({"kernel": "exact"}, "--kernel 'exact': expected epick|epeck|float"),
    ({"path_camera": -1}, "--path-camera -1: must be >= 0"),
])
def test_usage_errors_raise_value_error(kwargs, message):
    with pytest.raises(ValueError) as e:
        fftess.check(EXAMPLES / "grid.toml", **kwargs)
    assert message in str(e.value)
