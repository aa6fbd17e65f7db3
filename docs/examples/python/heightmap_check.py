#!/usr/bin/env python3
"""Makes a heightmap with NumPy, writes it and a scene next to it, checks the scene and reads the findings.

    PYTHONPATH=build/python python3 docs/examples/python/heightmap_check.py

The heightmap is a raw 16-bit little-endian file (the scene loader's displacement.kind = "raw", docs/verify.md); the
scene tessellates it as a heightmap grid of 8 x 8 patches. Checked twice: with a LOD that measures each edge from the
patch centre (lod.scheme = "patch_center", deliberately broken: the two sides of a shared edge disagree) and with
the edge-midpoint LOD of a uniform grid's constant factor (lod.scheme = "constant": watertight). Exit status 0 when
the checker found what it should (cracks, then none), 1 otherwise (this file is run by ctest).
"""

import collections
import sys
import tempfile
from pathlib import Path

import numpy as np

import fftess

PATCHES, CELLS = 8, 16          # 8 x 8 patches of 16 x 16 texels
SIZE = PATCHES * CELLS + 1      # the texture of a heightmap grid: patches * cells_per_patch + 1 texels across


def heightmap():
    """Rolling hills and a ridge, 0..1, as uint16 (texel value 65535 = height 1 = displacement.height_scale)."""
    y, x = np.mgrid[0:SIZE, 0:SIZE] / (SIZE - 1)
    h = 0.5 + 0.25 * np.sin(6.0 * x) * np.cos(4.0 * y) + 0.2 * np.exp(-((x - y) ** 2) / 0.01)
    h = (h - h.min()) / (h.max() - h.min())
    return np.round(h * 65535).astype("<u2")  # little endian, as the loader reads bits = 16


SCENE = f"""name = "python-heightmap"

[layout]
kind = "heightmap_grid"
cells_per_patch = {CELLS}
cell_size = 1.0

[displacement]
kind = "raw"
file = "heights.raw"            # relative to this scene file
width = {SIZE}
height = {SIZE}
bits = 16
height_scale = 30.0

[lod]
scheme = "patch_center"
target_pixels = 8.0

[tessellation]
partitioning = "fractional_odd"

[camera]
eye = [0.0, 60.0, -110.0]
target = [0.0, 0.0, 0.0]
"""


def main():
    with tempfile.TemporaryDirectory() as d:
        folder = Path(d)
        heightmap().tofile(folder / "heights.raw")
        scene = folder / "heightmap.toml"
        scene.write_text(SCENE)

        report = fftess.check(scene)
        stats = report["stats"]
        print(f"{scene.name}: {report['verdict']}: {stats['cracks']} cracks, {stats['t_junctions']} T-junctions "
              f"over {stats['edges_checked']} shared edges, worst gap {stats['worst_gap_pixels']:.2f} px")
        causes = collections.Counter(f["cause"] for f in report["findings"] if f["classification"] == "crack")
        for cause, n in causes.most_common():
            print(f"  {n:4d} x {cause}")
        worst = max((f for f in report["findings"] if f["classification"] == "crack"),
                    key=lambda f: f["gap_pixels"], default=None)
        if worst:
            a, b = worst["a"], worst["b"]
            print(f"  worst: patch {a['patch']['index']} {a['edge']} against patch {b['patch']['index']} {b['edge']}, "
                  f"{worst['gap_pixels']:.2f} px\n  fix: {worst['fix']}")

        fixed = fftess.check(scene, {"lod.scheme": "constant", "lod.factor": 8})
        print(f"with lod.scheme = constant: {fixed['verdict']}")
        return 0 if report["verdict"] == "cracks" and causes and fixed["verdict"] == "watertight" else 1


if __name__ == "__main__":
    sys.exit(main())
