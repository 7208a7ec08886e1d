#!/bin/sh
# Running the targets leaves the tree clean: make bench QUICK=1, make accuracy, make demo and
# make submission write only to ignored folders (build/results, results/submission), never to
# committed files, and leave no helper files (.dat, .gp) beside the results.
# Runs them in a temporary copy of the tree (tracked and untracked files, made a git
# repository) with tiny arguments, on the already built binaries, then asks git status.
# usage: clean_tree.sh RETRO   (retro-bench is taken from the same directory)
set -u
here=$(pwd)
retro=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
bench=$(dirname "$retro")/retro-bench
for b in "$retro" "$bench"; do
  [ -x "$b" ] || { echo "FAIL: $b not built (make check builds it)"; exit 1; }
done
shared=$(cd "${RETRO_SHARED:-../shared}" 2>/dev/null && pwd || echo /nonexistent)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
copy=$tmp/tree
mkdir "$copy"
git ls-files -co --exclude-standard -z | (cd "$here" && xargs -0 cp -p --parents -t "$copy")
# The generated maps, older than the binaries, so make-maps.sh regenerates none of them.
cp -p maps/*.pgm maps/*.ppm "$copy/maps/" 2>/dev/null
[ -d maps/test ] && cp -rp maps/test "$copy/maps/"
find "$copy/maps" -name '*.p?m' -exec touch {} +
cd "$copy" || exit 1
git init -q . && git add -A && git -c user.name=t -c user.email=t@t commit -qm copy || {
  echo "FAIL: could not make the copy a git repository"; exit 1; }
# The binaries and libraries are taken as built, through copies, so nothing this test runs can
# touch the real ones: with no objects to depend on, make (and its sub-makes, which inherit
# these) rebuilds nothing. BUILD is named because make asan's BUILD would reach these makes
# through the environment and send their output elsewhere.
mkdir "$tmp/bin"
cp -p "$retro" "$bench" "$(dirname "$(dirname "$retro")")/libretro.a" \
  "$(dirname "$(dirname "$retro")")/libretro-course.a" "$tmp/bin/" || { echo "FAIL: cannot copy the binaries"; exit 1; }
retro=$tmp/bin/retro bench=$tmp/bin/retro-bench
mk() { make --no-print-directory BUILD=build RETRO="$retro" BENCH_BIN="$bench" LIB="$tmp/bin/libretro.a" \
  COURSE_LIB="$tmp/bin/libretro-course.a" LIB_OBJ= COURSE_SRC= \
  CLI_OBJ= BENCH_OBJ= SHARED="$shared" "$@" >"$tmp/log.$1" 2>&1 || { tail -n 15 "$tmp/log.$1"; return 1; }; }
fail=0
mk bench QUICK=1 BENCH_ARGS="--scene=maps/test/flat-64 --size=32x24 --distance=16 \
--benchmark_filter=exact/flat-64/naive/1t/32x24/D16 --benchmark_min_time=0.001" ||
  { echo "FAIL: make bench QUICK=1 failed"; fail=1; }
[ -f build/results/BENCH.md ] || { echo "FAIL: make bench wrote no build/results/BENCH.md"; fail=1; }
mk accuracy ACCURACY_ARGS="--poses 1" || { echo "FAIL: make accuracy failed"; fail=1; }
[ -f build/results/ACCURACY.md ] || { echo "FAIL: make accuracy wrote no build/results/ACCURACY.md"; fail=1; }
mk demo || { echo "FAIL: make demo failed"; fail=1; }
mk submission SHARED=/nonexistent || { echo "FAIL: make submission failed"; fail=1; }
# A quick run must not be publishable.
if mk publish >/dev/null; then echo "FAIL: make publish accepted a quick run"; fail=1; fi
if mk publish-accuracy >/dev/null; then echo "FAIL: make publish-accuracy accepted a one-pose run"; fail=1; fi
dirty=$(git status --porcelain --untracked-files=all)
if [ -n "$dirty" ]; then
  echo "FAIL: the targets changed the tree:"
  printf '%s\n' "$dirty" | head -n 20
  fail=1
fi
helpers=$(find . -path ./.git -prune -o \( -name '*.dat' -o -name '*.gp' \) -print | grep -v '^./build/bench-charts.gp$')
if [ -n "$helpers" ]; then
  echo "FAIL: helper files left: $helpers"
  fail=1
fi
[ "$fail" != 0 ] && exit 1
echo "ok: make bench QUICK=1, accuracy, demo and submission leave git status clean"
