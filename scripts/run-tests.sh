#!/bin/sh
# Runs every test program and ends with one line "N passed, N failed".
# usage: run-tests.sh RETRO CRITERION_BINARY...
set -u
. "$(dirname "$0")/usage.sh"
script_args 1 - "$@"
retro=$1
shift
passed=0
failed=0
status=0
for t in "$@"; do
  echo "== $t"
  out=$("$t" -j2 2>&1)
  rc=$?
  printf '%s\n' "$out" | grep -v '^\[----\]' || true
  line=$(printf '%s\n' "$out" | grep 'Synthesis:' | tail -n 1)
  if [ -z "$line" ]; then
    echo "error: $t printed no summary (exit $rc)"
    failed=$((failed + 1)); status=1; continue
  fi
  p=$(printf '%s' "$line" | sed -n 's/.*Passing: \([0-9]*\).*/\1/p')
  f=$(printf '%s' "$line" | sed -n 's/.*Failing: \([0-9]*\).*/\1/p')
  c=$(printf '%s' "$line" | sed -n 's/.*Crashing: \([0-9]*\).*/\1/p')
  passed=$((passed + p)); failed=$((failed + f))
  [ "$rc" -ne 0 ] && status=1
  : "$c"
done
for t in tests/*.sh; do
  echo "== $t"
  if sh "$t" "$retro"; then passed=$((passed + 1)); else failed=$((failed + 1)); status=1; fi
done
# The case x kernel table is long: it goes to a log beside the binaries; the summary, and any
# row that is not all identical, are printed.
log="$(dirname "$(dirname "$retro")")/verify-quick.log"
echo "== retro verify --quick (full table: $log)"
if "$retro" verify --quick >"$log" 2>&1; then
  passed=$((passed + 1))
  tail -n 1 "$log"
else
  failed=$((failed + 1)); status=1
  head -n 1 "$log"
  grep -E 'px differ|error:' "$log" | tail -n 40
  tail -n 1 "$log"
fi
echo "$passed passed, $failed failed"
exit $status
