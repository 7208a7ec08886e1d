#!/bin/sh
# make install PREFIX=... gives a library others can link: retro.pc, libretro.so with a
# soname and libretro.a, the headers and a man page; a program that defines its own render()
# builds with `pkg-config --cflags --libs retro` against the shared library and with --static
# against the static one, and runs. The installed retro works outside the source tree:
# --version, and verify with --maps and with maps it generates into its cache.
# usage: install.sh RETRO   (the build folder is RETRO's ../..)
set -u
here=$(pwd)
build=$(dirname "$(dirname "$1")")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
fail() { echo "FAIL: $*"; exit 1; }
make --no-print-directory install BUILD="$build" PREFIX="$prefix" >"$tmp/log" 2>&1 ||
  { tail -n 20 "$tmp/log"; fail "make install failed"; }
for f in bin/retro lib/libretro.a lib/libretro.so lib/libretro.so.0 lib/pkgconfig/retro.pc \
  include/retro/retro.h include/retro/render.h share/man/man1/retro.1; do
  [ -e "$prefix/$f" ] || fail "make install did not install $f"
done
readelf -d "$prefix/lib/libretro.so" | grep -q 'SONAME.*\[libretro\.so\.0\]' || fail "libretro.so has no soname libretro.so.0"
for lib in "$prefix/lib/libretro.so" "$prefix/lib/libretro.a"; do
  course=$(nm -g --defined-only "$lib" 2>/dev/null | awk 'NF == 3 { print $3 }' |
    grep -E '^(render|draw_line|update_player|bonus_implemented)$')
  [ -z "$course" ] || fail "$lib exports the course names: $course"
  other=$(nm -g --defined-only "$lib" 2>/dev/null | awk 'NF == 3 && $2 ~ /[TDBR]/ { print $3 }' |
    grep -v '^retro_' | grep -v '^_' | head -n 3)
  [ -z "$other" ] || fail "$lib exports names without the retro_ prefix: $other"
done
grep -q '^\.TH RETRO' "$prefix/share/man/man1/retro.1" || fail "retro.1 is not a man page"
grep -q 'genmap' "$prefix/share/man/man1/retro.1" || fail "retro.1 does not list the commands"
grep -q '^\.SS "retro accuracy"' "$prefix/share/man/man1/retro.1" || fail "retro.1 lacks the subcommands' options"
# A sanitized build's library needs the sanitizer runtime in the program too.
san=""
nm "$prefix/lib/libretro.a" 2>/dev/null | grep -q __asan_ && san="-fsanitize=address,undefined"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
cc=${CC:-cc}
# shellcheck disable=SC2046
$cc -std=c11 -Wall -Wextra -Werror $san tests/install/own_render.c $(pkg-config --cflags --libs retro) \
  -o "$tmp/own-shared" 2>"$tmp/cc.log" || { cat "$tmp/cc.log"; fail "linking with pkg-config --libs retro (shared)"; }
LD_LIBRARY_PATH="$prefix/lib" "$tmp/own-shared" >"$tmp/out" || fail "the program linked shared did not run"
ldd_out=$(LD_LIBRARY_PATH="$prefix/lib" ldd "$tmp/own-shared")
printf '%s\n' "$ldd_out" | grep -q "libretro.so.0 => $prefix/lib/libretro.so.0" || fail "not linked to the installed libretro.so.0"
static=$(pkg-config --libs --static retro | sed 's/-lretro/-Wl,-Bstatic -lretro -Wl,-Bdynamic/')
# shellcheck disable=SC2086
$cc -std=c11 -Wall -Wextra -Werror $san tests/install/own_render.c $(pkg-config --cflags retro) $static \
  -o "$tmp/own-static" 2>"$tmp/cc.log" || { cat "$tmp/cc.log"; fail "linking with pkg-config --static --libs retro"; }
ldd "$tmp/own-static" | grep -q libretro && fail "the static program still needs libretro.so"
"$tmp/own-static" | cmp -s - "$tmp/out" || fail "the static and shared programs disagree"
# Outside the source tree.
mkdir "$tmp/elsewhere" && cd "$tmp/elsewhere" || exit 1
"$prefix/bin/retro" --version | grep -q '^retro [0-9]' || fail "retro --version"
"$prefix/bin/retro" verify --quick -k ybuffer --maps "$here/maps" >"$tmp/v1" 2>&1 ||
  { tail -n 5 "$tmp/v1"; fail "installed retro verify --maps failed outside the tree"; }
XDG_CACHE_HOME="$tmp/cache" RETRO_SHARED=/nonexistent "$prefix/bin/retro" verify --quick -k ybuffer >"$tmp/v2" 2>&1 ||
  { tail -n 5 "$tmp/v2"; fail "installed retro verify failed outside the tree without --maps"; }
grep -q "maps from $tmp/cache/retro/maps" "$tmp/v2" || fail "verify did not say where its maps are"
cmp -s "$tmp/cache/retro/maps/alpine.pgm" "$here/maps/alpine.pgm" || fail "the cache's alpine differs from make maps'"
[ -z "$(ls -A "$tmp/elsewhere")" ] || fail "verify wrote into the current folder: $(ls -A "$tmp/elsewhere")"
echo "ok: make install: retro.pc, libretro.so.0 and .a linked by a program with its own render(); retro runs outside the tree"
