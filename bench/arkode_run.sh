#!/bin/bash
# arkode_run.sh VIGEN [BUILD_DIR] [SUNDIALS_SRC] — the emitted mechanical
# steppers side by side with SUNDIALS ARKODE's SPRKStep on the same methods
# (bench/arkode_bench.c; docs/benchmarks.md, "ARKODE SPRKStep side by
# side"), on Kepler and the outer solar system, in one run.
#
# SUNDIALS is not a dependency of vigen: the Debian package predates
# SPRKStep, so the benchmark builds ARKODE from source, from SUNDIALS_SRC
# (default bench/peers/sundials, ignored by git; cloned from
# github.com/LLNL/sundials there when missing), with CMake (Release, -O3,
# static, ARKODE alone) into BUILD_DIR/sundials.  The steppers are emitted
# by the vigen binary VIGEN; the runtime, the problem library, the emitted
# code and the driver are compiled with gcc -O3 (the flags ARKODE is built
# with).  Prints Markdown and rewrites the block between the arkode-figures
# markers of docs/benchmarks.md.  ARK_STEPS_SCALE (default 1) multiplies the
# step counts for a short trial.  About ten minutes on 2 cores the first time
# (building ARKODE), a minute afterwards.  Not a test.
set -euo pipefail
VIGEN=$(realpath "${1:?usage: arkode_run.sh VIGEN [BUILD_DIR] [SUNDIALS_SRC]}")
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=${2:-/tmp/vigen-bench-arkode}
SUN=${3:-$SRC/bench/peers/sundials}
SCALE=${ARK_STEPS_SCALE:-1}
mkdir -p "$OUT/obj"

if [ ! -f "$SUN/include/arkode/arkode_sprkstep.h" ]; then
    mkdir -p "$(dirname "$SUN")"
    git clone --depth 1 https://github.com/LLNL/sundials "$SUN" >&2
fi
if [ ! -f "$OUT/sundials/install/lib/libsundials_arkode.a" ]; then
    cmake -S "$SUN" -B "$OUT/sundials/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_FLAGS=-O3 \
        -DBUILD_SHARED_LIBS=OFF -DBUILD_STATIC_LIBS=ON -DBUILD_ARKODE=ON -DBUILD_CVODE=OFF -DBUILD_CVODES=OFF \
        -DBUILD_IDA=OFF -DBUILD_IDAS=OFF -DBUILD_KINSOL=OFF -DEXAMPLES_ENABLE_C=OFF -DEXAMPLES_ENABLE_CXX=OFF \
        -DEXAMPLES_INSTALL=OFF -DCMAKE_INSTALL_PREFIX="$OUT/sundials/install" >/dev/null
    cmake --build "$OUT/sundials/build" -j2 --target install >/dev/null
fi
SUNINC=$OUT/sundials/install/include
SUNLIB=$OUT/sundials/install/lib
SUNVER=$(sed -n 's/^#define SUNDIALS_VERSION "\(.*\)"/\1/p' "$SUNINC/sundials/sundials_config.h")

