#!/bin/sh
# make bench's per-column figure of occlusion skipping (docs/SKIPPING.md): the samples the
# ybuffer kernel's counting build evaluates, and those that paint, along each screen column of
# the benchmark's alpine frame (its default view, 640x480, D 800, mode exact), with skipping and
# without. No timing: counts only.
# usage: skip-columns.sh RETRO OUTDIR
# Writes OUTDIR/skip-columns.csv (retro render --columns), OUTDIR/skip-columns.txt (the frame and
# its --stats totals) and OUTDIR/skip-columns.svg (and .png where gnuplot has a png terminal).
set -eu
retro=$1
out=$2
scene=alpine
mkdir -p "$out"
frame="$scene at its default view, 640x480, D 800, mode exact"
{
  echo "frame: $frame"
  "$retro" render "maps/$scene" -s 640x480 -d 800 -m exact --stats --columns "$out/skip-columns.csv"
} >"$out/skip-columns.txt.tmp"
mv "$out/skip-columns.txt.tmp" "$out/skip-columns.txt"
if ! command -v gnuplot >/dev/null 2>&1; then
  echo "note: gnuplot not found (make deps): no skip-columns chart" >&2
  exit 0
fi
gp=$(dirname "$0")/skip-columns.gp
gnuplot -e "term=\"svg size 800,450 dynamic background rgb 'white'\"; ext='svg'; out='$out'; frame='$frame'" "$gp"
made="$out/skip-columns.svg"
for t in pngcairo png; do
  if gnuplot -e "set terminal $t" </dev/null >/dev/null 2>&1; then
    gnuplot -e "term='$t size 800,450'; ext='png'; out='$out'; frame='$frame'" "$gp"
    made="$made and .png ($t)"
    break
  fi
done
echo "  wrote $out/skip-columns.csv, .txt, $made"
