#!/bin/sh
# The retro CLI's contract: bad input gives one line on stderr, exit 2, and no output file.
set -u
retro=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
map=maps/test/ramp-64

expect_bad() { # DESCRIPTION ARGS...
  what=$1; shift
  out="$tmp/out.png"
  rm -f "$out"
  "$retro" "$@" 2>"$tmp/err" >/dev/null
  rc=$?
  lines=$(wc -l <"$tmp/err")
  if [ "$rc" -ne 2 ] || [ "$lines" -ne 1 ] || [ -e "$out" ] || ls "$tmp" | grep -q tmp; then
    echo "FAIL: $what: exit $rc, $lines stderr lines: $(cat "$tmp/err")"
    fails=$((fails + 1))
  fi
}

printf 'P5\n4 4\n255\n' >"$tmp/trunc.pgm"; printf 'P6\n4 4\n255\n' >"$tmp/trunc.ppm"
printf 'P5\n4 2\n255\n12345678' >"$tmp/rect.pgm"; printf 'P6\n4 2\n255\n' >"$tmp/rect.ppm"
printf 'P5\n2 2\n255\n1234' >"$tmp/mis.pgm"; printf 'P6\n3 3\n255\n123456789012345678901234567' >"$tmp/mis.ppm"
printf 'P5\n2 2\n15\n1234' >"$tmp/mv.pgm"; printf 'P6\n2 2\n255\n123456789012' >"$tmp/mv.ppm"

expect_bad "missing map" render "$tmp/none" -o "$tmp/out.png"
expect_bad "truncated map" render "$tmp/trunc" -o "$tmp/out.png"
expect_bad "non-square map" render "$tmp/rect" -o "$tmp/out.png"
expect_bad "size mismatch" render "$tmp/mis" -o "$tmp/out.png"
expect_bad "maxval" render "$tmp/mv" -o "$tmp/out.png"
expect_bad "absurd screen" render $map -s 100000x100000 -o "$tmp/out.png"
expect_bad "zero screen" render $map -s 0x10 -o "$tmp/out.png"
expect_bad "negative screen" render $map -s -3x10 -o "$tmp/out.png"
expect_bad "bad distance" render $map -d 12x -o "$tmp/out.png"
expect_bad "nan position" render $map -p nan,3 -o "$tmp/out.png"
expect_bad "inf position" render $map -p 1,inf -o "$tmp/out.png"
expect_bad "unknown kernel" render $map -k warp -o "$tmp/out.png"
expect_bad "unknown mode" render $map -m fast -o "$tmp/out.png"
expect_bad "unknown isa" render $map --isa mmx -o "$tmp/out.png"
expect_bad "unwritable output" render $map -o "$tmp/no/such/dir/out.png"
expect_bad "unknown extension" render $map -o "$tmp/out.gif"
expect_bad "no output" render $map
expect_bad "unknown command" frobnicate
expect_bad "unknown genmap style" genmap volcano -o "$tmp/v"
expect_bad "course on a 1x1 map" render maps/test/flat-1 -m course -o "$tmp/out.png"

for cmd in "" render kernels verify genmap accuracy; do
  "$retro" $cmd --help >/dev/null 2>&1 || { echo "FAIL: retro $cmd --help"; fails=$((fails + 1)); }
done
"$retro" render $map -s 64x48 -o "$tmp/ok.png" && [ -s "$tmp/ok.png" ] || { echo "FAIL: render to png"; fails=$((fails + 1)); }
"$retro" render $map -s 64x48 -m course -k naive -o "$tmp/ok.ppm" && head -c 2 "$tmp/ok.ppm" | grep -q P6 ||
  { echo "FAIL: render to ppm"; fails=$((fails + 1)); }
