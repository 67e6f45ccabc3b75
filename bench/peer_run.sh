#!/bin/bash
# peer_run.sh VIGEN [BUILD_DIR] — the emitted mechanical steppers side by side
# with their peers, in one run (docs/benchmarks.md, "Mechanical steppers and
# their peers"): on Kepler, the outer solar system and an FPUT chain of
# n = 1000 from the problem collection, bench/peer_bench.c (hand-written
# Gauss-2 and Verlet, the emitted Gauss-2, Verlet, mclachlan_rkn_4 and
# yoshida_4 with --dim and direct force and through the callbacks, GSL's
# rk4imp) and bench/peer_boost.cpp (Boost.Odeint's
# symplectic_rkn_sb3a_mclachlan, the same method as mclachlan_rkn_4).
# Emits the steppers with the vigen binary VIGEN, builds into BUILD_DIR
# (default /tmp/vigen-bench-peer; gcc and g++ -O2), runs, prints Markdown and
# rewrites the block between the peer-figures markers of docs/benchmarks.md.
# Installs libboost-dev (header only, for this benchmark alone) with apt-get
# when /usr/include/boost/numeric/odeint.hpp is missing.  PEER_STEPS_SCALE
# (default 1) multiplies every step count, for a short trial run;
# PEER_SKIP_GSL=1 leaves out rk4imp (on the chain ~10 s per apply).  A few
# minutes on 2 cores.  Not a test.
set -euo pipefail
VIGEN=$(realpath "${1:?usage: peer_run.sh VIGEN [BUILD_DIR]}")
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=${2:-/tmp/vigen-bench-peer}
SCALE=${PEER_STEPS_SCALE:-1}
rm -rf "$OUT/obj"
mkdir -p "$OUT/obj"

if [ ! -f /usr/include/boost/numeric/odeint.hpp ]; then
    echo "peer_run.sh: installing libboost-dev (Boost.Odeint, header only) for the Boost rows" >&2
    SUDO=
    [ "$(id -u)" = 0 ] || SUDO=sudo
    $SUDO apt-get update -qq >&2
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq libboost-dev >&2
fi

# the problems: id (problem_<id>.c), collection name, parameters, dimension,
# unit masses, h, steps, rk4imp applies and runs, title
PROBLEMS=(
    "kepler|kepler|e=0.6|2|1|(2 * 3.14159265358979323846 / 200)|1000000|20000|5|Kepler, e = 0.6, h = 2 pi/200"
    "outer_solar_system|outer-solar-system||18|0|10.0|100000|2000|5|Outer solar system (Sun and five outer bodies, HLW data), h = 10 days"
    "fput|fput|n=1000|1000|1|0.05|5000|1|2|FPUT-beta chain, n = 1000, beta = 1, first normal mode of amplitude 1, h = 0.05"
)

CFLAGS="-std=c11 -O2 -Wall -Wextra -Wpedantic"
CXXFLAGS="-std=c++17 -O2 -Wall -Wextra -Wpedantic"
INC=(-I"$SRC/runtime/include" -I"$SRC/runtime/problems" -I"$SRC/bench")

