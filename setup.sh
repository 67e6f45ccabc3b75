#!/usr/bin/env bash
# setup.sh — install what vigen needs, build it, and run it.
#
#   ./setup.sh run    install missing packages, configure, build, run the main job
#   ./setup.sh test   install missing packages, configure, build, run the test suite
#
# Debian 12 (or Ubuntu) as root, or a user with sudo.  Safe to run again: it
# installs only what is missing and rebuilds only what changed.
set -euo pipefail
cd "$(dirname "$0")"

# python3-*: the Python package (python/, docs/python.md) loads libvigen with
# cffi and hands arrays out as NumPy's; pytest runs its tests; matplotlib
# draws its plots (its tests and the docs' examples use it)
packages=(build-essential cmake pkg-config libflint-arb-dev libflint-dev libgsl-dev liblua5.4-dev clang libclang-rt-dev python3 gnuplot-nox libopenmpi-dev openmpi-bin
          python3-dev python3-cffi python3-numpy python3-pytest python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  echo "setup.sh: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
# the build's progress goes to a log; it is shown only when the build fails
if ! cmake --build build -j"$(nproc)" >build/build.log 2>&1; then
  cat build/build.log >&2
  echo "setup.sh: the build failed (the log above is also in build/build.log)" >&2
  exit 1
fi
echo "setup.sh: built build/vigen and the tests (log: build/build.log)"
# `import vigen` for the python3 on PATH (which may be another interpreter
# than Debian's /usr/bin/python3, e.g. pyenv's): a vigen.pth in its
# site-packages names build/python and, when needed, Debian's dist-packages
# for numpy and cffi (docs/python.md, "Install")
if command -v python3 >/dev/null 2>&1; then
  python3 python/setup_path.py build/python || echo "setup.sh: PYTHONPATH=$PWD/build/python makes 'import vigen' work" >&2
fi

case "${1:-run}" in
  run)
    # The main job: the tableau of Leok & Zhang's Example 4, certified to 34
    # digits, written to a tableau file and shown with its symplecticity
    # residual; its order and symplecticity certified by the checker; the
    # tableau compiled into a C stepper (build/ex4/leok_zhang_ex4.[ch]); then
    # the method run on the Kepler problem next to Gauss s = 2 and
    # Stormer-Verlet (energy error, invariants, error against the exact
    # solution, cost), its empirical order next to the certified one, and the
    # figures (SVG and PNG, with their data as CSV) written under out/.
    build/vigen generate tableaux/specs/leok_zhang_ex4.lua -o build/leok_zhang_ex4.lua
    build/vigen show build/leok_zhang_ex4.lua
    echo
    build/vigen check build/leok_zhang_ex4.lua
    mkdir -p build/ex4
    build/vigen emit build/leok_zhang_ex4.lua --name leok_zhang_ex4 -o build/ex4
    echo
    build/vigen try build/leok_zhang_ex4.lua gauss_2 stormer_verlet_velocity --problem kepler --plot out
    echo
    build/vigen order build/leok_zhang_ex4.lua --problem kepler --plot out
    echo
    build/vigen try build/leok_zhang_ex4.lua gauss_2 stormer_verlet_velocity --problem kepler \
      --work-precision --levels 5 --plot out
    echo
    echo "setup.sh: the figures are in out/: energy.svg (energy error against time), orbit.svg,"
    echo "          order.svg, work_precision_evals.svg and work_precision_seconds.svg (and .png,"
    echo "          with the data of each as .csv)"
    ;;
  test)
    ctest --test-dir build --output-on-failure -j"$(nproc)"
    ;;
  *)
    echo "usage: ./setup.sh [run|test]" >&2
    exit 2
    ;;
esac