"$retro" kernels | awk '{print $1}' | grep -qx naive || { echo "FAIL: kernels lists naive first column"; fails=$((fails + 1)); }
# This seed's first pose lies on the 1024 maps' edge (y rounds to 1024): make asan sees any
# read past the height map.
"$retro" accuracy --poses 1 --seed 8732044540224338163 -o "$tmp/acc.md" --chart "$tmp/acc.svg" 2>/dev/null &&
  [ "$(grep -c '^| [a-z]' "$tmp/acc.md")" -ge 8 ] && grep -q '<svg' "$tmp/acc.svg" ||
  { echo "FAIL: retro accuracy table and chart"; fails=$((fails + 1)); }
# The chart names each variant of the table once, beside its point (accuracy_metrics.c places
# the labels itself).
awk -F'|' '/^\| variant/ { t = 1; next } t && /^\|--/ { next } t && /^\| / { gsub(/^ +| +$/, "", $2); print $2; next } t { exit }' \
  "$tmp/acc.md" >"$tmp/acc.labels"
[ "$(wc -l <"$tmp/acc.labels")" -ge 8 ] || { echo "FAIL: retro accuracy: no variants read from the table"; fails=$((fails + 1)); }
while IFS= read -r label; do
  [ "$(grep -c "<text>$label</text>" "$tmp/acc.svg")" -eq 1 ] ||
    { echo "FAIL: retro accuracy: the chart does not name '$label' once"; fails=$((fails + 1)); }
done <"$tmp/acc.labels"
# binary32 and binary64 disagree only at cell and row boundaries: a large error means a frame
# was rendered from the wrong map (a stale cache across scenes).
exact_err=$(awk -F'|' '/^\| variant/ { for (i = 1; i <= NF; i++) if ($i ~ /pixels differ/) col = i }
  col && $2 ~ /^ exact / { gsub(/[ %]/, "", $col); print $col }' "$tmp/acc.md")
awk -v e="$exact_err" 'BEGIN { exit !(e != "" && e + 0 < 1) }' ||
  { echo "FAIL: retro accuracy: exact differs from truth in $exact_err% of pixels"; fails=$((fails + 1)); }
# Across families: every voxel variant and mesh mode against the mesh in binary64, whose own row
# is exactly 0; its chart beside the first, the picture pair beside the table.
[ "$(grep -c '^| voxel | ' "$tmp/acc.md")" -ge 8 ] && [ "$(grep -c '^| mesh | mesh ' "$tmp/acc.md")" -eq 3 ] &&
  grep -q '^| mesh | mesh binary64 | .* | 0\.000% | 0\.00% | 0\.000 | 0 | ∞ |$' "$tmp/acc.md" &&
  grep -q '<svg' "$tmp/accuracy-families.svg" ||
  { echo "FAIL: retro accuracy: no families table or chart"; fails=$((fails + 1)); }
for f in voxel mesh diff; do
  [ -s "$tmp/accuracy-pair-$f.png" ] || { echo "FAIL: retro accuracy: no accuracy-pair-$f.png"; fails=$((fails + 1)); }
done
expect_bad "unknown render mode" render $map -m approximate -o "$tmp/out.png"
expect_bad "bad lod" render $map -m lod --lod -1 -o "$tmp/out.png"
# An option given last without a value: an unknown one is called unknown (it was once said to
# need a value), a known one is said to need one.
for c in render fly view genmap accuracy; do
  pos=$map
  [ $c = accuracy ] && pos="--seed 1" # it takes no MAP
  expect_bad "retro $c with an unknown option last" $c $pos --no-such-option
  grep -q "unknown option '--no-such-option'" "$tmp/err" ||
    { echo "FAIL: retro $c: an unknown option given last: $(cat "$tmp/err")"; fails=$((fails + 1)); }
done
for c in "render -s" "render --columns" "fly --frames" "view --keys" "genmap --size" "accuracy --poses"; do
  pos=$map
  [ "${c% *}" = accuracy ] && pos="--seed 1"
  expect_bad "retro $c without its value" ${c% *} $pos ${c#* }
  grep -q "option ${c#* } needs a value" "$tmp/err" ||
    { echo "FAIL: retro $c without its value: $(cat "$tmp/err")"; fails=$((fails + 1)); }
done
echo "cli: $fails failures"
[ "$fails" -eq 0 ]
