#!/bin/sh
# retro render --no-skip and --stats (docs/SKIPPING.md): the same image either way, and counts
# that add up: as many samples paint with skipping as without, fewer are evaluated.
set -u
retro=$1
. tests/lib/cli_test.sh
map=maps/test/alpine-200
args="-s 160x120 -d 400 -p 100,100 -a 30 -o"

"$retro" render $map $args "$tmp/skip.ppm" --stats >"$tmp/on.txt" || fail "render --stats"
"$retro" render $map --no-skip $args "$tmp/noskip.ppm" --stats >"$tmp/off.txt" || fail "render --no-skip --stats"
"$retro" render $map -k naive $args "$tmp/naive.ppm" || fail "render naive"
cmp -s "$tmp/skip.ppm" "$tmp/noskip.ppm" || fail "--no-skip changed the image"
cmp -s "$tmp/skip.ppm" "$tmp/naive.ppm" || fail "the skipping frame differs from naive"
grep -q '^samples: 63840 (W x (D-1)), skipping on$' "$tmp/on.txt" || fail "--stats: $(head -n 1 "$tmp/on.txt")"
grep -q 'skipping off$' "$tmp/off.txt" || fail "--no-skip --stats: $(head -n 1 "$tmp/off.txt")"
num() { sed -n "s/^$1: \([0-9]*\).*/\1/p" "$2"; }
[ "$(num painting "$tmp/on.txt")" = "$(num painting "$tmp/off.txt")" ] || fail "painting counts differ"
on=$(num evaluated "$tmp/on.txt"); off=$(num evaluated "$tmp/off.txt")
[ -n "$on" ] && [ -n "$off" ] && [ "$on" -lt "$off" ] || fail "evaluated: $on with skipping, $off without"
# the ideal bounds' lines (docs/studies/SKIPPING_LIMITS.md, "How far a max bound can go"): with
# skipping only, and evaluating no more than the frame's samples
grep -q '^ideal max bound evaluates: [0-9.]*% with blocks down to 4 cells, [0-9.]*% with blocks down to 2 cells$' \
    "$tmp/on.txt" || fail "--stats: no ideal bound line"
! grep -q '^ideal' "$tmp/off.txt" || fail "--no-skip --stats printed an ideal bound"
ideal=$(sed -n 's/^ideal max bound evaluates: \([0-9.]*\)%.*/\1/p' "$tmp/on.txt")
awk -v a="$ideal" 'BEGIN { exit !(a > 0 && a <= 100) }' || fail "ideal share '$ideal'"
# and the plane bound's ("Other bounds at the same granularity"), for plain samples only
grep -q '^ideal plane bound evaluates: [0-9.]*% with blocks down to 4 cells, [0-9.]*% with blocks down to 2 cells$' \
    "$tmp/on.txt" || fail "--stats: no ideal plane bound line"
plane=$(sed -n 's/^ideal plane bound evaluates: \([0-9.]*\)%.*/\1/p' "$tmp/on.txt")
awk -v a="$plane" 'BEGIN { exit !(a > 0 && a <= 100) }' || fail "ideal plane share '$plane'"
# and the oracle's, which skips exactly the runs none of whose samples paints: no more than the max
grep -q '^ideal oracle bound evaluates: [0-9.]*% with blocks down to 4 cells, [0-9.]*% with blocks down to 2 cells$' \
    "$tmp/on.txt" || fail "--stats: no oracle line"
oracle=$(sed -n 's/^ideal oracle bound evaluates: \([0-9.]*\)%.*/\1/p' "$tmp/on.txt")
awk -v o="$oracle" -v a="$ideal" 'BEGIN { exit !(o > 0 && o <= a) }' || fail "oracle share '$oracle', max '$ideal'"
# the walk given one part of the ideal walk at a time ("Window or schedule"): with skipping only
pat="^the column walk evaluates, with the run's own box: [0-9.]*% ([0-9]* windows), one probe per sample: [0-9.]*% ([0-9]* windows), unaligned windows: [0-9.]*% ([0-9]* windows), unaligned windows and one probe per sample: [0-9.]*% ([0-9]* windows)\$"
grep -q "$pat" "$tmp/on.txt" || fail "--stats: no column walk parts line"
! grep -q '^the column walk' "$tmp/off.txt" || fail "--no-skip --stats printed the column walk's parts"
# lanes walking alone (docs/studies/SKIPPING_LIMITS.md, "How far a max bound can go"): 16 x each
# group's busiest column of the walk --columns writes, as a share of the frame's samples, and never
# below the column walk's own share (a group's busiest column evaluates at least its mean)
"$retro" render $map $args "$tmp/cols.ppm" --columns "$tmp/cols.csv" || fail "render --columns"
alone=$(sed -n 's/^lanes walking alone, 16 to a group: \([0-9.]*\)% (each group as many steps as its busiest column)$/\1/p' \
    "$tmp/on.txt")
