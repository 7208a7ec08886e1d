#!/bin/sh
# Installs the Debian packages the suite needs, only those missing, as root or through sudo.
# usage: install-deps.sh   (make deps)
set -eu
. "$(dirname "$0")/usage.sh"
script_args 0 0 "$@"
# libclang-rt-dev (libFuzzer, clang's sanitizers) and libomp-dev (clang's OpenMP) are only
# recommended by clang: make fuzz and the clang half of make asan need them.
# python3 writes the README's figures from the committed run; help2man the man page; git
# applies and checks the replay study's patch (make study-replay, tests/study_replay.sh).
# libsdl2-dev is retro view's window; xvfb, xdotool, x11-apps (xwd) and netpbm run and
# photograph it in the tests.
PKGS="build-essential clang libclang-rt-dev libomp-dev pkg-config libspng-dev libcriterion-dev libbenchmark-dev libhwloc-dev hwloc libinih-dev gnuplot-nox python3 help2man libsdl2-dev xvfb xdotool x11-apps netpbm git"
missing=""
for p in $PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "installing:$missing"
if [ "$(id -u)" = 0 ]; then SUDO=""; elif command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
  echo "error: missing packages:$missing; install them as root: apt-get install$missing" >&2
  exit 2
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq $missing >/dev/null
