"""Builds the compiled part of the Python package elasticlab with CMake (pyproject.toml).

setuptools drives; the extension elasticlab._core is the CMake target `elasticlab` (python/), built
in the build directory setuptools gives, with the interpreter pip runs (so a virtual
environment's python3 gets a module for its version), and copied into the package beside the
Python files of python/elasticlab/. The GUI, the tests and the benchmarks are not built.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        target = Path(self.get_ext_fullpath(ext.name)).resolve()
        target.parent.mkdir(parents=True, exist_ok=True)
        # A module already built by the project's own CMake build (the install test, packagers):
        # copied as it is instead of building simcore and simlab again.
        prebuilt = os.environ.get("ELASTIC_LAB_PREBUILT_CORE")
        if prebuilt:
            shutil.copyfile(prebuilt, target)
            return
        build = Path(self.build_temp).resolve() / "cmake"
        build.mkdir(parents=True, exist_ok=True)
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                        "-DELASTIC_LAB_BUILD_GUI=OFF", "-DELASTIC_LAB_BUILD_TESTS=OFF", "-DELASTIC_LAB_BUILD_BENCH=OFF",
                        "-DELASTIC_LAB_MAN_PAGES=OFF", f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "elasticlab"], check=True)
        built = next((build / "python" / "elasticlab").glob("_core*.so"))
        shutil.copyfile(built, target)


def version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(ElasticLab VERSION ([0-9.]+)", text).group(1)


setup(
    version=version(),
    packages=["elasticlab"],
    package_dir={"elasticlab": "python/elasticlab"},
    package_data={"elasticlab": ["py.typed", "*.pyi"]},
    ext_modules=[CMakeExtension("elasticlab._core")],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
