#!/bin/sh
# retro-bench runs one tiny case and records it: in the JSON (with its counters), in BENCH.md
# and in the charts script. A functional check, not a timing one: one short repetition.
# usage: bench_smoke.sh RETRO   (retro-bench is taken from the same directory)
set -u
bench="$(dirname "$1")/retro-bench"
case=exact/flat-64/naive/1t/32x24/D16
if [ ! -x "$bench" ]; then
  echo "FAIL: $bench not built (make check builds it)"
  exit 1
fi
if [ ! -f maps/test/flat-64.pgm ]; then
  echo "FAIL: maps/test/flat-64 missing (sh scripts/make-maps.sh RETRO test)"
  exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# run_bench DIR WHAT ARGS...: one short repetition of the cases ARGS select, the report and
# DIR/bench.json in DIR, or the test fails with retro-bench's output. No re-timing unless ARGS
# ask for it (--retime=N comes later and wins), so that these runs do the same on any machine.
run_bench() {
  dir=$1 what=$2
  shift 2
  mkdir -p "$dir"
  if ! "$bench" --retime=0 "$@" --benchmark_repetitions=1 --benchmark_min_time=0.001 --benchmark_min_warmup_time=0 \
    --report="$dir" --benchmark_out="$dir/bench.json" --benchmark_out_format=json >"$dir/out" 2>&1; then
    echo "FAIL: retro-bench exited with an error$what:"
    cat "$dir/out"
    exit 1
  fi
}
run_bench "$tmp" "" --scene=maps/test/flat-64 --size=32x24 --distance=16 --charts="$tmp/charts.gp" \
  --benchmark_filter="^($case|peer/flat-64/classic-voxelspace/1t/32x24/D16)\$"
fail=0
check() { # FILE PATTERN WHAT
  if ! grep -q -- "$2" "$1"; then
    echo "FAIL: $3 ($1 lacks $2)"
    fail=1
  fi
}
check "$tmp/bench.json" "\"name\": \"$case\"" "the case is not in the JSON"
check "$tmp/bench.json" '"ms/frame"' "no ms/frame counter"
check "$tmp/bench.json" '"Mpixel/s"' "no Mpixel/s counter"
check "$tmp/bench.json" '"retro_binding"' "no binding in the JSON context"
check "$tmp/BENCH.md" '| `naive` | 1 |' "no naive row in BENCH.md"
check "$tmp/charts.gp" '"naive"' "no naive bar in the charts script"
check "$tmp/out" "$case" "no progress line for the case"
# the speedup chart's key below the plot: outside at the top, gnuplot put it above the title
sed -n '/bench-speedup/,/^plot/p' "$tmp/charts.gp" | grep -q '^set key below$' ||
  { echo "FAIL: the speedup chart's key is not below the plot"; fail=1; }
# A noisy run's warning on the speedup chart, a clause per line, each short enough to fit the
# 800-pixel chart (on one line it ran past both edges). Whether this run is noisy depends on
# the machine, so the check applies when it is.
note=$(sed -n 's/^set label 1 "\(.*\)" at graph.*/\1/p' "$tmp/charts.gp")
if [ -n "$note" ]; then
  long=$(printf '%s\n' "$note" | sed 's/\\n/\n/g' | awk 'length > 70')
  [ -z "$long" ] || { echo "FAIL: a line of the chart's noisy note is too long for the chart: $long"; fail=1; }
