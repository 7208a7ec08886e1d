#!/bin/sh
# Every relative link in README.md and docs/ leads to a file, and every reference to a section
# of a doc, in the docs or in a comment of the code, names a section that doc has
# (scripts/doc_refs.py), and no path names a file that has moved. And the check can fail: a
# link to a missing file, a section renamed, a reference to one that never was and a path to a
# moved file are each reported, in a small tree of its own and in a copy of this one with a
# heading renamed.
# usage: doc_refs.sh RETRO   (RETRO unused: every test takes it)
set -u
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
check=scripts/doc_refs.py

if ! python3 "$check" . >"$tmp/out" 2>&1; then
  echo "FAIL: broken references in the tree:"
  cat "$tmp/out"
  fail=1
fi

# a tree of its own: good references of each kind, and three broken ones
mkdir -p "$tmp/t/docs" "$tmp/t/src"
printf '# A\n\n## Real section\n\nSee [B](B.md) and [A](A.md).\n\n**Run-in title.** Text.\n' >"$tmp/t/docs/A.md"
printf '/* docs/A.md, "Real section"; (docs/A.md, "Run-in title"); (docs/A.md, "Gone section") */\n' >"$tmp/t/src/x.c"
printf '/* x.c lives in src/x.c, not in src/old/x.c; src/render.c is the course'"'"'s */\n' >"$tmp/t/src/render_note.h"
git -C "$tmp/t" init -q && git -C "$tmp/t" add -A
python3 "$check" "$tmp/t" >"$tmp/out" 2>&1
rc=$?
if [ "$rc" -ne 1 ] || [ "$(wc -l <"$tmp/out")" -ne 3 ] ||
  ! grep -q 'docs/A.md:5: link to B.md' "$tmp/out" || ! grep -q '"Gone section"' "$tmp/out" ||
  ! grep -q 'src/render_note.h:1: src/old/x.c does not exist; src/x.c does' "$tmp/out"; then
  echo "FAIL: in a tree with a missing link target, a missing section and a moved file, want status 1 and those three lines; got $rc:"
  cat "$tmp/out"
  fail=1
fi

# a copy of this tree's docs, results and sources with one heading renamed: its references are reported
mkdir -p "$tmp/c"
git ls-files -z docs src tests results README.md | tar -cf - --null -T - | tar -xf - -C "$tmp/c"
sed 's/^## Window or schedule$/## Window or plan/' docs/studies/SKIPPING_LIMITS.md >"$tmp/c/docs/studies/SKIPPING_LIMITS.md"
git -C "$tmp/c" init -q && git -C "$tmp/c" add -A
python3 "$check" "$tmp/c" >"$tmp/out" 2>&1
rc=$?
n=$(grep -c '"Window or schedule"' "$tmp/out")
if [ "$rc" -ne 1 ] || [ "$n" -lt 2 ] || grep -qv '"Window or schedule"' "$tmp/out"; then
  echo "FAIL: with the heading \"Window or schedule\" renamed, want status 1 and only its references (at least 2); got $rc:"
  cat "$tmp/out"
  fail=1
fi

[ "$fail" -eq 0 ] && echo "ok: the docs' links and section references lead somewhere; a missing file, a renamed section, a section that never was and a moved file are each caught"
exit "$fail"
