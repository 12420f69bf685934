"""Builds the frictionid Python package: the pure-Python part from python/frictionid, the
extension frictionid._frictionid by CMake (target frictionid_python), the version from
CMakeLists.txt's project(VERSION) (the one place it is written).

Environment:
    FRICTIONID_BUILD_DIR  a CMake build directory of this tree to build the extension in;
                          reused as configured, only frictionid_python is brought up to date.
                          Default: a fresh directory under the setuptools build directory.
    FRICTIONID_SETUP_BUILD_BASE  setuptools' build directory (default build-python).
    CMAKE_BUILD_PARALLEL_LEVEL, CMAKE_CXX_COMPILER_LAUNCHER  as CMake reads them.
"""

import glob
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
BUILD_BASE = os.environ.get("FRICTIONID_SETUP_BUILD_BASE", "build-python")


def cmake_version() -> str:
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        match = re.search(r"project\(\s*frictionid\s+VERSION\s+([0-9][0-9A-Za-z.]*)", f.read())
    if not match:
        raise RuntimeError("CMakeLists.txt: no project(frictionid VERSION ...)")
    return match.group(1)


class CMakeBuild(build_ext):
    """Runs CMake for the extension and puts it, and the _version.py CMake wrote, into the
    package being built."""

    def build_extension(self, ext: Extension) -> None:
        build_dir = os.environ.get("FRICTIONID_BUILD_DIR") or os.path.abspath(
            os.path.join(self.build_temp, "cmake"))
        if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
            subprocess.check_call([
                "cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                "-DFRICTIONID_BUILD_TESTS=OFF", "-DFRICTIONID_BUILD_PYTHON=ON",
                f"-DFRICTIONID_PYTHON={sys.executable}"])
        build = ["cmake", "--build", build_dir, "--target", "frictionid_python"]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            build += ["--parallel", str(min(os.cpu_count() or 1, 4))]
        subprocess.check_call(build)
        package = os.path.join(build_dir, "python", "frictionid")
        built = glob.glob(os.path.join(package, "_frictionid*.so"))
        if len(built) != 1:
            raise RuntimeError(f"{package}: expected one _frictionid*.so, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)
        shutil.copyfile(os.path.join(package, "_version.py"),
                        os.path.join(os.path.dirname(target), "_version.py"))


setup(
    version=cmake_version(),
    packages=["frictionid"],
    package_dir={"": "python"},
    package_data={"frictionid": ["py.typed"]},
    ext_modules=[Extension("frictionid._frictionid", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": BUILD_BASE}, "egg_info": {"egg_base": BUILD_BASE}},
    zip_safe=False,
)
