#!/bin/sh
# The replay study of docs/studies/SKIPPING_LIMITS.md ("What the probes cost", "What the stores
# cost"): how a skipping frame of simd-avx512 splits between probing, the sample walk and the
# stores.
usage() {
  cat <<'EOF'
usage: scripts/study-replay.sh [-n N] [-o OUT.md] [--shared DIR]

Builds retro from a clone of HEAD with docs/studies/replay.patch applied (in a temporary
folder, removed at exit), then times simd-avx512 on one thread on the benchmark's six scenes
and poses at 640x480, D 800 and at 1920x1080, D 4000, in N interleaved rounds (default 7) of
four frames: with skipping, with free probes (each probe replays frame 0's answer), stores
only (each group replays frame 0's paint batches, no sample), and without skipping, then
omp on two threads with and without skipping.
Before timing, it checks that free probes give the same frame byte for byte and that stores
only cover the same pixels. Prints tables of the medians (ms per frame) and what they allow,
and writes it to OUT.md as well if given (only when the study completes).
  -n N          rounds per scene and size, 1..99 (default 7)
  -o OUT.md     also write the tables there
  --shared DIR  where course/ lies (default ../shared): without it, only the generated maps
Needs make deps, a CPU with AVX-512 and python3. Takes a few minutes; progress on stderr.
EOF
}
set -eu
die() { echo "study-replay: $*" >&2; exit 2; }
rounds=7 out= shared=../shared
while [ $# -gt 0 ]; do
  case $1 in
    -h|--help) usage; exit 0 ;;
    -n) [ $# -ge 2 ] || die "-n needs a count"; rounds=$2; shift 2 ;;
    -o) [ $# -ge 2 ] || die "-o needs a path"; out=$2; shift 2 ;;
    --shared) [ $# -ge 2 ] || die "--shared needs a folder"; shared=$2; shift 2 ;;
    *) die "unknown argument '$1' (--help lists them)" ;;
  esac
done
case $rounds in ''|*[!0-9]*) die "-n wants 1..99, not '$rounds'" ;; esac
[ "$rounds" -ge 1 ] && [ "$rounds" -le 99 ] || die "-n wants 1..99, not '$rounds'"
root=$(git rev-parse --show-toplevel 2>/dev/null) || die "run it inside the retro repository"
cd "$root"
grep -q avx512f /proc/cpuinfo 2>/dev/null || die "this CPU has no AVX-512: simd-avx512 does not run here"
command -v python3 >/dev/null || die "python3 not found"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
echo "study-replay: building HEAD $(git rev-parse --short HEAD) with docs/studies/replay.patch in $tmp" >&2
git clone -q "$root" "$tmp/retro"
git -C "$tmp/retro" apply "$root/docs/studies/replay.patch" || die "docs/studies/replay.patch no longer applies to HEAD"
make -C "$tmp/retro" -s -j2 build/bin/retro >"$tmp/build.log" 2>&1 || { tail -n 20 "$tmp/build.log" >&2; die "the study build failed"; }
study=$tmp/retro/build/bin/retro
make -s maps >/dev/null || die "make maps failed"

. scripts/bench-scenes.sh
cases="alpine islands canyon"
course=$shared/course
if [ -d "$course" ]; then
  cases="$cases valley island pyramids"
else
  echo "study-replay: $course absent: the course scenes are left out" >&2
fi

