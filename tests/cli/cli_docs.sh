#!/bin/bash
# cli_docs.sh VIGEN SRC — the documents say what the code does and where
# they are:
# - the lists in docs/spec.md that name what spec files may contain (node
#   families, basis families, functions of expressions) say exactly what
#   `vigen help spec` prints, which the code writes from its own tables
#   (nodes.def, basis.def, functions.def): a family or function added to a
#   table and not to docs/spec.md, or documented and not in the code, fails;
# - docs/README.md names every document of docs/ and no other file, and
#   every docs/ file README.md links to exists;
# - README.md fits on a page: at most 200 lines, and the commands of its
#   tour run (exit status 0) and write what it says;
# - the Kepler program listed in docs/compile.md is examples/kepler's, and
#   the outputs of vigen check and vigen emit that docs/check.md and
#   docs/compile.md show are what the commands print.
set -u
VIGEN=$1
SRC=$2
fail=0
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
help=$("$VIGEN" help spec) || { echo "FAIL: vigen help spec exits $?"; exit 1; }
# names in one section of the help: the first word of each indented row
section() { echo "$help" | awk -v h="$1" 'index($0, h) == 1 {on = 1; next} /^$/ {on = 0} on && /^  [a-z_]+(\([sx]\))?  / {print $1}'; }
nodes=$(section "Node families" | sed 's/(s)$//' | sort)
basis=$(section "Basis families" | sed 's/(s)$//' | sort)
funcs=$(section "Functions and constants" | sed 's/(x)$//' | sort)
[ -n "$nodes" ] && [ -n "$basis" ] && [ -n "$funcs" ] || { echo "FAIL: vigen help spec lacks a section"; exit 1; }

# the lists of docs/spec.md: the Nodes and Basis sections, and the **Expressions** paragraph
SPEC_DOC="$SRC/docs/spec.md"
doc_section() { awk -v h="$1" '$0 == h {on = 1; next} /^#/ {on = 0} on' "$SPEC_DOC"; }
r_nodes=$(doc_section "## Nodes" | grep -o '`[a-z_]*(s)`' | tr -d '`' | sed 's/(s)$//' | sort -u)
r_basis=$(doc_section "## Basis" | grep -o '`[a-z_]*(s)`' | tr -d '`' | sed 's/(s)$//' | sort -u)
r_funcs=$(awk '/^\*\*Expressions\*\*/ {on = 1} on && /^$/ {exit} on' "$SPEC_DOC" | grep -o '`[a-z]*`' | tr -d '`' | sort -u)

same() { # label code doc
  if [ "$2" != "$3" ]; then
    echo "FAIL: $1: the code has [$(echo $2)], docs/spec.md lists [$(echo $3)]"
    fail=1
  fi
}
same "node families" "$nodes" "$r_nodes"
same "basis families" "$basis" "$r_basis"
same "functions of expressions" "$funcs" "$r_funcs"

# every kind of method file the registry reads is named in the help
for k in tableau galerkin; do
  echo "$help" | grep -q "^  $k " || { echo "FAIL: vigen help spec does not list the kind '$k'"; fail=1; }
done
# docs/README.md: one row per document of docs/, each naming a file there
index="$SRC/docs/README.md"
listed=$(grep -o '^| \[[^]]*\]([^)]*)' "$index" | sed 's/.*(\(.*\))$/\1/' | sort)
present=$(cd "$SRC/docs" && ls *.md | grep -vx README.md | sort)
[ -n "$listed" ] || { echo "FAIL: docs/README.md lists no document"; fail=1; }
for f in $present; do
  echo "$listed" | grep -qx "$f" || { echo "FAIL: docs/$f is not listed in docs/README.md"; fail=1; }
done
for f in $listed; do
  [ -f "$SRC/docs/$f" ] || { echo "FAIL: docs/README.md lists $f, which is not in docs/"; fail=1; }
done
dups=$(echo "$listed" | uniq -d)
[ -z "$dups" ] || { echo "FAIL: docs/README.md lists $(echo $dups) more than once"; fail=1; }

# README.md: a page, and its links into docs/ lead somewhere
lines=$(wc -l <"$SRC/README.md")
[ "$lines" -le 200 ] || { echo "FAIL: README.md has $lines lines (at most 200: the rest belongs in docs/)"; fail=1; }
for f in $(grep -o '(docs/[^)#]*' "$SRC/README.md" | sed 's/^(//' | sort -u); do
  [ -f "$SRC/$f" ] || { echo "FAIL: README.md links to $f, which does not exist"; fail=1; }
done

# README's tour, run as written from a tree whose build/ is this vigen's
tour=$(awk '$0 == "## A short tour" {seen = 1} seen && $0 == "```sh" {on = 1; next} on && $0 == "```" {exit} on' "$SRC/README.md")
mkdir -p "$T/tour"
ln -s "$SRC/tableaux" "$T/tour/tableaux"
ln -s "$(dirname "$VIGEN")" "$T/tour/build"
if [ -z "$tour" ]; then
  echo "FAIL: README.md has no tour (a sh block after '## A short tour')"; fail=1
elif ! (cd "$T/tour" && bash -e -c "$tour") >"$T/tour.log" 2>&1; then
  echo "FAIL: README.md's tour fails:"; tail -5 "$T/tour.log"; fail=1
elif [ ! -s "$T/tour/ex4.lua" ] || [ ! -s "$T/tour/out/ex4.c" ] || [ ! -s "$T/tour/out/ex4.h" ] || [ ! -s "$T/tour/out/energy.svg" ]; then
  echo "FAIL: README.md's tour does not write ex4.lua, out/ex4.h, out/ex4.c and out/energy.svg"; fail=1
fi

# the Kepler program and its CMakeLists.txt as docs/compile.md lists them
block() { awk -v lang="$1" -v after="$2" 'index($0, after) {seen = 1} seen && $0 == "```" lang {on = 1; next} on && $0 == "```" {exit} on' "$SRC/docs/compile.md"; }
block c '`kepler.c`:' | cmp -s - "$SRC/examples/kepler/kepler.c" ||
  { echo "FAIL: docs/compile.md lists a kepler.c other than examples/kepler/kepler.c"; fail=1; }
block cmake 'Its `CMakeLists.txt`:' | cmp -s - "$SRC/examples/kepler/CMakeLists.txt" ||
  { echo "FAIL: docs/compile.md lists a CMakeLists.txt other than examples/kepler's"; fail=1; }

# the outputs shown: vigen check and the warnings of vigen emit on Leok &
# Zhang's Example 5 (iii) as printed
ex5=tableaux/published/leok_zhang_ex5_iii.lua
(cd "$SRC" && "$VIGEN" check $ex5) >"$T/check.txt"
awk -v f="(\`$ex5\`):" 'index($0, f) {seen = 1} seen && $0 == "```" {if (on) exit; on = 1; next} on' "$SRC/docs/check.md" |
  cmp -s - "$T/check.txt" || { echo "FAIL: docs/check.md shows an output of 'vigen check $ex5' other than the command's"; fail=1; }
(cd "$SRC" && "$VIGEN" emit $ex5 --name ex5 -o "$T" -q) >/dev/null 2>"$T/warn.txt"
grep "^  vigen: warning: $ex5" "$SRC/docs/compile.md" | sed 's/^  //' | cmp -s - "$T/warn.txt" ||
  { echo "FAIL: docs/compile.md shows warnings of 'vigen emit $ex5' other than the command's"; fail=1; }

[ $fail -eq 0 ] && echo "cli_docs: the documents agree with the tables, the index, the examples and the outputs"
exit $fail
