#!/bin/sh
# Scenes on the command line: retro render SCENE, retro fly, and the maps scenes need.
set -u
retro=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
here=$(pwd)
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# WIDTH HEIGHT of a PNG, from its IHDR.
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{print $3 * 256 + $4, $7 * 256 + $8}'; }

expect_bad() { # DESCRIPTION NEEDLE ARGS... (the output, if any, is $tmp/out.png)
  what=$1 needle=$2; shift 2
  rm -f "$tmp/out.png"
  "$retro" "$@" 2>"$tmp/err" >/dev/null
  rc=$?
  lines=$(wc -l <"$tmp/err")
  if [ "$rc" -ne 2 ] || [ "$lines" -ne 1 ] || [ -e "$tmp/out.png" ] || ! grep -qF -- "$needle" "$tmp/err"; then
    fail "$what: exit $rc, $lines stderr lines, want '$needle': $(cat "$tmp/err")"
  fi
}

cat >"$tmp/ok.scene" <<EOF
[scene]
map = $here/maps/test/alpine-200
sky = 87b5e8
[camera]
x = 100
y = 150
height = 190
angle = 90
[screen]
width = 80
height = 60
distance = 300
[fog]
start = 50
end = 250
[water]
level = 40
EOF
cat >"$tmp/path.scene" <<EOF
[scene]
map = $here/maps/test/alpine-200
[screen]
width = 40
height = 30
[path]
frames = 4
key = 0 100 150 190 90
key = 1 120 100 200 60
EOF
cat >"$tmp/bad.scene" <<EOF
[scene]
map = $here/maps/test/alpine-200
[camera]
angel = 30
EOF
# Morph keyframes must match the map's size: flat-64 does, checker-2 does not.
cat >"$tmp/morph.scene" <<EOF
[scene]
map = $here/maps/test/ramp-64
[morph]
map = $here/maps/test/flat-64
t = 0.5
EOF
sed "s|test/flat-64|test/checker-2|" "$tmp/morph.scene" >"$tmp/morph-size.scene"
sed "s|test/flat-64|test/none|" "$tmp/morph.scene" >"$tmp/morph-none.scene"
printf '[scene]\nmap = alpine-0\n' >"$tmp/missing-map.scene"

# A scene renders with the file's screen, and options override the file.
"$retro" render "$tmp/ok.scene" -o "$tmp/ok.png" && [ "$(png_size "$tmp/ok.png")" = "80 60" ] ||
  fail "render a scene at its [screen] size: $(png_size "$tmp/ok.png" 2>&1)"
"$retro" render "$tmp/ok.scene" -s 64x48 -o "$tmp/s.png" && [ "$(png_size "$tmp/s.png")" = "64 48" ] ||
  fail "-s 64x48 overrides the scene's screen"
"$retro" render "$tmp/ok.scene" -k naive -o "$tmp/naive.png" && "$retro" render "$tmp/ok.scene" -o "$tmp/best.png" &&
  cmp -s "$tmp/naive.png" "$tmp/best.png" || fail "a scene with effects: the best kernel differs from naive"
"$retro" render "$tmp/ok.scene" -a 0 -o "$tmp/a0.png" && ! cmp -s "$tmp/a0.png" "$tmp/ok.png" ||
  fail "-a overrides the scene's camera"
"$retro" render "$tmp/morph.scene" -s 32x24 -o "$tmp/m.png" || fail "render a morph scene"
"$retro" render "$tmp/path.scene" -o "$tmp/p.png" && "$retro" fly "$tmp/path.scene" --frames 1 -o "$tmp/f%d.png" 2>/dev/null &&
  cmp -s "$tmp/p.png" "$tmp/f0.png" || fail "a scene with a path and no camera renders the path's start"

# The committed scenes and the maps they name (make maps).
for s in islands alpine canyon tide; do
  "$retro" render "maps/$s.scene" -s 64x48 -o "$tmp/$s.png" || fail "maps/$s.scene (run make maps)"
done

