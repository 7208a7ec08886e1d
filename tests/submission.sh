#!/bin/sh
# The generated submission, built alone with the course-style driver as the course builds it:
# gcc and clang, -O0 -g with ASan+UBSan and -O3, -Wall -Wextra -pedantic, -lm only, and no
# warning allowed. Then the course's public tests (several frames and maps in one process: the
# threads kept between frames, joined at exit, leak-free under ASan), the build without
# pthreads, and equality with `retro render -k naive -m course` on seeded random poses and
# sizes, at every ISA level and several thread counts.
set -u
retro=$1
shared=${RETRO_SHARED:-../shared}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

sh scripts/make-submission.sh "$tmp/render.c" || { echo "FAIL: generation"; exit 1; }
cp include/render.h tests/submission_driver.c "$tmp/"
for cc in gcc clang; do
  for flags in "-O0 -g -fsanitize=address -fsanitize=undefined" "-O3"; do
    name="$cc$(echo "$flags" | cut -c1-3 | tr -d ' -')"
    if ! (cd "$tmp" && $cc -Wall -Wextra -pedantic $flags -o "$name" render.c submission_driver.c -lm) \
         >"$tmp/cc.log" 2>&1; then
      fail "$cc $flags does not build: $(head -n 3 "$tmp/cc.log")"; continue
    fi
    [ -s "$tmp/cc.log" ] && fail "$cc $flags warns: $(head -n 3 "$tmp/cc.log")"
    if [ -d "$shared/course" ]; then
      for isa in avx512 avx2 sse2 none; do # every level the strip table can pick at
        case $isa in avx2) threads=3 ;; sse2) threads=1 ;; none) threads=4 ;; *) threads=2 ;; esac
        (cd "$tmp" && RETRO_PTHREADS=$threads RETRO_ISA=$isa "./$name" selftest "$(cd "$OLDPWD" && cd "$shared" && pwd)") \
          >"$tmp/self.log" 2>&1 || fail "$cc $flags isa $isa course tests: $(grep -v '^ok' "$tmp/self.log" | head -n 3)"
      done
    fi
  done
done
[ -d "$shared/course" ] || echo "skipped: $shared/course absent: no course frames checked"

# Where pthreads are not in libc (glibc before 2.34) the submission, linked with -lm only, must
# still build and render, on one thread: RETRO_PT_WEAK=1 makes the references weak as they are
# there, and renaming two of the functions makes them absent from this libc.
absent="-DRETRO_PT_WEAK=1 -Dpthread_create=retro_absent_pthread_create -Dpthread_join=retro_absent_pthread_join"
if (cd "$tmp" && gcc -Wall -Wextra -pedantic -O3 $absent -o nothreads render.c submission_driver.c -lm) \
     >"$tmp/cc.log" 2>&1 && [ ! -s "$tmp/cc.log" ]; then
  nm "$tmp/nothreads" | grep -q ' w retro_absent_pthread_create$' ||
    fail "without pthreads: pthread_create is not a weak reference"
  if [ -d "$shared/course" ]; then
    (cd "$tmp" && RETRO_PTHREADS=4 ./nothreads selftest "$(cd "$OLDPWD" && cd "$shared" && pwd)") \
      >"$tmp/self.log" 2>&1 || fail "without pthreads: course tests: $(grep -v '^ok' "$tmp/self.log" | head -n 3)"
  fi
else
  fail "without pthreads: does not build warning-free: $(head -n 3 "$tmp/cc.log")"
fi

# The course's flags do not turn contraction off and AVX-512 implies FMA: a fused a*b + c
# rounds once and can change a pixel on some pose no test happens to hit, so the object code
# itself must hold no FMA instruction.
for cc in gcc clang; do
  (cd "$tmp" && $cc -O3 -c render.c -o fma.o) 2>/dev/null || { fail "$cc -O3 -c"; continue; }
  n=$(objdump -d "$tmp/fma.o" | grep -cE 'vf(n)?m(add|sub)')
  [ "$n" -eq 0 ] || fail "$cc -O3 emits $n FMA instructions: contraction is not off"
done

# Random poses against naive mode course, on a generated map and the course maps when present.
maps="maps/test/alpine-200 maps/test/checker-2"
[ -d "$shared/course" ] && maps="$maps $shared/course/valley $shared/course/island"
awk 'BEGIN { srand(9); for (i = 0; i < 60; i++)
  printf "%d %d %d %.3f %.3f %d %d\n", 1 + int(rand() * 400), 1 + int(rand() * 300), int(rand() * 1200),
    rand() * 5000 - 2000, rand() * 5000 - 2000, int(rand() * 500) - 100, int(rand() * 1440) - 720 }' >"$tmp/poses"
n=0
while read -r W H D x y z a; do
  set -- $maps
  shift $((n % $#)); map=$1; n=$((n + 1))
  "$retro" render "$map" -k naive -m course -s "${W}x$H" -d "$D" -p "$x,$y" -z "$z" -a "$a" -o "$tmp/ref.ppm" ||
    { fail "retro render $map pose $n"; continue; }
  isa=$(echo "avx512 avx2 sse2 none" | cut -d' ' -f$((n % 4 + 1)))
  # The thread count (RETRO_PTHREADS, 1..64; anything else means the default 2), and the
  # build without pthreads every seventh pose.
  threads=$(echo "1 2 3 5 64 0 2x" | cut -d' ' -f$((n % 7 + 1)))
  bin=gccO3
  [ $((n % 7)) -eq 3 ] && [ -x "$tmp/nothreads" ] && bin=nothreads
  RETRO_PTHREADS=$threads RETRO_ISA=$isa "$tmp/$bin" frame "$map" "$W" "$H" "$D" "$x" "$y" "$z" "$a" "$tmp/got.ppm" &&
    cmp -s "$tmp/ref.ppm" "$tmp/got.ppm" || fail "pose $n ($map ${W}x$H D $D at $x,$y z $z a $a, isa $isa, threads $threads, $bin) differs from naive"
done <"$tmp/poses"
echo "submission: $n random poses, $fails failures"
[ "$fails" -eq 0 ]
