#!/bin/sh
# retro view: headless key replays against the course's update_player (retro-view-pose) and
# against retro render at the final pose, also after kernel and mode switches mid-flight;
# saving a frame with its scene; bad input. The window itself: tests/view_xvfb.sh.
# Under make asan every replay below is also a leak check: LeakSanitizer fails the run.
set -u
retro=$1
pose_bin=$(dirname "$retro")/retro-view-pose
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
here=$(pwd)
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

if [ ! -x "$pose_bin" ]; then
  echo "FAIL: $pose_bin is missing (make check builds it)"; exit 1
fi
if [ ! -f maps/islands.pgm ]; then
  echo "FAIL: maps/islands.pgm is missing (make maps)"; exit 1
fi

# A small scene of its own: fog (per sample) and water (baked), a known camera.
cat >"$tmp/isl.scene" <<EOF2
[scene]
map = $here/maps/islands
sky = 87b5e8
[camera]
x = 200
y = 820
height = 120
angle = 20
[screen]
width = 160
height = 120
distance = 800
[water]
level = 67
[fog]
start = 250
end = 950
EOF2
START="200 820 120 20" D0=800

# The kernels this CPU runs, in table order, both families: "name modes family effects" lines.
"$retro" kernels | awk '!/^#/ && NR > 1 && $4 == "yes" {print $1, $3, $2, $6}' >"$tmp/kernels"
nk=$(wc -l <"$tmp/kernels")
[ "$nk" -ge 2 ] || { echo "FAIL: retro kernels lists no kernels this CPU runs"; exit 1; }
kname() { sed -n "$(($1 + 1))p" "$tmp/kernels" | cut -d' ' -f1; }
kmodes() { sed -n "$(($1 + 1))p" "$tmp/kernels" | cut -d' ' -f2; }
kfam() { sed -n "$(($1 + 1))p" "$tmp/kernels" | cut -d' ' -f3; }
kindex() { awk -v k="$1" '$1 == k {print NR - 1}' "$tmp/kernels"; }
has_mode() { echo ",$(kmodes "$1")," | grep -q ",$2,"; }
# Whether kernel index $1 renders the scene's effects (fog and water).
renders_fx() { e=",$(sed -n "$(($1 + 1))p" "$tmp/kernels" | cut -d' ' -f4),"
  case $e in *,fog,*) case $e in *,water,*) return 0 ;; esac ;; esac; return 1; }
first_mode() { [ "$(kfam "$1")" = mesh ] && echo binary32 || echo exact; }

# The expected state after a script, per docs/VIEW.md: the velocities of each frame for the
# pose driver, and the kernel, mode, effects and distance in force at the end.
expect() { # START_KERNEL SCRIPT -> $tmp/vel, and K MODE FX D
  k=$(kindex "$1") fx=1 d=$D0
  m=$(first_mode "$k") paused=0
  : >"$tmp/vel"
  for item in $(echo "$2" | tr ',' ' '); do
    key=${item%%\**} n=1
    [ "$key" != "$item" ] && n=${item#*\*}
    i=0
    while [ $i -lt "$n" ]; do
      i=$((i + 1)); vel="0 0 0"
      case $key in
        w|up) vel="4 0 0" ;; s|down) vel="-4 0 0" ;; a|left) vel="0 0 2" ;; d|right) vel="0 0 -2" ;;
        q) vel="0 2 0" ;; e) vel="0 -2 0" ;;
        pageup|plus) d=$((d + 100)) ;; pagedown|minus) d=$((d - 100)); [ $d -lt 100 ] && d=100 ;;
        tab|shift+tab)
          was=$(kfam "$k")
          [ "$key" = tab ] && k=$(((k + 1) % nk)) || k=$(((k + nk - 1) % nk))
          # modes are per family: another family starts at its first mode
          { [ "$(kfam "$k")" = "$was" ] && has_mode "$k" "$m"; } || m=$(first_mode "$k")
          renders_fx "$k" || fx=0 ;;
        m) voxel=0; order="binary32 binary64 int"
           [ "$(kfam "$k")" = voxel ] && voxel=1 order="exact course truth fixed lod"
           cur=$m
           for _ in 1 2 3 4 5; do
             cur=$(echo "$order $order" | tr ' ' '\n' | awk -v c="$cur" 'f {print; exit} $0 == c {f = 1}')
             [ $voxel = 1 ] && [ $fx = 1 ] && [ "$cur" != exact ] && [ "$cur" != lod ] && continue
             has_mode "$k" "$cur" && break
           done
           m=$cur ;;
        f) if [ $fx = 1 ]; then fx=0
           elif renders_fx "$k"; then fx=1
             if [ "$(kfam "$k")" = voxel ] && [ "$m" != exact ] && [ "$m" != lod ]; then m=exact; fi
           fi ;;
        p) paused=$((1 - paused)) ;;
      esac
      [ $paused = 0 ] && echo "$vel" >>"$tmp/vel"
    done
  done
  K=$(kname "$k") MODE=$m FX=$fx D=$d
}

