"""`pip install .`: the Python module fftess._fftess built by the project's CMake (docs/python.md, Install).

build_ext configures the project (FFTESS_PYTHON=ON, no tests, benchmarks or GPU modules) in setuptools' temporary
folder, builds the target fftess_python and copies the module into the wheel next to python/fftess/. With the
environment variable FFTESS_CMAKE_BUILD_DIR set, it builds that already configured tree instead (CI: no second
compile); the tree must have FFTESS_PYTHON=ON and this interpreter's extension suffix. setuptools' own build folder is
build-python/ (setup.cfg-free: see `options` below), so it never meets CMake's build/.
"""

import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(fftess VERSION ([0-9.]+)", text).group(1)


def cache_value(build, key):
    cache = build / "CMakeCache.txt"
    if not cache.exists():
        return None
    m = re.search(rf"^{re.escape(key)}:[A-Z]+=(.*)$", cache.read_text(), re.M)
    return m.group(1) if m else None


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        given = os.environ.get("FFTESS_CMAKE_BUILD_DIR")
        if given:
            build = Path(given).resolve()
            if cache_value(build, "FFTESS_PYTHON") not in ("ON", "TRUE", "1"):
                raise RuntimeError(f"FFTESS_CMAKE_BUILD_DIR={given}: not a build tree configured with -DFFTESS_PYTHON=ON")
        else:
            build = Path(self.build_temp).resolve() / "cmake"
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.check_call(["cmake", "-S", str(ROOT), "-B", str(build), *generator,
                                   "-DCMAKE_BUILD_TYPE=Release", "-DFFTESS_PYTHON=ON", "-DFFTESS_TESTS=OFF",
                                   "-DFFTESS_BENCHMARKS=OFF", "-DFFTESS_GPU=OFF",
                                   f"-DPython3_EXECUTABLE={sys.executable}"])
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.check_call(["cmake", "--build", str(build), "--target", "fftess_python", "-j", jobs])
        built = build / "python" / "fftess" / f"_fftess{suffix}"
        if not built.exists():
            found = sorted(p.name for p in (build / "python" / "fftess").glob("_fftess*"))
            raise RuntimeError(f"{built} not built (found {found}): the build tree's Python is not {sys.executable}")
        dest = Path(self.get_ext_fullpath(ext.name))
        dest.parent.mkdir(parents=True, exist_ok=True)
        for stale in dest.parent.glob("_fftess*"):  # an earlier build's (build-python/ stays between installs)
            stale.unlink()
        shutil.copyfile(built, dest)


setup(
    version=project_version(),
    packages=["fftess"],
    package_dir={"fftess": "python/fftess"},
    ext_modules=[Extension("fftess._fftess", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-python"}, "egg_info": {"egg_base": "build-python"}},
    zip_safe=False,
)
