#!/bin/sh
# retro accuracy hands its chart path to gnuplot inside a script: a quote in the name must stay
# part of the name (never end the string and run a command), and a control character, which
# would end the script's line, is refused before any work with one line and exit 2, as is a
# maps folder without the maps.
set -u
retro=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
maps=$(pwd)/maps
fails=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1

if "$retro" accuracy --poses 1 --maps "$maps" -o "a'b.md" --chart "it's; system('touch pwned').svg" \
    >out 2>err; then
  [ -e pwned ] && { echo "FAIL: a quote in the chart path ran a gnuplot command"; fails=$((fails + 1)); }
  [ -s "it's; system('touch pwned').svg" ] || { echo "FAIL: the chart was not written under its own name"; fails=$((fails + 1)); }
  [ -s "a'b.md" ] || { echo "FAIL: the report was not written under its own name"; fails=$((fails + 1)); }
else
  echo "FAIL: accuracy with quoted paths exited non-zero: $(tail -n 1 err)"; fails=$((fails + 1))
fi

for opt in -o --chart; do
  "$retro" accuracy --poses 1 --maps "$maps" "$opt" "$(printf 'bad\nname')" >out 2>err
  rc=$?
  if [ "$rc" -ne 2 ] || [ "$(wc -l <err)" -ne 1 ] || ls | grep -q '^bad'; then
    echo "FAIL: $opt with a newline: exit $rc, stderr '$(cat err)'"; fails=$((fails + 1))
  fi
done

# A maps folder without the generated maps: an error naming the fix, exit 2, no report or chart.
mkdir nomaps
"$retro" accuracy --poses 1 --maps "$tmp/nomaps" -o none.md --chart none.svg >out 2>err
rc=$?
if [ "$rc" -ne 2 ] || ! tail -n 1 err | grep -q "alpine.*run make maps" || ls | grep -q '^none'; then
  echo "FAIL: accuracy without maps: exit $rc, stderr '$(cat err)'"; fails=$((fails + 1))
fi

[ "$fails" -eq 0 ] && echo "accuracy paths: ok" || echo "accuracy paths: $fails failure(s)"
[ "$fails" -eq 0 ]
