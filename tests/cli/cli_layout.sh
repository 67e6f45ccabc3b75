#!/usr/bin/env bash
# cli_layout.sh VIGEN SRCDIR — the shape of the source tree:
#   (a) no file in src/, cli/ or include/ is longer than 1,200 lines;
#   (b) the modules src/<module>/ include each other without a cycle (the
#       edges are the `#include "<module>/..."` lines of their .c, .h and .def
#       files; a module including itself is no edge);
#   (c) cli/ includes, among quoted includes, only public "vigen/..." headers,
#       the headers of the support library ("support/...", not installed)
#       and its own files;
#   (d) the public headers include/vigen/ include, among quoted includes, only
#       "vigen/..." headers;
#   (e) no two source files (.c, .h, .def) of src/, cli/, include/ and
#       runtime/ share a name, so that a name says which file it is;
#   (f) every function declared in a public header (include/vigen/*.h and
#       runtime/include/vigen/*.h, inside extern "C" too) has a
#       comment: at the end of its line, or a comment block right above it or
#       above the declarations it is grouped with (no blank line between);
#   (g) vigen.h includes every public header, and only those;
#   (h) a private header of a module (NAME_internal.h) is included only by
#       the files of its own folder (and by the unit tests, which test the
#       module from inside).
# One line per violation; exit status 1 if there is any.  VIGEN is unused
# (the tree is what is tested) and taken like every cli test's.
set -u
src=$2
cd "$src" || exit 2
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# quoted_includes FILE...: "file:line:target" for every #include "target"
quoted_includes() {
  awk '{ if (match($0, /^[ \t]*#[ \t]*include[ \t]*"[^"]*"/)) {
           s = substr($0, RSTART, RLENGTH); sub(/^[^"]*"/, "", s); sub(/"$/, "", s)
           print FILENAME ":" FNR ":" s } }' "$@"
}

# (a) file lengths
max_lines=1200
while IFS= read -r f; do
  n=$(wc -l <"$f")
  [ "$n" -gt "$max_lines" ] && fail "$f has $n lines (at most $max_lines)"
done < <(find src cli include -type f | sort)

# (b) the module include graph
modules=$(find src -mindepth 1 -maxdepth 1 -type d -printf '%f\n' | sort)
is_module() { printf '%s\n' $modules | grep -qx -- "$1"; }
edges=$(mktemp)
trap 'rm -f "$edges"' EXIT
for m in $modules; do
  files=$(find "src/$m" -maxdepth 1 -type f \( -name '*.c' -o -name '*.h' -o -name '*.def' \) | sort)
  [ -n "$files" ] || continue
  quoted_includes $files | while IFS=: read -r file line target; do
    case $target in */*) ;; *) continue ;; esac
    to=${target%%/*}
    [ "$to" != "$m" ] && is_module "$to" && echo "$m $to $file:$line"
  done
done >"$edges"
if ! loop=$(cut -d' ' -f1,2 "$edges" | sort -u | tsort 2>&1 >/dev/null); then
  fail "the modules include each other in a cycle:"
  # tsort names the modules of the loop; show the includes between them
  members=$(printf '%s\n' "$loop" | grep -v 'input contains a loop' | sed 's/^tsort: //')
  while read -r from to where; do
    printf '%s\n' $members | grep -qx -- "$from" && printf '%s\n' $members | grep -qx -- "$to" &&
      echo "  $from -> $to ($where)"
  done <"$edges"
fi

# (c) the command line sees the public headers and the support library only
while IFS=: read -r file line target; do
  case $target in
    vigen/*) ;;
    support/*) [ -f "src/$target" ] || fail "$file:$line includes \"$target\", which src/support/ does not have" ;;
    */*) fail "$file:$line includes \"$target\"; cli/ may include only public \"vigen/...\" and \"support/...\" headers" ;;
    *) [ -f "cli/$target" ] ||
         fail "$file:$line includes \"$target\"; cli/ may include only public \"vigen/...\" and \"support/...\" headers and its own files" ;;
  esac
done < <(quoted_includes $(find cli -type f | sort))

