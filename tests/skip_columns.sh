#!/bin/sh
# retro render --columns (docs/SKIPPING.md): one CSV row per screen column whose counts add up
# to --stats' frame totals, with skipping and without, in modes exact and lod; the same samples
# paint in each column either way; bad input exits 2 and writes neither the CSV nor the image.
set -u
retro=$1
. tests/lib/cli_test.sh
map=maps/test/alpine-200
view="-s 160x120 -d 400 -p 100,100 -a 30"
num() { sed -n "s/^$1: \([0-9]*\).*/\1/p" "$2"; }
# column sums of fields 3..6 of a CSV: evaluated painting evaluated_noskip painting_noskip
sums() { awk -F, 'NR > 1 { e += $3; p += $4; en += $5; pn += $6 } END { print e, p, en, pn }' "$1"; }

for mode in exact lod; do
  csv="$tmp/$mode.csv"
  "$retro" render $map $view -m $mode --stats --columns "$csv" -o "$tmp/$mode.ppm" >"$tmp/on.txt" 2>/dev/null ||
    fail "$mode: render --stats --columns"
  "$retro" render $map $view -m $mode --no-skip --stats -o "$tmp/off.ppm" >"$tmp/off.txt" 2>/dev/null ||
    fail "$mode: render --no-skip --stats"
  [ -s "$tmp/$mode.ppm" ] || fail "$mode: no image beside the CSV"
  [ "$(head -n 1 "$csv")" = "column,samples,evaluated,painting,evaluated_noskip,painting_noskip" ] ||
    fail "$mode: header '$(head -n 1 "$csv")'"
  [ "$(($(wc -l <"$csv") - 1))" -eq 160 ] || fail "$mode: $(($(wc -l <"$csv") - 1)) rows for 160 columns"
  # every row: its column in order, six non-negative integers, painting <= evaluated <= samples,
  # and the same painting count with skipping as without
  bad=$(awk -F, 'NR > 1 && (NF != 6 || $1 != NR - 2 || $0 !~ /^[0-9]+,[0-9]+,[0-9]+,[0-9]+,[0-9]+,[0-9]+$/ ||
                            $4 > $3 || $3 > $2 || $6 > $5 || $5 > $2 || $4 != $6) { print NR; exit }' "$csv")
  [ -z "$bad" ] || fail "$mode: bad row at line $bad: $(sed -n "${bad}p" "$csv")"
  # samples per column: (W x (D-1)) / W from --stats' first line
  all=$(sed -n 's/^samples: \([0-9]*\) .*/\1/p' "$tmp/on.txt")
  [ -n "$all" ] && [ "$(awk -F, 'NR == 2 { print $2 * 160 }' "$csv")" = "$all" ] || fail "$mode: samples per column"
  set -- $(sums "$csv")
  [ "$1" = "$(num evaluated "$tmp/on.txt")" ] || fail "$mode: evaluated sums to $1, --stats says $(num evaluated "$tmp/on.txt")"
  [ "$2" = "$(num painting "$tmp/on.txt")" ] || fail "$mode: painting sums to $2, --stats says $(num painting "$tmp/on.txt")"
  [ "$3" = "$(num evaluated "$tmp/off.txt")" ] || fail "$mode: evaluated_noskip sums to $3, --no-skip --stats says $(num evaluated "$tmp/off.txt")"
  [ "$4" = "$(num painting "$tmp/off.txt")" ] || fail "$mode: painting_noskip sums to $4"
  [ "$1" -lt "$3" ] || fail "$mode: skipping evaluated $1 samples, not fewer than $3"
done
# --no-skip: both halves are the frame without skipping
"$retro" render $map $view --no-skip --columns "$tmp/ns.csv" 2>/dev/null || fail "render --no-skip --columns"
[ -z "$(awk -F, 'NR > 1 && ($3 != $5 || $4 != $6)' "$tmp/ns.csv")" ] || fail "--no-skip: the two halves differ"
# --columns alone is an output: no -o needed, and nothing on stdout without --stats
"$retro" render $map $view --columns "$tmp/alone.csv" >"$tmp/alone.txt" 2>/dev/null || fail "--columns without -o"
cmp -s "$tmp/alone.csv" "$tmp/exact.csv" || fail "--columns without -o differs from with -o"
[ ! -s "$tmp/alone.txt" ] || fail "--columns printed on stdout without --stats"

# bad input: exit 2, one line on stderr, neither file written
bad() { # WHAT ARGS...
  what=$1
  shift
  "$retro" render "$@" >"$tmp/bad.out" 2>"$tmp/bad.err"
  rc=$?
  [ "$rc" -eq 2 ] || fail "$what: exit $rc, not 2"
  [ "$(wc -l <"$tmp/bad.err")" -eq 1 ] || fail "$what: stderr '$(cat "$tmp/bad.err")'"
  [ ! -e "$tmp/bad.csv" ] && [ ! -e "$tmp/bad.ppm" ] || fail "$what: an output was written"
  [ -z "$(ls "$tmp" | grep retro-tmp)" ] || fail "$what: a temporary was left"
  rm -f "$tmp/bad.csv" "$tmp/bad.ppm"
}
bad "mesh kernel" $map $view -k mesh-zbuffer --columns "$tmp/bad.csv" -o "$tmp/bad.ppm"
bad "missing value" $map $view -o "$tmp/bad.ppm" --columns
bad "folder" $map $view --columns "$tmp" -o "$tmp/bad.ppm"
bad "missing folder" $map $view --columns "$tmp/none/bad.csv" -o "$tmp/bad.ppm"
bad "bad image type" $map $view --columns "$tmp/bad.csv" -o "$tmp/bad.txt"
bad "bad distance" $map -d 12x --columns "$tmp/bad.csv" -o "$tmp/bad.ppm"
echo "skip columns: $fails failures"
[ "$fails" -eq 0 ]
