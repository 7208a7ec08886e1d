#!/bin/sh
# Photographs retro view's window, overlay included, under a private Xvfb: results/view.png
# (the README's picture). Flies forward for a moment first, so the overlay's median covers 30
# rendered frames.
# usage: view-screenshot.sh RETRO [OUT.png]
set -eu
. "$(dirname "$0")/usage.sh"
script_args 1 2 "$@"
retro=$1
out=${2:-results/view.png}
. scripts/xvfb.sh
missing=$(xvfb_tools)
[ -z "$missing" ] || { echo "error: needs $missing(make deps)" >&2; exit 2; }
[ -f maps/islands.pgm ] || sh scripts/make-maps.sh "$retro" >/dev/null
tmp=$(mktemp -d)
vpid=
cleanup() { [ -n "$vpid" ] && kill "$vpid" 2>/dev/null; xvfb_stop; rm -rf "$tmp"; }
trap cleanup EXIT
xvfb_start 800 600
SDL_VIDEODRIVER=x11 SDL_RENDER_DRIVER=software timeout 60 "$retro" view maps/islands.scene >"$tmp/log" 2>&1 &
vpid=$!
wid=$(timeout 20 xdotool search --sync --onlyvisible --name '^retro view' | head -n 1)
[ -n "$wid" ] || { echo "error: no window: $(cat "$tmp/log")" >&2; exit 1; }
window_geometry "$wid"
timeout 5 xdotool mousemove --window "$wid" 20 20 windowfocus --sync "$wid" 2>/dev/null || true
timeout 5 xdotool keydown w; sleep 2; timeout 5 xdotool keyup w; sleep 1
xvfb_shot "$tmp/screen.ppm"
timeout 5 xdotool key Escape
pamcut -left "$WX" -top "$WY" -width "$WW" -height "$WH" "$tmp/screen.ppm" | pnmtopng >"$tmp/view.png"
mv "$tmp/view.png" "$out"
echo "  GEN     $out (${WW}x${WH})"
