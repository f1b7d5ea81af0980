# SPDX-License-Identifier: MIT
"""Builds the extension sparsedyn._sparsedyn with the project's CMake (python/CMakeLists.txt).

The metadata is in pyproject.toml. Environment:
  SPARSEDYN_CMAKE_BUILD_DIR  reuse this CMake build tree (scripts/test.sh passes build/release,
                             where the module is already built) instead of a fresh Release one
  SPARSEDYN_BUILD_JOBS       parallel build jobs (default: the machine's cores)
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        tree = os.environ.get("SPARSEDYN_CMAKE_BUILD_DIR")
        build = Path(tree).resolve() if tree else Path(self.build_temp).resolve() / "cmake"
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DSPARSEDYN_BUILD_PYTHON=ON",
                     f"-DPython_EXECUTABLE={sys.executable}"]
        if not tree:
            configure += ["-DCMAKE_BUILD_TYPE=Release", "-DSPARSEDYN_BUILD_TESTS=OFF",
                          "-DSPARSEDYN_BUILD_BENCHMARKS=OFF", "-DSPARSEDYN_BUILD_TOOLS=OFF",
                          "-DSPARSEDYN_BUILD_EXAMPLES=OFF", "-DSPARSEDYN_BUILD_PEERS=OFF"]
        jobs = os.environ.get("SPARSEDYN_BUILD_JOBS", str(os.cpu_count() or 1))
        print(f"sparsedyn: building the module with CMake in {build} (minutes the first time)",
              file=sys.stderr, flush=True)
        subprocess.run(configure, check=True, stdout=subprocess.DEVNULL)
        subprocess.run(["cmake", "--build", str(build), "--target", "sparsedyn_python",
                        "-j", jobs], check=True)
        built = next((build / "python" / "sparsedyn").glob("_sparsedyn*.so"))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(ext_modules=[Extension("sparsedyn._sparsedyn", sources=[])],
      cmdclass={"build_ext": CMakeBuild})
