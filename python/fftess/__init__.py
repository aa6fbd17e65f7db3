"""fftess from Python: the bit-exact D3D11 tessellator and the crack checker (docs/python.md).

tessellate()   patches in (NumPy factors), points and indices out (NumPy arrays), bit-exact with the C++ API.
check()        `fftess check SCENE --json FILE`: the report as a dict.
sweep()        `fftess sweep SCENE --json FILE`: the report as a dict.
compare()      `fftess compare PATCHES CAPTURE --json`: the report as a dict.

Bad arguments, scenes and captures raise ValueError with the command line's message (its exit status 2); findings
(cracks, holes, differing patches) are in the dict, never an exception.
"""

import os
from typing import NamedTuple

import numpy as np

from . import _fftess

__version__ = _fftess.__version__

__all__ = ["Tessellation", "tessellate", "check", "sweep", "compare", "__version__"]


class Tessellation(NamedTuple):
    """The output of tessellate(): N patches packed one after the other.

    points: float32 (P, 2), each point's (u, v) (tri: w = 1 - u - v is the caller's to compute).
    indices: uint32 (I,), counting from the patch's own first point (as Tessellator::tessellate).
    point_offsets, index_offsets: int64 (N + 1,): patch i's points are points[point_offsets[i]:point_offsets[i + 1]],
    its indices indices[index_offsets[i]:index_offsets[i + 1]]. A culled patch has none.
    """

    points: np.ndarray
    indices: np.ndarray
    point_offsets: np.ndarray
    index_offsets: np.ndarray

    def patch(self, i):
        """(points, indices) of patch i: views into the packed arrays."""
        p0, p1 = self.point_offsets[i], self.point_offsets[i + 1]
        i0, i1 = self.index_offsets[i], self.index_offsets[i + 1]
        return self.points[p0:p1], self.indices[i0:i1]


def tessellate(domain, partitioning, primitive, factors, stage="hw", flush_denormals=False, threads=0):
    """Tessellates N patches of one domain, partitioning, output primitive and stage.

    domain: "quad" | "tri" | "isoline"; partitioning: "integer" | "pow2" | "fractional_odd" | "fractional_even";
    primitive: "point" | "line" | "triangle_cw" | "triangle_ccw" (isoline: point or line); stage: "hw" | "hlsl-avg" |
    "hlsl-min" | "hlsl-max" | "hlsl-avg-1axis" | "hlsl-min-1axis" | "hlsl-max-1axis" (the batch format's names).
    factors: shape (N, k) or (k,), k the domain's factor count (quad 6: Ueq0 Veq0 Ueq1 Veq1 insideU insideV; tri 4:
    Ueq0 Veq0 Weq0 inside; isoline 2: density detail) or 6 (the rest ignored). float32 is read bit for bit (NaN
    payloads, -0, denormals; IEEE bits as uint32: pass bits.view(np.float32)); other dtypes are cast as
    astype(np.float32) does. Any value is defined (NaN, inf, negative, above 64).
    flush_denormals: Options::flushDenormals. threads: tessellateBatch's, 0 (one per hardware thread) to 1024; the output does
    not depend on it. Returns a Tessellation.
    """
    return Tessellation(*_fftess.tessellate(domain, partitioning, primitive, factors, stage, flush_denormals, threads))


def _path(p):
    return "" if p is None else os.fspath(p)


def check(scene, overrides=None, *, kernel="epick", flush_denormals="auto", offscreen=False, gpu_float="off",
          cameras=None, camera_index=None, path_camera=None, svg=None, gltf=None, view=None):
    """`fftess check SCENE --json FILE`: the report (docs/cli.md, "JSON reports") as a dict.

    overrides: dict {"lod.adjacency_clamp": "none", "camera.eye": [0, 30, -80]} or list ["KEY=VALUE", ...] (--set).
    The other keywords are check's options of the same name (--kernel, --flush-denormals, --offscreen, --gpu-float,
    --cameras, --camera-index, --path-camera, and the --svg / --gltf / --view files, written as the command line
    writes them). The verdict is report["verdict"]; the findings report["findings"], report["holes"], ...
    """
    return _fftess.check(os.fspath(scene), overrides, kernel, flush_denormals, offscreen, gpu_float, _path(cameras),
                         camera_index, path_camera, _path(svg), _path(gltf), _path(view))


def sweep(scene, overrides=None, *, orbit=None, flyover=None, random=None, seed=1, threads=0, kernel="epick",
          flush_denormals="auto", offscreen=False, gpu_float="off", cameras=None, label=None, shard=None,
          visible_first=True, result_cache=True, svg=None, gltf=None):
    """`fftess sweep SCENE --json FILE`: the report (docs/cli.md, "JSON reports") as a dict.

    Cameras: orbit=N, flyover=N, random=N (with seed) or cameras=FILE; none of them: the scene's camera path, else a
    flyover of 200. threads: worker threads, 0 (all cores) to 1024. shard: "K/N". visible_first=False / result_cache=False:
    --no-visible-first / --no-result-cache. Ctrl-C stops the sweep and raises KeyboardInterrupt.
    """
    return _fftess.sweep(os.fspath(scene), overrides, orbit, flyover, random, seed, threads, kernel, flush_denormals,
                         offscreen, gpu_float, _path(cameras), label or "", shard or "", visible_first, result_cache,
                         _path(svg), _path(gltf))


def compare(patches, capture, *, format="auto", strict_order=False, flush_denormals=False, show=20, details=4,
            svg=None):
    """`fftess compare PATCHES CAPTURE --json`: the report (docs/compare.md) as a dict.

    patches: the batch file the port was fed; capture: its output (hex blocks or CSV). report["differing"] counts the
    differing patches, report["listed"] details the first `show` of them.
    """
    return _fftess.compare(os.fspath(patches), os.fspath(capture), format, strict_order, flush_denormals, show,
                           details, _path(svg))
