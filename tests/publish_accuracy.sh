#!/bin/sh
# make publish and make publish-accuracy never publish an accuracy run whose machine changed
# speed during it (its ACCURACY.md opens with a Noisy run note): publish-accuracy refuses it
# with exit 2 and copies nothing, the full publish keeps the published run and says why. A
# steady run of the same figures is copied. Runs scripts/publish.sh on copies of results/ and
# the README; the run folders are made from the committed run.
set -u
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
[ -f results/ACCURACY.md ] && [ -f results/BENCH.md ] || { echo "FAIL: no committed results/"; exit 1; }

# A run folder holding the committed run, its ACCURACY.md dated $1 and, with $2 = noisy, the note.
make_run() {
  rm -rf "$tmp/runs" && cp -r results "$tmp/runs"
  sed "s/^Measured [^U]* UTC by/Measured $1 UTC by/" results/ACCURACY.md >"$tmp/acc.md"
  if [ "$2" = noisy ]; then
    awk '{ print } /^Machine: / { print ""; print "> **Noisy run.** The reference frame'"'"'s time spread 30% (a test)." }' \
      "$tmp/acc.md" >"$tmp/runs/ACCURACY.md"
  else
    # the committed run's own Machine steadiness section, where it has one, gives way to this one
    { awk '/^## / { skip = ($0 == "## Machine steadiness") } !skip' "$tmp/acc.md"
      printf '\n## Machine steadiness\n\nSpread: 3.2%% with `omp`, 4.1%% with `ybuffer`, over 25 checkpoints: steady.\n'; } \
      >"$tmp/runs/ACCURACY.md"
  fi
}
fresh_dest() { rm -rf "$tmp/dest" && cp -r results "$tmp/dest" && cp README.md "$tmp/README.md"; }

make_run "2031-01-01 00:00" noisy
fresh_dest
sh scripts/publish.sh "$tmp/runs" "$tmp/dest" "$tmp/README.md" --accuracy >"$tmp/out" 2>"$tmp/err"
rc=$?
[ "$rc" -eq 2 ] || fail "publish-accuracy of a noisy run exited $rc, not 2"
grep -q "noisy" "$tmp/err" || fail "publish-accuracy of a noisy run did not say why: $(cat "$tmp/err")"
cmp -s results/ACCURACY.md "$tmp/dest/ACCURACY.md" || fail "publish-accuracy of a noisy run replaced ACCURACY.md"
cmp -s README.md "$tmp/README.md" || fail "publish-accuracy of a noisy run changed the README"

fresh_dest
if sh scripts/publish.sh "$tmp/runs" "$tmp/dest" "$tmp/README.md" >"$tmp/out" 2>"$tmp/err"; then
  cmp -s results/ACCURACY.md "$tmp/dest/ACCURACY.md" || fail "make publish copied a noisy accuracy run"
  grep -q "accuracy run stays as published.*noisy" "$tmp/err" ||
    fail "make publish kept the noisy accuracy run without saying so: $(cat "$tmp/err")"
else
  fail "make publish of the committed run failed: $(tail -n 3 "$tmp/err")"
fi

make_run "2031-01-01 00:00" steady
fresh_dest
if sh scripts/publish.sh "$tmp/runs" "$tmp/dest" "$tmp/README.md" --accuracy >"$tmp/out" 2>"$tmp/err"; then
  cmp -s "$tmp/runs/ACCURACY.md" "$tmp/dest/ACCURACY.md" || fail "publish-accuracy did not copy a steady run"
  grep -q "on 2031-01-01 00:00 UTC" "$tmp/README.md" || fail "publish-accuracy did not put the steady run in the README"
  grep -q "spread 3.2% with \`omp\` and 4.1% with \`ybuffer\` across the run's 25 checkpoints" "$tmp/README.md" ||
    fail "the README does not quote the steady run's spread"
else
  fail "publish-accuracy refused a steady run: $(tail -n 3 "$tmp/err")"
fi
[ "$fails" -eq 0 ] && echo "publish accuracy: ok" || { echo "publish accuracy: $fails failure(s)"; exit 1; }
