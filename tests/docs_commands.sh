#!/bin/sh
# docs/COMMANDS.md promises every command and option: each command `retro --help` lists has its
# own section, each option its --help names appears in that section (or in retro render's, for
# the commands that take render's options), each option of retro-bench in its section (not
# google-benchmark's own --benchmark_* flags), and each target `make help` lists in the file.
# A new option or target without its line in the docs fails here.
# usage: docs_commands.sh RETRO
set -u
retro=${1:?usage: docs_commands.sh RETRO}
doc=docs/COMMANDS.md
bench=$(dirname "$retro")/retro-bench
fail=0
n=0

# section TITLE_PREFIX: the lines from the heading that starts with it to the next heading of
# the same or a higher level
section() {
  awk -v want="$1" '
    index($0, want) == 1 { on = 1; split($0, h, " "); lvl = length(h[1]); next }
    on && /^#+ / { split($0, h, " "); if (length(h[1]) <= lvl) exit }
    on { print }' "$doc"
}

# options: the -x and --long-name tokens of a --help text, one per line (not a file name's
# "-diff.png" in its prose)
options() {
  grep -oE -- '(^|[][ |(])--?[a-zA-Z][a-zA-Z0-9_-]*([] =|)]|$)' |
    sed 's/^[][ |(]//; s/[] =|)]$//' |
    grep -v -- '^--benchmark_' | sort -u
}

check_options() { # NAME HELP_TEXT_FILE SECTION_TEXT_FILE
  for o in $(options <"$2"); do
    n=$((n + 1))
    if ! grep -q -- "\`$o\b\|\[$o\b\|[ (]$o[ =]" "$3"; then
      echo "FAIL: $1: option $o of --help is not in its section of $doc"
      fail=1
    fi
  done
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
section '### `retro render`' >"$tmp/render"
cmds=$("$retro" --help | awk '/^Commands:/ { on = 1; next } on && NF { print $1 }')
[ -n "$cmds" ] || { echo "FAIL: retro --help lists no commands"; exit 1; }
for c in $cmds; do
  section "### \`retro $c\`" >"$tmp/sec"
  if [ ! -s "$tmp/sec" ]; then
    echo "FAIL: retro $c has no section '### \`retro $c\`' in $doc"
    fail=1
    continue
  fi
  "$retro" "$c" --help >"$tmp/help" 2>&1
  if grep -q "retro render's" "$tmp/help"; then cat "$tmp/render" >>"$tmp/sec"; fi
  check_options "retro $c" "$tmp/help" "$tmp/sec"
done

if [ -x "$bench" ]; then
  section '## `retro-bench`' >"$tmp/sec"
  "$bench" --help >"$tmp/help" 2>&1
  check_options retro-bench "$tmp/help" "$tmp/sec"
else
  echo "FAIL: $bench not built"
  fail=1
fi

for t in $(make -s --no-print-directory help | awk '/^Variables/ { exit } /^[a-z]/ { print $1 }'); do
  n=$((n + 1))
  grep -q "make $t\b" "$doc" || { echo "FAIL: make $t (make help) is not in $doc"; fail=1; }
done

[ "$n" -gt 60 ] || { echo "FAIL: only $n options and targets found: is the --help format parsed?"; fail=1; }
[ "$fail" -eq 0 ] && echo "ok: docs/COMMANDS.md names the $n options and make targets of the programs' --help"
exit "$fail"
