#!/bin/sh
# make submission's second half: the file just written is built as the course builds it
# (-Wall -Wextra -pedantic, at -O0 -g with ASan+UBSan and at -O3, -lm only) beside a copy of
# include/render.h and the course-style driver, and must build without a warning; then, when
# the course data is present, the course's public tests run on it (render frames, draw_line
# image, player). Ends by saying where the file goes.
# usage: check-submission.sh RENDER.c SHARED
set -u
. "$(dirname "$0")/usage.sh"
script_args 2 2 "$@"
src=$1
shared=$2
cc=${CC:-cc}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$src" "$tmp/render.c" && cp include/render.h tests/submission_driver.c "$tmp/" || exit 1
for flags in "-O0 -g -fsanitize=address -fsanitize=undefined" "-O3"; do
  if ! (cd "$tmp" && $cc -Wall -Wextra -pedantic $flags -o driver render.c submission_driver.c -lm) >"$tmp/cc.log" 2>&1; then
    echo "error: $src does not build with $cc -Wall -Wextra -pedantic $flags:" >&2
    head -n 20 "$tmp/cc.log" >&2
    exit 1
  fi
  if [ -s "$tmp/cc.log" ]; then
    echo "error: $src builds with warnings ($cc -Wall -Wextra -pedantic $flags):" >&2
    head -n 20 "$tmp/cc.log" >&2
    exit 1
  fi
  echo "  CHECK   $src builds warning-free: $cc -Wall -Wextra -pedantic $flags -lm"
done
if [ -d "$shared/course" ]; then
  if ! (cd "$tmp" && ./driver selftest "$(cd "$OLDPWD" && cd "$shared" && pwd)") >"$tmp/self.log" 2>&1; then
    echo "error: $src fails the course's public tests:" >&2
    grep -v '^ok' "$tmp/self.log" | head -n 20 >&2
    exit 1
  fi
  echo "  CHECK   the course's public tests pass ($shared/course: island01, pyramids01, valley01, draw_line image, player)"
else
  echo "  SKIP    the course's public tests: $shared/course is absent (SHARED=DIR)"
fi
echo "  It goes in the course project as src/render.c (the course takes only that file from a"
echo "  submission): cp $src COURSE_PROJECT/src/render.c"