fi
check "$tmp/BENCH.md" '^| machine | \(quiet\|busy\): ' "BENCH.md does not say how busy the machine was"
check "$tmp/BENCH.md" '^| settings | full run |' "BENCH.md does not say whether the run was quick"
check "$tmp/BENCH.md" '^### Peer algorithm: the classic voxel-space demo' "no peer table in BENCH.md"
check "$tmp/BENCH.md" '^| flat-64 | [0-9]' "no peer row in BENCH.md"
python3 scripts/bench-csv.py "$tmp/bench.json" >"$tmp/bench.csv" 2>&1
check "$tmp/bench.csv" "^$case,exact,flat-64,naive,1,32x24,16,\(repetition\|median\),[0-9]" "make bench-csv's converter lost the case"
check "$tmp/BENCH.md" 'library_build_type' "BENCH.md does not explain library_build_type"
check "$tmp/bench.json" '"retro_quick": "false"' "the JSON does not record whether the run was quick"
# --no-skip: each mode exact case also timed with skipping off, side by side, with the samples
# the counting build evaluates per frame beside the time (docs/SKIPPING.md)
yb=exact/flat-64/ybuffer/1t/32x24/D16
run_bench "$tmp/ns" " with --no-skip" --scene=maps/test/flat-64 --size=32x24 --distance=16 --no-skip \
  --modes=exact --charts="$tmp/ns.gp" --benchmark_filter="^exact/flat-64/ybuffer/1t/32x24/D(16|100)(/noskip)?\$"
check "$tmp/ns/bench.json" "\"name\": \"$yb/noskip\"" "--no-skip planned no twin"
check "$tmp/ns/bench.json" "\"name\": \"$yb\"" "--no-skip lost the skipping case"
check "$tmp/ns/bench.json" '"evaluated/frame"' "no evaluated/frame counter"
check "$tmp/ns/BENCH.md" '| `ybuffer` (no skipping) | 1 |' "no row without skipping in BENCH.md"
check "$tmp/ns.gp" '"ybuffer, no skipping"' "no line without skipping in the charts script"
# the sweep charts pad their x range (a point on the border lost its tick label) and keep the
# key below the plot, clear of the lines
check "$tmp/ns.gp" '^set xrange \[[0-9.]*:[0-9.]*\]$' "the sweep charts' x range is not set"
check "$tmp/ns.gp" '^set key below$' "the sweep charts' key is not below the plot"

# The large-frame pair (issue 18's skipping ratio): omp with and without skipping at 1920x1080,
# D 4000, planned without --no-skip, and its table with the ratio, the ratio of the pairs timed
# in turn after the run (its median between its quartiles) and the geometric means.
run_bench "$tmp/large" " on the large-frame pair" --scene=maps/test/flat-64 --modes=exact \
  --benchmark_filter="^exact/flat-64/omp/[0-9]+t/1920x1080/D4000(/noskip)?/real_time\$"
check "$tmp/large/bench.json" '"name": "exact/flat-64/omp/[0-9]*t/1920x1080/D4000/noskip/real_time"' "no large-frame case without skipping"
check "$tmp/large/bench.json" '"name": "exact/flat-64/omp/[0-9]*t/1920x1080/D4000/real_time"' "no large-frame case with skipping"
check "$tmp/large/BENCH.md" '^### Occlusion skipping at a large frame (`omp`, [0-9]* threads, mode exact, 1920×1080, D 4000)' \
  "no large-frame table in BENCH.md"
check "$tmp/large/BENCH.md" '^| flat-64 | [0-9.]* | [0-9.]* | [0-9.]*× | [0-9.]*× ([0-9.]*–[0-9.]*) | ' \
  "no large-frame row with a ratio and one timed in turn"
check "$tmp/large/BENCH.md" '^| geomean (1 scenes) | [0-9.]* | [0-9.]* | [0-9.]*× | [0-9.]*× |' "no large-frame geometric mean"
check "$tmp/large/out" 'flat-64: 150 pairs timed in turn, ratio [0-9.]*$' "no progress line for the pairs timed in turn"
grep '^| flat-64 | ' "$tmp/large/BENCH.md" | sed 's/[×()–|]/ /g' | awk '{ exit !($6 <= $5 && $5 <= $7) }' ||
  { echo "FAIL: the in-turn ratio is not between its quartiles: $(grep '^| flat-64 | ' "$tmp/large/BENCH.md")"; fail=1; }

# The effect table's ratios timed in turn after the run (bench/in_turn.h): bilinear's fastest
# kernel against none's, the median between its quartiles; islands is a default scene.
run_bench "$tmp/fx" " on the effect pairs" --benchmark_filter='^effects/islands/(none|bilinear)/'
check "$tmp/fx/BENCH.md" '^| bilinear | [0-9.]* | [-+0-9]*% | [^|]* | [0-9.]* | [0-9.]*× | [0-9.]*× ([0-9.]*–[0-9.]*) |$' \
  "no bilinear row with a ratio timed in turn"
