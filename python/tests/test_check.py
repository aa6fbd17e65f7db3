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


# Issue [8/8]: a NUL in a Python str ended the path there (the part before it was checked and called watertight).
@pytest.mark.parametrize("call, message", [
    (lambda: fftess.check(str(EXAMPLES / "rings_small.toml") + "\0/other"),
     "scene: a NUL character at position " + str(len(str(EXAMPLES / "rings_small.toml")))),
    (lambda: fftess.check(EXAMPLES / "grid.toml", cameras="cams.txt\0x"), "cameras: a NUL character at position 8"),
    (lambda: fftess.check(EXAMPLES / "grid.toml", {"lod.scheme": "distance\0"}), "overrides: a NUL character"),
    (lambda: fftess.sweep(EXAMPLES / "grid.toml\0", orbit=1), "scene: a NUL character"),
    (lambda: fftess.compare("a\0.batch", "b.csv"), "patches: a NUL character at position 1"),
])
def test_nul_in_a_path_or_word_raises_value_error(call, message):
    with pytest.raises(ValueError) as e:
        call()
    assert message in str(e.value)


# Issue [8/8]: -j 100000 aborted in std::terminate; the Python entry points refuse it as the command line does.
def test_threads_beyond_1024_raise_value_error():
    with pytest.raises(ValueError, match=r"--threads 100000: must be 0 \(all cores\) to 1024"):
        fftess.sweep(EXAMPLES / "grid.toml", orbit=1, threads=100000)
    with pytest.raises(ValueError, match=r"threads -1: must be 0"):
        fftess.tessellate("quad", "integer", "triangle_cw", [[4, 4, 4, 4, 4, 4]], threads=-1)