# Replays SCRIPT from kernel K0 and checks pose and frame. $3 names the check.
check_replay() { # K0 SCRIPT WHAT
  expect "$1" "$2"
  want=$("$pose_bin" "$here/maps/islands" $START <"$tmp/vel")
  rm -f "$tmp/view.png" "$tmp/ref.png"
  got=$("$retro" view "$tmp/isl.scene" -k "$1" --keys "$2" --screenshot "$tmp/view.png" 2>"$tmp/err")
  rc=$?
  if [ $rc -ne 0 ] || [ "$got" != "$want" ]; then
    fail "$3: exit $rc, pose '$got', update_player gives '$want': $(head -n 2 "$tmp/err")"; return
  fi
  set -- $got
  if [ "$FX" = 1 ]; then src=$tmp/isl.scene; else src=$here/maps/islands; fi
  "$retro" render "$src" -s 160x120 --sky 87b5e8 -k "$K" -m "$MODE" -d "$D" -p "$1,$2" -z "$3" -a "$4" \
    -o "$tmp/ref.png" 2>"$tmp/err" || { fail "$3: retro render failed: $(cat "$tmp/err")"; return; }
  cmp -s "$tmp/view.png" "$tmp/ref.png" || fail "$WHAT: frame differs from retro render -k $K -m $MODE (effects $FX)"
}

# Every prefix that ends right after a switch is checked too: no frame of a flight differs.
flight() { # K0 SCRIPT
  prefix=""
  for item in $(echo "$2" | tr ',' ' '); do
    prefix=${prefix:+$prefix,}$item
    case $item in tab|shift+tab|m|f) WHAT="$1: $prefix"; check_replay "$1" "$prefix" "$WHAT" ;; esac
  done
  WHAT="$1: $2"; check_replay "$1" "$2" "$WHAT"
}

first=$(kname 0)
flight "$first" "w*30,a*10,tab,q*5,m,d*3,tab,e*4,s*2,m,left,right,up,down,shift+tab,pageup,w"
flight ybuffer "f,m,w*5,m,tab,m,a*4,f,m,minus,q*3,tab,m,p,w*3,p,s"
# From the last voxel kernel Tab goes on into the mesh family (mesh-painter cannot render the
# scene's water: effects off) and round to the first kernel.
last=$(awk '$3 == "voxel" {k = $1} END {print k}' "$tmp/kernels")
flight "$last" "tab,w*8,m,tab,m,m,tab,d*2"

# Bad input: one line, exit 2, nothing written.
expect_bad() { # WHAT NEEDLE ENV... -- ARGS...
  what=$1 needle=$2; shift 2
  rm -f "$tmp/out.png"
  env "$@" >/dev/null 2>"$tmp/err" </dev/null
  rc=$?
  lines=$(wc -l <"$tmp/err")
  if [ $rc -ne 2 ] || [ "$lines" -ne 1 ] || [ -e "$tmp/out.png" ] || ! grep -qF -- "$needle" "$tmp/err"; then
    fail "$what: exit $rc, $lines stderr lines, want '$needle': $(cat "$tmp/err")"
  fi
}

