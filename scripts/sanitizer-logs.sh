#!/bin/sh
# Fails if any sanitized process wrote a report: make asan points every process's
# ASAN_OPTIONS/UBSAN_OPTIONS log_path into DIR (DIR/san.PID), so a report from a Criterion
# worker, a retro started by a shell test or a fuzz target is seen even where the test
# framework swallowed or miscounted it, and so is a sanitizer that crashed itself.
# usage: sanitizer-logs.sh DIR [LABEL]
set -u
. "$(dirname "$0")/usage.sh"
script_args 1 2 "$@"
dir=$1
label=${2:-sanitizers}
found=0
for f in "$dir"/*; do
  [ -s "$f" ] || continue
  found=$((found + 1))
  echo "== sanitizer report: $f"
  head -n 60 "$f"
done
if [ "$found" -ne 0 ]; then
  echo "FAIL: $label: $found sanitizer report(s) in $dir"
  exit 1
fi
echo "$label: no sanitizer report"
