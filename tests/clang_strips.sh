#!/bin/sh
# The SIMD strips built by clang keep their samples in registers: no strip of modes exact and
# lod calls memmove. clang once turned the shift of the samples loaded ahead into a memmove of
# the whole array on every step (docs/studies/KERNEL_STUDIES.md, "Which compiler", measures what
# that cost). Times are for benchmarks; this checks the code itself: the three ISA files built
# by clang with the suite's own flags, and the calls their exact strips make. Without clang it
# says so and passes (the suite builds with cc).
# usage: clang_strips.sh RETRO
set -u
cc=${CLANG:-clang}
if ! command -v "$cc" >/dev/null 2>&1; then
  echo "SKIP: $cc not found (make deps installs it)"
  exit 0
fi
. tests/lib/cli_test.sh
objs="src/arch/x86/kernel_simd_sse2.o src/arch/x86/kernel_simd_avx2.o src/arch/x86/kernel_simd_avx512.o"
targets=
for o in $objs; do targets="$targets $tmp/$o"; done
# the caller's make variables (CC=gcc, SAN=... under make asan) must not reach this build
# shellcheck disable=SC2086
if ! env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s BUILD="$tmp" CC="$cc" $targets >"$tmp/log" 2>&1; then
  echo "FAIL: the strips do not build with $cc:"
  head -n 20 "$tmp/log"
  exit 1
fi
strips=0
for o in $objs; do
  # function by function: each exact or lod strip, and the relocations of its calls
  found=$(objdump -dr "$tmp/$o" | awk '
    /^[0-9a-f]+ <[^>]*>:$/ { fn = $2; gsub(/[<>:]/, "", fn); if (fn ~ /_strip_lod[01]_fog[01]_/) n++ }
    fn ~ /_strip_lod[01]_fog[01]_/ && /R_X86_64_PLT32[ \t]+memmove/ { print fn }
    END { print "strips", n + 0 }')
  n=$(printf '%s\n' "$found" | sed -n 's/^strips //p')
  bad=$(printf '%s\n' "$found" | grep -v '^strips ' | sort -u)
  strips=$((strips + n))
  if [ "$n" -eq 0 ]; then
    fail "$o: no exact strip found (renamed? this test looks for *_strip_lod<0|1>_fog<0|1>_*)"
  elif [ -n "$bad" ]; then
    fail "$o: built by $cc, these strips call memmove (their samples live in memory):"
    printf '%s\n' "$bad" | sed 's/^/  /'
  fi
done
[ "$fails" -eq 0 ] || exit 1
echo "ok: $strips exact and lod strips built by $cc ($($cc --version | head -n 1)), none calls memmove"
