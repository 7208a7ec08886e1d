# Sourced by tests/hostile*.sh. The contract for bad input: exit 2, exactly one line on
# stderr, no file created, an existing output byte-identical, no temporary left. Every command
# runs under timeout, so a regression that blocks (on a FIFO) fails instead of hanging.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out="$tmp/out"
mkdir -p "$out"
printf 'P6\n1 1\n255\nabc' >"$tmp/keep.orig"
fails=0
allow=""  # a pattern of stderr lines a case may add (the OpenMP runtime's own warnings)

# run OUTPATH CMD...: CMD with each argument OUT replaced by OUTPATH; status in $rc.
run() {
  o=$1; shift
  n=$#
  for a in "$@"; do
    [ "$a" = OUT ] && a=$o
    set -- "$@" "$a"
  done
  shift "$n"
  timeout 20 "$@" 2>"$tmp/err" >/dev/null
  rc=$?
}

lines() {
  if [ -n "$allow" ]; then grep -cv -e "$allow" -e '^$' "$tmp/err"; else wc -l <"$tmp/err"; fi
}

# bad DESC CMD...: the contract, once writing to a new path and once over an existing file.
bad() {
  what=$1; shift
  for target in new keep; do
    rm -f "$out/new.ppm"
    cp "$tmp/keep.orig" "$out/keep.ppm"
    run "$out/$target.ppm" "$@"
    l=$(lines)
    left=$(ls -A "$out" | grep -v -x -e keep.ppm -e new.ppm -e isdir.ppm)
    if [ "$rc" -ne 2 ] || [ "$l" -ne 1 ] || [ -e "$out/new.ppm" ] ||
      ! cmp -s "$out/keep.ppm" "$tmp/keep.orig" || [ -n "$left" ]; then
      echo "FAIL: $what ($target output): exit $rc, $l stderr lines, left: $left: $(head -c 300 "$tmp/err")"
      fails=$((fails + 1))
      return
    fi
  done
}

# good DESC CMD...: exit 0 and an output file.
good() {
  what=$1; shift
  rm -f "$out/new.ppm"
  run "$out/new.ppm" "$@"
  if [ "$rc" -ne 0 ] || [ ! -s "$out/new.ppm" ]; then
    echo "FAIL: $what: exit $rc: $(head -c 300 "$tmp/err")"
    fails=$((fails + 1))
  fi
}

# says DESC PATTERN: the last case's stderr matches PATTERN.
says() {
  grep -q -e "$2" "$tmp/err" || { echo "FAIL: $1: stderr '$(cat "$tmp/err")' lacks '$2'"; fails=$((fails + 1)); }
}
