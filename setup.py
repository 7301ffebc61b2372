"""`/usr/bin/python3 -m pip install --no-build-isolation .` builds the extension with the project's
CMake (FAIRSURF_PYTHON, static libfairsurf so the module stands alone) and installs the package
python/fairsurf. Needs only Debian's packages (scripts/install-deps.sh) and no network."""

import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = ROOT / "build" / "pip"
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                        "-DBUILD_SHARED_LIBS=OFF", "-DFAIRSURF_BUILD_TESTS=OFF", "-DFAIRSURF_BUILD_BENCH=OFF",
                        "-DFAIRSURF_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "_fairsurf", "-j", str(os.cpu_count() or 1)],
                       check=True)
        built = next((build_dir / "python" / "fairsurf").glob("_fairsurf*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    name="fairsurf",
    version="0.1.0",
    description="Fair surfaces on triangle meshes with sixth-order geometric flows",
    packages=["fairsurf"],
    package_dir={"": "python"},
    ext_modules=[Extension("fairsurf._fairsurf", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
    zip_safe=False,
)