# A kernel that cannot render the scene's effects (bilinear is per sample; the SIMD kernels
# lack it): switching to it turns effects off, and the frame is retro render's of the plain map.
sed 's/^\[water\]$/[bilinear]\nenabled = yes\n[water]/' "$tmp/isl.scene" >"$tmp/bil.scene"
for k0 in $(cut -d' ' -f1 "$tmp/kernels"); do
  k1=$(kname $((($(kindex "$k0") + 1) % nk)))
  rm -f "$tmp/view.png"
  if ! "$retro" render "$tmp/bil.scene" -k "$k0" -o "$tmp/ref.png" 2>/dev/null; then
    expect_bad "bilinear scene with $k0" "does not render" "$retro" view "$tmp/bil.scene" -k "$k0" \
      --keys w --screenshot "$tmp/out.png"
    continue
  fi
  got=$("$retro" view "$tmp/bil.scene" -k "$k0" --keys "w*3,tab,w" --screenshot "$tmp/view.png" 2>"$tmp/err") ||
    { fail "bilinear $k0 -> $k1: $(cat "$tmp/err")"; continue; }
  set -- $got
  pose="-p $1,$2 -z $3 -a $4"
  # shellcheck disable=SC2086
  if "$retro" render "$tmp/bil.scene" -k "$k1" $pose -o "$tmp/ref.png" 2>/dev/null; then
    cmp -s "$tmp/view.png" "$tmp/ref.png" || fail "bilinear $k0 -> $k1: frame differs from retro render of the scene"
  elif "$retro" render "$here/maps/islands" -s 160x120 --sky 87b5e8 -k "$k1" $pose -o "$tmp/ref.png"; then
    cmp -s "$tmp/view.png" "$tmp/ref.png" || fail "bilinear $k0 -> $k1: effects not turned off for a kernel without them"
  else
    fail "bilinear $k0 -> $k1: retro render fails"
  fi
done

# Ctrl+S / F12: the PNG is the frame, its scene reproduces it through retro render.
rm -rf "$tmp/saved"
out=$("$retro" view "$tmp/isl.scene" -k ybuffer --keys "w*12,a*5,f12,q*2,m,ctrl+s" --save-dir "$tmp/saved" \
  --screenshot "$tmp/last.png" 2>"$tmp/err")
if [ $? -ne 0 ] || [ ! -f "$tmp/saved/isl-000.png" ] || [ ! -f "$tmp/saved/isl-001.scene" ]; then
  fail "save: $(cat "$tmp/err"); $(ls "$tmp/saved" 2>&1)"
else
  cmp -s "$tmp/saved/isl-001.png" "$tmp/last.png" || fail "save: the saved frame is not the last frame"
  for n in 000 001; do
    mode=$(sed -n 's/.* -m \([a-z]*\) .*/\1/p' "$tmp/saved/isl-$n.scene" | head -n 1)
    "$retro" render "$tmp/saved/isl-$n.scene" -k ybuffer -m "$mode" -o "$tmp/re.png" 2>"$tmp/err" &&
      cmp -s "$tmp/re.png" "$tmp/saved/isl-$n.png" ||
      fail "save: retro render isl-$n.scene -m $mode does not reproduce isl-$n.png: $(cat "$tmp/err")"
  done
fi

expect_bad "missing map" "nosuch" "$retro" view "$tmp/nosuch" --keys w --screenshot "$tmp/out.png"
expect_bad "missing scene" "nosuch" "$retro" view "$tmp/nosuch.scene" --keys w --screenshot "$tmp/out.png"
expect_bad "unknown kernel" "unknown kernel" "$retro" view "$tmp/isl.scene" -k warp --keys w --screenshot "$tmp/out.png"
for bad in "jump" "w*0" "w*" "w,,a" "w*3x" "*4" "w*9999999" ""; do
  expect_bad "key script '$bad'" "key" "$retro" view "$tmp/isl.scene" --keys "$bad" --screenshot "$tmp/out.png"
done
expect_bad "no display" "no display" -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$retro" view "$tmp/isl.scene"
expect_bad "empty DISPLAY" "no display" -u SDL_VIDEODRIVER DISPLAY= WAYLAND_DISPLAY= "$retro" view "$tmp/isl.scene"
expect_bad "dummy video driver" "no display" SDL_VIDEODRIVER=dummy "$retro" view "$tmp/isl.scene"
expect_bad "offscreen video driver" "no display" SDL_VIDEODRIVER=offscreen "$retro" view "$tmp/isl.scene"
expect_bad "screenshot without keys" "--keys" "$retro" view "$tmp/isl.scene" --screenshot "$tmp/out.png"
expect_bad "screenshot extension" ".png" "$retro" view "$tmp/isl.scene" --keys w --screenshot "$tmp/out.gif"
expect_bad "unknown option" "unknown option" "$retro" view "$tmp/isl.scene" --fly x
"$retro" view --help | grep -q "ctrl+s" || fail "retro view --help lacks the key names"

[ $fails -eq 0 ] && echo "view: ok" && exit 0
echo "view: $fails failure(s)"
exit 1
