#!/bin/bash
# cli_docs.sh VIGEN SRC — the lists in README.md that name what spec files
# may contain (node families, basis families, functions of expressions) say
# exactly what `vigen help spec` prints, which the code writes from its own
# tables (nodes.def, basis.def, functions.def): a family or function added to
# a table and not to the README, or documented and not in the code, fails.
set -u
VIGEN=$1
SRC=$2
fail=0
help=$("$VIGEN" help spec) || { echo "FAIL: vigen help spec exits $?"; exit 1; }
# names in one section of the help: the first word of each indented row
section() { echo "$help" | awk -v h="$1" 'index($0, h) == 1 {on = 1; next} /^$/ {on = 0} on && /^  [a-z_]+(\([sx]\))?  / {print $1}'; }
nodes=$(section "Node families" | sed 's/(s)$//' | sort)
basis=$(section "Basis families" | sed 's/(s)$//' | sort)
funcs=$(section "Functions and constants" | sed 's/(x)$//' | sort)
[ -n "$nodes" ] && [ -n "$basis" ] && [ -n "$funcs" ] || { echo "FAIL: vigen help spec lacks a section"; exit 1; }

# the README's lists: the Nodes and Basis sections, and the **Expressions** paragraph
readme_section() { awk -v h="$1" '$0 == h {on = 1; next} /^#/ {on = 0} on' "$SRC/README.md"; }
r_nodes=$(readme_section "### Nodes" | grep -o '`[a-z_]*(s)`' | tr -d '`' | sed 's/(s)$//' | sort -u)
r_basis=$(readme_section "### Basis" | grep -o '`[a-z_]*(s)`' | tr -d '`' | sed 's/(s)$//' | sort -u)
r_funcs=$(awk '/^\*\*Expressions\*\*/ {on = 1} on && /^$/ {exit} on' "$SRC/README.md" | grep -o '`[a-z]*`' | tr -d '`' | sort -u)

same() { # label code readme
  if [ "$2" != "$3" ]; then
    echo "FAIL: $1: the code has [$(echo $2)], README.md lists [$(echo $3)]"
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
[ $fail -eq 0 ] && echo "cli_docs: README lists agree with the tables"
exit $fail
