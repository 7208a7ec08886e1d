#!/bin/sh
# The README's figures are those of the committed run: every generated block of README.md
# (<!-- NAME:begin --> ... <!-- NAME:end -->) matches what scripts/readme-figures.py writes from
# results/BENCH.md and results/ACCURACY.md; and a changed figure in the run is caught.
# usage: readme_figures.sh RETRO (unused)
set -u
if ! command -v python3 >/dev/null 2>&1; then
  echo "FAIL: python3 missing (make deps)"
  exit 1
fi
python3 scripts/readme-figures.py --check results README.md || exit 1
# The check must be able to fail: alter one median of the run in a copy and expect a diff.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp results/ACCURACY.md "$tmp/"
sed 's/^\(| `ybuffer` | 1 | \)[0-9.]*/\199.99/' results/BENCH.md >"$tmp/BENCH.md"
if cmp -s "$tmp/BENCH.md" results/BENCH.md; then
  echo "FAIL: could not alter results/BENCH.md's ybuffer row for the negative check"
  exit 1
fi
if python3 scripts/readme-figures.py --check "$tmp" README.md >/dev/null 2>&1; then
  echo "FAIL: a README figure differing from the run was not caught"
  exit 1
fi
echo "ok: README figures match the committed run, and a changed figure is caught"
