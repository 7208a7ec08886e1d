#!/bin/sh
# Renders the fastest kernel's pictures: each scene file maps/NAME.scene (effects on) to
# results/NAME.png, each default map without effects to results/NAME-plain.png, and the
# islands fly-through to results/fly/.
set -eu
retro=$1
mkdir -p results/fly
for map in alpine islands canyon; do
  echo "  RENDER  results/$map-plain.png"
  "$retro" render "maps/$map" -s 640x480 -d 800 -o "results/$map-plain.png"
done
for scene in islands alpine canyon tide; do
  echo "  RENDER  results/$scene.png (maps/$scene.scene)"
  "$retro" render "maps/$scene.scene" -o "results/$scene.png"
done
echo "  FLY     results/fly/islands-NNN.png (maps/islands.scene)"
"$retro" fly maps/islands.scene -o "results/fly/islands-%03d.png"