# A malformed scene: one line naming file:line and [section] key, exit 2, no output.
expect_bad "malformed scene" "$tmp/bad.scene:4: [camera] angel: unknown key" render "$tmp/bad.scene" -o "$tmp/out.png"
expect_bad "missing scene" "$tmp/none.scene: No such file or directory" render "$tmp/none.scene" -o "$tmp/out.png"
expect_bad "scene naming a missing map" "alpine-0.pgm" render "$tmp/missing-map.scene" -o "$tmp/out.png"
expect_bad "morph keyframe of another size" "is 2x2 but the map" render "$tmp/morph-size.scene" -o "$tmp/out.png"
expect_bad "missing morph keyframe" "test/none.pgm" render "$tmp/morph-none.scene" -o "$tmp/out.png"
expect_bad "effects in mode course" "effects need mode exact or lod" render "$tmp/ok.scene" -m course -o "$tmp/out.png"
expect_bad "fly: malformed scene" "bad.scene:4: [camera] angel" fly "$tmp/bad.scene" -o "$tmp/out%d.png"
expect_bad "fly: no such map" "maps/test/none" fly maps/test/none -o "$tmp/out%d.png"
expect_bad "fly: pattern without %d" "bad output pattern" fly "$tmp/path.scene" -o "$tmp/out.png"
expect_bad "fly: pattern with two %d" "bad output pattern" fly "$tmp/path.scene" -o "$tmp/%d-%d.png"
expect_bad "fly: bad frame count" "bad frame count" fly "$tmp/path.scene" --frames 0 -o "$tmp/out%d.png"

# retro fly: N frames, a progress line each, and one line saying which kernel and mode ran.
"$retro" fly "$tmp/path.scene" -o "$tmp/fly-%03d.png" 2>"$tmp/progress" || fail "retro fly"
[ "$(ls "$tmp" | grep -c '^fly-00[0-3]\.png$')" -eq 4 ] && [ ! -e "$tmp/fly-004.png" ] ||
  fail "retro fly writes the scene's 4 frames: $(ls "$tmp" | grep fly- | tr '\n' ' ')"
[ "$(grep -c '^retro fly: [0-9]/4 ' "$tmp/progress")" -eq 4 ] && [ "$(wc -l <"$tmp/progress")" -eq 5 ] &&
  grep -q '^retro fly: kernel .*, mode exact, ' "$tmp/progress" ||
  fail "one progress line per frame and one for the kernel: $(cat "$tmp/progress")"
cmp -s "$tmp/fly-000.png" "$tmp/fly-003.png" && fail "the path moves the camera"
"$retro" fly "$tmp/path.scene" --frames 7 -s 16x12 -o "$tmp/n%d.png" 2>/dev/null &&
  [ -e "$tmp/n6.png" ] && [ ! -e "$tmp/n7.png" ] && [ "$(png_size "$tmp/n3.png")" = "16 12" ] ||
  fail "retro fly --frames 7 -s 16x12"
"$retro" fly "$tmp/ok.scene" -o "$tmp/still-%d.png" 2>/dev/null && [ -e "$tmp/still-0.png" ] &&
  [ ! -e "$tmp/still-1.png" ] && cmp -s "$tmp/still-0.png" "$tmp/ok.png" || fail "retro fly without a path: one frame"

for cmd in render fly; do
  "$retro" $cmd --help | grep -q scene || fail "retro $cmd --help mentions scenes"
done

# Maps for the scenes: STYLE-unlit keeps the heights, --height-offset shifts and clamps them.
"$retro" genmap alpine --size 32 -o "$tmp/lit" && "$retro" genmap alpine-unlit --size 32 -o "$tmp/unlit" &&
  cmp -s "$tmp/lit.pgm" "$tmp/unlit.pgm" && ! cmp -s "$tmp/lit.ppm" "$tmp/unlit.ppm" ||
  fail "alpine-unlit: alpine's heights, other colours"
"$retro" genmap flat --size 2 --height-offset -24 -o "$tmp/low" &&
  [ "$(tail -c 4 "$tmp/low.pgm" | od -An -tu1 | tr -s ' ')" = " 26 26 26 26" ] || fail "--height-offset -24 on flat 50"
"$retro" genmap flat --size 2 --height-offset 255 -o "$tmp/high" &&
  [ "$(tail -c 4 "$tmp/high.pgm" | od -An -tu1 | tr -s ' ')" = " 255 255 255 255" ] || fail "--height-offset clamps at 255"
expect_bad "bad height offset" "bad height offset" genmap flat --height-offset 300 -o "$tmp/x"

echo "scene cli: $fails failures"
[ "$fails" -eq 0 ]
