#!/bin/sh
# The mesh family from the command line: retro kernels lists both families, retro render
# draws maps and scenes with mesh kernels in their modes, --stats gives the mesh counts,
# --time says what ran for kernels of both families, and bad requests exit 2 with one line.
set -u
retro=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
map=maps/test/ramp-64
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

"$retro" kernels >"$tmp/k"
grep -q '^# family mesh: reference mesh-zbuffer$' "$tmp/k" || fail "retro kernels: no mesh family line"
grep -q '^mesh-painter *mesh *binary32,binary64,int ' "$tmp/k" || fail "retro kernels: no mesh-painter row"
grep -q '^naive *voxel ' "$tmp/k" || fail "retro kernels: no voxel row"

for k in mesh-zbuffer mesh-painter; do
  for m in binary32 binary64 int; do
    "$retro" render "$map" -k $k -m $m -s 64x48 -d 100 -o "$tmp/$k-$m.ppm" 2>"$tmp/err" \
      || fail "render -k $k -m $m: $(cat "$tmp/err")"
    grep -q "kernel $k, mode $m, 64x48" "$tmp/err" || fail "render -k $k -m $m said: $(cat "$tmp/err")"
  done
done
# -m binary64 alone picks the mesh family's reference
"$retro" render "$map" -m binary64 -s 64x48 -d 100 -o "$tmp/b64.ppm" 2>"$tmp/err" || fail "render -m binary64"
cmp -s "$tmp/b64.ppm" "$tmp/mesh-zbuffer-binary64.ppm" || fail "-m binary64 is not mesh-zbuffer's image"

# A scene with mesh-only effects, and one the painter must refuse (water).
cat >"$tmp/m.scene" <<EOF2
[scene]
map = $(pwd)/$map
[camera]
x = 20
y = 30
height = 90
angle = 45
[screen]
width = 80
height = 60
distance = 120
[fog]
[gouraud]
[cull]
EOF2
"$retro" render "$tmp/m.scene" -k mesh-zbuffer -m int -o "$tmp/s.png" 2>"$tmp/err" || fail "mesh scene: $(cat "$tmp/err")"
"$retro" render "$tmp/m.scene" -k mesh-zbuffer --stats -o "$tmp/s2.png" >"$tmp/st" 2>/dev/null || fail "--stats"
for w in "triangles submitted:" "after culling:" "after clipping:" "fragments:"; do
  grep -q "^$w [1-9]" "$tmp/st" || fail "--stats lacks '$w': $(cat "$tmp/st")"
done
sub=$(awk '/^triangles submitted:/ {print $3}' "$tmp/st")
front=$(awk '/^after culling:/ {print $3}' "$tmp/st")
[ "$front" -lt "$sub" ] || fail "[cull] culled nothing: $front of $sub"

# --time: the kernel actually used, the mode, the scene's effects, median and minimum
"$retro" render "$tmp/m.scene" -k mesh-painter -m binary64 --time 3 >"$tmp/t" 2>"$tmp/err" || fail "--time mesh"
grep -Eq '^kernel mesh-painter \(family mesh\), mode binary64, 80x60, D 120, effects fog,gouraud,cull: median [0-9.]+ ms, min [0-9.]+ ms per frame over 3 frames$' "$tmp/t" \
  || fail "--time mesh said: $(cat "$tmp/t" "$tmp/err")"
"$retro" render "$map" -s 32x24 -d 50 --time 2 >"$tmp/t" 2>"$tmp/err" || fail "--time voxel"
grep -Eq '^kernel [a-z0-9-]+ \(family voxel\), mode exact, 32x24, D 50: median' "$tmp/t" || fail "--time voxel said: $(cat "$tmp/t")"
"$retro" render "$map" -s 32x24 -d 50 --time >"$tmp/t" 2>/dev/null && grep -q "over 50 frames" "$tmp/t" \
  || fail "--time without N is not 50 frames: $(cat "$tmp/t")"

expect_bad() { # DESCRIPTION WANT ARGS...
  what=$1 want=$2; shift 2
  rm -f "$tmp/out.png"
  "$retro" "$@" >/dev/null 2>"$tmp/err"
  rc=$?
  if [ "$rc" -ne 2 ] || [ "$(wc -l <"$tmp/err")" -ne 1 ] || [ -e "$tmp/out.png" ] || ! grep -q "$want" "$tmp/err"; then
    fail "$what: exit $rc: $(cat "$tmp/err")"
  fi
}
sed 's/^\[cull\]$/[water]/' "$tmp/m.scene" >"$tmp/w.scene"
expect_bad "painter with water" "kernel mesh-painter does not render water" render "$tmp/w.scene" -k mesh-painter -o "$tmp/out.png"
expect_bad "voxel mode on a mesh kernel" "has no mode 'exact'" render "$map" -k mesh-zbuffer -m exact -o "$tmp/out.png"
expect_bad "mesh mode on a voxel kernel" "has no mode 'int'" render "$map" -k naive -m int -o "$tmp/out.png"
expect_bad "unknown mode" "unknown mode" render "$map" -m float -o "$tmp/out.png"
printf '[texture]\n' >>"$tmp/m.scene"
expect_bad "texture and gouraud" "exclusive" render "$tmp/m.scene" -k mesh-zbuffer -o "$tmp/out.png"
expect_bad "voxel kernel with a mesh effect" "kernel naive does not render texture" render "$tmp/m.scene" -k naive -o "$tmp/out.png"
expect_bad "bad --time count" "frame count" render "$map" --time 0 -o "$tmp/out.png"
expect_bad "verify the family's reference" "mesh family's reference" verify -k mesh-zbuffer

[ $fails -eq 0 ] && echo "mesh_cli: all passed"
exit $((fails > 0))
