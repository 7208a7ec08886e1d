#!/bin/sh
# Hostile files (issue 13): special files, symlink loops, huge declared sizes in tiny files,
# trailing data, NUL bytes, maxvals, PNG layouts, scenes with NUL bytes, output paths, and the
# genmap pair. Each bad case: exit 2, one stderr line, nothing created, an existing output kept
# (tests/lib/hostile.sh).
set -u
retro=$1
. tests/lib/hostile.sh
m="$tmp/m"
mkdir -p "$m"
"$retro" genmap ramp --size 8 -o "$m/ok" && "$retro" genmap ramp --size 8 --png -o "$m/png" ||
  { echo "FAIL: genmap"; exit 1; }
pgm() { cp "$m/ok.ppm" "$m/$1.ppm"; }  # NAME.pgm made by the caller, a valid colour map beside
R="$retro render"

# --- height and colour maps -------------------------------------------------------------
ln -s /dev/zero "$m/zero.pgm"; pgm zero
mkfifo "$m/fifo.pgm"; pgm fifo
mkdir "$m/dir.pgm"; pgm dir
ln -s "$m/loop2.pgm" "$m/loop1.pgm"; ln -s "$m/loop1.pgm" "$m/loop2.pgm"; pgm loop1
cp "$m/ok.pgm" "$m/cfifo.pgm"; mkfifo "$m/cfifo.ppm"
cp "$m/ok.pgm" "$m/czero.pgm"; ln -s /dev/zero "$m/czero.ppm"
printf 'P5\n16384 16384\n255\nxy' >"$m/huge.pgm"; pgm huge
cp "$m/ok.pgm" "$m/hugec.pgm"; printf 'P6\n16384 16384\n255\nxyz' >"$m/hugec.ppm"
cp "$m/ok.pgm" "$m/trail.pgm"; printf 'junk' >>"$m/trail.pgm"; pgm trail
cp "$m/ok.pgm" "$m/trailc.pgm"; cp "$m/ok.ppm" "$m/trailc.ppm"; printf 'P6\n1 1\n255\nabc' >>"$m/trailc.ppm"
cp "$m/ok.pgm" "$m/padded.pgm"; truncate -s 3G "$m/padded.pgm"; pgm padded  # sparse: no disk
printf 'P5\n8\0008\n255\n' >"$m/nulhdr.pgm"; head -c 64 /dev/zero >>"$m/nulhdr.pgm"; pgm nulhdr
printf 'P5\n8 8\n255\0' >"$m/nulsep.pgm"; head -c 64 /dev/zero >>"$m/nulsep.pgm"; pgm nulsep
for v in 0 256 65535; do
  printf 'P5\n8 8\n%s\n' "$v" >"$m/max$v.pgm"; head -c 128 /dev/zero >>"$m/max$v.pgm"; pgm "max$v"
done
{ printf 'P5\n#'; head -c 5000 /dev/zero | tr '\0' c; printf '\n8 8\n255\n'; head -c 64 /dev/zero; } >"$m/longhdr.pgm"
pgm longhdr
# PNG colour maps: trailing data, truncation, no IEND, an invalid colour type, a declared size
# far above the file, and a tiny image padded with a 2 MiB chunk.
png() { cp "$m/ok.pgm" "$m/$1.pgm"; }
n=$(wc -c <"$m/png.png")
png ptrail; { cat "$m/png.png"; printf 'x'; } >"$m/ptrail.png"
png ptrunc; head -c $((n - 20)) "$m/png.png" >"$m/ptrunc.png"
png pnoend; head -c $((n - 12)) "$m/png.png" >"$m/pnoend.png"
png ptype; { head -c 25 "$m/png.png"; printf '\005'; tail -c +27 "$m/png.png"; } >"$m/ptype.png"
png pbig; { head -c 16 "$m/png.png"; printf '\000\000\100\000\000\000\100\000'; tail -c +25 "$m/png.png"; } >"$m/pbig.png"
png ppad; { head -c $((n - 12)) "$m/png.png"; printf '\000\040\000\000tEXt'; head -c 2097156 /dev/zero
  tail -c 12 "$m/png.png"; } >"$m/ppad.png"

for c in zero fifo dir loop1 cfifo czero huge hugec trail trailc padded nulhdr nulsep max0 max256 \
  max65535 longhdr ptrail ptrunc pnoend ptype pbig ppad; do
  bad "map $c" $R "$m/$c" -s 16x12 -o OUT
