"""Makes `import vigen` work for an interpreter: writes vigen.pth into its
site-packages (the first writable one, else the user's), naming the build
tree's package folder and, when the interpreter cannot import numpy and cffi
by itself, Debian's /usr/lib/python3/dist-packages, where python3-numpy and
python3-cffi are (appended to sys.path: the interpreter's own packages come
first).  Then checks that `import vigen, numpy` works in a fresh process.

    python3 python/setup_path.py BUILD/python [--site DIR]

Run by ./setup.sh with the python3 found on PATH (docs/python.md, "Install").
Exit status 0 when vigen imports afterwards, 1 otherwise (with a message).
"""
import argparse
import os
import site
import subprocess
import sys

DEBIAN_DIST_PACKAGES = "/usr/lib/python3/dist-packages"


def imports(*modules, path=None):
    """Whether a fresh process of this interpreter imports the modules
    (with the folders of path added as site directories)."""
    code = "import site\n" + "".join(f"site.addsitedir({p!r})\n" for p in (path or [])) + \
        "".join(f"import {m}\n" for m in modules)
    return subprocess.run([sys.executable, "-c", code], capture_output=True).returncode == 0


def writable_site_dir():
    """The first site-packages folder of this interpreter one can write to,
    else the user's (created)."""
    for d in site.getsitepackages():
        if os.path.isdir(d) and os.access(d, os.W_OK):
            return d
    if site.ENABLE_USER_SITE:
        d = site.getusersitepackages()
        os.makedirs(d, exist_ok=True)
        return d
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("package_parent", help="the folder holding the package folder vigen/ (BUILD/python)")
    ap.add_argument("--site", help="write vigen.pth here instead of the interpreter's site-packages")
    args = ap.parse_args()
    lines = [os.path.abspath(args.package_parent)]
    target = args.site or writable_site_dir()
    if target is None:
        print(f"setup_path: no site-packages of {sys.executable} is writable; "
              f"use PYTHONPATH={lines[0]}", file=sys.stderr)
        return 1
    pth = os.path.join(target, "vigen.pth")
    # whether the interpreter imports numpy and cffi by itself: without a
    # vigen.pth of an earlier run, which may name Debian's folder already
    # (and a build tree since removed); a --site folder is read as the
    # interpreter's site-packages would be
    if os.path.exists(pth):
        os.remove(pth)
    if not imports("numpy", "cffi", path=[target] if args.site else None) and os.path.isdir(DEBIAN_DIST_PACKAGES) \
            and os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3"):
        lines.append(DEBIAN_DIST_PACKAGES)
    tmp = pth + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write("".join(line + "\n" for line in lines))
    os.replace(tmp, pth)
    # a .pth is read from site-packages at start-up; with --site, add it as one
    if not imports("vigen", "numpy", path=[target] if args.site else None):
        print(f"setup_path: {sys.executable} still cannot import vigen and numpy with {pth}; "
              f"install python3-numpy and python3-cffi, or use /usr/bin/python3", file=sys.stderr)
        return 1
    print(f"setup_path: {sys.executable} imports vigen from {lines[0]} ({pth})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
