"""fftess.tessellate: bit-exact with the C++ tessellator (the golden outputs of Microsoft's reference, and the fftess
binary's own hex output for rows of special factors), the packed layout, and its argument errors."""

import numpy as np
import pytest

import fftess
from conftest import GOLDEN, run_cli

PER_LINE = {"triangle_cw": 3, "triangle_ccw": 3, "line": 2, "point": 1}


def factor_bits(token):
    """A batch-format factor token as its IEEE-754 bits (0x + 8 hex digits, or a decimal: float32 as strtof)."""
    if token.startswith("0x"):
        return int(token, 16)
    return int(np.array([float(token)], np.float64).astype(np.float32).view(np.uint32)[0])


def hex_blocks(lines, flush_denormals=False, threads=0):
    """The golden .out text of batch lines, from fftess.tessellate: one call per line (each line has its own domain,
    partitioning, primitive and stage), blocks numbered from 0."""
    out = []
    for n, line in enumerate(lines):
        tok = line.split()
        domain, partitioning, primitive, stage = tok[:4]
        bits = np.array([factor_bits(t) for t in tok[4:10]], np.uint32)
        t = fftess.tessellate(domain, partitioning, primitive, bits.view(np.float32)[None, :], stage=stage,
                              flush_denormals=flush_denormals, threads=threads)
        assert t.point_offsets.tolist() == [0, len(t.points)] and t.index_offsets.tolist() == [0, len(t.indices)]
        pts = t.points.view(np.uint32)
        out.append(f"patch {n} points {len(pts)} indices {len(t.indices)}\n")
        out.extend(f"{u:08x} {v:08x}\n" for u, v in pts.tolist())
        k = 1 if primitive == "point" else 2 if domain == "isoline" else PER_LINE[primitive]
        idx = t.indices.tolist()
        out.extend(" ".join(map(str, idx[i:i + k])) + "\n" for i in range(0, len(idx), k))
    return "".join(out)


def batch_lines(path):
    return [s for s in path.read_text().splitlines() if s.strip() and not s.lstrip().startswith("#")]


@pytest.mark.parametrize("name", ["quad-hw", "quad-hlsl", "tri-hw", "tri-hlsl", "isoline-hw", "isoline-hlsl"])
def test_golden_outputs_bit_exact(name):
    if not (GOLDEN / f"{name}.in").exists():
        pytest.fail(f"golden data missing: {GOLDEN / name}.in (FFTESS_GOLDEN_DIR)")
    got = hex_blocks(batch_lines(GOLDEN / f"{name}.in"))
    want = (GOLDEN / f"{name}.out").read_text()
    assert got == want


# NaN (quiet, signalling, negative), +-inf, -0, denormals (positive and negative), values above 64, a huge finite one.
SPECIAL_ROWS = [
    "quad fractional_odd triangle_cw hw 0x7fc00000 0x40000000 0x40000000 0x40000000 0x40000000 0x40000000",
    "quad fractional_even triangle_ccw hw 0x00000001 0x42c80000 0x7f7fffff 0x00400000 0x42800001 0x4f000000",
    "quad integer triangle_cw hw 0x42c80000 0x43800000 0x42810000 0x7f800000 0x7fa00000 0xff800000",
    "quad pow2 line hlsl-max 0x42c80000 0x00000010 0x80000001 0x42000000 0x3f000000 0x7fc00001",
    "tri fractional_odd triangle_cw hw 0x00000010 0x42c80000 0x42800001 0x00800000 0x00000000 0x00000000",
    "tri integer point hlsl-avg 0x80000000 0x41000000 0x41000000 0x00000003 0x00000000 0x00000000",
    "tri fractional_even triangle_ccw hlsl-min 0x42c80000 0x007fffff 0x4b000000 0x3f800000 0x00000000 0x00000000",
    "isoline fractional_odd line hw 0x42c80000 0x00000001 0x00000000 0x00000000 0x00000000 0x00000000",
    "isoline integer point hlsl-avg 0x00000005 0x43000000 0x00000000 0x00000000 0x00000000 0x00000000",
]


