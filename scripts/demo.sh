#!/bin/sh
# Renders each default scene with the fastest kernel to results/NAME.png.
set -eu
retro=$1
mkdir -p results
for scene in alpine islands canyon; do
  echo "  RENDER  results/$scene.png"
  "$retro" render "maps/$scene" -s 640x480 -d 800 -o "results/$scene.png"
done