raw=$tmp/raw.txt
# frame STUDY RENDER-ARGS: simd-avx512's frame with RETRO_STUDY=STUDY into $tmp/STUDY.ppm (plain
# when empty); the switch needs frame 0 recorded, so a study frame is the second of two.
frame() {
  st=$1
  shift
  RETRO_STUDY=$st "$study" render "$@" -k simd-avx512 ${st:+--time 2} -o "$tmp/${st:-plain}.ppm" \
    >/dev/null 2>"$tmp/err" || die "$name: $(tail -n 1 "$tmp/err")"
}
# timed STUDY RENDER-ARGS: appends the median ms per frame of a timed run to the round's row
timed() {
  st=$1
  shift
  ms=$(RETRO_STUDY=$st "$study" render "$@" --time "$frames" 2>&1 | grep -o 'median [0-9.]*' | cut -d' ' -f2)
  case $ms in ''|*[!0-9.]*) die "$name: a timed render printed no median" ;; esac
  printf ' %s' "$ms" >>"$raw"
}
: >"$raw"
for size in "640x480 800 100" "1920x1080 4000 30"; do
  set -- $size
  wh=$1 D=$2 frames=$3
  for name in $cases; do
    echo "study-replay: $name at ${wh}, D $D: checking, then $rounds rounds" >&2
    # shellcheck disable=SC2046
    set -- $(bench_scene_args "$name" "$course") -s "$wh" -d "$D"
    frame "" "$@"
    frame probes "$@"
    frame stores "$@"
    cmp -s "$tmp/plain.ppm" "$tmp/probes.ppm" || die "$name: free probes changed the frame"
    python3 - "$tmp/plain.ppm" "$tmp/stores.ppm" <<'EOF' || die "$name: stores only covered other pixels"
import sys
def px(p):
    b = open(p, 'rb').read()
    _, size, _, data = b.split(b'\n', 3)
    return data
a, b = px(sys.argv[1]), px(sys.argv[2])
sky = bytes.fromhex('66a3ff')
sys.exit(any((a[i:i + 3] == sky) != (b[i:i + 3] == sky) for i in range(0, len(a), 3)))
EOF
    stats=$("$study" render "$@" -k simd-avx512 --stats -o "$tmp/stats.png" 2>/dev/null)
    evaluated=$(printf '%s\n' "$stats" | sed -n 's/^simd-avx512 evaluated: \([0-9]*\).*/\1/p')
    total=$(printf '%s\n' "$stats" | sed -n 's/^samples: \([0-9]*\).*/\1/p')
    ideal=$(printf '%s\n' "$stats" | sed -n 's/^ideal max bound evaluates: \([0-9.]*\)%.*/\1/p')
    [ -n "$evaluated" ] && [ -n "$total" ] && [ -n "$ideal" ] || die "$name: retro render --stats printed no counts"
    i=0
    while [ $i -lt "$rounds" ]; do
      printf '%s' "$wh $name $evaluated $total $ideal" >>"$raw"
      timed "" "$@" -k simd-avx512
      timed probes "$@" -k simd-avx512
      timed stores "$@" -k simd-avx512
      timed "" "$@" -k simd-avx512 --no-skip
      timed "" "$@" -k omp --threads 2
      timed "" "$@" -k omp --threads 2 --no-skip
      echo >>"$raw"
      i=$((i + 1))
    done
  done
done

python3 - "$raw" "$(git rev-parse --short HEAD)" "$rounds" >"$tmp/table.md" <<'EOF'
import math, os, statistics as st, sys, time, platform
rows = [l.split() for l in open(sys.argv[1])]
info = {}
for l in open('/proc/cpuinfo'):
    k, _, v = l.partition(':')
    info.setdefault(k.strip(), v.strip())
cpu = f"{info.get('model name', platform.machine())}, family {info.get('cpu family', '?')} model {info.get('model', '?')}"
# the rounds of each (size, scene), in the order they ran: their counts, and per timing its rounds
cells = {}
for r in rows:
    c = cells.setdefault((r[0], r[1]), {'counts': (int(r[2]), int(r[3]), float(r[4])), 't': [[] for _ in range(6)]})
    for k in range(6):
        c['t'][k].append(float(r[5 + k]))
# noise: each cell's rounds, (max - min) / median; the run is flagged when their median passes 10%
spreads = [(max(v) - min(v)) / st.median(v) for c in cells.values() for v in c['t']]
noise = st.median(spreads)
print(f"Replay study of {sys.argv[2]}, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, {cpu}, "
      f"{os.cpu_count()} CPUs; medians of {sys.argv[3]} interleaved rounds, ms per frame. Spread of a cell's "
      f"rounds, (max - min) / median: median {100 * noise:.1f}%, largest {100 * max(spreads):.1f}%.\n")