check "$tmp/fx/out" 'effects on islands: 1 sets timed in turn against none, 200 pairs each' "no progress line for the effect pairs"
grep '^| bilinear | ' "$tmp/fx/BENCH.md" | sed 's/.*| \([0-9.]*\)× (\([0-9.]*\)–\([0-9.]*\)) |$/\1 \2 \3/' |
  awk 'NF == 3 { ok = $2 <= $1 && $1 <= $3 } END { exit !ok }' ||
  { echo "FAIL: bilinear's in-turn ratio is not between its quartiles: $(grep '^| bilinear | ' "$tmp/fx/BENCH.md")"; fail=1; }

# Machine steadiness (bench/steady.h): the reference frame at checkpoints through the run, at one
# thread and at every core, each with its median, and the spread per thread count.
run_bench "$tmp/steady" " on the checkpoints" --scene=maps/test/flat-64 --size=32x24 --distance=16 \
  --benchmark_filter='^steady/'
check "$tmp/steady/BENCH.md" '^### Machine steadiness' "no steadiness section in BENCH.md"
check "$tmp/steady/BENCH.md" '^| 2 | [0-9]* s | [0-9.]* |' "no third checkpoint with a time and a median"
check "$tmp/steady/BENCH.md" '^| spread | | [0-9.]*% ([0-9.]* – [0-9.]*)' "no spread of the checkpoints"
check "$tmp/steady/bench.json" '"name": "steady/flat-64/[a-z0-9-]*/1t/32x24/D16/check00' "no first checkpoint in the JSON"
n=$(grep -c '"run_name": "steady/flat-64/[^"]*/1t/[^"]*/check[0-9]*' "$tmp/steady/bench.json")
if [ "$n" -lt 9 ]; then # three checkpoints at least, three repetitions each
  echo "FAIL: only $n single-thread checkpoint repetitions in the JSON"
  fail=1
fi
# The machine probes (bench/machine_probe.h) beside each single-thread checkpoint: clock and
# throughput on each core, memory on the first; a time per checkpoint, their spreads, and the
# counters in every 1-thread repetition.
cores=$(grep -m1 '^| checkpoint |' "$tmp/steady/BENCH.md" | grep -o 'clock, core [0-9]*' | wc -l)
[ "$(nproc)" -lt 2 ] || [ "$cores" -ge 2 ] || { echo "FAIL: the probes visited $cores of $(nproc) cores"; fail=1; }
probe_cols= counters=
for kind in clock throughput; do
  c=0
  while [ "$c" -lt "$cores" ]; do
    probe_cols="$probe_cols| $kind, core $c " counters="$counters;$kind probe ms, core $c"
    c=$((c + 1))
  done
done
probe_cols="$probe_cols| memory |" counters="${counters#;};memory probe ms" probes=$((2 * cores + 1))
check "$tmp/steady/BENCH.md" "^| checkpoint | at | 1 thread |.* threads $probe_cols\$" \
  "no probe columns in the steadiness table"
check "$tmp/steady/BENCH.md" "^| 2 | [0-9]* s | [0-9.]* | [0-9.]* \(| [0-9.]*[1-9][0-9.]* \)\{$probes\}|\$" \
  "no third checkpoint with $probes positive probe times"
check "$tmp/steady/BENCH.md" "^| spread | |.*\(| [0-9.]*% ([0-9.]* – [0-9.]*) \)\{$probes\}|\$" \
  "no spread of the probes"
IFS=';'
for counter in $counters; do
  m=$(grep -c "\"$counter\": [0-9]" "$tmp/steady/bench.json")
  [ "$m" -ge "$n" ] || { echo "FAIL: \"$counter\" in $m of the JSON's runs, fewer than its $n single-thread checkpoint repetitions"; fail=1; }
done
unset IFS
# A run the checkpoints call noisy says what the probes saw (bench/steady.cc, steady_probe_note).
if grep -q '^> \*\*Noisy run.\*\*.*across the run.s checkpoints' "$tmp/steady/BENCH.md"; then
  check "$tmp/steady/BENCH.md" '^> \*\*Noisy run.\*\*.* The clock probe.*r = ' "no probes' reading in the noisy note"
