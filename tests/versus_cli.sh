#!/bin/sh
# retro render --time N --versus ARGS (docs/COMMANDS.md): the second configuration is the first
# with ARGS on top (a MAP or SCENE among them replacing the first's), both are timed in turn and
# named in their own lines, the ratio line's median
# lies between its quartiles, -o keeps the first's frame, and bad requests exit 2 with one line
# and write nothing. Timings are never checked: only what was timed and how it is reported.
set -u
retro=$1
. tests/lib/cli_test.sh
map=maps/test/alpine-200
frame="-s 32x24 -d 50 -p 100,100"
num='[0-9]+\.[0-9]+'

"$retro" render $map $frame -k ybuffer --time 3 --versus "--no-skip" >"$tmp/out" 2>"$tmp/err" ||
  fail "--versus --no-skip: $(cat "$tmp/err")"
[ "$(wc -l <"$tmp/out")" -eq 3 ] || fail "--versus printed $(wc -l <"$tmp/out") lines, not 3"
grep -Eq "^kernel ybuffer \(family voxel\), mode exact, 32x24, D 50: median $num ms, min $num ms per frame over 3 frames$" \
  "$tmp/out" || fail "first line: $(sed -n 1p "$tmp/out")"
grep -Eq "^versus: kernel ybuffer \(family voxel\), mode exact, 32x24, D 50, no skipping: median $num ms, min $num ms per frame over 3 frames$" \
  "$tmp/out" || fail "versus line: $(sed -n 2p "$tmp/out")"
line=$(grep '^versus / first: ' "$tmp/out")
printf '%s\n' "$line" |
  grep -Eq "^versus / first: $num \(median of 3 per-pair ratios, quartiles $num to $num; frames taken in turn\)$" ||
  fail "ratio line: $line"
printf '%s\n' "$line" | awk '{ m = $4; lo = $11; hi = $13 + 0; exit !(m > 0 && lo <= m && m <= hi) }' ||
  fail "the median ratio is not between its quartiles: $line"

# ARGS override the first configuration's options; the mesh family may be the other side
"$retro" render $map $frame -k ybuffer --time 2 --versus "-k naive -s 16x12 -d 20" >"$tmp/out" 2>"$tmp/err" ||
  fail "--versus -k naive: $(cat "$tmp/err")"
grep -Eq '^versus: kernel naive \(family voxel\), mode exact, 16x12, D 20: median' "$tmp/out" ||
  fail "-k naive -s 16x12 -d 20 not taken: $(sed -n 2p "$tmp/out")"
grep -Eq '^kernel ybuffer \(family voxel\), mode exact, 32x24, D 50: median' "$tmp/out" ||
  fail "ARGS changed the first configuration: $(sed -n 1p "$tmp/out")"
"$retro" render $map $frame -k ybuffer --time 2 --versus "-k mesh-zbuffer" >"$tmp/out" 2>"$tmp/err" ||
  fail "--versus -k mesh-zbuffer: $(cat "$tmp/err")"
grep -Eq '^versus: kernel mesh-zbuffer \(family mesh\), mode binary32, 32x24, D 50: median' "$tmp/out" ||
  fail "mesh versus line: $(sed -n 2p "$tmp/out")"

# a MAP or SCENE in ARGS replaces the first's: a scene's effects are named on its line only
printf '[scene]\nmap = %s/%s\n[bilinear]\n' "$(pwd)" "$map" >"$tmp/b.scene"
"$retro" render $map $frame --time 2 --versus "$tmp/b.scene" >"$tmp/out" 2>"$tmp/err" ||
  fail "--versus SCENE: $(cat "$tmp/err")"
grep -Eq '^versus: kernel [a-z0-9-]+ \(family voxel\), mode exact, 32x24, D 50, effects bilinear: median' "$tmp/out" ||
  fail "the scene's effects are not on the versus line: $(sed -n 2p "$tmp/out")"
! sed -n 1p "$tmp/out" | grep -q effects || fail "the first line names effects: $(sed -n 1p "$tmp/out")"
"$retro" render $map $frame --time 2 --versus "-k ybuffer maps/test/no-such-map" >/dev/null 2>"$tmp/err"
grep -q 'no-such-map' "$tmp/err" || fail "the MAP in ARGS was not the second's: $(cat "$tmp/err")"

# -o writes the first configuration's frame
"$retro" render $map $frame -k ybuffer -o "$tmp/alone.ppm" 2>/dev/null || fail "render -o"
"$retro" render $map $frame -k ybuffer --time 2 --versus "-k naive -d 20" -o "$tmp/v.ppm" >/dev/null 2>&1 ||
  fail "--versus with -o"
cmp -s "$tmp/alone.ppm" "$tmp/v.ppm" || fail "--versus -o did not write the first configuration's frame"

# two sets of workers on two threads each would slow each other: refused; one thread is fine, and
# so is omp against itself (libgomp's workers belong to the process)
"$retro" render $map $frame -k omp --threads 2 --time 2 --versus "-k pthreads --threads 1" >/dev/null 2>"$tmp/err" ||
  fail "omp beside pthreads on one thread: $(cat "$tmp/err")"
"$retro" render $map $frame -k omp --threads 2 --time 2 --versus "--no-skip" >/dev/null 2>"$tmp/err" ||
  fail "omp beside itself: $(cat "$tmp/err")"

# bad requests: exit 2, one line on stderr, nothing on stdout, no image
bad() {
  what=$1
  shift
  "$retro" render $map $frame -o "$tmp/bad.ppm" "$@" >"$tmp/bo" 2>"$tmp/be"
  rc=$?
  [ $rc -eq 2 ] || fail "$what: exit $rc, not 2"
  [ "$(wc -l <"$tmp/be")" -eq 1 ] || fail "$what: stderr is not one line: $(cat "$tmp/be")"
  [ ! -s "$tmp/bo" ] || fail "$what: printed $(cat "$tmp/bo")"
  [ ! -e "$tmp/bad.ppm" ] || fail "$what: wrote the image"
  rm -f "$tmp/bad.ppm"
}
bad "--versus without --time" --versus "--no-skip"
bad "--versus without ARGS" --time 2 --versus
bad "--versus ''" --time 2 --versus ""
bad "--versus of blanks" --time 2 --versus "   "
for w in -o --columns --stats --time --versus --isa --help -h; do
  bad "--versus '$w'" --time 2 --versus "$w x"
done
bad "--versus unknown kernel" --time 2 --versus "-k nosuch"
bad "--versus two maps" --time 2 --versus "maps/test/flat-64 maps/test/flat-1"
bad "--versus missing map" --time 2 --versus "maps/test/no-such-map"
bad "--versus bad value" --time 2 --versus "--threads 0"
bad "omp beside pthreads" -k omp --threads 2 --time 2 --versus "-k pthreads"
bad "pthreads beside itself" -k pthreads --threads 2 --time 2 --versus "--no-skip"

echo "versus cli: $fails failures"
[ "$fails" -eq 0 ]
