#!/usr/bin/env bash
# cli_bytes.sh VIGEN SRCDIR — bytes from spec and tableau files are handled
# exactly: a string holding a NUL byte is refused (exit 2) with one line naming
# the file and the entry, never cut short at the NUL; control characters and
# bytes that are not UTF-8 never reach the terminal raw (no ESC byte in any
# message or text report); the JSON reports stay valid JSON whatever bytes a
# name holds.  The refused files are tests/data/bad_*/hostile_bytes_*.lua;
# the valid ones with hostile texts are written below (the files in
# bad_tableaux/ must all be refused: cli_help runs every command on them).
set -u
vigen=$1
src=$2
tab=$src/tests/data/bad_tableaux
spec=$src/tests/data/bad_specs
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
esc=$'\x1b'

# run STATUS ARGS...: runs vigen ARGS into $work/out and $work/err, checks the
# exit status and that neither holds a raw control byte (but newline in out)
run() {
  local want=$1
  shift
  "$vigen" "$@" >"$work/out" 2>"$work/err"
  local got=$?
  [ "$got" = "$want" ] || { fail "vigen $*: exit status $got, expected $want"; cat "$work/err"; }
  [ "$(grep -c "$esc" "$work/err")" = 0 ] || fail "vigen $*: a raw ESC byte on stderr: $(cat -v "$work/err")"
  [ "$(grep -c "$esc" "$work/out")" = 0 ] || fail "vigen $*: a raw ESC byte on stdout: $(head -3 "$work/out" | cat -v)"
  LC_ALL=C grep -q $'[\x01-\x08\x0b-\x1f\x7f]' "$work/err" &&
    fail "vigen $*: a raw control byte on stderr: $(cat -v "$work/err")"
  return 0
}

# refused "COMMAND [OPTIONS]" FILE PHRASE...: exit 2, one line on stderr
# naming the file and holding each phrase (fixed strings); no output file
refused() {
  local command=$1 file=$2
  shift 2
  # shellcheck disable=SC2086 # the command and its options are words
  run 2 $command "$file"
  local lines
  lines=$(wc -l <"$work/err")
  [ "$lines" = 1 ] || fail "vigen $command $(basename "$file"): $lines lines on stderr, expected one: $(cat -v "$work/err")"
  grep -qF -- "$(basename "$file"):" "$work/err" || fail "vigen $command $(basename "$file"): the message does not name the file"
  for phrase in "$@"; do
    grep -qF -- "$phrase" "$work/err" || fail "vigen $command $(basename "$file"): the message lacks '$phrase': $(cat -v "$work/err")"
  done
}

# NUL bytes in tableau files: refused, naming the entry and the byte
refused show "$tab/hostile_bytes_nul_entry.lua" 'b[1] contains a NUL byte (\0 at byte 2); remove it'
refused check "$tab/hostile_bytes_nul_entry.lua" 'b[1] contains a NUL byte (\0 at byte 2)'
refused show "$tab/hostile_bytes_nul_matrix.lua" 'A[1][1] contains a NUL byte (\0 at byte 4)'
refused show "$tab/hostile_bytes_nul_name.lua" 'name contains a NUL byte (\0 at byte 6)'
refused show "$tab/hostile_bytes_nul_key.lua" "unknown field 'A\\0x'"
refused "emit --name nul -o $work/emitted" "$tab/hostile_bytes_nul_entry.lua" 'b[1] contains a NUL byte'
[ -e "$work/emitted" ] && fail "vigen emit wrote $(ls "$work/emitted") from a refused file"
refused "generate -o $work/generated.lua" "$spec/hostile_bytes_nul_family.lua" 'basis contains a NUL byte'
[ -e "$work/generated.lua" ] && fail "vigen generate wrote a tableau from a refused spec"
# ... and in spec files
refused generate "$spec/hostile_bytes_nul_node.lua" 'nodes[2] contains a NUL byte (\0 at byte 2); remove it'
refused generate "$spec/hostile_bytes_nul_basis.lua" 'basis[2] contains a NUL byte (\0 at byte 2)'
refused show "$spec/hostile_bytes_nul_name.lua" 'name contains a NUL byte (\0 at byte 5)'
refused generate "$spec/hostile_bytes_nul_family.lua" 'basis contains a NUL byte (\0 at byte 9)'
refused check "$spec/hostile_bytes_nul_nodes.lua" 'nodes contains a NUL byte (\0 at byte 15)'
refused generate "$spec/hostile_bytes_nul_exact.lua" 'exact()' 'byte' 'basis[2]'
# a key "name\0x" is not "name": warned about (escaped), and the spec's name stays "nul key"
run 0 show "$spec/hostile_bytes_nul_key.lua"
grep -qF "unknown field 'name\\0x' is ignored" "$work/err" || fail "spec key name\\0x: no warning: $(cat -v "$work/err")"
head -1 "$work/out" | grep -qx 'nul key: 2 stages' || fail "spec key name\\0x: $(head -1 "$work/out" | cat -v)"

