"""`cmake --install` puts an importable package under the prefix, linked to the installed library."""

import ast
import os
import pathlib
import subprocess
import sys
import sysconfig

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_cmake_install_gives_an_importable_package(tmp_path):
    build = pathlib.Path(os.environ.get("FAIRSURF_BUILD_DIR", ROOT / "build"))
    subprocess.run(["cmake", "--install", str(build), "--prefix", str(tmp_path)], check=True, capture_output=True)
    version = sysconfig.get_python_version()
    site = tmp_path / "lib" / f"python{version}" / "dist-packages"
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "LD_LIBRARY_PATH")}
    env["PYTHONPATH"] = str(site)
    script = ("import fairsurf; V, F = fairsurf.scene('fig4', edge_length=0.5); "
              "print(fairsurf.__file__); print(fairsurf.info(V, F)['boundary_loops'])")
    out = subprocess.run([sys.executable, "-c", script], env=env, cwd=tmp_path, check=True, capture_output=True,
                         text=True)  # not the cwd: ctest runs in build/python, beside the build tree's package
    module_file, loops = out.stdout.splitlines()
    assert pathlib.Path(module_file).is_relative_to(site)
    assert len(ast.literal_eval(loops)) == 2  # fig4: two caps, two rims
