#!/bin/sh
# retro view's real window under Xvfb: it appears, draws the overlay (yellow text, top left),
# moves while W is held, hides the overlay on O, and Esc exits 0. Skips without Xvfb.
set -u
retro=$1
. scripts/xvfb.sh
missing=$(xvfb_tools)
if [ -n "$missing" ]; then
  echo "SKIP: retro view window test needs $missing(make deps installs xvfb xdotool x11-apps netpbm)"
  exit 0
fi
tmp=$(mktemp -d)
vpid=
cleanup() {
  [ -n "$vpid" ] && kill "$vpid" 2>/dev/null
  xvfb_stop
  rm -rf "$tmp"
}
trap cleanup EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
here=$(pwd)

cat >"$tmp/v.scene" <<EOF2
[scene]
map = $here/maps/islands
[camera]
x = 200
y = 820
height = 120
angle = 20
[screen]
width = 320
height = 240
[water]
level = 67
EOF2

xvfb_start 480 360 || { echo "FAIL: Xvfb does not start"; exit 1; }
# SDL's X11 driver (no Wayland probe) and its software renderer (Xvfb has no GPU). Leaks are not
# checked here (ASan's memory errors and UBSan are): SDL's D-Bus connection leaks blocks from a
# library SDL unloads at exit, which no suppression can then name. The headless replays of
# tests/view.sh are the leak check, without suppressions.
SDL_VIDEODRIVER=x11 SDL_RENDER_DRIVER=software ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
  timeout 90 "$retro" view "$tmp/v.scene" -k ybuffer >"$tmp/out" 2>&1 &
vpid=$!
wid=$(timeout 20 xdotool search --sync --onlyvisible --name '^retro view' 2>/dev/null | head -n 1)
if [ -z "$wid" ]; then
  echo "FAIL: no retro view window appeared: $(head -n 3 "$tmp/out")"; exit 1
fi
window_geometry "$wid"
timeout 5 xdotool mousemove --window "$wid" 20 20 windowfocus --sync "$wid" 2>/dev/null

# Waits (at most 10 s) until the overlay box holds at least MIN (or, with "none", no) yellow
# text pixels; leaves the screenshot in $1.
yellow() { count_color "$1" "$WX" "$WY" 200 60 "ff ff 00"; }
wait_overlay() { # OUT.ppm MIN|none
  i=0
  while [ $i -lt 50 ]; do
    xvfb_shot "$1"
    y=$(yellow "$1")
    if [ "$2" = none ]; then [ "$y" -eq 0 ] && return 0; else [ "$y" -ge "$2" ] && return 0; fi
    i=$((i + 1)); sleep 0.2
  done
  return 1
}

wait_overlay "$tmp/a.ppm" 100 || fail "no overlay text in the window's top left ($(yellow "$tmp/a.ppm") yellow pixels)"
# Below the overlay: the terrain, before and after W is held.
ty=$((WY + WH / 2)) th=$((WH / 2))
pamcut -left "$WX" -top "$ty" -width "$WW" -height "$th" "$tmp/a.ppm" >"$tmp/a-low.ppm" 2>/dev/null
timeout 5 xdotool keydown w; sleep 0.6; timeout 5 xdotool keyup w; sleep 0.5
xvfb_shot "$tmp/b.ppm"
pamcut -left "$WX" -top "$ty" -width "$WW" -height "$th" "$tmp/b.ppm" >"$tmp/b-low.ppm" 2>/dev/null
[ -s "$tmp/a-low.ppm" ] && ! cmp -s "$tmp/a-low.ppm" "$tmp/b-low.ppm" || fail "the view did not change while W was held"

timeout 5 xdotool key o
wait_overlay "$tmp/c.ppm" none || fail "the overlay stayed after O ($(yellow "$tmp/c.ppm") yellow pixels)"

timeout 5 xdotool key Escape
i=0
while kill -0 "$vpid" 2>/dev/null && [ $i -lt 100 ]; do i=$((i + 1)); sleep 0.1; done
wait "$vpid"
rc=$?
vpid=
[ $rc -eq 0 ] || fail "Esc: exit $rc, want 0: $(head -n 5 "$tmp/out")"

[ $fails -eq 0 ] && echo "view window: ok" && exit 0
echo "view window: $fails failure(s)"
exit 1
