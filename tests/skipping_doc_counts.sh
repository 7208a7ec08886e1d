#!/bin/sh
# The skipping docs' tables of counts (docs/studies/SKIPPING_LIMITS.md: "How far a max bound can
# go": lanes walking alone; "Other bounds at the same granularity"; "Window or schedule"; "Cone
# steps"; docs/SKIPPING.md: "Modes truth and fixed") against `retro render --stats` of the same
# frames, rendered here. Counts are exact and the same on any machine, so a change to the walk,
# the probe or the counting that moves one fails this test until the table is written again from
# --stats. Rows of the course's scenes are skipped, with a message, where ../shared/course is
# absent, and the simd-avx512 columns where this CPU does not run AVX-512.
set -u
retro=$1
. tests/lib/cli_test.sh
course=${RETRO_SHARED:-../shared}/course
docs="docs/SKIPPING.md docs/studies/SKIPPING_LIMITS.md"
doc="docs/SKIPPING.md or docs/studies/SKIPPING_LIMITS.md" # for messages

. scripts/bench-scenes.sh
# rows HEADER: the rows of the table under that header line, separator left out
rows() {
  # shellcheck disable=SC2086
  awk -v h="$1" '$0 == h { on = 1; getline; next } on && /^\|/ { print; next } on { exit }' $docs
}
# stats SCENE SIZE D [MODE]: the path of that frame's --stats output (mode exact by default),
# rendered once
stats() {
  mode=${4:-exact}
  out=$tmp/$1-$2-$3-$mode.txt
  if [ ! -f "$out" ]; then
    # shellcheck disable=SC2046
    "$retro" render $(bench_scene_args "$1" "$course") -m "$mode" -s "$2" -d "$3" --stats -o "$tmp/frame.ppm" \
      >"$out" 2>"$tmp/err" || { fail "$1 $2 D $3 mode $mode: --stats: $(tail -n 1 "$tmp/err")"; : >"$out"; }
  fi
  echo "$out"
}
pick() { sed -n "$1" "$2"; }
# check TABLE-ROW WANT GOT: one cell against its --stats value
check() {
  [ "$2" = "$3" ] || fail "$doc, $1: the table says $2, --stats gives ${3:-nothing}"
}

checked=0
skipped=""
avx512=1
"$retro" kernels | awk '$1 == "simd-avx512" && $4 == "yes" { y = 1 } END { exit !y }' || avx512=0
[ "$avx512" = 1 ] || echo "skip: this CPU does not run AVX-512: the simd-avx512 columns are not checked"

# each_row HEADER: sets label, scene, size, dist and the cells c1.. of every row, then calls row_check
each_row() {
  size="" dist=""
  rows "$1" >"$tmp/rows"
  [ -s "$tmp/rows" ] || { fail "$doc has no table headed: $1"; return; }
  while IFS= read -r line; do
    label=$(printf '%s' "$line" | awk -F'|' '{ gsub(/^ +| +$/, "", $2); print $2 }')
    scene=${label%%,*}
    case $label in
      *,*) # "alpine, 640×480, D 800" sets the frame of the rows below it
        frame=${label#*, }
        size=$(printf '%s' "${frame%%,*}" | sed 's/×/x/')
        dist=${frame##*D } ;;
    esac
    bench_scene_args "$scene" "$course" >/dev/null || { fail "$doc: unknown scene in row '$label'"; continue; }
    if bench_scene_course "$scene" && [ ! -d "$course" ]; then
      case " $skipped " in *" $scene "*) ;; *) skipped="$skipped $scene" ;; esac
      continue
    fi
    [ -n "$size" ] && [ -n "$dist" ] || { fail "$doc: row '$label' has no frame above it"; continue; }
    # the cells after the label, without their % signs
    set -- $(printf '%s' "$line" | awk -F'|' '{ for (i = 3; i < NF; i++) { gsub(/[ %]/, "", $i); printf "%s ", $i } }')
    s=$(stats "$scene" "$size" "$dist")
    row_check "$@"
    checked=$((checked + 1))
  done <"$tmp/rows"
}