@pytest.mark.parametrize("flush", [False, True])
def test_special_factor_rows_match_the_fftess_binary(tmp_path, flush):
    batch = tmp_path / "special.batch"
    batch.write_text("\n".join(SPECIAL_ROWS) + "\n")
    args = ["tessellate", batch, "--format", "hex"] + (["--flush-denormals"] if flush else [])
    _, want = run_cli(*args, expect=(0,))
    assert hex_blocks(SPECIAL_ROWS, flush_denormals=flush) == want
    # The rows do exercise what they claim: a denormal edge is culled only when flushed, a NaN edge always.
    t = fftess.tessellate("quad", "fractional_even", "triangle_ccw",
                          np.array([[0x00000001, 0x42c80000, 0x7f7fffff, 0x00400000, 0x42800001, 0x4f000000]],
                                   np.uint32).view(np.float32), flush_denormals=flush)
    assert (len(t.points) == 0) == flush


def test_packed_batch_is_the_patches_one_after_the_other():
    rng = np.random.default_rng(7)
    factors = rng.uniform(-2.0, 70.0, size=(200, 6)).astype(np.float32)
    factors[::17, 2] = np.nan
    factors[5::23, 0] = np.float32(1e-42)  # denormal
    batch = fftess.tessellate("quad", "fractional_odd", "triangle_cw", factors, threads=3)
    assert batch.points.dtype == np.float32 and batch.points.shape[1] == 2
    assert batch.indices.dtype == np.uint32
    assert batch.point_offsets.shape == (201,) and batch.index_offsets.shape == (201,)
    assert batch.point_offsets[-1] == len(batch.points) and batch.index_offsets[-1] == len(batch.indices)
    one = fftess.tessellate("quad", "fractional_odd", "triangle_cw", factors, threads=1)
    for a, b in zip(batch, one):  # the same bytes on any thread count
        assert a.tobytes() == b.tobytes()
    culled = 0
    for i in range(len(factors)):
        single = fftess.tessellate("quad", "fractional_odd", "triangle_cw", factors[i])
        pts, idx = batch.patch(i)
        assert pts.tobytes() == single.points.tobytes() and idx.tobytes() == single.indices.tobytes()
        if len(idx):
            assert idx.max() < len(pts)  # indices count from the patch's own first point
        culled += len(pts) == 0
    assert 0 < culled < len(factors)


def test_domain_factor_counts_and_dtypes():
    tri4 = fftess.tessellate("tri", "integer", "triangle_cw", [[3, 4, 5, 6]])
    tri6 = fftess.tessellate("tri", "integer", "triangle_cw", np.array([[3, 4, 5, 6, 99, -1]], np.float64))
    assert tri4.points.tobytes() == tri6.points.tobytes() and tri4.indices.tobytes() == tri6.indices.tobytes()
    iso = fftess.tessellate("isoline", "integer", "line", [2, 3])
    assert len(iso.points) == 2 * 4 and len(iso.indices) == 2 * 3 * 2
    empty = fftess.tessellate("quad", "integer", "point", np.zeros((0, 6), np.float32))
    assert empty.points.shape == (0, 2) and empty.point_offsets.tolist() == [0]


@pytest.mark.parametrize("args, message", [
    (("hex", "integer", "triangle_cw", [[1] * 6]), "domain 'hex': expected quad|tri|isoline"),
    (("quad", "odd", "triangle_cw", [[1] * 6]), "partitioning 'odd': expected"),
    (("quad", "integer", "strip", [[1] * 6]), "primitive 'strip': expected"),
    (("isoline", "integer", "triangle_cw", [[1, 1]]), "an isoline's output is point or line"),
    (("quad", "integer", "triangle_cw", [[1] * 4]), "factors: expected an array of shape (N, 6)"),
    (("tri", "integer", "triangle_cw", [[1] * 5]), "factors: expected an array of shape (N, 4) or (N, 6)"),
    (("quad", "integer", "triangle_cw", np.ones((2, 2, 6))), "got 3 dimensions"),
])
def test_bad_arguments_raise_value_error(args, message):
    with pytest.raises(ValueError) as e:
        fftess.tessellate(*args)
    assert message in str(e.value)


def test_bad_stage_raises_value_error():
    with pytest.raises(ValueError, match="stage 'hlsl': expected hw"):
        fftess.tessellate("quad", "integer", "triangle_cw", [[1] * 6], stage="hlsl")
