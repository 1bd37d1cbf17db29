"""Builds the module rocking_q with the project's CMake for `pip install .` (pyproject.toml).

The extension has no sources of its own here: CMake compiles rocking_core and the
pybind11 module (python/CMakeLists.txt), and the built file is copied where setuptools
packs it.  ROCKING_BUILD_DIR names a CMake build tree to build in (a configured one is
reused: the tests do so); by default build/pip under the source tree, configured for
the interpreter running pip.  ROCKING_BUILD_JOBS sets the parallel jobs (default: the
cores).  setuptools' own scratch files go under that tree too, not into the sources.
"""
import os
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = os.path.dirname(os.path.abspath(__file__))
BUILD = os.path.abspath(os.environ.get("ROCKING_BUILD_DIR", os.path.join(SOURCE, "build", "pip")))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if not os.path.exists(os.path.join(BUILD, "CMakeCache.txt")):
            subprocess.run(["cmake", "-S", SOURCE, "-B", BUILD, "-DCMAKE_BUILD_TYPE=Release",
                            "-DPython3_EXECUTABLE=" + os.path.realpath(sys.executable)], check=True)
        jobs = os.environ.get("ROCKING_BUILD_JOBS", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", BUILD, "--target", "rocking_q_python", "-j", jobs], check=True)
        # The file CMake wrote must be one this interpreter can import.
        name = "rocking_q" + sysconfig.get_config_var("EXT_SUFFIX")
        built = os.path.join(BUILD, "python", name)
        if not os.path.exists(built):
            raise RuntimeError(f"{built} was not built: the build tree {BUILD} targets another Python "
                               f"(this one is {sys.executable}, {sys.version.split()[0]}); remove it or set "
                               "ROCKING_BUILD_DIR to a new folder")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built, target)


scratch = os.path.join(BUILD, "setuptools")
os.makedirs(scratch, exist_ok=True)
setup(ext_modules=[Extension("rocking_q", sources=[])],
      cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": scratch}, "egg_info": {"egg_base": scratch}})
