#!/bin/sh
# Hostile environment and runs (issue 13): every environment variable retro reads is parsed
# strictly (exit 2, one line, nothing written), valid settings render the same bytes, and a
# render that may take long says so first.
set -u
retro=$1
. tests/lib/hostile.sh
m="$tmp/m"
mkdir -p "$m"
"$retro" genmap alpine --size 64 -o "$m/a" || { echo "FAIL: genmap"; exit 1; }
R="$retro render $m/a -s 40x30"

for v in 2147483647 0 -1 abc '' ' 64' 64x +64 0x40 16385 99999999999999999999; do
  bad "RETRO_OMP_CHUNK='$v'" env RETRO_OMP_CHUNK="$v" $R -k omp -o OUT
done
for v in 0 -1 65 abc '' ' 2' 2x +2 0x2 99999999999999999999; do
  bad "RETRO_PTHREADS='$v'" env RETRO_PTHREADS="$v" $R -k pthreads -o OUT
done
for v in 3 65 0 -1 abc '' ' 16' 16x 0x10 99999999999999999999; do
  bad "RETRO_CONE_SECTORS='$v'" env RETRO_CONE_SECTORS="$v" $R -o OUT
done
for v in 0 33 -1 abc '' ' 8' 8x 99999999999999999999; do
  bad "RETRO_CONE_R='$v'" env RETRO_CONE_R="$v" $R -o OUT
done
for v in bogus '' AVX2 'sse2 ' 'avx2
x'; do
  bad "RETRO_ISA='$v'" env RETRO_ISA="$v" $R -o OUT
done
bad "RETRO_SHARED=''" env RETRO_SHARED= $R -o OUT
bad "RETRO_SHARED too long" env RETRO_SHARED="$(printf '%500s' '' | tr ' ' d)" $R -o OUT
# The OpenMP runtime reads OMP_NUM_THREADS before retro starts and may warn on its own (libgomp
# does); retro's refusal is then the one line of its own.
allow='^libgomp: '
for v in 0 -2 abc '' '4,' ',4' '4,,2' 1048577; do
  bad "OMP_NUM_THREADS='$v'" env OMP_NUM_THREADS="$v" $R -k omp -o OUT
done
allow=""
bad "env errors name the variable" env RETRO_OMP_CHUNK=2147483647 $R -k omp -o OUT
says "variable named" "RETRO_OMP_CHUNK"

# Valid settings: the omp kernel's chunking never changes a byte.
"$retro" render "$m/a" -s 40x30 -k naive -o "$tmp/ref.ppm" || { echo "FAIL: reference"; exit 1; }
for c in 1 3 64 16384; do
  good "RETRO_OMP_CHUNK=$c" env RETRO_OMP_CHUNK=$c $R -k omp -o OUT
  cmp -s "$out/new.ppm" "$tmp/ref.ppm" || { echo "FAIL: RETRO_OMP_CHUNK=$c changed the frame"; fails=$((fails + 1)); }
done
for v in 1 '4,2' 3; do
  good "OMP_NUM_THREADS=$v" env OMP_NUM_THREADS="$v" $R -k omp -o OUT
  cmp -s "$out/new.ppm" "$tmp/ref.ppm" || { echo "FAIL: OMP_NUM_THREADS=$v changed the frame"; fails=$((fails + 1)); }
done
for v in 1 3 64; do
  good "RETRO_PTHREADS=$v" env RETRO_PTHREADS="$v" $R -k pthreads -o OUT
  cmp -s "$out/new.ppm" "$tmp/ref.ppm" || { echo "FAIL: RETRO_PTHREADS=$v changed the frame"; fails=$((fails + 1)); }
done
# The largest accepted count, with a single-thread kernel: 64 threads (the cap) of libomp
# under the sanitizers on two cores would only measure the machine.
good "OMP_NUM_THREADS=1048576" env OMP_NUM_THREADS=1048576 $R -k ybuffer -o OUT
good "RETRO_ISA=none" env RETRO_ISA=none $R -o OUT
env RETRO_ISA=bogus "$retro" render --help >/dev/null 2>&1 ||
  { echo "FAIL: --help refused under a bad environment"; fails=$((fails + 1)); }

# Bounded work: the slow reference at a huge size announces itself before rendering (stopped
# by timeout long before it would end), and nothing is written; a small frame warns of nothing.
rm -f "$out/new.ppm"
timeout 5 "$retro" render "$m/a" -k naive -s 4096x4096 -d 4194304 -o "$out/new.ppm" 2>"$tmp/err"
rc=$?
if [ "$rc" -ne 124 ] || [ "$(wc -l <"$tmp/err")" -ne 1 ] || [ -e "$out/new.ppm" ]; then
  echo "FAIL: long naive render: exit $rc, stderr '$(cat "$tmp/err")'"; fails=$((fails + 1))
fi
says "long render warned" "warning: each frame may take about .* h (kernel naive"
good "a small frame" $R -k naive -o OUT
# A small frame warns of nothing: its one stderr line says what ran (issue 19), no more.
grep -q 'warning' "$tmp/err" && { echo "FAIL: a small frame warned '$(cat "$tmp/err")'"; fails=$((fails + 1)); }
[ "$(wc -l <"$tmp/err")" -le 1 ] || { echo "FAIL: a small frame printed '$(cat "$tmp/err")'"; fails=$((fails + 1)); }

echo "hostile env: $fails failures"
[ "$fails" -eq 0 ]