# (d) the public headers stand on each other only
while IFS=: read -r file line target; do
  case $target in
    vigen/*) ;;
    *) fail "$file:$line includes \"$target\"; a public header may include only \"vigen/...\" headers" ;;
  esac
done < <(quoted_includes $(find include/vigen -type f | sort))

# (e) one file per name
while read -r name; do
  fail "several source files are called $name: $(find src cli include runtime -type f -name "$name" | sort | tr '\n' ' ')"
done < <(find src cli include runtime -type f \( -name '*.c' -o -name '*.h' -o -name '*.def' \) -printf '%f\n' | sort | uniq -d)

# (f) the public functions documented where they are declared, in the
# installed headers of libvigen and of the runtime (undocumented_allowed:
# headers exempt, none today)
undocumented_allowed=''
while IFS= read -r hit; do
  case " $undocumented_allowed " in *" ${hit%%:*} "*) continue ;; esac
  fail "${hit}: a public function without a comment right above it (say what it does, takes and returns)"
done < <(awk '
# the public functions of a header without a comment: prints "file:line: name"
FNR == 1 { depth = 0; incomment = 0; delete text }
{
  line = $0; text[FNR] = line
  # track comments and braces (comments removed from the copy we scan)
  scan = line; out = ""
  while (length(scan) > 0) {
    if (incomment) { p = index(scan, "*/"); if (p == 0) { scan = "" } else { scan = substr(scan, p + 2); incomment = 0 } }
    else { p = index(scan, "/*"); if (p == 0) { out = out scan; scan = "" } else { out = out substr(scan, 1, p - 1); scan = substr(scan, p + 2); incomment = 1 } }
  }
  code = out
  # a declaration: "type vigen_name(" or, repeated per real type, "type VIGEN_SFX(vigen_name)("
  plain = code ~ /^[A-Za-z_][A-Za-z0-9_ \t\*]*[ \t\*]vigen_[A-Za-z0-9_]+[ \t]*\(/
  typed = code ~ /^[A-Za-z_][A-Za-z0-9_ \t\*()]*[ \t\*]VIGEN_SFX\(vigen_[A-Za-z0-9_]+\)[ \t]*\(/
  if (depth == 0 && (plain || typed) && code !~ /^[ \t]*(typedef|return|#|static)/) {
    name = code
    if (typed) { sub(/^.*VIGEN_SFX\(/, "", name); sub(/\).*/, "", name) }
    else { sub(/[ \t]*\(.*/, "", name); sub(/.*[ \t\*]/, "", name) }
    documented = (line ~ /\/\*.*\*\/[ \t]*$/)   # a comment at the end of the line
    for (k = FNR - 1; !documented && k >= 1; k--) {
      if (text[k] ~ /\*\/[ \t]*$/) documented = 1
      else if (text[k] ~ /^[ \t]*$/ || text[k] ~ /[{}]/) break
    }
    if (!documented) print FILENAME ":" FNR ": " name
  }
  # the braces of extern "C" { ... } (C++ linkage) enclose declarations, not a body
  if (code ~ /^[ \t]*extern[ \t]+"C"[ \t]*\{/) next
  if (code ~ /^[ \t]*\}[ \t]*$/ && depth == 0) next
  n = gsub(/\{/, "{", code); m = gsub(/\}/, "}", code); depth += n - m
}
' include/vigen/*.h runtime/include/vigen/*.h)

# (g) vigen.h includes every public header
for h in include/vigen/*.h; do
  name=${h#include/}
  [ "$name" = vigen/vigen.h ] && continue
  grep -q "^#include \"$name\"" include/vigen/vigen.h || fail "include/vigen/vigen.h does not include \"$name\""
done
while IFS=: read -r file line target; do
  [ -f "include/$target" ] || fail "$file:$line includes \"$target\", which is not a public header"
done < <(quoted_includes include/vigen/vigen.h)

# (h) private headers stay in their folder
while IFS=: read -r file line target; do
  case $target in *_internal.h) ;; *) continue ;; esac
  dir=$(dirname "$file")
  [ -f "$dir/$(basename "$target")" ] && { [ "$target" = "$(basename "$target")" ] || [ "src/$target" = "$dir/$(basename "$target")" ] || [ "$target" = "${dir#*/}/$(basename "$target")" ]; } ||
    fail "$file:$line includes \"$target\", a private header of another folder"
done < <(quoted_includes $(find src cli runtime -type f \( -name '*.c' -o -name '*.h' \) | sort))

[ "$failures" -eq 0 ] || exit 1
echo "cli_layout: all checks passed"