# the runtime and the problem library, compiled once
for f in "$SRC"/runtime/{core,drive,diagnostics,lagrangian,poincare,nbody}/*.c "$SRC"/runtime/problems/*.c; do
    gcc $CFLAGS "${INC[@]}" -c "$f" -o "$OUT/obj/$(basename "${f%.c}").o"
done
# the steppers used through their callbacks (any dimension)
"$VIGEN" emit "$SRC/tableaux/published/gauss_2.lua" --name peer_g2 -o "$OUT" -q
"$VIGEN" emit "$SRC/tableaux/published/stormer_verlet_velocity.lua" --name peer_sv -o "$OUT" -q
"$VIGEN" emit "$SRC/tableaux/published/mclachlan_rkn_4.lua" --name peer_mcl -o "$OUT" -q
for n in g2 sv mcl; do
    gcc $CFLAGS -I"$SRC/runtime/include" -c "$OUT/peer_$n.c" -o "$OUT/obj/peer_$n.o"
done

for row in "${PROBLEMS[@]}"; do
    IFS='|' read -r id name params dim unit h steps applies runs title <<<"$row"
    dir="$OUT/$id"
    mkdir -p "$dir"
    # the steppers with the dimension fixed and the force called directly
    "$VIGEN" emit "$SRC/tableaux/published/gauss_2.lua" --name peer_g2d --dim "$dim" -o "$dir" -q
    "$VIGEN" emit "$SRC/tableaux/published/gauss_3.lua" --name peer_g3d --dim "$dim" -o "$dir" -q
    "$VIGEN" emit "$SRC/tableaux/published/lobatto_iiia_iiib_3.lua" --name peer_l3d --dim "$dim" -o "$dir" -q
    "$VIGEN" emit "$SRC/tableaux/published/stormer_verlet_velocity.lua" --name peer_svd --dim "$dim" -o "$dir" -q
    "$VIGEN" emit "$SRC/tableaux/published/mclachlan_rkn_4.lua" --name peer_mcld --dim "$dim" -o "$dir" -q
    "$VIGEN" emit "$SRC/tableaux/published/yoshida_4.lua" --name peer_y4d --dim "$dim" -o "$dir" -q
    defs=(-DPEER_FILE="\"problem_$id.c\"" -DPEER_NAME="\"$name\"" -DPEER_PARAMS="\"$params\""
          -DPEER_TITLE="\"$title\"" -DPEER_DIM="$dim" -DPEER_UNIT_MASS="$unit" -DPEER_H="$h"
          -DPEER_STEPS="$steps" -DPEER_GSL_APPLIES="$applies" -DPEER_GSL_RUNS="$runs")
    # the problem's file is compiled inside peer_bench.c: link the others
    others=()
    for o in "$OUT"/obj/*.o; do
        case "$(basename "$o")" in problem_$id.o | peer_*.o) ;; *) others+=("$o") ;; esac
    done
    gcc $CFLAGS "${INC[@]}" -I"$OUT" -I"$dir" "${defs[@]}" "$SRC/bench/peer_bench.c" \
        "$OUT"/obj/peer_*.o "${others[@]}" -lgsl -lgslcblas -lm -o "$dir/peer_bench"
    gcc $CFLAGS -flto "${INC[@]}" "${defs[@]}" -DPEER_FORCE_ONLY -c "$SRC/bench/peer_bench.c" -o "$dir/force.o"
    g++ $CXXFLAGS -flto "${INC[@]}" "${defs[@]}" -c "$SRC/bench/peer_boost.cpp" -o "$dir/boost.o"
    g++ -O2 -flto "$dir/boost.o" "$dir/force.o" "${others[@]}" -lgsl -lgslcblas -lm -o "$dir/peer_boost"
done

{
    echo "<!-- peer-figures:begin (written by bench/peer_run.sh) -->"
    echo "Machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores;" \
        "$(date -u '+%Y-%m-%d %H:%M UTC'); load average before the run $(cut -d' ' -f1-3 /proc/loadavg);" \
        "gcc $(gcc -dumpfullversion) ($CFLAGS), g++ $(g++ -dumpfullversion) ($CXXFLAGS, -flto for the Boost" \
        "program), Boost $(sed -n 's/^#define BOOST_LIB_VERSION "\(.*\)"/\1/p' /usr/include/boost/version.hpp)."
    echo
    for row in "${PROBLEMS[@]}"; do
        IFS='|' read -r id name params dim unit h steps applies runs title <<<"$row"
        n=$(awk -v s="$steps" -v k="$SCALE" 'BEGIN { n = int(s * k); print (n > 0 ? n : 1) }')
        "$OUT/$id/peer_boost" "$n" "$OUT/$id/boost.txt"
        "$OUT/$id/peer_bench" "$n" "$OUT/$id/boost.txt"
    done
    echo "<!-- peer-figures:end -->"
} >"$OUT/figures.md"

python3 - "$SRC/docs/benchmarks.md" "$OUT/figures.md" <<'PY'
import re, sys
doc, fig = sys.argv[1], open(sys.argv[2]).read()
text = open(doc).read()
pat = re.compile(r"<!-- peer-figures:begin.*?<!-- peer-figures:end -->\n?", re.S)
if not pat.search(text):
    sys.exit("docs/benchmarks.md has no peer-figures block (section \"Mechanical steppers and their peers\")")
open(doc, "w").write(pat.sub(lambda m: fig, text))
PY
cat "$OUT/figures.md"
