# Sourced by tests/view_xvfb.sh and scripts/view-screenshot.sh: a private Xvfb display, its
# screenshots as PPM, and pixel counts. Every wait is bounded.

xvfb_tools() { # prints the missing tools, nothing when all are there
  for t in Xvfb xdotool xwd xwdtopnm pamdepth pamcut pnmtopng; do
    command -v "$t" >/dev/null 2>&1 || printf '%s ' "$t"
  done
}

xvfb_start() { # W H: starts Xvfb on a free display (Xvfb picks it: no race with other runs)
  XVFB_FD_FILE=$(mktemp)
  Xvfb -displayfd 5 -screen 0 "${1}x${2}x24" -nolisten tcp 5>"$XVFB_FD_FILE" >/dev/null 2>&1 &
  XVFB_PID=$!
  i=0
  until n=$(tr -dc 0-9 <"$XVFB_FD_FILE") && [ -n "$n" ]; do
    i=$((i + 1))
    if [ $i -gt 100 ] || ! kill -0 "$XVFB_PID" 2>/dev/null; then
      echo "Xvfb did not start" >&2; rm -f "$XVFB_FD_FILE"; return 1
    fi
    sleep 0.1
  done
  rm -f "$XVFB_FD_FILE"
  export DISPLAY=":$n"
  i=0
  until xdotool getmouselocation >/dev/null 2>&1; do
    i=$((i + 1))
    [ $i -gt 50 ] && { echo "Xvfb :$n does not answer" >&2; return 1; }
    sleep 0.1
  done
}

xvfb_stop() {
  [ -n "${XVFB_PID:-}" ] && kill "$XVFB_PID" 2>/dev/null && wait "$XVFB_PID" 2>/dev/null
  XVFB_PID=
}

xvfb_shot() { # OUT.ppm: the whole screen
  timeout 10 xwd -root -silent | xwdtopnm 2>/dev/null | pamdepth 255 >"$1" 2>/dev/null
}

# The window's geometry: sets WX WY WW WH.
window_geometry() { # WINDOW_ID
  eval "$(timeout 5 xdotool getwindowgeometry --shell "$1" | sed -n 's/^\(X\|Y\|WIDTH\|HEIGHT\)=\([0-9]*\)$/G_\1=\2/p')"
  WX=${G_X:-0} WY=${G_Y:-0} WW=${G_WIDTH:-0} WH=${G_HEIGHT:-0}
}

# Pixels of colour RRGGBB (hex, lower case, as "ff ff 00") in a region of a PPM.
count_color() { # PPM X Y W H "rr gg bb"
  pamcut -left "$2" -top "$3" -width "$4" -height "$5" "$1" 2>/dev/null | tail -c $(($4 * $5 * 3)) |
    od -An -v -tx1 -w3 | grep -c " $6\$"
}