# "Other bounds at the same granularity"
row_check() {
  check "$label, painting" "$1" "$(pick 's/^painting: [0-9]* (\([0-9.]*\)%)$/\1/p' "$s")"
  check "$label, ideal max" "$2" "$(pick 's/^ideal max bound evaluates: \([0-9.]*\)% with blocks down to 4 cells.*/\1/p' "$s")"
  check "$label, plane" "$3" "$(pick 's/^ideal plane bound evaluates: \([0-9.]*\)% with blocks down to 4 cells.*/\1/p' "$s")"
  check "$label, oracle" "$4" "$(pick 's/^ideal oracle bound evaluates: \([0-9.]*\)% with blocks down to 4 cells.*/\1/p' "$s")"
  check "$label, oracle at 2 cells" "$5" "$(pick 's/^ideal oracle bound evaluates: .*, \([0-9.]*\)% with blocks down to 2 cells$/\1/p' "$s")"
  [ "$avx512" = 0 ] ||
    check "$label, simd-avx512" "$6" "$(pick 's/^simd-avx512 evaluated: [0-9]* (\([0-9.]*\)%).*/\1/p' "$s")"
}
each_row '| scene | painting | ideal max | plane | oracle | oracle, blocks down to 2 cells | `simd-avx512` |'

# "How far a max bound can go": the column walk, lanes walking alone, the SIMD groups
row_check() {
  check "$label, column walk" "$1" "$(pick 's/^evaluated: [0-9]* (\([0-9.]*\)%)$/\1/p' "$s")"
  alone=$(pick 's/^lanes walking alone, 16 to a group: \([0-9.]*\)% .*/\1/p' "$s")
  check "$label, lanes walking alone" "$2" "$alone"
  [ "$avx512" = 1 ] || return 0
  simd=$(pick 's/^simd-avx512 evaluated: [0-9]* (\([0-9.]*\)%).*/\1/p' "$s")
  check "$label, simd-avx512" "$3" "$simd"
  [ -n "$alone" ] && [ -n "$simd" ] &&
    check "$label, alone / simd-avx512" "$4" "$(awk -v a="$alone" -v s="$simd" 'BEGIN { printf "%.2f", a / s }')"
}
each_row '| scene | column walk | lanes walking alone | `simd-avx512` | alone / `simd-avx512` |'

# "Window or schedule": the column walk with one part of the ideal walk at a time
# part NAME [windows]: that part's share in the column walk line, or the windows it read
part() {
  pick 's/^the column walk evaluates, with //p' "$s" |
    awk -v n="$1: " -v k="${2:-share}" 'BEGIN { RS = ", " } index($0, n) == 1 {
      v = substr($0, length(n) + 1)
      if (k == "share") { sub(/%.*/, "", v) } else { sub(/^[^(]*\(/, "", v); sub(/ windows\).*/, "", v) }
      print v }'
}
row_check() {
  check "$label, the walk" "$1" "$(pick 's/^evaluated: [0-9]* (\([0-9.]*\)%)$/\1/p' "$s")"
  check "$label, own box" "$2" "$(part "the run's own box")"
  check "$label, one probe per sample" "$3" "$(part "one probe per sample")"
  check "$label, ideal max" "$4" "$(pick 's/^ideal max bound evaluates: \([0-9.]*\)% with blocks down to 4 cells.*/\1/p' "$s")"
  check "$label, unaligned windows" "$5" "$(part "unaligned windows")"
  check "$label, unaligned, one probe per sample" "$6" "$(part "unaligned windows and one probe per sample")"
}
each_row '| scene | the walk | own box | one probe per sample | both: ideal max | unaligned windows | unaligned, one probe per sample |'

# the same walks' samples and windows over the walk's own
row_check() {
  all=$(pick 's/^samples: \([0-9]*\) .*/\1/p' "$s")
  ev=$(pick 's/^evaluated: \([0-9]*\) .*/\1/p' "$s")
  win=$(pick 's/^probes: [0-9]*, pyramid windows read: \([0-9]*\)$/\1/p' "$s")
  check "$label, windows the walk reads" "$1" "$win"
  shift
  for name in "the run's own box" "one probe per sample" "unaligned windows" \
    "unaligned windows and one probe per sample"; do
    got=$(awk -v a="$all" -v e="$ev" -v w="$win" -v p="$(part "$name")" -v pw="$(part "$name" windows)" \
      'BEGIN { if (p == "" || pw == "" || e + w == 0) exit; printf "%.2f", (p / 100 * a + pw) / (e + w) }')
    check "$label, $name: samples and windows over the walk's" "$1" "$got"
    shift
  done
}
each_row '| scene | windows the walk reads | own box | one probe per sample | unaligned windows | unaligned, one probe per sample |'

