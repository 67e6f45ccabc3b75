"""The package installed by `cmake --install` works from the prefix alone:
`PYTHONPATH=PREFIX/lib/python3/dist-packages python3 -c "import vigen"`
from an unrelated folder finds the installed library, templates and
tableaux (not the source tree's), also after the prefix is moved; and
python/setup_path.py makes an interpreter import the build's package."""
import json
import os
import shutil
import subprocess
import sys

import pytest

SOURCE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD_DIR = os.environ.get("VIGEN_BUILD_DIR", os.path.join(SOURCE_DIR, "build"))

PROBE = """
import json, os, vigen, vigen._paths as p
t = vigen.generate(os.environ["SPEC"], digits=12)
print(json.dumps({"build_tree": p.BUILD_TREE, "templates": p.TEMPLATE_DIR, "package": os.path.dirname(vigen.__file__),
                  "order": vigen.check("gauss_2")["order"], "gauss_2": vigen.resolve("gauss_2"),
                  "runtime": os.path.isfile(p.RUNTIME_LIBRARY), "problems": os.path.isfile(p.PROBLEMS_LIBRARY),
                  "headers": all(os.path.isfile(os.path.join(d, "vigen", "runtime.h")) for d in p.INCLUDE_DIRS),
                  "A": t.A}))
"""


def probe(pythonpath, cwd, spec):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIGEN_TEMPLATE_DIR", "VIGEN_PATH")}
    env.update(PYTHONPATH=pythonpath, SPEC=spec)
    proc = subprocess.run([sys.executable, "-c", PROBE], cwd=cwd, env=env, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    if not os.path.isfile(os.path.join(BUILD_DIR, "CMakeCache.txt")):
        pytest.skip("no build directory to install from")
    root = tmp_path_factory.mktemp("install")
    proc = subprocess.run(["cmake", "--install", BUILD_DIR, "--prefix", str(root / "prefix")],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return root


def test_installed_package_uses_the_prefix(prefix, tmp_path):
    site = prefix / "prefix" / "lib" / "python3" / "dist-packages"
    assert (site / "vigen" / "libvigen_python.so").is_file()
    spec = os.path.join(SOURCE_DIR, "tableaux", "specs", "gauss_legendre_s2.lua")
    got = probe(str(site), str(tmp_path), spec)
    assert got["build_tree"] is False
    assert got["package"] == str(site / "vigen")
    assert got["templates"] == str(prefix / "prefix" / "share" / "vigen" / "templates")
    assert os.path.isdir(os.path.join(got["templates"], "prk"))
    share = prefix / "prefix" / "share" / "vigen"
    assert os.path.normpath(got["gauss_2"]) == str(share / "tableaux" / "published" / "gauss_2.lua")
    assert got["order"] == 4
    assert got["runtime"] and got["problems"] and got["headers"]
    # the same digits as the build tree's package
    assert got["A"] == probe(os.path.join(BUILD_DIR, "python"), str(tmp_path), spec)["A"]


def test_moved_prefix_still_finds_its_files(prefix, tmp_path):
    moved = prefix / "moved"
    shutil.copytree(prefix / "prefix", moved, symlinks=True)
    site = moved / "lib" / "python3" / "dist-packages"
    spec = os.path.join(SOURCE_DIR, "tableaux", "specs", "gauss_legendre_s2.lua")
    got = probe(str(site), str(tmp_path), spec)
    assert os.path.normpath(got["gauss_2"]) == str(moved / "share" / "vigen" / "tableaux" / "published" / "gauss_2.lua")
    assert got["order"] == 4


def test_build_tree_package_uses_the_source_tree(tmp_path):
    spec = os.path.join(SOURCE_DIR, "tableaux", "specs", "gauss_legendre_s2.lua")
    got = probe(os.path.join(BUILD_DIR, "python"), str(tmp_path), spec)
    assert got["build_tree"] is True
    assert got["gauss_2"] == os.path.join(SOURCE_DIR, "tableaux", "published", "gauss_2.lua")


@pytest.mark.parametrize("interpreter", sorted({sys.executable, shutil.which("python3") or sys.executable}))
def test_setup_path_makes_vigen_importable(tmp_path, interpreter):
    # into a folder of our own (--site), not the interpreter's site-packages
    site = tmp_path / "site"
    site.mkdir()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    proc = subprocess.run([interpreter, os.path.join(SOURCE_DIR, "python", "setup_path.py"),
                           os.path.join(BUILD_DIR, "python"), "--site", str(site)],
                          env=env, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    lines = (site / "vigen.pth").read_text().splitlines()
    assert lines[0] == os.path.join(BUILD_DIR, "python")
    code = f"import site; site.addsitedir({str(site)!r}); import vigen, numpy; print(vigen.check('gauss_2')['order'])"
    out = subprocess.run([interpreter, "-c", code], env=env, capture_output=True, text=True, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["4"]