fi

# Re-timing (bench/retime.h): block 0, asked for, is timed again with its checkpoints; the JSON
# keeps only the last timing of each case and BENCH.md says what was re-timed.
run_bench "$tmp/retime" " when re-timing" --scene=maps/test/flat-64 --size=32x24 --distance=16 \
  --benchmark_filter='^steady/' --retime=1 --retime-block=0 --quiet-wait=0
check "$tmp/retime/out" '^  block 0: asked for (--retime-block)$' "block 0 was not re-timed when asked"
check "$tmp/retime/out" '^re-timing [1-9][0-9]* cases (block 0, 1 of 1 this round)$' "no re-timing pass"
# (the form scripts/readme-figures.py reads)
check "$tmp/retime/BENCH.md" "^Re-timed, of the run's [1-9][0-9]* blocks of cases (.*): [1-9][0-9]* blocks\\{0,1\\} ([1-9][0-9]* cases with their checkpoints) in round 1\\." \
  "BENCH.md does not say what was re-timed"
n=$(grep -c '"name": "steady/flat-64/[^"]*/1t/[^"]*/check00[^"]*_median"' "$tmp/retime/bench.json")
if [ "$n" != 1 ]; then
  echo "FAIL: checkpoint 0 has $n medians in the JSON after its re-timing, not 1"
  fail=1
fi
# The re-timing's budget (--retime-budget): a tenth of the first pass cannot hold block 0, which
# here is every case of the run, so it is left as it is and BENCH.md says it is still disturbed.
run_bench "$tmp/budget" " with a small re-timing budget" --scene=maps/test/flat-64 --size=32x24 --distance=16 \
  --benchmark_filter='^steady/' --retime=1 --retime-block=0 --quiet-wait=0 --retime-budget=0.1
check "$tmp/budget/out" '^  1 left as they are: the re-timing has taken its [0-9]* s (0.1× the first pass)$' \
  "--retime-budget=0.1 did not stop the re-timing"
if grep -q '^re-timing ' "$tmp/budget/out"; then
  echo "FAIL: --retime-budget=0.1 re-timed a block the budget cannot hold"
  fail=1
fi
check "$tmp/budget/BENCH.md" "Still disturbed when re-timing stopped: 1 block\\." \
  "BENCH.md does not say the block the budget left is still disturbed"
# The wait for a quiet machine before a round (--quiet-wait): it ends one way or the other, and
# BENCH.md says which: a round re-timed, or blocks left because the machine stayed slow.
run_bench "$tmp/wait" " when waiting for a quiet machine" --scene=maps/test/flat-64 --size=32x24 --distance=16 \
  --benchmark_filter='^steady/' --retime=1 --retime-block=0 --quiet-wait=5
if grep -q '^  the machine is quiet: the reference frame takes [0-9.]* ms (fastest [0-9.]* ms), after [0-9]* s$' "$tmp/wait/out"; then
  check "$tmp/wait/out" '^re-timing [1-9][0-9]* cases (block 0, 1 of 1 this round)$' "no re-timing pass after the machine was quiet"
  check "$tmp/wait/BENCH.md" "in round 1" "BENCH.md does not say what was re-timed after the wait"
elif grep -q '^  the machine stayed slow for [0-9]* s: ' "$tmp/wait/out"; then
  check "$tmp/wait/BENCH.md" "Still disturbed when re-timing stopped: 1 block, the machine having stayed slow" \
    "BENCH.md does not say the machine stayed slow"
else
  echo "FAIL: the wait for a quiet machine said neither quiet nor slow:"
  cat "$tmp/wait/out"
  fail=1
