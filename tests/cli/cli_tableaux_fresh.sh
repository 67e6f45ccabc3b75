#!/usr/bin/env bash
# cli_tableaux_fresh.sh VIGEN SRCDIR — the committed tableaux/generated/ files
# are exactly what the current generator produces from tableaux/specs/, and
# every spec has its generated file (no stale or missing tableau).
set -u
vigen=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$src/tableaux/regenerate.sh" "$vigen" "$work" || { echo "FAIL: regeneration failed"; exit 1; }
if ! diff -r "$work" "$src/tableaux/generated" >"$work.diff" 2>&1; then
  echo "FAIL: tableaux/generated/ is stale; run tableaux/regenerate.sh build/vigen"
  head -40 "$work.diff"
  rm -f "$work.diff"
  exit 1
fi
rm -f "$work.diff"
echo ok
