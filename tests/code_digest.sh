#!/bin/sh
# scripts/code_digest.py tells changed machine code from an unchanged one and from another
# build: a comment or a moved line leaves an object's digest as it was, a changed constant, a
# renamed callee or another optimisation level does not, and an object built with other flags
# is reported as built otherwise, not as changed code. Objects come from tiny C files compiled
# here as the Makefile compiles the library (-g, so each names its compiler and flags).
# usage: code_digest.sh RETRO (unused)
set -u
if ! command -v python3 >/dev/null 2>&1 || ! command -v readelf >/dev/null 2>&1; then
  echo "FAIL: python3 or readelf missing (make deps; binutils)"
  exit 1
fi
# gcc, as for the published runs: its DW_AT_producer names the flags, clang's (without
# -grecord-command-line) only the compiler, so flags could not be told apart under clang
cc=gcc
command -v gcc >/dev/null 2>&1 || { echo "FAIL: gcc missing (the builds this digests are gcc's)"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/run/src" "$tmp/now/src"
src() { # FILE CONSTANT CALLEE [EXTRA LINE]
  printf '%s\nint %s(int);\nint kernel(int x)\n{\n    return %s(x) * %s;\n}\n' "${4:-}" "$3" "$3" "$2" >"$1"
}
build() { # DIR [CFLAGS]: the object of DIR/k.c in DIR/src/k.o
  $cc -O2 -g -ffp-contract=off ${2:-} -c "$1/k.c" -o "$1/src/k.o" || { echo "FAIL: $cc could not compile"; exit 1; }
}
diffs() { # what code_digest.py diff says of run's digest against now
  python3 scripts/code_digest.py diff "$tmp/run.txt" "$tmp/now" 2>&1
}
src "$tmp/run/k.c" 3 helper
build "$tmp/run"
python3 scripts/code_digest.py write "$tmp/run" "$tmp/run.txt" "commit: 0123456" || { echo "FAIL: code_digest.py write"; exit 1; }
grep -q '^# commit: 0123456$' "$tmp/run.txt" || { echo "FAIL: the digest lacks its comment"; exit 1; }
grep -q '^# build [0-9a-f]\{8\}: GNU C' "$tmp/run.txt" || { echo "FAIL: the digest does not name the compiler: $(cat "$tmp/run.txt")"; exit 1; }

case_() { # NAME EXPECTED-LINE CONSTANT CALLEE [EXTRA] [CFLAGS]
  src "$tmp/now/k.c" "$3" "$4" "${5:-}"
  build "$tmp/now" "${6:-}"
  out=$(diffs)
  case "$out" in
    *"$2"*) ;;
    *) echo "FAIL: $1: expected '$2' in: $out"; exit 1 ;;
  esac
}
case_ "the same source" "changed: 0" 3 helper
case_ "a comment and a moved line" "changed: 0" 3 helper "/* a comment */

"
case_ "another constant" "changed: 1" 5 helper
case_ "another callee" "changed: 1" 3 other
case_ "another optimisation level" "built otherwise: 1" 3 helper "" -O1
# an object the run had and this build lacks is named gone, one it lacks new
mv "$tmp/now/src/k.o" "$tmp/now/src/j.o"
out=$(diffs)
case "$out" in
  *"new: 1"*"gone: 1"*) ;;
  *) echo "FAIL: a renamed object is not reported new and gone: $out"; exit 1 ;;
esac
# not an object: refused with a one-line error and exit code 2, and no output written
printf 'not elf' >"$tmp/now/src/j.o"
err=$(python3 scripts/code_digest.py write "$tmp/now" "$tmp/bad.txt" 2>&1 >/dev/null)
rc=$?
if [ $rc -ne 2 ] || [ -e "$tmp/bad.txt" ] || [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ]; then
  echo "FAIL: a file that is not ELF: exit $rc, output left: $([ -e "$tmp/bad.txt" ] && echo yes || echo no), error: $err"
  exit 1
fi
# make accuracy (and make bench alike) digest the build only where the binaries that ran are its
# own: binaries named from elsewhere leave a note instead (make -n: the commands, run nothing)
out=$(make -n --no-print-directory accuracy BUILD=build 2>&1)
case $out in
  *"scripts/code_digest.py write build build/results/accuracy-code.txt"*) ;;
  *) echo "FAIL: make accuracy would not digest its build: $out" | head -c 600; exit 1 ;;
esac
out=$(make -n --no-print-directory accuracy BUILD=build RETRO=/bin/true 2>&1)
case $out in
  *"note: no build/results/accuracy-code.txt: /bin/true not built in build"*) ;;
  *) echo "FAIL: make accuracy would digest a build its retro is not from: $out" | head -c 600; exit 1 ;;
esac
echo "ok: code_digest.py tells changed code from comments and from other builds; make digests its own builds only"
