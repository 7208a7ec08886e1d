#!/bin/sh
# What a newcomer meets first: retro --version; genmap's unknown style answered with the list
# of styles; render and fly saying which kernel and mode ran; fly taking a plain map (a default
# circuit) as well as a scene.
# usage: newcomer_cli.sh RETRO
set -u
retro=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
no() { echo "FAIL: $*"; fail=1; }
"$retro" --version | grep -qE '^retro [0-9]+\.[0-9]+\.[0-9]+$' || no "retro --version"
"$retro" --help | grep -q -- '--version' || no "retro --help does not mention --version"
"$retro" genmap nosuchstyle -o "$tmp/m" 2>"$tmp/err"
[ $? = 2 ] || no "genmap with an unknown style does not exit 2"
grep -q "unknown style 'nosuchstyle'; the styles are alpine, islands, canyon" "$tmp/err" || no "genmap does not list the styles: $(cat "$tmp/err")"
[ -e "$tmp/m.pgm" ] && no "genmap wrote a map for an unknown style"
"$retro" genmap flat --size 512 -o "$tmp/big" 2>"$tmp/err" || no "genmap flat 512"
grep -q "generating flat, 512x512" "$tmp/err" || no "genmap does not announce a long generation"
"$retro" render maps/test/alpine-200 -s 32x24 -d 50 -o "$tmp/r.ppm" 2>"$tmp/err" || no "render failed"
grep -qE '^retro render: kernel [a-z0-9-]+ \(the fastest here for the mode\), mode exact, 32x24, D 50$' "$tmp/err" ||
  no "render does not say which kernel and mode: $(cat "$tmp/err")"
"$retro" render maps/test/alpine-200 -k naive -m course -s 32x24 -d 50 -o "$tmp/r.ppm" 2>"$tmp/err" || no "render -k naive -m course"
grep -q '^retro render: kernel naive, mode course, 32x24, D 50$' "$tmp/err" || no "render -k naive -m course: $(cat "$tmp/err")"
"$retro" fly maps/test/alpine-200 --frames 3 -s 32x24 -d 50 -o "$tmp/f-%d.ppm" 2>"$tmp/err" || no "fly with a plain map failed: $(cat "$tmp/err")"
for i in 0 1 2; do [ -s "$tmp/f-$i.ppm" ] || no "fly with a map did not write frame $i"; done
grep -q '^retro fly: kernel ' "$tmp/err" || no "fly does not say which kernel ran"
cmp -s "$tmp/f-0.ppm" "$tmp/f-1.ppm" && no "the default circuit does not move"
[ "$fail" = 0 ] && echo "ok: --version, genmap's style list and progress, render and fly say what ran, fly flies a map"
exit $fail
