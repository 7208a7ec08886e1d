#!/bin/sh
# Every program under scripts/ (a file with a #! line; the others are sourced) answers --help
# with its usage on stdout and status 0, and a wrong call with status 2, one line on stderr that
# points to --help, nothing on stdout and nothing written to the tree. The wrong call is chosen
# so that no script could start its work: too few arguments, or one too many for those that
# take none (make deps's installer), or an unknown option for those that parse their own.
# usage: scripts_usage.sh RETRO   (RETRO unused: every test takes it)
set -u
fail=0
before=$(git status --porcelain 2>/dev/null)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
n=0
for s in scripts/*; do
  head -n 1 "$s" | grep -q '^#!' || continue
  case $s in *.py) run="python3 $s" ;; *) run="sh $s" ;; esac
  n=$((n + 1))
  if ! $run --help >"$tmp/out" 2>"$tmp/err" || ! grep -q 'usage:' "$tmp/out"; then
    echo "FAIL: $s --help: status not 0 or no usage on stdout"
    fail=1
  fi
  # the arguments of a wrong call, from the script's own script_args MIN MAX
  counts=$(sed -n 's/^script_args \([0-9]*\) \([0-9-]*\) "\$@"$/\1 \2/p' "$s")
  set --
  if [ -z "$counts" ]; then
    set -- --no-such-option
  elif [ "${counts% *}" -eq 0 ]; then
    i=0
    while [ "$i" -le "${counts#* }" ]; do set -- "$@" x; i=$((i + 1)); done
  fi
  $run "$@" >"$tmp/out" 2>"$tmp/err" </dev/null
  rc=$?
  # the line points to the usage: a shell's own "parameter not set" would not
  if [ "$rc" -ne 2 ] || [ -s "$tmp/out" ] || [ "$(wc -l <"$tmp/err")" -ne 1 ] || ! grep -q -- '--help' "$tmp/err"; then
    echo "FAIL: $s $*: want status 2, one line on stderr naming --help and none on stdout; got $rc:"
    cat "$tmp/out" "$tmp/err"
    fail=1
  fi
done
after=$(git status --porcelain 2>/dev/null)
if [ "$before" != "$after" ]; then
  echo "FAIL: the wrong calls changed the tree:"
  printf '%s\n' "$after"
  fail=1
fi
[ "$n" -ge 15 ] || { echo "FAIL: only $n programs under scripts/"; fail=1; }
[ "$fail" -eq 0 ] && echo "ok: $n programs under scripts/ answer --help and refuse a wrong call with status 2"
exit "$fail"
