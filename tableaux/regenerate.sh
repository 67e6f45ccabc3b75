#!/usr/bin/env bash
# regenerate.sh VIGEN [OUTDIR] — generate every spec in tableaux/specs/ into
# OUTDIR (default: tableaux/generated/, the committed copies) with the digits
# the project ships (50).  The test cli_tableaux_fresh runs this into a
# scratch directory and fails when a committed tableau differs.
set -euo pipefail
vigen=$1
here=$(cd "$(dirname "$0")" && pwd)
out=${2:-$here/generated}
mkdir -p "$out"
for spec in "$here"/specs/*.lua; do
  name=$(basename "$spec" .lua)
  "$vigen" generate "$spec" --digits 50 --quiet -o "$out/$name.lua"
done
