# SPDX-License-Identifier: BSD-3-Clause
"""`pip install --no-build-isolation .`: setuptools drives the project's CMake (the one build system) to build the
extension target `_restitution` (python/CMakeLists.txt) in a build folder of its own, and packages it with
python/restitution/*.py, *.pyi and py.typed. The version is CMake's (cmake/version.cmake: git and the file VERSION,
e.g. 0.4.0.dev252+gf916007b96cf); `python3 -m build --sdist` writes it into the sdist as SDIST_VERSION, so that
a build from the sdist, which is no git checkout, names the same version and commit. MANIFEST.in lists what
the sdist carries: everything the build reads; setup.py adds third_party/sundials, the CVODE source of Debian's
source package (BSD-3-Clause) that scripts/sundials pruned, which a build from the sdist compiles optimized.

Only the module and the libraries it links are built: no tests, benchmarks or program. Extra CMake arguments
come from the environment, e.g. CMAKE_ARGS="-DSUNDIALS_DIR=/opt/sundials/lib/cmake/sundials"; the parallel
build level from CMAKE_BUILD_PARALLEL_LEVEL (default: every core); a compiler launcher such as ccache from
CMAKE_CXX_COMPILER_LAUNCHER, which CMake reads itself. RESTITUTION_CMAKE_BUILD_DIR=FOLDER builds the target in a
folder the project's own build already configured instead (CI: build/release, built by scripts/test just before).
"""
import os
import pathlib
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.sdist import sdist

ROOT = pathlib.Path(__file__).resolve().parent


def computed_version():
    """The version and commit cmake/version.cmake computes (the same CMake's configure computes)."""
    lines = subprocess.run(["cmake", f"-DROOT={ROOT}", "-P", str(ROOT / "cmake" / "version.cmake")], check=True,
                           capture_output=True, text=True).stdout.split()
    if len(lines) != 2:
        sys.exit(f"setup.py: cmake/version.cmake printed {lines}, expected a version and a commit")
    return lines[0], lines[1]


VERSION, COMMIT = computed_version()


class CMakeExtension(Extension):
    """An extension whose sources CMake compiles; setuptools only copies the result."""

    def __init__(self, name, target):
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        reuse = os.environ.get("RESTITUTION_CMAKE_BUILD_DIR")
        if reuse:  # a folder the project's own build configured (CI: build/release): build the target there
            build = pathlib.Path(reuse).resolve()
            if not (build / "CMakeCache.txt").exists():
                sys.exit(f"setup.py: RESTITUTION_CMAKE_BUILD_DIR={reuse} is not a configured CMake build folder")
            self.build_in(build, ext)
            return
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     "-DRESTITUTION_BUILD_TESTS=OFF", "-DRESTITUTION_BUILD_BENCH=OFF",
                     "-DRESTITUTION_BUILD_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"]
        if "CMAKE_GENERATOR" not in os.environ and shutil.which("ninja") and not (build / "CMakeCache.txt").exists():
            configure += ["-G", "Ninja"]
        configure += shlex.split(os.environ.get("CMAKE_ARGS", ""))
        subprocess.run(configure, check=True)
        self.build_in(build, ext)

    def build_in(self, build, ext):
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build), "--target", ext.target, "--parallel", jobs], check=True)
        built = sorted((build / "python" / "restitution").glob(f"{ext.target}*.so"))
        if len(built) != 1:
            sys.exit(f"setup.py: expected one {ext.target}*.so in {build}/python/restitution, found {built}")
        destination = pathlib.Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], destination)


def sundials_bundle():
    """The CVODE source the sdist carries as third_party/sundials: the bundle scripts/sundials made from Debian's
    source package of the installed libsundials-dev (build/sundials/<version>/bundle), or, for an sdist made from
    an sdist, the one it carries. None if there is neither."""
    carried = ROOT / "third_party" / "sundials"
    if (carried / "DEBIAN_VERSION").exists():
        return carried
    version = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "libsundials-dev"], capture_output=True,
                             text=True).stdout
    made = ROOT / "build" / "sundials" / version / "bundle"
    return made if version and (made / "DEBIAN_VERSION").exists() else None


class SdistWithVersion(sdist):
    """An sdist is no git checkout: it carries the version and commit it was made from (cmake/version.cmake), and
    the CVODE source that a build from it compiles optimized (cmake/sundials.cmake)."""

    def make_release_tree(self, base_dir, files):
        super().make_release_tree(base_dir, files)
        target = pathlib.Path(base_dir) / "SDIST_VERSION"
        target.unlink(missing_ok=True)  # a hard link to the source's copy when an sdist is made from an sdist
        target.write_text(f"{VERSION}\n{COMMIT}\n", encoding="ascii")
        bundle = sundials_bundle()
        if bundle is None:  # pip would link Debian's unoptimized libsundials: no sdist rather than a slow one
            sys.exit("setup.py: no CVODE source to put into the sdist: run bash scripts/sundials (it makes "
                     "build/sundials/<version>/bundle from Debian's source package), then make the sdist again")
        destination = pathlib.Path(base_dir) / "third_party" / "sundials"
        if destination.exists():  # hard links to the source's copy when an sdist is made from an sdist
            shutil.rmtree(destination)
        shutil.copytree(bundle, destination)


setup(
    version=VERSION,
    packages=["restitution"],
    package_dir={"": "python"},
    package_data={"restitution": ["*.pyi", "py.typed"]},
    ext_modules=[CMakeExtension("restitution._restitution", target="_restitution")],
    cmdclass={"build_ext": CMakeBuild, "sdist": SdistWithVersion},
    zip_safe=False,
)
