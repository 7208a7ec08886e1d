#!/usr/bin/env python3
"""Cross-references in the docs and the code that no longer lead anywhere.

Docs move: a study grows out of its page into docs/studies/, a section is renamed. The text that
points at it, in another doc or in a comment of the code, does not move with it. This lists:

  - a relative Markdown link, in README.md or a file under docs/, to a file that does not exist;
  - a reference to a section, a doc's name followed by a quoted title, as in
    (docs/KERNELS.md, "Where the stores go") or [SKIPPING.md](SKIPPING.md), "Mode course",
    whose doc has no heading, bold run-in title or paragraph that starts with that title;
  - a path to a file of the tree (src/..., tests/..., docs/X.md and the like) that does not
    exist while a tracked file of the same name does elsewhere: a file that moved. Two paths
    are not this tree's: src/render.c is the course project's file that the submission
    becomes, and include/retro/ is where `make install` puts the headers.

It reads the files git tracks under DIR (default: the current directory): the Markdown files,
the C, C++, shell and Python sources, patches and Makefiles. A reference names its doc as a path
from the top (docs/X.md), from the referring file's folder, or by its bare name under docs/ or
docs/studies/. Titles that look like code rather than prose (starting in lower case, or holding
one of $ ; | < > = { } \\) are not references and are skipped.

usage: doc_refs.py [DIR]   print each broken reference, one per line; status 1 if any, else 0
"""
import os
import re
import subprocess
import sys

SOURCES = re.compile(r"\.(md|c|h|cc|sh|py|patch)$|(^|/)Makefile$")
LINK = re.compile(r"\]\(([^)\s]+)\)")
# a doc's name (optionally as a link), then at most a few lower-case words, then "Title"
SECTION = re.compile(
    r"((?:docs/)?(?:studies/)?[A-Z][A-Z_]*\.md)\]?(?:\([^)\s]*\))?[,:]?\s*"
    r"(?:[a-z][a-z0-9 -]*,\s*)?\(?\"([^\"]{3,90})\"")
PATH = re.compile(r"\b(?:src|tests|scripts|bench|tools|include|docs)/[A-Za-z0-9_./-]+"
                  r"\.(?:c|h|cc|sh|py|md|patch)\b")
NOT_OURS = re.compile(r"src/render\.c$|include/retro/")  # the course's file; installed headers
# the line breaks of comments and prose, with a comment's leading * # // or a patch's +
BREAK = re.compile(r"\n[ \t]*(?:\*|#|//|\+)?[ \t]*")


def usage_error(msg):
    print(f"doc_refs.py: {msg} (doc_refs.py --help)", file=sys.stderr)
    sys.exit(2)


def line_of(text, pos):
    return text.count("\n", 0, pos) + 1


def tracked(top):
    r = subprocess.run(["git", "-C", top, "ls-files"], capture_output=True, text=True)
    if r.returncode != 0:
        usage_error(f"{top} is not a git checkout")
    return [f for f in r.stdout.split("\n") if f and SOURCES.search(f)]


def titles(path):
    """What a reference may name in PATH: headings, bold run-in titles, and paragraph starts."""
    text = open(path, encoding="utf-8", errors="replace").read()
    found = set()
    for line in text.split("\n"):
        m = re.match(r"#+ (.*)", line)
        if m:
            found.add(m.group(1).strip())
    text = re.sub(r"(?m)^#+ .*$", "", text)
    for para in re.split(r"\n\s*\n", text):
        para = re.sub(r"\s+", " ", para.strip())
        for bold in re.findall(r"\*\*([^*]+)\*\*", para):
            found.add(bold.rstrip(".:"))
        found.add(re.sub(r"^- ", "", para))
    return found


def broken(top):
    files = tracked(top)
    out = []
    cache = {}
    by_name = {}
    for f in files:
        by_name.setdefault(os.path.basename(f), []).append(f)
    for f in files:
        path = os.path.join(top, f)
        if not os.path.isfile(path):
            continue
        text = open(path, encoding="utf-8", errors="replace").read()
        if f.endswith(".md") and (f == "README.md" or f.startswith("docs/")):
            for m in LINK.finditer(text):
                target = m.group(1).split("#")[0]
                if not target or re.match(r"[a-z]+:", target):
                    continue
                if not os.path.exists(os.path.join(top, os.path.dirname(f), target)):
                    at = line_of(text, m.start())
                    out.append(f"{f}:{at}: link to {target}, which does not exist")
        for m in PATH.finditer(text):
            p = m.group(0)
            if NOT_OURS.match(p) or os.path.exists(os.path.join(top, p)):
                continue
            now = [g for g in by_name.get(os.path.basename(p), []) if g != p]
            if now:
                at = line_of(text, m.start())
                out.append(f"{f}:{at}: {p} does not exist; {' or '.join(now)} does")
        for m in SECTION.finditer(BREAK.sub(" ", text)):
            name, title = m.group(1), re.sub(r"\s+", " ", m.group(2))
            if re.search(r"[$;|<>={}\\]", title) or not re.match(r"[A-Z`]", title):
                continue
            tries = [os.path.join(os.path.dirname(f), name), name, "docs/" + name,
                     "docs/studies/" + os.path.basename(name)]
            doc = next((t for t in tries if os.path.isfile(os.path.join(top, t))), None)
            if doc is None:
                continue  # a doc outside this tree (../shared/SEMANTICS.md) or none
            doc = os.path.normpath(doc)
            if doc not in cache:
                cache[doc] = titles(os.path.join(top, doc))
            if not any(t == title or t.startswith(title) for t in cache[doc]):
                out.append(f'{f}: {name}, "{title}": {doc} has no such section')
    return out


def main(argv):
    if argv and argv[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0
    if argv and argv[0].startswith("-"):
        usage_error(f"unknown option {argv[0]}")
    if len(argv) > 1:
        usage_error("at most one DIR")
    top = argv[0] if argv else "."
    if not os.path.isdir(top):
        usage_error(f"{top} is not a directory")
    bad = broken(top)
    for b in bad:
        print(b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
