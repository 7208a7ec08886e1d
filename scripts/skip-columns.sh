#!/bin/sh
# make bench's per-column figure of occlusion skipping (docs/SKIPPING.md): the samples the
# ybuffer kernel's counting build evaluates, and those that paint, along each screen column of
# the benchmark's alpine frame (its default view, 640x480, D 800, mode exact), with skipping and
# without. No timing: counts only.
# usage: skip-columns.sh RETRO OUTDIR
# Writes OUTDIR/skip-columns.csv (retro render --columns), OUTDIR/skip-columns.txt (the frame and
# its --stats totals) and OUTDIR/skip-columns.svg (and .png where gnuplot has a png terminal).
set -eu
. "$(dirname "$0")/usage.sh"
script_args 2 2 "$@"
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
# The chart, given to gnuplot on stdin so no helper file is left beside the results; term, ext,
# out and frame are set on its command line.
plot() {
  cat <<'EOF'
eval('set terminal '.term)
set termoption noenhanced
set encoding utf8
set datafile separator ','
set output out.'/skip-columns.'.ext
set title "Samples the ybuffer kernel evaluates, per screen column\n".frame
set xlabel 'screen column'
set ylabel "share of the column's samples (%)"
set yrange [0:105]
set autoscale xfix
set grid
set key below horizontal
plot out.'/skip-columns.csv' every ::1 using 1:(100.0 * $5 / $2) with lines lw 2 lc rgb '#999999' title 'evaluated without skipping', \
  '' every ::1 using 1:(100.0 * $3 / $2) with lines lw 2 lc rgb '#1f77b4' title 'evaluated with skipping', \
  '' every ::1 using 1:(100.0 * $4 / $2) with lines lw 2 lc rgb '#d62728' title 'painting (either way)'
EOF
}
plot | gnuplot -e "term=\"svg size 800,450 dynamic background rgb 'white'\"; ext='svg'; out='$out'; frame='$frame'" -
made="$out/skip-columns.svg"
for t in pngcairo png; do
  if gnuplot -e "set terminal $t" </dev/null >/dev/null 2>&1; then
    plot | gnuplot -e "term='$t size 800,450'; ext='png'; out='$out'; frame='$frame'" -
    made="$made and .png ($t)"
    break
  fi
done
echo "  wrote $out/skip-columns.csv, .txt, $made"