[ -n "$alone" ] || fail "--stats: no lanes walking alone line"
want=$(awk -F, 'NR > 1 { g = int($1 / 16); if ($3 > m[g]) m[g] = $3; n[g]++; all += $2 }
    END { for (g in m) s += n[g] * m[g]; printf "%.2f", 100 * s / all }' "$tmp/cols.csv")
[ "$alone" = "$want" ] || fail "lanes walking alone: --stats says $alone%, the columns give $want%"
walk=$(sed -n 's/^evaluated: [0-9]* (\([0-9.]*\)%)$/\1/p' "$tmp/on.txt")
awk -v a="$alone" -v w="$walk" 'BEGIN { exit !(a >= w && a <= 100) }' || fail "lanes alone $alone%, column walk $walk%"
! grep -q '^lanes walking alone' "$tmp/off.txt" || fail "--no-skip --stats printed lanes walking alone"
printf '[scene]\nmap = %s\n[bilinear]\nenabled = true\n' "$(pwd)/$map" >"$tmp/bil.scene"
"$retro" render "$tmp/bil.scene" $args "$tmp/bil.ppm" --stats >"$tmp/bil.txt" || fail "render bilinear --stats"
grep -q '^ideal max bound' "$tmp/bil.txt" || fail "bilinear --stats: no ideal max bound line"
! grep -q '^ideal plane' "$tmp/bil.txt" || fail "bilinear --stats printed an ideal plane bound"
grep -q '^ideal oracle' "$tmp/bil.txt" || fail "bilinear --stats: no oracle line"
# mode course skips in the ybuffer strip too (skip_course.h): --stats says so and counts its probes
"$retro" render $map -m course $args "$tmp/c.ppm" --stats >"$tmp/con.txt" || fail "render -m course --stats"
"$retro" render $map -m course --no-skip $args "$tmp/cn.ppm" --stats >"$tmp/coff.txt" || fail "course --no-skip --stats"
cmp -s "$tmp/c.ppm" "$tmp/cn.ppm" || fail "mode course: --no-skip changed the image"
grep -q 'skipping on$' "$tmp/con.txt" || fail "course --stats: $(head -n 1 "$tmp/con.txt")"
grep -q 'skipping off$' "$tmp/coff.txt" || fail "course --no-skip --stats: $(head -n 1 "$tmp/coff.txt")"
grep -q '^probes: [1-9][0-9]*, pyramid windows read: [1-9]' "$tmp/con.txt" || fail "course --stats: no probes counted"
grep -q '^probes: 0, pyramid windows read: 0$' "$tmp/coff.txt" || fail "course --no-skip --stats counted probes"
on=$(num evaluated "$tmp/con.txt"); off=$(num evaluated "$tmp/coff.txt")
[ -n "$on" ] && [ -n "$off" ] && [ "$on" -lt "$off" ] || fail "course evaluated: $on with skipping, $off without"
# modes truth and fixed skip in the ybuffer strip with their own probe (skip_wide.h)
for m in truth fixed; do
  "$retro" render $map -m $m $args "$tmp/w.ppm" --stats >"$tmp/won.txt" || fail "render -m $m --stats"
  "$retro" render $map -m $m --no-skip $args "$tmp/wn.ppm" --stats >"$tmp/woff.txt" || fail "$m --no-skip --stats"
  "$retro" render $map -m $m -k naive $args "$tmp/wnaive.ppm" || fail "render -m $m naive"
  cmp -s "$tmp/w.ppm" "$tmp/wnaive.ppm" || fail "mode $m: the skipping frame differs from naive"
  cmp -s "$tmp/w.ppm" "$tmp/wn.ppm" || fail "mode $m: --no-skip changed the image"
  grep -q 'skipping on$' "$tmp/won.txt" || fail "$m --stats: $(head -n 1 "$tmp/won.txt")"
  grep -q '^probes: [1-9][0-9]*, pyramid windows read: [1-9]' "$tmp/won.txt" || fail "$m --stats: no probes counted"
  grep -q '^probes: 0, pyramid windows read: 0$' "$tmp/woff.txt" || fail "$m --no-skip --stats counted probes"
  [ "$(num painting "$tmp/won.txt")" = "$(num painting "$tmp/woff.txt")" ] || fail "$m: painting counts differ"
  on=$(num evaluated "$tmp/won.txt"); off=$(num evaluated "$tmp/woff.txt")
  [ -n "$on" ] && [ -n "$off" ] && [ "$on" -lt "$off" ] || fail "$m evaluated: $on with skipping, $off without"
done
# no stats and no output file when the input is bad
"$retro" render $map --stats -d 12x -o "$tmp/bad.ppm" >"$tmp/bad.txt" 2>/dev/null
[ $? -eq 2 ] && [ ! -e "$tmp/bad.ppm" ] && [ ! -s "$tmp/bad.txt" ] || fail "bad input with --stats"
echo "skipping cli: $fails failures"
[ "$fails" -eq 0 ]
