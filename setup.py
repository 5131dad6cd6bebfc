"""`pip install --no-build-isolation .`: setuptools drives the project's CMake (the one build system) to build the
extension target `_restitution` (python/CMakeLists.txt) in a build folder of its own, and packages it with
python/restitution/*.py, *.pyi and py.typed. The version is the file VERSION, as for CMake's project().

Only the module and the libraries it links are built: no tests, benchmarks or program. Extra CMake arguments
come from the environment, e.g. CMAKE_ARGS="-DSUNDIALS_DIR=/opt/sundials/lib/cmake/sundials"; the parallel
build level from CMAKE_BUILD_PARALLEL_LEVEL (default: every core); a compiler launcher such as ccache from
CMAKE_CXX_COMPILER_LAUNCHER, which CMake reads itself.
"""
import os
import pathlib
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
VERSION = (ROOT / "VERSION").read_text(encoding="ascii").strip()


class CMakeExtension(Extension):
    """An extension whose sources CMake compiles; setuptools only copies the result."""

    def __init__(self, name, target):
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     "-DRESTITUTION_BUILD_TESTS=OFF", "-DRESTITUTION_BUILD_BENCH=OFF",
                     "-DRESTITUTION_BUILD_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"]
        if "CMAKE_GENERATOR" not in os.environ and shutil.which("ninja") and not (build / "CMakeCache.txt").exists():
            configure += ["-G", "Ninja"]
        configure += shlex.split(os.environ.get("CMAKE_ARGS", ""))
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", ext.target, "--parallel", jobs], check=True)

        built = sorted((build / "python" / "restitution").glob(f"{ext.target}*.so"))
        if len(built) != 1:
            sys.exit(f"setup.py: expected one {ext.target}*.so in {build}/python/restitution, found {built}")
        destination = pathlib.Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], destination)


setup(
    version=VERSION,
    packages=["restitution"],
    package_dir={"": "python"},
    package_data={"restitution": ["*.pyi", "py.typed"]},
    ext_modules=[CMakeExtension("restitution._restitution", target="_restitution")],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