# control characters echoed from a file: escaped, on one line
refused show "$tab/hostile_bytes_newline_entry.lua" 'b[1]: ' '"1\n+ junk("'
refused check "$tab/hostile_bytes_escape_entry.lua" 'b[1]: ' '\x1b[2J\x1b]0;pwned\x07'
refused generate "$spec/hostile_bytes_error.lua" '\x1b[31mboom\x1b[0m\nsecond line'

# a valid tableau and a valid spec whose texts hold terminal escape sequences
# (ESC, BEL, a C1 CSI), bytes that are not UTF-8 (a lone 0xff, an overlong
# "/", a truncated euro sign) and a right-to-left override: text, LaTeX and
# JSON reports
valid_tab=$work/hostile_bytes_escape.lua
valid_spec=$work/hostile_bytes_escape_spec.lua
cat >"$valid_tab" <<'EOF'
return {
  name = "\27[31mred\27[0m \xff\xfe \xc0\xaf \xc2\x9b2J \u{202E}txt.exe",
  description = "\27]0;title\7 desc \xe2\x82",
  source = "\27[2J\r\n\tsource",
  s = 1, c = { "1/2" }, A = { { "1/2" } }, b = { "1" },
}
EOF
cat >"$valid_spec" <<'EOF'
return {
  name = "\27[31mred\27[0m \xff \xc2\x9b2J",
  description = "\27]0;title\7 \xe2\x82",
  ["\27[5mblink"] = 1,
  nodes = { "0", "1" }, basis = "lagrange",
}
EOF
name_shown='\x1b[31mred\x1b[0m \xff\xfe \xc0\xaf \u009b2J \u202etxt.exe'
run 0 show "$valid_tab"
head -1 "$work/out" | grep -qxF "$name_shown: 1 stage" || fail "show text: name line $(head -1 "$work/out" | cat -v)"
grep -qxF '\x1b]0;title\x07 desc \xe2\x82' "$work/out" || fail "show text: description not escaped: $(cat -v "$work/out")"
grep -qxF 'source: \x1b[2J\r\n\tsource' "$work/out" || fail "show text: source not escaped: $(cat -v "$work/out")"
run 0 show "$valid_tab" --format latex
head -1 "$work/out" | grep -qxF "% $name_shown (vigen)" || fail "show latex: $(head -1 "$work/out" | cat -v)"
run 0 check "$valid_tab"
head -1 "$work/out" | grep -qF "($name_shown)" || fail "check text: $(head -1 "$work/out" | cat -v)"
run 0 show "$valid_spec" --digits 10
grep -qF "unknown field '\\x1b[5mblink' is ignored" "$work/err" || fail "spec warning: $(cat -v "$work/err")"
head -1 "$work/out" | grep -qxF '\x1b[31mred\x1b[0m \xff \u009b2J: 2 stages' || fail "show spec: $(head -1 "$work/out" | cat -v)"

# JSON: valid whatever the bytes, no raw control character, the name as the
# file holds it where it is UTF-8
json_ok() {
  python3 - "$1" "$2" <<'EOF' || fail "$3: $(head -c 300 "$1" | cat -v)"
import json, sys
raw = open(sys.argv[1], 'rb').read()
assert not any(b < 0x20 and b != 0x0a for b in raw), "raw control byte"
d = json.loads(raw.decode('utf-8'))
name = d['name'] if 'name' in d else d['tableau']['name']
assert name.startswith('\x1b[31mred\x1b[0m '), name
want = sys.argv[2].encode().decode('unicode_escape')
assert want in name, (want, name)
EOF
}
run 0 show "$valid_tab" --format json
json_ok "$work/out" '\u202etxt.exe' "show --format json"
run 0 check "$valid_tab" --json
json_ok "$work/out" '\u202etxt.exe' "check --json"
run 0 check "$valid_spec" --json
json_ok "$work/out" ' ' "check --json of a spec"

# a generator field with a newline: the tableau file vigen writes from it
# stays one comment line and reads back (it cannot carry Lua code of the
# author's choice into the rewritten file)
cat >"$work/gen.lua" <<'LUA'
return { name = "gen", s = 1, c = { "1/2" }, A = { { "1/2" } }, b = { "1" },
         generator = "x\nreturn { name = 'injected', s = 1, c = { '0' }, A = { { '0' } }, b = { '1' } } --" }
LUA
run 0 show "$work/gen.lua" --format lua
cp "$work/out" "$work/gen_out.lua"
run 0 show "$work/gen_out.lua" --format json
grep -q '"name": "gen"' "$work/out" || fail "the rewritten tableau file does not read back as itself: $(head -3 "$work/gen_out.lua")"

[ "$failures" -eq 0 ] || exit 1
echo "cli_bytes: all checks passed"