done
printf '[scene]\nmap = ok\n[morph]\nmap = fifo\n' >"$m/mscene.scene"
bad "morph keyframe is a FIFO" $R "$m/mscene.scene" -s 16x12 -o OUT
bad "map zero" $R "$m/zero" -o OUT
says "device named" "is a device"
bad "map fifo" $R "$m/fifo" -o OUT
says "FIFO named" "is a FIFO"
bad "map trail" $R "$m/trail" -o OUT
says "trailing data named" "trailing data"
good "valid PGM + PPM" $R "$m/ok" -s 16x12 -o OUT
good "valid PGM + PNG" $R "$m/png" -s 16x12 -o OUT

# --- scene files --------------------------------------------------------------------------
s="$m/ok.scene"  # scenes sit beside the map: map = ok
printf '[scene]\nmap = ok\n[screen]\nheight = 30\000width = 40\n' >"$m/nul1.scene"
printf '[scene]\nmap = ok\n[camera]\nx = 5\000junk\n' >"$m/nul2.scene"
{ printf '[scene]\nmap = ok\n[camera]\nx = 1\000'; head -c 3000 /dev/zero | tr '\0' a
  printf '\n[screen]\nwidth = 16\nheight = 12\n[bogus]\n'; } >"$m/nul3.scene"
ln -s /dev/zero "$m/zero.scene"; mkfifo "$m/fifo.scene"; mkdir "$m/dir.scene"
printf '[scene]\nmap = ok\n[screen]\ndistance = 0\n' >"$m/d0.scene"
for c in nul1 nul2 nul3 zero fifo dir d0; do
  bad "scene $c" $R "$m/$c.scene" -o OUT
done
bad "scene nul1" $R "$m/nul1.scene" -o OUT
says "NUL line number" "nul1.scene:4: NUL byte"
bad "scene nul3" $R "$m/nul3.scene" -o OUT
says "NUL in a long line, its line number" "nul3.scene:4: "
printf '[scene]\nmap = ok\n[camera]\nx = 1e-320\ny = -1e-40\n[screen]\nwidth = 16\nheight = 12\n' >"$s"
good "subnormal scene position" $R "$s" -o OUT
good "subnormal -p" $R "$m/ok" -s 16x12 -p 1e-40,-1e-45 -o OUT

# --- the distance: one rule -----------------------------------------------------------------
for d in 0 -1 -2147483648 4194305; do bad "-d $d" $R "$m/ok" -s 16x12 -d "$d" -o OUT; done
good "-d 1 (sky only)" $R "$m/ok" -s 16x12 -d 1 -o OUT

# --- output paths ----------------------------------------------------------------------------
mkdir "$out/isdir.ppm"
bad "output is a directory" $R "$m/ok" -s 16x12 -o "$out/isdir.ppm"
rmdir "$out/isdir.ppm"
long() { printf "%$1s" "" | tr ' ' n; }
for len in 245 251 255; do
  name="$out/$(long $((len - 4))).ppm"
  if ! $R "$m/ok" -s 16x12 -o "$name" 2>"$tmp/err" || [ ! -s "$name" ]; then
    echo "FAIL: a $len-byte output name: $(cat "$tmp/err")"; fails=$((fails + 1))
  fi
  rm -f "$name"
done
bad "a 256-byte output name" $R "$m/ok" -s 16x12 -o "$out/$(long 252).ppm"

# --- genmap: the pair is written whole or not at all -------------------------------------------
g="$tmp/g"
mkdir -p "$g"
"$retro" genmap flat --size 8 -o "$g/pair" && cp "$g/pair.pgm" "$g/pgm.orig" && cp "$g/pair.ppm" "$g/ppm.orig"
for broken in ppm pgm png; do
  rm -rf "$g/pair.ppm" "$g/pair.png" "$g/pair.pgm"
  cp "$g/pgm.orig" "$g/pair.pgm"; cp "$g/ppm.orig" "$g/pair.ppm"
  rm -rf "$g/pair.$broken"; mkdir "$g/pair.$broken"
  flag=; [ $broken = png ] && flag=--png
  timeout 20 "$retro" genmap alpine --size 8 $flag -o "$g/pair" 2>"$tmp/err"
  rc=$?
  ok=1
  [ $broken = pgm ] || cmp -s "$g/pair.pgm" "$g/pgm.orig" || ok=0
  [ $broken = ppm ] || cmp -s "$g/pair.ppm" "$g/ppm.orig" || ok=0
  [ -e "$g/pair.png" ] && [ ! -d "$g/pair.png" ] && ok=0
  ls -A "$g" | grep -q retro-tmp && ok=0
  if [ "$rc" -ne 2 ] || [ "$(wc -l <"$tmp/err")" -ne 1 ] || [ $ok -ne 1 ]; then
    echo "FAIL: genmap with pair.$broken a directory: exit $rc, changed or left files: $(ls -A "$g")"
    fails=$((fails + 1))
  fi
done

echo "hostile files: $fails failures"
[ "$fails" -eq 0 ]
