#!/bin/sh
# Fuzz smoke test: builds the libFuzzer targets (make fuzz-build, clang) and runs each over
# its seed corpus plus a few hundred to a few thousand mutations, on a scratch copy so tests/
# is never written. A crash, a sanitizer report or a contract violation fails the test. Without
# clang or libFuzzer it says so and passes: `make fuzz` is where fuzzing really happens.
# usage: fuzz_smoke.sh RETRO   (the build directory is taken from RETRO's path)
set -u
build=$(dirname "$(dirname "$1")")
fuzz_build=${FUZZ_BUILD:-$build/fuzz}
cc=${FUZZ_CC:-clang}

if ! command -v "$cc" >/dev/null 2>&1; then
  echo "SKIP: $cc not found; install clang and libclang-rt-dev to fuzz (make deps)"
  exit 0
fi
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
printf 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n) { (void)d; (void)n; return 0; }\n' \
  >"$probe/p.c"
if ! "$cc" -fsanitize=fuzzer,address,undefined "$probe/p.c" -o "$probe/p" >"$probe/log" 2>&1; then
  echo "SKIP: $cc cannot link libFuzzer (install libclang-rt-dev):"
  sed 's/^/  /' "$probe/log" | head -n 5
  exit 0
fi

# The caller's make variables (CC=gcc, SAN=... under make asan) must not leak into the
# fuzz build, which is clang's and sanitized its own way.
if ! env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s -j2 fuzz-build BUILD="$build" \
  FUZZ_BUILD="$fuzz_build" FUZZ_CC="$cc" >"$probe/build.log" 2>&1; then
  echo "FAIL: make fuzz-build:"
  tail -n 30 "$probe/build.log"
  exit 1
fi

fail=0
for src in tests/fuzz/fuzz_*.c; do
  t=$(basename "$src" .c)
  # Frames cost far more than parsing a string: fewer mutations where inputs render.
  case $t in fuzz_kernels | fuzz_scene) runs=400 ;; *) runs=2000 ;; esac
  work="$probe/$t"
  mkdir -p "$work/corpus"
  cp tests/fuzz/corpus/"$t"/* "$work/corpus/"
  # shellcheck disable=SC2046
  if "$fuzz_build/bin/$t" -runs=$runs -max_total_time=30 -print_final_stats=1 \
    -artifact_prefix="$work/" $(cat tests/fuzz/"$t".options 2>/dev/null) "$work/corpus" \
    >"$work/log" 2>&1; then
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log")
    cov=$(grep -o 'cov: [0-9]*' "$work/log" | tail -n 1)
    # fewer inputs than asked means the 30 s ran out: each input costs too much to fuzz well
    echo "ok: $t: $execs of $runs inputs, $cov"
  else
    echo "FAIL: $t:"
    grep -v '^#[0-9]' "$work/log" | grep -v '^INFO' | head -n 40
    for a in "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-*; do
      [ -e "$a" ] && echo "  reproducer (base64): $(base64 -w0 "$a")"
    done
    fail=1
  fi
done
exit $fail
