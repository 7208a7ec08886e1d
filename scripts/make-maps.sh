#!/bin/sh
# Generates the maps the suite uses, skipping those newer than the generator.
# usage: make-maps.sh RETRO [test]   (test: only the small analytic maps the tests need)
set -eu
retro=$1
only=${2:-all}
gen() { # NAME STYLE SIZE SEED
  if [ ! -f "maps/$1.pgm" ] || [ "$retro" -nt "maps/$1.pgm" ]; then
    mkdir -p "$(dirname "maps/$1")"
    echo "  GEN     maps/$1 ($2, ${3}x$3, seed $4)"
    "$retro" genmap "$2" --size "$3" --seed "$4" -o "maps/$1"
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
