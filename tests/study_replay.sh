#!/bin/sh
# The replay study (scripts/study-replay.sh; docs/studies/SKIPPING_LIMITS.md, "What the probes
# cost" and "What the stores cost"): its patch still applies to the kernels it studies, its
# script answers --help and refuses bad input with exit 2, and every figure those sections quote
# is in the committed run, results/study-replay.md, whose commit and date they name. The study
# itself is not run here: it times frames, and tests never do.
set -u
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

git apply --check docs/studies/replay.patch 2>"$tmp/apply" ||
  fail "docs/studies/replay.patch no longer applies: $(head -n 1 "$tmp/apply")"

sh scripts/study-replay.sh --help >"$tmp/help" 2>&1 || fail "--help exits $?"
grep -q '^usage: scripts/study-replay.sh' "$tmp/help" || fail "--help prints no usage"
for bad in "-n 0" "-n 100" "-n x" "--frobnicate" "-o"; do
  # shellcheck disable=SC2086
  sh scripts/study-replay.sh $bad >"$tmp/out" 2>"$tmp/err"
  rc=$?
  [ $rc -eq 2 ] || fail "'$bad' exits $rc, not 2"
  [ "$(wc -l <"$tmp/err")" -eq 1 ] || fail "'$bad' prints $(wc -l <"$tmp/err") lines of error, not one"
  [ ! -s "$tmp/out" ] || fail "'$bad' printed to stdout"
done

run=results/study-replay.md
doc=docs/studies/SKIPPING_LIMITS.md
if [ ! -f "$run" ]; then
  fail "$run is missing"
else
  # the two sections, from their heading to the next
  awk '/^## /{on = ($0 == "## What the probes cost" || $0 == "## What the stores cost")} on' "$doc" \
    >"$tmp/sections"
  [ "$(grep -c '^## ' "$tmp/sections")" -eq 2 ] || fail "$doc lacks one of the two sections"
  commit=$(sed -n '1s/^Replay study of \([0-9a-f]*\), .*/\1/p' "$run")
  date=$(sed -n '1s/^Replay study of [0-9a-f]*, \([0-9-]*\) .*/\1/p' "$run")
  [ -n "$commit" ] && [ -n "$date" ] || fail "$run names no commit and date on its first line"
  # quotes TEXT WHAT [ALSO]: TEXT names the run's commit and date, and every decimal figure in it
  # (ratios printed x in the run, × in the docs), but for issue 18's target of 0.10 ms, which
  # the docs compare with, is in the run (or in the file ALSO)
  quotes() {
    grep -q "$commit" "$1" || fail "$2 do not name the run's commit $commit"
    grep -q "$date" "$1" || fail "$2 do not name the run's date $date"
    grep -o '[0-9][0-9]*\.[0-9][0-9]*' "$1" | sort -u | grep -vx '0\.10' >"$tmp/figures"
    [ -s "$tmp/figures" ] || fail "$2 quote no figure"
    while read -r x; do
      re="\(^\|[^0-9.]\)$(printf '%s' "$x" | sed 's/\./\\./')\([^0-9]\|$\)"
      grep -q "$re" "$run" || { [ -n "${3:-}" ] && grep -q "$re" "$3"; } ||
        fail "$2 in $doc quote $x, which $run${3:+ and the rest of the file} do not hold"
    done <"$tmp/figures"
  }
  quotes "$tmp/sections" "the sections"

  # the summary "Issue 18's targets against the method's measured limits" quotes the same run
  # and the count tables further down (which tests/skipping_doc_counts.sh checks): each figure
  # must be in the run or elsewhere in that file
  summary="## Issue 18's targets against the method's measured limits"
  awk -v h="$summary" '/^## /{on = ($0 == h)} on' "$doc" >"$tmp/summary"
  awk -v h="$summary" '/^## /{on = ($0 == h)} !on' "$doc" >"$tmp/rest"
  [ -s "$tmp/summary" ] || fail "$doc lacks the section '$summary'"
  quotes "$tmp/summary" "the summary's lines" "$tmp/rest"
fi

[ $fails -eq 0 ] && echo "ok: study_replay"
[ $fails -eq 0 ]
