#!/usr/bin/env bash
# cli_output.sh VIGEN SRCDIR — where output goes, and what untrusted tableau
# files cannot do:
#   - a failed generation leaves an existing -o file untouched;
#   - -o through a symbolic link replaces the file it points to and keeps the
#     link; -o onto a device (/dev/null) or a FIFO writes into it instead of
#     replacing it; an existing file keeps its permissions; no temporary
#     files are left behind; a write error on a file or on standard output
#     (/dev/full, a read-only directory) is a message and exit status 3;
#   - hostile or malformed tableau files (metatables, wrong shapes, floats,
#     bad expressions, unknown fields) get a message naming the file and the
#     entry, exit status 2, and never crash show or check.
set -u
vigen=$1
src=$2
bad=$src/tests/data/bad_tableaux
spec=$src/tableaux/specs/gauss_legendre_s1.lua
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
cd "$work" || exit 1

echo keep >kept.lua
"$vigen" generate "$src/tests/data/bad_specs/singular_m.lua" -o kept.lua 2>/dev/null
[ "$(cat kept.lua)" = keep ] || fail "a failed generation changed the existing output file"

echo old >target.lua
chmod 640 target.lua
ln -s target.lua link.lua
"$vigen" generate "$spec" -q -o link.lua || fail "generate through a link"
[ -L link.lua ] || fail "the symbolic link was replaced"
grep -q 'name = "gauss_legendre_s1"' target.lua || fail "the link target was not written"
[ "$(stat -c %a target.lua)" = 640 ] || fail "permissions changed to $(stat -c %a target.lua)"

"$vigen" generate "$spec" -q -o /dev/null || fail "generate -o /dev/null"
[ -c /dev/null ] || fail "/dev/null is no longer a device"

mkfifo pipe.lua
cat pipe.lua >from_pipe.txt &
"$vigen" generate "$spec" -q -o pipe.lua || fail "generate into a FIFO"
wait
[ -p pipe.lua ] || fail "the FIFO was replaced"
grep -q gauss_legendre_s1 from_pipe.txt || fail "nothing came through the FIFO"

# /dev/stdout into a pipe (a link to a pipe with no path)
"$vigen" generate "$spec" -q -o /dev/stdout | grep -q 'name = "gauss_legendre_s1"' || fail "-o /dev/stdout into a pipe"

# emit creates its output directory
"$vigen" emit "$src/tests/data/emit/verlet.lua" --name verlet -q -o newdir/ && [ -f newdir/verlet.c ] && [ -f newdir/verlet.h ] ||
  fail "emit -o into a missing directory"

# write errors on files are failures: a full device, a directory without
# write permission (when not running as root, who may write anyway)
if [ -w /dev/full ]; then
  "$vigen" generate "$spec" -q -o /dev/full 2>err.txt
  [ $? = 3 ] && grep -q "cannot write /dev/full: No space left on device" err.txt ||
    fail "generate -o /dev/full: $(cat err.txt)"
  "$vigen" show "$spec" --format lua >/dev/full 2>err.txt
  [ $? = 3 ] && grep -q "cannot write the standard output" err.txt || fail "show >/dev/full: $(cat err.txt)"
fi
mkdir locked && chmod 555 locked
if ! touch locked/probe 2>/dev/null; then
  "$vigen" emit "$src/tests/data/emit/verlet.lua" --name verlet -q -o locked 2>err.txt
  [ $? = 3 ] && grep -q "temporary file next to locked/verlet" err.txt || fail "emit into a read-only directory: $(cat err.txt)"
  [ -z "$(ls -A locked)" ] || fail "emit into a read-only directory left $(ls -A locked)"
fi
chmod 755 locked

leftovers=$(ls | grep -c '\.tmp\.' || true)
[ "$leftovers" = 0 ] || fail "temporary files left: $(ls)"

# expect FILE PHRASE: show and check refuse FILE with status 2 and a message naming it
expect() {
  local f=$1 phrase=$2
  for cmd in show check; do
    timeout 20 "$vigen" "$cmd" "$bad/$f" >out.txt 2>err.txt
    local st=$?
    [ $st = 2 ] || { fail "$cmd $f: exit status $st, expected 2"; cat err.txt out.txt | head -5; continue; }
    grep -q "$f" err.txt out.txt || fail "$cmd $f: the message does not name the file"
    grep -qi -- "$phrase" err.txt out.txt || { fail "$cmd $f: message lacks '$phrase'"; cat err.txt out.txt | head -5; }
  done
}
expect metatable_top.lua      "plain table"
expect metatable_len.lua      "plain list"
expect short_row.lua          "A\[2\]"
expect float_entry.lua        "c\[1\] is the Lua float"
expect bad_expression.lua     "cosh"
expect unknown_field.lua      "unknown field 'AT'; did you mean 'At'?"
expect missing_A.lua          "'A' is missing"
expect division_by_zero.lua   "A\[1\]\[1\]"
expect spec_without_nodes.lua "nodes is missing"
expect no_kind.lua            "s, c, A and b (a tableau file), name, nodes and basis (a spec), splitting"
expect not_a_table.lua        "returns a string"

[ $failures -gt 0 ] && { echo "$failures failure(s)"; exit 1; }
echo ok
