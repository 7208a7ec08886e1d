#!/bin/sh
# make publish: copies the last full benchmark run (and the accuracy run, the replay study and
# demo pictures, if any) from the runs' folder into the committed results/, then rewrites the
# README's figures from them. The only way results/ changes, so a quick or partial run never
# replaces it.
# usage: publish.sh RUNS RESULTS README [--accuracy]
# --accuracy (make publish-accuracy) copies the accuracy run alone, for a machine that gives a
# steady make accuracy but no steady make bench: the benchmark's figures stay as they are.
set -eu
. "$(dirname "$0")/usage.sh"
script_args 3 4 "$@"
case ${4:---accuracy} in --accuracy) ;; *) echo "publish.sh: unknown option '$4' (--help)" >&2; exit 2 ;; esac
runs=$1
dest=$2
readme=$3
# the files of a make accuracy run, copied by both kinds of publishing
copy_accuracy() {
  for f in ACCURACY.md accuracy-code.txt accuracy-pareto.svg accuracy-pareto.png accuracy-families.svg accuracy-families.png \
    accuracy-pair-voxel.png accuracy-pair-mesh.png accuracy-pair-diff.png; do
    [ -f "$runs/$f" ] && cp "$runs/$f" "$dest/$f" && echo "  COPY    $dest/$f"
  done
  # a digest of an earlier run's build must not stand beside this run
  [ -f "$runs/accuracy-code.txt" ] || rm -f "$dest/accuracy-code.txt"
}
# Why the accuracy run in RUNS may not be published, or nothing: a partial run (ACCURACY_ARGS=
# --poses N below the default 120), one of edited sources, or one whose machine changed speed
# during the run never replaces the published one.
accuracy_unpublishable() {
  poses=$(sed -n 's/^Measured .* by `make accuracy`: \([0-9]*\) seeded random poses.*/\1/p' "$runs/ACCURACY.md")
  if [ "${poses:-0}" -lt 120 ]; then
    echo "$runs/ACCURACY.md rendered ${poses:-no} poses: run make accuracy with the default 120 to publish"
  elif ! grep -q '^Machine: .*\. Commit: [0-9a-f]*\.$' "$runs/ACCURACY.md"; then
    echo "$runs/ACCURACY.md names no clean commit (edited sources?): commit, then make accuracy"
  elif grep -q '^> \*\*Noisy run' "$runs/ACCURACY.md"; then
    echo "$runs/ACCURACY.md says the run was noisy (its Machine steadiness): rerun make accuracy on a quiet machine"
  fi
}
if [ "${4:-}" = --accuracy ]; then
  if [ ! -f "$runs/ACCURACY.md" ]; then
    echo "error: no accuracy run in $runs (make accuracy first)" >&2
    exit 2
  fi
  why=$(accuracy_unpublishable)
  if [ -n "$why" ]; then
    echo "error: $why" >&2
    exit 2
  fi
  copy_accuracy
  python3 scripts/readme-figures.py "$dest" "$readme"
  echo "  published; review with git diff, then commit $dest and $readme"
  exit 0
fi
if [ ! -f "$runs/BENCH.md" ] || [ ! -f "$runs/bench.json" ]; then
  echo "error: no benchmark run in $runs (make bench first)" >&2
  exit 2
fi
if grep -q '"retro_quick": "true"' "$runs/bench.json" || ! grep -q '^| settings | full run |' "$runs/BENCH.md"; then
  echo "error: $runs/BENCH.md is a quick run (make bench QUICK=1): run make bench in full to publish" >&2
  exit 2
fi
if grep -q '^| filter |' "$runs/BENCH.md"; then
  echo "error: $runs/BENCH.md is a partial run (BENCH_ARGS filter): run make bench in full to publish" >&2
  exit 2
fi
if grep -q '^> \*\*Noisy run' "$runs/BENCH.md"; then
  echo "warning: $runs/BENCH.md says the run was noisy; publishing it anyway (it says so)" >&2
fi
mkdir -p "$dest"
for f in BENCH.md bench.json bench-code.txt bench-speedup.svg bench-resolution.svg bench-distance.svg \
  bench-speedup.png bench-resolution.png bench-distance.png \
  bench-mesh-resolution.svg bench-mesh-distance.svg bench-mesh-resolution.png bench-mesh-distance.png \
  skip-columns.csv skip-columns.txt skip-columns.svg skip-columns.png study-replay.md; do
  [ -f "$runs/$f" ] && cp "$runs/$f" "$dest/$f" && echo "  COPY    $dest/$f"
done
[ -f "$runs/bench-code.txt" ] || rm -f "$dest/bench-code.txt"
if [ -f "$runs/ACCURACY.md" ]; then
  why=$(accuracy_unpublishable)
  if [ -n "$why" ]; then
    echo "warning: the accuracy run stays as published: $why" >&2
  else
    copy_accuracy
  fi
fi
for f in alpine islands canyon tide alpine-plain islands-plain canyon-plain; do
  [ -f "$runs/$f.png" ] && cp "$runs/$f.png" "$dest/$f.png" && echo "  COPY    $dest/$f.png"
done
python3 scripts/readme-figures.py "$dest" "$readme"
echo "  published; review with git diff, then commit $dest and $readme"
