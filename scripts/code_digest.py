#!/usr/bin/env python3
"""The machine code of a build, object by object, and how it differs from a run's build.

A published benchmark or accuracy run stays the README's source of figures until a steady run
of newer code replaces it. Counting the commits since the run says that the sources changed, not
whether the code the run timed did: a commit to the counting build, the CLI or a comment leaves
the kernels' objects as they were. This compares the objects themselves.

usage: code_digest.py write BUILD OUT [COMMENT]   digest BUILD's objects into OUT
       code_digest.py diff DIGEST BUILD           what differs between DIGEST and BUILD now

An object's code digest covers what the linker and loader use: every allocated section's bytes
(code, constants, data, unwind tables; debugging sections are left out, so a moved line or a
comment does not count), its relocations with the symbols they name, and its defined symbols.
Its build is the compiler and flags that made it (DWARF's DW_AT_producer; -g is always on),
so a build with other flags (make asan's) is told apart from changed code rather than counted
as every object changed. gcc names its flags there; clang (without -grecord-command-line) names
only itself, so between two clang builds other flags would count as changed code. Objects: BUILD/src, BUILD/tools and BUILD/bench (the library, the
CLI and the benchmark harness), not the tests or the other builds nested in BUILD.
"""
import functools
import hashlib
import os
import re
import struct
import subprocess
import sys

SHF_ALLOC = 0x2
SHT_SYMTAB, SHT_RELA, SHT_NOBITS, SHT_REL = 2, 4, 8, 9
STT_SECTION, STT_FILE = 3, 4
DIRS = ("src", "tools", "bench")


def sections(data):
    """(name, type, flags, offset, size, link, info, align, entsize) of each section of ELF64 data."""
    if data[:4] != b"\x7fELF" or data[4] != 2 or data[5] != 1:
        raise ValueError("not a little-endian ELF64 object")
    shoff, = struct.unpack_from("<Q", data, 0x28)
    shentsize, shnum, shstrndx = struct.unpack_from("<HHH", data, 0x3A)
    raw = [struct.unpack_from("<IIQQQQIIQQ", data, shoff + i * shentsize) for i in range(shnum)]
    strtab = raw[shstrndx]

    def name(off):
        start = strtab[4] + off
        return data[start:data.index(b"\0", start)].decode()

    return [(name(s[0]), s[1], s[2], s[4], s[5], s[6], s[7], s[8], s[9]) for s in raw]