fi
for bad in --retime=x --retime=-1 --quiet-wait=-1 --quiet-wait=x --quiet-wait=nan --retime-budget=0 \
  --retime-budget=21 --retime-budget=x --retime-budget=nan --benchmark_out_format=csv; do
  "$bench" "$bad" >"$tmp/bad.out" 2>&1
  rc=$?
  if [ "$rc" != 2 ] || [ "$(wc -l <"$tmp/bad.out")" != 1 ]; then
    echo "FAIL: retro-bench $bad exited $rc with $(wc -l <"$tmp/bad.out") lines, not 2 with one:"
    cat "$tmp/bad.out"
    fail=1
  fi
done

# The submission's spread across its 10 runs (issue 18), on the course's valley when present.
if [ -d "${RETRO_SHARED:-../shared}/course" ]; then
  run_bench "$tmp/sub" " on the submission cases" --benchmark_filter='^submission/valley/'
  check "$tmp/sub/BENCH.md" '| submission spread | runs |$' "no spread column in the submission table"
  check "$tmp/sub/BENCH.md" '^| valley | [0-9.]* | – | – | [0-9.]* | [0-9.]*× | [0-9.]*% | 10 |$' \
    "the submission did not run 10 times with a spread"
  # each run's time is the median of its frames (BenchCase::frame_median), one per repetition
  n=$(grep -c '"frame median ms": [0-9]' "$tmp/sub/bench.json")
  if [ "$n" -lt 10 ]; then
    echo "FAIL: $n submission runs carry their frames' median in the JSON, not 10"
    fail=1
  fi
else
  echo "note: ${RETRO_SHARED:-../shared}/course absent: the submission spread is not checked"
fi

# A mesh row beside a voxel one, at a distance where the flat map is in view: its counters in
# the JSON and its row in BENCH.md's mesh table (counts are exact, times are not checked).
mcase=binary32/flat-64/mesh-zbuffer/1t/32x24/D200
run_bench "$tmp/mesh" " on the mesh case" --scene=maps/test/flat-64 --size=32x24 --distance=200 \
  --benchmark_filter="^($mcase/.*|exact/flat-64/ybuffer/1t/32x24/D200)\$"
# (its name carries the fixed iterations and repetitions: .../iterations:2/repeats:3)
check "$tmp/mesh/bench.json" "\"run_name\": \"$mcase/" "the mesh case is not in the JSON"
for counter in tri_submitted tri_drawn fragments triangles/s fragments/s; do
  check "$tmp/mesh/bench.json" "\"$counter\"" "no $counter counter on the mesh case"
done
check "$tmp/mesh/BENCH.md" '^### Mesh family: the same scenes and poses as triangles' "no mesh table in BENCH.md"
check "$tmp/mesh/BENCH.md" '^| flat-64 | `mesh-zbuffer` | [0-9.]* | [1-9][0-9]* | [1-9][0-9]* | [1-9][0-9]* | .* | [0-9]*× `ybuffer`/1t |' \
  "no mesh row with counts and a ratio to the voxel kernel in BENCH.md"
python3 scripts/bench-csv.py "$tmp/mesh/bench.json" >"$tmp/mesh/bench.csv" 2>&1
check "$tmp/mesh/bench.csv" "^$mcase[^,]*,binary32,flat-64,mesh-zbuffer,1,32x24,200," "make bench-csv's converter lost the mesh case"
# Bad values of retro-bench's own options: status 2, one line, no report written. These once
# ran (a distance of -5 or 0, trailing junk) or aborted on an allocation (a huge screen).
for bad in --distance=-5 --distance=0 --distance=800abc --size=640x480junk --size=100000x100000 \
  --size=0x5 --retime=99999999999 --retime=-1 --quiet-wait=nan --quiet-wait=1e9 --modes=fast; do
  rm -rf "$tmp/bad"
  "$bench" "$bad" --scene=maps/test/flat-64 --report="$tmp/bad" >"$tmp/bad.out" 2>"$tmp/bad.err"
  rc=$?
  if [ "$rc" -ne 2 ] || [ "$(wc -l <"$tmp/bad.err")" -ne 1 ] || [ -e "$tmp/bad" ]; then
    echo "FAIL: retro-bench $bad: want status 2, one line and no report; got $rc: $(cat "$tmp/bad.err")"
    fail=1
  fi
done
[ "$fail" = 0 ] && echo "ok: retro-bench timed $case and $mcase"
exit "$fail"
