#!/bin/sh
# Compares the frames of this tree's library with another build's, byte for byte: builds
# tests/frame_digest.c against each (BASE is a worktree already built with `make`), runs both
# over the verify cases and POSES seeded random poses, every kernel, mode, effect set, ISA
# level and thread count, and diffs the digests. Exit 0 when every frame is identical.
# With "naive", naive alone renders (each build's checker proves its variants equal its naive;
# every variant costs a fresh context, and the threaded ones load the hwloc topology each).
# usage: compare-frames.sh BASE [POSES [naive]]   e.g. compare-frames.sh /tmp/base-ba5e92b 200
set -eu
. "$(dirname "$0")/usage.sh"
script_args 1 3 "$@"
base=$1 poses=${2:-200} which=${3:-all}
shared=${RETRO_SHARED:-../shared}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
flags="-std=c11 -D_POSIX_C_SOURCE=200809L -O2 -ffp-contract=off"
libs="$(pkg-config --libs spng hwloc inih) -fopenmp -lm"
incs() { find "$1/include" "$1/src" -name '*.h' -exec dirname {} \; | sort -u | sed 's/^/-I/'; }
build() { # TREE OUT
  $CC $flags $(incs "$1") tests/frame_digest.c "$1/src/cli/verify_cases.c" "$1/build/libretro.a" $libs -o "$2"
}
CC=${CC:-cc}
build "$base" "$tmp/base"
build . "$tmp/new"
"$tmp/base" maps "$shared" "$poses" "$which" >"$tmp/base.txt" &
bpid=$!
"$tmp/new" maps "$shared" "$poses" "$which" >"$tmp/new.txt"
wait $bpid
lines=$(wc -l <"$tmp/new.txt")
if cmp -s "$tmp/base.txt" "$tmp/new.txt"; then
  echo "compare-frames: $lines frames identical to $base"
else
  diff "$tmp/base.txt" "$tmp/new.txt" | head -20
  echo "compare-frames: frames differ from $base"
  exit 1
fi