if noise > 0.10:
    print("> **Noisy run**: the median spread passes 10%; do not quote it.\n")
gm = lambda v: math.exp(sum(map(math.log, v)) / len(v))
for size in dict.fromkeys(size for size, _ in cells):
    names = [name for sz, name in cells if sz == size]
    t = {name: cells[size, name]['t'] for name in names}
    med = {name: [st.median(x) for x in t[name]] for name in names}
    print(f"**{size}**, ms per frame: `simd-avx512` on one thread with skipping, with free probes, stores only and "
          f"without skipping; `omp` on two threads with and without skipping.\n")
    print("| scene | skipping | free probes | stores only | no skipping | omp, skipping | omp, no skipping |")
    print("|---|" + "--:|" * 6)
    for name in names:
        print(f"| {name} | " + " | ".join(f"{v:.3f}" for v in med[name]) + " |")
    print(f"\n**{size}**, per scene: samples evaluated and the ideal bound's share of W x (D-1); no skipping over "
          f"skipping, over free probes and over stores only (one thread); the sample walk per 16-lane step (ns), with "
          f"skipping (free probes less stores only) and without (no skipping less stores only); the estimate for "
          f"the ideal bound's samples "
          f"with free probes (one thread, ms) and no skipping over it; omp's two threads over one with skipping, "
          f"the estimate divided by that, and omp's own no skipping over skipping.\n")
    print("| scene | evaluated | ideal bound | / skipping | / free probes | / stores only | walk, skipping "
          "| walk, no skipping | ideal, free probes | no skipping / that | omp speed-up | that on omp "
          "| omp: no skipping / skipping |")
    print("|---|" + "--:|" * 12)
    cols = {k: [] for k in ('skip', 'free', 'stores', 'walk', 'walk_all', 'ideal', 't_ideal', 'speedup', 'omp_ideal',
                            'omp_ratio')}
    for name in names:
        ev, total, ideal = cells[size, name]['counts']
        skip, free, stores, noskip, omp, omp_noskip = med[name]
        x = t[name]
        ratio = lambda a, b: st.median(p / q for p, q in zip(x[a], x[b]))
        # the walk: what free probes add to the stores, per 16-lane step of the samples evaluated;
        # then a frame that evaluated only the ideal bound's samples and probed for free
        step = (free - stores) / (ev / 16)
        t_ideal = stores + ideal / 100 * total / 16 * step
        v = dict(skip=ratio(3, 0), free=ratio(3, 1), stores=ratio(3, 2), walk=1e6 * step,
                 walk_all=1e6 * (noskip - stores) / (total / 16), t_ideal=t_ideal, ideal=noskip / t_ideal,
                 speedup=ratio(0, 4), omp_ratio=ratio(5, 4))
        v['omp_ideal'] = t_ideal / v['speedup']
        for k in cols:
            cols[k].append(v[k])
        print(f"| {name} | {100 * ev / total:.1f}% | {ideal:.1f}% | {v['skip']:.2f}x | {v['free']:.2f}x | "
              f"{v['stores']:.2f}x | {v['walk']:.1f} | {v['walk_all']:.1f} | {t_ideal:.3f} | {v['ideal']:.2f}x | "
              f"{v['speedup']:.2f}x | {v['omp_ideal']:.3f} | {v['omp_ratio']:.2f}x |")
    g = {k: gm(v) for k, v in cols.items()}
    print(f"| geomean | | | {g['skip']:.2f}x | {g['free']:.2f}x | {g['stores']:.2f}x | {g['walk']:.1f} | "
          f"{g['walk_all']:.1f} | {g['t_ideal']:.3f} | {g['ideal']:.2f}x | {g['speedup']:.2f}x | "
          f"{g['omp_ideal']:.3f} | {g['omp_ratio']:.2f}x |\n")
EOF
cat "$tmp/table.md"
if [ -n "$out" ]; then
  cp "$tmp/table.md" "$out.tmp.$$" && mv "$out.tmp.$$" "$out" || { rm -f "$out.tmp.$$"; die "cannot write $out"; }
  echo "study-replay: wrote $out" >&2
fi
