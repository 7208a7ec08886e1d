#!/bin/sh
# Renders the fastest kernel's pictures into OUT (make demo: build/results): each scene file
# maps/NAME.scene (effects on) to OUT/NAME.png, each default map without effects to
# OUT/NAME-plain.png, and the islands fly-through to OUT/fly/.
# usage: demo.sh RETRO OUT
set -eu
. "$(dirname "$0")/usage.sh"
script_args 2 2 "$@"
retro=$1
out=$2
mkdir -p "$out/fly"
for map in alpine islands canyon; do
  echo "  RENDER  $out/$map-plain.png"
  "$retro" render "maps/$map" -s 640x480 -d 800 -o "$out/$map-plain.png"
done
for scene in islands alpine canyon tide; do
  echo "  RENDER  $out/$scene.png (maps/$scene.scene)"
  "$retro" render "maps/$scene.scene" -o "$out/$scene.png"
done
echo "  FLY     $out/fly/islands-NNN.png (maps/islands.scene)"
"$retro" fly maps/islands.scene -o "$out/fly/islands-%03d.png"