# "Modes truth and fixed": the ybuffer walk's share in each mode
row_check() {
  n=1
  for mode in exact truth fixed; do
    eval "want=\${$n}"
    check "$label, mode $mode" "$want" \
      "$(pick 's/^evaluated: [0-9]* (\([0-9.]*\)%)$/\1/p' "$(stats "$scene" "$size" "$dist" "$mode")")"
    n=$((n + 1))
  done
}
each_row '| scene | exact | truth | fixed |'

# "Cone steps": the three cone walks beside the bounds they are set against
# cone WHICH: the cone steps line's share for walk WHICH (alone, pyramid, ideal)
cone() {
  pick 's/^cone steps ([0-9]* sectors, radius [0-9]* cells) evaluate: //p' "$s" |
    awk -v w="$1" -F', ' '{ i = w == "alone" ? 1 : w == "pyramid" ? 2 : 3; v = $i; sub(/%.*/, "", v); print v }'
}
row_check() {
  check "$label, painting" "$1" "$(pick 's/^painting: [0-9]* (\([0-9.]*\)%)$/\1/p' "$s")"
  check "$label, one probe per sample" "$2" "$(part "one probe per sample")"
  check "$label, ideal max" "$3" "$(pick 's/^ideal max bound evaluates: \([0-9.]*\)% with blocks down to 4 cells.*/\1/p' "$s")"
  check "$label, oracle" "$4" "$(pick 's/^ideal oracle bound evaluates: \([0-9.]*\)% with blocks down to 4 cells.*/\1/p' "$s")"
  check "$label, cone steps alone" "$5" "$(cone alone)"
  check "$label, cones and the pyramid" "$6" "$(cone pyramid)"
  check "$label, cones and the ideal max" "$7" "$(cone ideal)"
}
each_row '| scene | painting | one probe per sample | ideal max | oracle | cone steps alone | cones and the pyramid | cones and the ideal max |'

# the cone map's shapes on pyramids, 640×480, D 800 (RETRO_CONE_SECTORS, RETRO_CONE_R)
if [ -d "$course" ]; then
  rows '| sectors | radius | cone steps alone | cones and the pyramid | cones and the ideal max |' >"$tmp/rows"
  [ -s "$tmp/rows" ] || fail "$doc has no table of the cone map's shapes"
  while IFS= read -r line; do
    set -- $(printf '%s' "$line" | awk -F'|' '{ for (i = 2; i < NF; i++) { gsub(/[ %]/, "", $i); printf "%s ", $i } }')
    label="pyramids, $1 sectors, radius $2"
    s=$tmp/cone-$1-$2.txt
    # shellcheck disable=SC2046
    RETRO_CONE_SECTORS=$1 RETRO_CONE_R=$2 "$retro" render $(bench_scene_args pyramids "$course") -s 640x480 -d 800 \
      --stats -o "$tmp/frame.ppm" >"$s" 2>"$tmp/err" || fail "$label: --stats: $(tail -n 1 "$tmp/err")"
    grep -q "^cone steps ($1 sectors, radius $2 cells)" "$s" || fail "$label: --stats did not take the shape"
    check "$label, alone" "$3" "$(cone alone)"
    check "$label, cones and the pyramid" "$4" "$(cone pyramid)"
    check "$label, cones and the ideal max" "$5" "$(cone ideal)"
    checked=$((checked + 1))
  done <"$tmp/rows"
else
  case " $skipped " in *" pyramids "*) ;; *) skipped="$skipped pyramids" ;; esac
fi

[ -z "$skipped" ] || echo "skip: $course absent: rows of$skipped not checked"
[ "$checked" -gt 0 ] || fail "no row of $doc's count tables was checked"
[ "$fails" -eq 0 ] && echo "ok: skipping_doc_counts ($checked rows)"
[ "$fails" -eq 0 ]