def code_digest(path):
    """sha256 of the object's allocated sections, relocations and defined symbols."""
    data = open(path, "rb").read()
    secs = sections(data)
    h = hashlib.sha256()

    def put(*fields):
        h.update(("\x1f".join(str(f) for f in fields) + "\x1e").encode())

    symbols = []
    for s in secs:
        if s[1] == SHT_SYMTAB:
            strtab = secs[s[5]]
            for i in range(s[4] // 24):
                st_name, info, other, shndx, value, size = struct.unpack_from("<IBBHQQ", data, s[3] + i * 24)
                start = strtab[3] + st_name
                symbols.append((data[start:data.index(b"\0", start)].decode(), info, shndx, value, size))

    def symbol(i):
        n, info, shndx, _, _ = symbols[i]
        if info & 0xF == STT_SECTION:
            return "section " + (secs[shndx][0] if shndx < len(secs) else str(shndx))
        return n

    for s in secs:
        if s[2] & SHF_ALLOC:
            put("section", s[0], s[1], s[2], s[4], s[7])
            if s[1] != SHT_NOBITS:
                h.update(data[s[3]:s[3] + s[4]])
        elif s[1] in (SHT_RELA, SHT_REL) and secs[s[6]][2] & SHF_ALLOC:
            size = 24 if s[1] == SHT_RELA else 16
            for i in range(s[4] // size):
                off, info = struct.unpack_from("<QQ", data, s[3] + i * size)
                addend = struct.unpack_from("<q", data, s[3] + i * size + 16)[0] if size == 24 else 0
                put("reloc", secs[s[6]][0], off, info & 0xFFFFFFFF, addend, symbol(info >> 32))
    for n, info, shndx, value, size in symbols:
        if n and info & 0xF != STT_FILE and 0 < shndx < len(secs):
            put("symbol", n, info, secs[shndx][0], value, size)
    return h.hexdigest()[:16]


def producer(path):
    """The compiler and flags the object was built with, or '' when readelf cannot say."""
    try:
        out = subprocess.run(["readelf", "--debug-dump=info", "--dwarf-depth=1", path],
                             capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return ""
    m = re.search(r"DW_AT_producer\s*:(?:\s*\([^)]*\):)?\s*(.*)", out)
    return m.group(1).strip() if m else ""


def objects(build):
    """Paths (relative to build) of the objects digested."""
    found = []
    for d in DIRS:
        for root, dirs, files in os.walk(os.path.join(build, d)):
            dirs.sort()
            found += [os.path.relpath(os.path.join(root, f), build) for f in sorted(files) if f.endswith(".o")]
    return found


@functools.lru_cache(maxsize=None)
def digest_build(build):
    """{object: (code digest, producer)} of build; ValueError naming an object that is not ELF64.
    Kept per build: readme-figures.py compares the benchmark's and the accuracy run's digests with
    the same build, and reading it runs readelf once per object. Callers do not modify it."""
    table = {}
    for o in objects(build):
        path = os.path.join(build, o)
        try:
            table[o] = (code_digest(path), producer(path))
        except (ValueError, struct.error, IndexError) as e:
            raise ValueError(f"{path}: {e}") from None
    return table


def write(build, out, comment=""):
    table = digest_build(build)
    if not table:
        raise ValueError(f"no objects under {build}/{{{','.join(DIRS)}}}: build first")
    producers = sorted({p for _, p in table.values()})
    key = {p: hashlib.sha256(p.encode()).hexdigest()[:8] for p in producers}
    lines = ["# The machine code of one build, object by object (scripts/code_digest.py)."]
    lines += [f"# {c}" for c in comment.splitlines() if c]
    lines += [f"# build {key[p]}: {p or 'unknown'}" for p in producers]
    lines += [f"{o} {c} {key[p]}" for o, (c, p) in sorted(table.items())]
    tmp = out + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, out)


def read(path):
    """{object: (code digest, producer)} of a digest file."""
    builds, table = {}, {}
    for line in open(path, encoding="utf-8"):
        m = re.match(r"# build ([0-9a-f]{8}): (.*)$", line.rstrip("\n"))
        if m:
            builds[m.group(1)] = "" if m.group(2) == "unknown" else m.group(2)
        elif line.strip() and not line.startswith("#"):
            o, c, b = line.split()
            table[o] = (c, builds.get(b, "?"))
    return table


def compare(digest, build):
    """(changed, added, removed, same, other) between the run's digest file and build now: other
    names the objects both have that were built with another compiler or other flags (then the
    code cannot be compared). None when either side has no objects."""
    try:
        run, now = read(digest), digest_build(build)
    except ValueError:
        return None
    if not run or not now:
        return None
    both = sorted(set(run) & set(now))
    other = [o for o in both if run[o][1] != now[o][1]]
    changed = [o for o in both if o not in other and run[o][0] != now[o][0]]
    same = [o for o in both if o not in other and o not in changed]
    return changed, sorted(set(now) - set(run)), sorted(set(run) - set(now)), same, other


def main(argv):
    if argv[1:2] in (["-h"], ["--help"]):
        print(__doc__)
        return 0
    if len(argv) in (4, 5) and argv[1] == "write":
        try:
            write(argv[2], argv[3], argv[4] if len(argv) > 4 else "")
        except (ValueError, OSError) as e:
            print(f"code_digest: {e}", file=sys.stderr)
            return 2
        return 0
    if len(argv) == 4 and argv[1] == "diff":
        try:
            r = compare(argv[2], argv[3])
        except (ValueError, OSError) as e:
            print(f"code_digest: {e}", file=sys.stderr)
            return 2
        if r is None:
            print("code_digest: nothing to compare (no objects on one side)", file=sys.stderr)
            return 2
        for label, names in zip(("changed", "new", "gone", "same", "built otherwise"), r):
            print(f"{label}: {len(names)}" + ("".join(f"\n  {n}" for n in names) if label != "same" else ""))
        return 0
    print("code_digest.py: usage: code_digest.py write BUILD OUT [COMMENT] | diff DIGEST BUILD (--help)",
          file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
