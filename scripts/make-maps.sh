#!/bin/sh
# Generates the maps the suite uses, skipping those newer than the generator.
# usage: make-maps.sh RETRO [test]   (test: only the small analytic maps the tests need)
set -eu
. "$(dirname "$0")/usage.sh"
script_args 1 2 "$@"
case ${2:-all} in all | test) ;; *) echo "make-maps.sh: unknown set '$2' (all or test)" >&2; exit 2 ;; esac
retro=$1
only=${2:-all}
gen() { # NAME STYLE SIZE SEED [GENMAP OPTIONS...]
  name=$1 style=$2 size=$3 seed=$4
  shift 4
  if [ ! -f "maps/$name.pgm" ] || [ "$retro" -nt "maps/$name.pgm" ]; then
    mkdir -p "$(dirname "maps/$name")"
    echo "  GEN     maps/$name ($style, ${size}x$size, seed $seed${*:+, $*})"
    "$retro" genmap "$style" --size "$size" --seed "$seed" "$@" -o "maps/$name"
  fi
}
gen test/flat-64 flat 64 0
gen test/ramp-64 ramp 64 0
gen test/spike-64 spike 64 0
gen test/checker-1000 checker 1000 0
gen test/ramp-1000 ramp 1000 0
gen test/flat-1 flat 1 0
gen test/ramp-3 ramp 3 0
gen test/checker-2 checker 2 0
gen test/alpine-200 alpine 200 7
[ "$only" = test ] && exit 0
gen alpine alpine 1024 1
gen islands islands 1024 1
gen canyon canyon 1024 1
# For the scenes (maps/*.scene): colours without baked light for [shade], and the tide's
# second height keyframe for [morph].
gen alpine-unlit alpine-unlit 1024 1
gen islands-low islands 1024 1 --height-offset -24
