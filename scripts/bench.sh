#!/bin/sh
# Runs retro-bench, then draws its charts with gnuplot.
# usage: bench.sh RETRO_BENCH OUTDIR CHARTS.gp [--quick] [retro-bench or --benchmark_* flags]
# Writes OUTDIR/bench.json (google-benchmark's raw JSON), OUTDIR/BENCH.md, CHARTS.gp (the
# charts' data and plots) and OUTDIR/bench-{speedup,resolution,distance}.svg (and .png).
set -eu
. "$(dirname "$0")/usage.sh"
script_args 3 - "$@"
bin=$1
out=$2
charts=$3
shift 3
mkdir -p "$out" "$(dirname "$charts")"
start=$(date +%s)
"$bin" --report="$out" --charts="$charts" --benchmark_out="$out/bench.json" \
  --benchmark_out_format=json "$@"
echo "  wrote $out/bench.json, $out/BENCH.md"
if ! command -v gnuplot >/dev/null 2>&1; then
  echo "note: gnuplot not found (make deps): no charts" >&2
  exit 0
fi
svg="svg size 800,450 dynamic background rgb 'white'"
gnuplot -e "term=\"$svg\"; ext='svg'; out='$out'" "$charts"
# gnuplot-nox builds differ: cairo's png, else libgd's, else SVG only.
png=""
for t in pngcairo png; do
  if gnuplot -e "set terminal $t" </dev/null >/dev/null 2>&1; then
    png=$t
    break
  fi
done
if [ -n "$png" ]; then
  gnuplot -e "term='$png size 800,450'; ext='png'; out='$out'" "$charts"
  echo "  wrote $out/bench-*.svg and $out/bench-*.png ($png) in $(($(date +%s) - start)) s"
else
  echo "  wrote $out/bench-*.svg in $(($(date +%s) - start)) s (this gnuplot has no png terminal)"
fi