CFLAGS="-std=c11 -O3 -Wall -Wextra"
INC=(-I"$SRC/runtime/include" -I"$SRC/runtime/problems" -I"$SUNINC")
for f in "$SRC"/runtime/{core,drive,diagnostics,lagrangian,poincare,nbody}/*.c "$SRC"/runtime/problems/*.c; do
    [ -f "$f" ] || continue
    gcc $CFLAGS "${INC[@]}" -c "$f" -o "$OUT/obj/$(basename "${f%.c}").o"
done

# id and method file of each pair (the ARKODE table is in arkode_bench.c).
# ARKODE's YOSHIDA_6_8 composes Yoshida's solution A of the kick-first
# (velocity) Verlet step, where the library's yoshida_6 composes the
# drift-first one: the same composition on the other base is written here.
PAIRS="lf:stormer_verlet_position plf:stormer_verlet_velocity ruth3:ruth_3 mcl2:mclachlan_atela_2
       mcl3:mclachlan_atela_3 cr4:candy_rozmus_4 y6:yoshida_6_velocity"
sed 's/base = "stormer_verlet_position"/base = "stormer_verlet_velocity"/; s/name = "yoshida_6"/name = "yoshida_6_velocity"/' \
    "$SRC/tableaux/published/yoshida_6.lua" >"$OUT/yoshida_6_velocity.lua"
grep -q 'base = "stormer_verlet_velocity"' "$OUT/yoshida_6_velocity.lua" ||
    { echo "arkode_run.sh: tableaux/published/yoshida_6.lua no longer names its base as expected" >&2; exit 1; }
method_file() { if [ -f "$SRC/tableaux/published/$1.lua" ]; then echo "$SRC/tableaux/published/$1.lua"; else echo "$OUT/$1.lua"; fi; }
for pr in $PAIRS; do
    id=${pr%%:*} file=${pr#*:}
    "$VIGEN" emit "$(method_file "$file")" --name "ak_${id}_any" -o "$OUT" -q
    gcc $CFLAGS -I"$SRC/runtime/include" -c "$OUT/ak_${id}_any.c" -o "$OUT/obj/ak_${id}_any.o"
done

# id (problem_<id>.c), collection name, parameters, dimension, unit masses, h, steps, title
PROBLEMS=(
    "kepler|kepler|e=0.6|2|1|(2 * 3.14159265358979323846 / 200)|1000000|Kepler, e = 0.6, h = 2 pi/200"
    "outer_solar_system|outer-solar-system||18|0|10.0|100000|Outer solar system (Sun and five outer bodies, HLW data), h = 10 days"
)
for row in "${PROBLEMS[@]}"; do
    IFS='|' read -r id name params dim unit h steps title <<<"$row"
    dir="$OUT/$id"
    mkdir -p "$dir"
    for pr in $PAIRS; do
        m=${pr%%:*} file=${pr#*:}
        "$VIGEN" emit "$(method_file "$file")" --name "ak_$m" --dim "$dim" -o "$dir" -q
    done
    others=()
    for o in "$OUT"/obj/*.o; do
        case "$(basename "$o")" in problem_$id.o) ;; *) others+=("$o") ;; esac
    done
    gcc $CFLAGS "${INC[@]}" -I"$dir" -DARK_FILE="\"problem_$id.c\"" -DARK_NAME="\"$name\"" \
        -DARK_PARAMS="\"$params\"" -DARK_TITLE="\"$title\"" -DARK_DIM="$dim" -DARK_UNIT_MASS="$unit" \
        -DARK_H="$h" -DARK_STEPS="$steps" "$SRC/bench/arkode_bench.c" "${others[@]}" \
        "$SUNLIB/libsundials_arkode.a" "$SUNLIB/libsundials_nvecserial.a" "$SUNLIB/libsundials_core.a" \
        -lgsl -lgslcblas -lm -o "$dir/arkode_bench"
done

{
    echo "<!-- arkode-figures:begin (written by bench/arkode_run.sh) -->"
    echo "Machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores;" \
        "$(date -u '+%Y-%m-%d %H:%M UTC'); load average before the run $(cut -d' ' -f1-3 /proc/loadavg);" \
        "gcc $(gcc -dumpfullversion) ($CFLAGS); SUNDIALS $SUNVER ($( [ -e "$SUN/.git" ] && git -C "$SUN" rev-parse --short HEAD 2>/dev/null || echo "unpacked source"), -O3, static)."
    echo
    for row in "${PROBLEMS[@]}"; do
        IFS='|' read -r id name params dim unit h steps title <<<"$row"
        n=$(awk -v s="$steps" -v k="$SCALE" 'BEGIN { n = int(s * k); print (n > 0 ? n : 1) }')
        "$OUT/$id/arkode_bench" "$n" | tee "$OUT/$id.rows"
        # instructions per step, free of the machine's load: callgrind's
        # count of a run of 2N steps less that of N, over N
        if command -v valgrind >/dev/null; then
            N=$(( steps / 100 ))
            ir() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$OUT/$id/arkode_bench" one "$1" "$2" "$3" 2>&1 |
                   sed -n 's/.*refs: *//p' | tr -d ,; }
            a=$(ir force - "$N"); b=$(ir force - "$((2 * N))")
            F=$(( (b - a) / N ))
            echo "Instructions per step (callgrind: runs of $((2 * N)) less $N steps, compensation off); one force"
            echo "evaluation alone costs $F instructions, and the force-bound of a step is vigen's forces per step"
            echo "times that (the same force function on both sides):"
            echo
            echo "| method | ARKODE | vigen --dim, direct force | vigen, force callback | ratio (--dim) | ratio (callback) | force-bound / ARKODE |"
            echo "|---|---|---|---|---|---|---|"
            for pr in $PAIRS; do
                m=${pr%%:*} file=${pr#*:}
                declare -A c=()
                for side in ark dim cb; do
                    a=$(ir "$m" "$side" "$N"); b=$(ir "$m" "$side" "$((2 * N))")
                    c[$side]=$(( (b - a) / N ))
                done
                nf=$(sed -n "s/^| vigen \`$file\`, --dim, direct force | [^|]* | \([0-9.]*\) |.*/\1/p" "$OUT/$id.rows" | head -1)
                awk -v f="$file" -v a="${c[ark]}" -v d="${c[dim]}" -v k="${c[cb]}" -v F="$F" -v nf="$nf" \
                    'BEGIN { printf "| `%s` | %d | %d | %d | %.2f | %.2f | %.2f |\n", f, a, d, k, d / a, k / a, nf * F / a }'
            done
            echo
        fi
    done
    echo "<!-- arkode-figures:end -->"
} >"$OUT/figures.md"

python3 - "$SRC/docs/benchmarks.md" "$OUT/figures.md" <<'PY'
import re, sys
doc, fig = sys.argv[1], open(sys.argv[2]).read()
text = open(doc).read()
pat = re.compile(r"<!-- arkode-figures:begin.*?<!-- arkode-figures:end -->\n?", re.S)
if pat.search(text):
    open(doc, "w").write(pat.sub(lambda m: fig, text))
else:
    print("docs/benchmarks.md has no arkode-figures block: figures left in", sys.argv[2], file=sys.stderr)
PY
cat "$OUT/figures.md"
