#!/usr/bin/env python3
"""Writes the README's figures from the committed run, so they cannot drift from it.

usage: readme-figures.py RESULTS_DIR README.md           rewrite the generated blocks
       readme-figures.py --check RESULTS_DIR README.md   exit 1 if a block differs from the run

Each block sits between <!-- NAME:begin --> and <!-- NAME:end --> in README.md and is
regenerated whole from RESULTS_DIR/BENCH.md (one `make bench` run) or RESULTS_DIR/ACCURACY.md
(one `make accuracy` run). Prose inside a block draws conclusions only from that block's run.
"""
import math
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts: make targets leave git status clean
import readme_skipping  # noqa: E402 (after the line above)


def effect_targets(rows, verdict):
    """Issue 18's targets for the per-sample effects on the fast path, from the effect table's
    second cost column (the fastest kernel for the effects against the fastest with none: the
    ratio of the two medians), with the ratio timed in turn beside it where the run has one."""
    h, out = rows[0], []
    col = [i for i, c in enumerate(h) if c == "cost"][-1]
    turn = h.index("in turn") if "in turn" in h else None
    cost = {r[0]: r[col] for r in rows[1:]}
    in_turn = {r[0]: r[turn].split(" ")[0] for r in rows[1:]} if turn is not None else {}
    for name, text, ok in (("bilinear", "bilinear ≤ 2.5× the plain frame", lambda x: x <= 2.5),
                           ("lod", "lod (step growth 0.02) faster than the plain exact frame", lambda x: x < 1)):
        if name in cost and cost[name].endswith("×"):
            x = float(cost[name].rstrip("×"))
            beside = f" (timed in turn: {in_turn[name]})" if in_turn.get(name, "–").endswith("×") else ""
            out.append(f"- **Target: with the fastest kernel, {text}** (issue 18): {cost[name]}{beside} — "
                       f"{verdict(ok(x))}.")
    return [""] + out if out else []


def tables(md):
    """{section title: [rows as lists of cells]} for every markdown table under a heading."""
    out, title, rows = {}, None, None
    for line in md.splitlines():
        if line.startswith("#"):
            title, rows = line.lstrip("#").strip(), None
        elif line.startswith("|") and title is not None:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if rows is None:
                rows = out.setdefault(title, [])
            if not all(re.fullmatch(r":?-+:?", c) for c in cells):
                rows.append(cells)
        else:
            rows = None
    return out


def num(cell):
    return float(cell.replace("×", "").replace("%", "").replace("⚠", "").strip())


def fmt(x, unit="×"):
    return (f"{x:.2f}" if x < 10 else f"{x:.1f}" if x < 100 else f"{x:.0f}") + unit


def context_field(md, name):
    m = re.search(r"^\| " + re.escape(name) + r" \| (.*) \|$", md, re.M)
    return m.group(1) if m else "unknown"


def noisy_note(md):
    """The run's own noise warning, carried into the README so no figure hides it: the rows whose
    repetitions spread, the reference frame's drift across the run, a machine busy at the start."""
    m = re.search(r"^> \*\*Noisy run\.\*\*(.*)$", md, re.M)
    if not m:
        return ""
    note = m.group(1)
    parts = []
    rows = re.search(r"(\d+) rows? ha(?:s|ve) a spread over repetitions above (\d+)%", note)
    if rows:
        n = int(rows.group(1))
        parts.append(f"{n} {'row spreads' if n == 1 else 'rows spread'} more than {rows.group(2)}% over "
                     f"{'its' if n == 1 else 'their'} repetitions (marked ⚠ below and in BENCH.md)")
    drift = re.search(r"reference frame's time at (\d+) threads? spread (\d+)%", note)
    if drift:
        t = int(drift.group(1))
        parts.append(f"the reference frame's time at {t} thread{'' if t == 1 else 's'} spread {drift.group(2)}% "
                     "across the run's checkpoints (results/BENCH.md, Machine steadiness)")
    if "machine was busy" in note:
        parts.append("the machine was busy when it started")
    if not parts:
        parts.append("see results/BENCH.md")
    return (" **This run was noisy:** " + "; ".join(parts) + ", so the medians concerned, and conclusions "
            "drawn from them, are provisional.")


def steadiness(md):
    """The reference frame's spread across the run's checkpoints (BENCH.md, Machine steadiness),
    per thread count, and the machine probes' spread where the table has them, as a clause for
    the README's context line; "" for a run without them. The probes time fixed loops, not the
    frame, so they are named apart: they tell whether the clock or the caches moved."""
    t = tables(md).get("Machine steadiness")
    if not t:
        return ""
    head = t[0]
    spread = next((r for r in t[1:] if r[0] == "spread"), None)
    if spread is None:
        return ""
    checkpoints = sum(1 for r in t[1:] if r[0].isdigit())
    frame, probes = [], []
    for h, cell in zip(head[2:], spread[2:]):
        m = re.match(r"([0-9.]+)%", cell)
        if not m:
            continue
        if re.fullmatch(r"\d+ threads?", h):
            frame.append(f"{m.group(1)}% at {h}")
        else:
            probes.append(f"{m.group(1)}% ({h})")
    if not frame:
        return ""
    clause = (f"the reference frame's time spread {' and '.join(frame)} across {checkpoints} checkpoints "
              "(max − min over the median)")
    if probes:
        listed = probes[0] if len(probes) == 1 else ", ".join(probes[:-1]) + " and " + probes[-1]
        clause += f", and the machine probes timed with it spread {listed}"
    return clause


def retimed(md):
    """How many blocks of cases the run timed again (BENCH.md's "Re-timed" paragraph, bench/retime.h)
    and how many stayed disturbed, as a clause for the README's context line; "" when none were."""
    m = re.search(r"^Re-timed, (.*)$", md, re.M)
    if not m:
        return ""
    rounds = re.findall(r"(\d+) blocks? \((\d+) cases with their checkpoints\) in round \d+", m.group(1))
    total = re.search(r"of the run's (\d+) blocks", m.group(1))
    if not rounds or not total:
        return ""
    first = int(rounds[0][0])
    clause = (f"{first} of its {total.group(1)} blocks of cases timed again after a slow checkpoint or a spread case"
              + (f", in {len(rounds)} rounds" if len(rounds) > 1 else ""))
    left = re.search(r"Still disturbed when re-timing stopped: (\d+) blocks?", m.group(1))
    budget = re.search(r"was given ([0-9.]+) times the first pass's duration", m.group(1))
    return (clause + (f" (within {budget.group(1)} times the first pass's duration)" if budget else "")
            + (f", {left.group(1)} still disturbed at the end" if left else ""))


def since_block(md, repo, digest=None, build=None):
    """Whether the kernels changed after the published run: the commits since the run's commit that
    touch src/ or include/, from git in repo, and with the run's digest of its build (digest) and
    a build of this code (build), which objects compile to other machine code. None when git or
    the objects cannot say (no repository, the run's commit is not in it, no comparable build):
    the README's block is then left as it is and not checked."""
    return since_commit(context_field(md, "commit"), repo, digest, build)


def digest_commit(digest):
    """The commit a digest file (scripts/code_digest.py) says it is of, or None."""
    for line in open(digest, encoding="utf-8"):
        m = re.match(r"# commit: ([0-9a-f]{7,40})$", line.rstrip("\n"))
        if m:
            return m.group(1)
    return None


def source_gone(obj, repo):
    """Whether the run's object obj (a path under the build, "src/x/y.o") has no source left in
    repo: the file was deleted, so no build of this tree can have the object."""
    import os
    stem = os.path.join(repo, obj[:-2]) if repo else None
    return bool(stem) and not any(os.path.exists(stem + ext) for ext in (".c", ".cc", ".cpp"))


def code_sentence(commit, digest, build, repo=None):
    """What the run's objects compile to now: '' when there is no digest of the run's commit
    (the block then counts commits alone), None when there is one but no build to compare with
    (an object missing whose source is still in repo, or built with another compiler or other
    flags, as make asan's are). Objects whose source was deleted since the run are named as
    gone, so a removed file does not leave the block unchecked."""
    import os
    if not digest or not os.path.exists(digest):
        return ""
    run = digest_commit(digest)
    if not run or not (run.startswith(commit) or commit.startswith(run)):
        return ""
    import code_digest
    r = code_digest.compare(digest, build) if build and os.path.isdir(build) else None
    if r is None or r[4] or not all(source_gone(o, repo) for o in r[2]):
        return None
    changed, gone, same = r[0], r[2], r[3]
    n = len(changed) + len(gone) + len(same)
    if not changed and not gone:
        return (f" Built now, all {n} objects of the run's build are its machine code byte for byte "
                "(`scripts/code_digest.py`): the figures hold for this code.")
    # the library's objects first, then the CLI's, then the benchmark harness's
    order = lambda o: (o.startswith("src/cli/") + 2 * o.startswith("bench/"), o)
    changed = sorted(changed, key=order)
    parts = []
    if changed:
        shown = ", ".join(f"`{o[:-2]}`" for o in changed[:12]) + (", …" if len(changed) > 12 else "")
        parts.append(f"{len(changed)} of the run's {n} objects compile to other machine code ({shown})")
    if gone:
        shown = ", ".join(f"`{o[:-2]}`" for o in sorted(gone, key=order)[:12]) + (", …" if len(gone) > 12 else "")
        verb = "has" if len(gone) == 1 else "have"
        whose = "" if changed else f" of the run's {n} objects"
        parts.append(f"{len(gone)}{whose} {verb} no source any more ({shown})")
    return (f" Built now, {' and '.join(parts)}; the other {len(same)} are the run's code byte for byte "
            "(`scripts/code_digest.py`).")


def since_commit(commit, repo, digest=None, build=None):
    """since_block's sentence for a run of commit (a hash; None when it is not one)."""
    import subprocess
    if not re.fullmatch(r"[0-9a-f]{7,40}", commit):
        return None
    try:
        log = subprocess.run(["git", "-C", repo, "log", "--format=%h", f"{commit}..HEAD", "--", "src", "include"],
                             capture_output=True, text=True, check=True).stdout.splitlines()
    except (OSError, subprocess.CalledProcessError):
        return None
    code = code_sentence(commit, digest, build, repo)
    if not log:
        same = f"The kernel sources (`src/`, `include/`) are those of the run's commit `{commit[:7]}`."
        # the same sources can still build to other code (another compiler, other flags): say so
        # only when a comparable build shows it, so that every other build gives the same block
        if code and "compile to other machine code" in code:
            return (same + code + " The figures here are those of the run's build until a steady run of "
                    "this build is published.")
        return same
    if code is None:
        return None
    hashes = list(reversed(log))
    n = len(hashes)
    shown = ", ".join(f"`{h}`" for h in hashes[:6]) + (", …" if n > 6 else "")
    return (f"**The kernels changed after this run:** {n} commit{'' if n == 1 else 's'} since `{commit[:7]}` "
            f"touch{'es' if n == 1 else ''} `src/` or `include/` ({shown}).{code} The figures here are those of the "
            "run's commit until a steady run of the new code is published.")


def bench_blocks(md, raw, raw_json=None):
    t = tables(md)
    key = next((k for k in t if k.startswith("Mode exact,")), None)
    if key is None:
        sys.exit("readme-figures: BENCH.md has no mode exact table")
    head, rows = t[key][0], t[key][1:]
    scenes = head[2:head.index("geomean")]
    byname = {}
    for r in rows:
        byname[(r[0].replace("`", ""), int(r[1]))] = r
    blocks = {}
    date = context_field(md, "date")
    commit = context_field(md, "commit")
    machine = context_field(md, "machine")
    settings = context_field(md, "settings")
    # the processor first: the same code's figures differ between machines of the same kind
    cpu = context_field(md, "CPU").split(";")[0]
    about = "; ".join(([f"on {cpu}"] if cpu != "unknown" else []) + [date, f"commit `{commit}`"] +
                      [x for x in (settings, machine) if x != "unknown"] + [x for x in (steadiness(md), retimed(md)) if x])
    blocks["bench:context"] = (
        f"Figures in this section come from one `make bench` run ({about}), published by "
        "`make publish`. The full table with every mode "
        "and the sweeps is in [`results/BENCH.md`](results/BENCH.md)"
        + ("; the raw numbers in `results/bench.json`." if raw else ".")
        + noisy_note(md))
    lines = ["| kernel | threads | " + " | ".join(scenes) + " | vs naive | vs ybuffer | max cv |",
             "|---|--:|" + "--:|" * (len(scenes) + 3)]
    for r in rows:
        lines.append("| " + " | ".join(r[:2 + len(scenes)] + r[-3:]) + " |")
    blocks["bench:exact"] = "\n".join(lines)

    def ms(kernel, threads, scene):
        r = byname.get((kernel, threads))
        return num(r[2 + scenes.index(scene)]) if r else math.nan

    def geo(xs):
        return math.exp(sum(math.log(x) for x in xs) / len(xs))

    default = [s for s in scenes if s in ("alpine", "islands", "canyon")]
    yb = [ms("naive", 1, s) / ms("ybuffer", 1, s) for s in default]
    plain = [kn for kn in byname if not kn[0].endswith("(no skipping)")]
    simd = [k for (k, n) in plain if k.startswith("simd-")]
    single = [k for (k, n) in plain if n == 1 and k not in ("naive",)]
    best_simd = min(simd, key=lambda k: geo([ms(k, 1, s) for s in scenes]))
    simd_r = [ms("ybuffer", 1, s) / ms(best_simd, 1, s) for s in scenes]
    best1 = min(single, key=lambda k: geo([ms(k, 1, s) for s in scenes]))
    omp_r = [ms(best1, 1, s) / ms("omp", 2, s) for s in scenes]
    best = min(plain, key=lambda kn: geo([ms(kn[0], kn[1], s) for s in scenes]))
    best_ms = [ms(best[0], best[1], s) for s in scenes]
    verdict = lambda ok: "met" if ok else "**not met**"

    def omp_verdict(r):
        # the target is on the geometric mean; the per-scene count says how near it is
        k, ok = sum(x >= 1.8 for x in r), geo(r) >= 1.8
        if k in (0, len(r)):
            return verdict(ok)
        return verdict(ok) + (" on average, not on every scene" if ok else f" on average (met on {k} of {len(r)} scenes)")

    tl = ["| target | measured in this run | verdict |", "|---|---|---|",
          f"| `ybuffer` ≥ 25× `naive`, mode exact, default scenes | "
          + ", ".join(f"{fmt(x)} on {s}" for x, s in zip(yb, default))
          + f" | {verdict(min(yb) >= 25)} |",
          f"| best SIMD ≥ 3× scalar `ybuffer`, single thread | `{best_simd}` {fmt(geo(simd_r))} "
          f"({fmt(min(simd_r), '')}–{fmt(max(simd_r))} per scene) | {verdict(min(simd_r) >= 3)} |",
          f"| `omp` on 2 cores ≥ 1.8× the best single-thread kernel | {fmt(geo(omp_r))} over "
          f"`{best1}` ({fmt(min(omp_r), '')}–{fmt(max(omp_r))} per scene) | "
          f"{omp_verdict(omp_r)} |",
          f"| best kernel < 0.3 ms per frame, 640×480, D 800 | `{best[0]}`, {best[1]} "
          f"thread{'s' if best[1] > 1 else ''}: {min(best_ms):.3f}–{max(best_ms):.3f} ms | "
          f"{verdict(max(best_ms) < 0.3)} |"]
    sub = next((v for k, v in t.items() if k.startswith("The course submission")), None)
    if sub:
        h = sub[0]
        for r in sub[1:]:
            if r[0] == "valley":
                ratio = num(r[h.index("submission vs painter")])
                tl.append(f"| submission ≥ 20× (goal 40×) the plain course painter at `-O3`, valley | "
                          f"{fmt(ratio)} ({r[h.index('submission (-O3)')]} ms against "
                          f"{r[h.index('course painter (-O3)')]} ms) | {verdict(ratio >= 20)}"
                          f"{', goal met' if ratio >= 40 else ''} |")
    blocks["bench:targets"] = "\n".join(tl)
    if sub:
        h, r = sub[0], {row[0]: row for row in sub[1:]}
        ratio = h.index("submission vs painter")
        parts = [f"{r[s][ratio]}{' the plain course painter at `-O3`' if i == 0 else ''} on {s} "
                 f"({r[s][h.index('submission (-O3)')]} ms against {r[s][h.index('course painter (-O3)')]} ms)"
                 for i, s in enumerate(s for s in ("valley", "island", "pyramids") if s in r)]
        v = num(r["valley"][ratio]) if "valley" in r else None
        target = (f" Against the target of 150× on valley (issue 18): {fmt(v)} — {verdict(v >= 150)}."
                  + readme_skipping.submission_spread(h, r["valley"]) if v is not None else "")
        blocks["bench:submission"] = ("**Speed** in the published run: " + ", ".join(parts) + ". Its worker "
                                      "threads start with the first frame and are kept, and joined at exit, "
                                      "for the life of the process (`RETRO_PTHREADS` sets how many)." + target)
    eff_key = next((k for k in t if k.startswith("What each effect costs")), None)
    if eff_key:
        e = t[eff_key]
        turn = ("; in turn: the same ratio from pairs of frames timed one after the other after the run"
                if "in turn" in e[0] else "")
        lines = [f"Cost of each effect ({eff_key[len('What each effect costs '):].strip('()')}; "
                 "`ybuffer` against itself with no effect, and the fastest kernel for the effects "
                 f"against the fastest with none{turn}):", "",
                 "| " + " | ".join(e[0]) + " |", "|---|--:|--:|---|--:|--:|" + "--:|" * (len(e[0]) - 6)]
        lines += ["| " + " | ".join(row) + " |" for row in e[1:]]
        m = re.search(r"^Effects not called for cost nothing: .*$", md, re.M)
        if m:
            lines += ["", m.group(0)]
        lines += effect_targets(e, verdict)
        blocks["bench:effects"] = "\n".join(lines)

    mesh_key = next((k for k in t if k.startswith("Mesh family")), None)
    if mesh_key:
        blocks["bench:mesh"] = mesh_block(t[mesh_key], scenes, ms, geo, verdict)
    blocks["bench:skipping"] = skipping_block(byname, scenes, ms, geo, t, raw_json)
    large = readme_skipping.skip_large_block(t)
    if large:
        blocks["bench:skip-large"] = large
    sweep = mesh_sweep_block(t)
    if sweep:
        blocks["bench:mesh-sweep"] = sweep
    return blocks


def mesh_sweep_block(t):
    """The two families' cost against resolution and distance, and how their ratio moves."""
    lines = []
    for what in ("resolution", "distance"):
        key = next((k for k in t if k.startswith(f"Mesh and voxel cost against {what}")), None)
        if key is None:
            return None
        head, rows = t[key][0], t[key][1:]
        lines += [f"*{key}*", "", "| " + " | ".join(head) + " |", "|---|---|" + "--:|" * (len(head) - 2)]
        lines += ["| " + " | ".join(r) + " |" for r in rows]
        ratio = next((r for r in rows if r[0].startswith("best mesh")), None)
        if ratio:
            pts = ", ".join(f"{h}: {c}" for h, c in zip(head[2:], ratio[2:]))
            lines += ["", f"The best mesh kernel takes this many times the best voxel kernel's time, by {what}: "
                      f"{pts}."]
        lines.append("")
    return "\n".join(lines).rstrip("\n")


def mesh_block(table, scenes, voxel_ms, geo, verdict):
    """The mesh family against the voxel family, and the mesh speed targets, from one run."""
    head, rows = table[0], table[1:]
    c = {name: i for i, name in enumerate(head)}
    m, tn = {}, {}
    for r in rows:
        # "`mesh-omp` 2t": a threaded kernel at each thread count; the README quotes the most
        name, _, th = r[c["kernel"]].partition(" ")
        name, th = name.strip("`"), int(th.rstrip("t") or 1)
        if th < tn.get(name, 0):
            continue
        if th > tn.get(name, 0):
            m[name], tn[name] = {}, th
        m[name][r[c["scene"]]] = num(r[c["ms/frame"]])
    sc = [s for s in scenes if all(s in v for v in m.values())]
    g = {k: geo([v[s] for s in sc]) for k, v in m.items()}
    single = [k for k in m if k in ("mesh-avx2", "mesh-avx512")]
    best1 = min(single, key=g.get) if single else None
    best = min(m, key=g.get)
    vox = geo([voxel_ms("omp", 2, s) for s in sc])
    lines = ["| kernel | " + " | ".join(sc) + " | geomean | vs `mesh-zbuffer` | vs `omp`, 2 threads (voxel) |",
             "|---|" + "--:|" * (len(sc) + 3)]
    for k, v in m.items():
        lines.append(f"| `{k}` | " + " | ".join(f"{v[s]:.2f}" for s in sc)
                     + f" | {g[k]:.2f} | {fmt(g['mesh-zbuffer'] / g[k])} | {fmt(g[k] / vox)} slower |")
    lines += ["", f"- **Mesh against voxel.** The fastest mesh kernel, `{best}`, takes {g[best]:.1f} ms per "
              f"frame (geometric mean over the scenes), {fmt(g[best] / vox)} the time of the voxel kernel "
              f"`omp` on 2 threads ({vox:.3f} ms) at the same size and distance."]
    if best1:
        r1 = g["mesh-zbuffer"] / g[best1]
        lines.append(f"- **Target: best single-thread mesh SIMD ≥ 5× `mesh-zbuffer`.** `{best1}`: {fmt(r1)} — "
                     f"{verdict(r1 >= 5)}.")
        if "mesh-omp" in g:
            r2 = g[best1] / g["mesh-omp"]
            lines.append(f"- **Target: `mesh-omp` on 2 threads ≥ 1.8× the best single-thread mesh kernel.** "
                         f"{fmt(r2)} — {verdict(r2 >= 1.8)}.")
    return "\n".join(lines)


def skipping_block(byname, scenes, ms, geo, t, raw_json):
    """Occlusion skipping: each kernel with and without it in the same run, and issue 18's targets."""
    lines = ["| kernel | threads | with skipping | without | speedup |", "|---|--:|--:|--:|--:|"]
    for (k, n) in byname:
        if k.endswith(" (no skipping)") or (k + " (no skipping)", n) not in byname:
            continue
        a = geo([ms(k, n, s) for s in scenes])
        b = geo([ms(k + " (no skipping)", n, s) for s in scenes])
        lines.append(f"| `{k}` | {n} | {a:.3f} | {b:.3f} | {fmt(b / a)} |")
    sweep = next((v for kk, v in t.items() if kk.startswith("Distance sweep")), None)
    if sweep:
        h = sweep[0]
        rows = {r[0]: r for r in sweep[1:]}
        yb, ns = rows.get("`ybuffer`"), rows.get("`ybuffer` (no skipping)")
        if yb and ns:
            lines += ["", "`ybuffer` on the distance sweep (alpine, 640×480), ms per frame with and without "
                      "skipping: " + ", ".join(f"{h[i]} {yb[i]} / {ns[i]}" for i in range(2, len(h))) + "."]
    shares, ideal, oracle = {}, {}, {}
    if raw_json:
        for kernel in ("ybuffer", "omp"):
            ev = {}
            threads = "1t" if kernel == "ybuffer" else "2t"
            for b in raw_json.get("benchmarks", []):
                name = b.get("run_name", "")
                if (b.get("aggregate_name") == "median" and name.startswith("exact/")
                        and f"/{kernel}/{threads}/640x480/D800" in name and "noskip" not in name
                        and "evaluated%" in b):
                    ev[name.split("/")[1]] = b["evaluated%"]
                    if "ideal%" in b:
                        ideal[name.split("/")[1]] = b["ideal%"]
                    if "oracle%" in b:
                        oracle[name.split("/")[1]] = b["oracle%"]
            shares[kernel] = ev
        for kernel, what in (("ybuffer", "`ybuffer` evaluates (one column at a time)"),
                             ("omp", "the SIMD strips evaluate (`simd-avx512`'s, which `omp` runs; a group "
                              "of 16 columns skips where all its lanes may)")):
            ev = shares[kernel]
            if ev:
                lines += ["", f"Samples {what}, as a share of W×(D−1): "
                          + ", ".join(f"{s} {ev[s]:.0f}%" for s in scenes if s in ev) + "."]
    omp = geo([ms("omp", 2, s) for s in scenes])
    lines += ["", f"- **Target: `omp` on 2 threads ≤ 0.10 ms per frame** (geometric mean): {omp:.3f} ms — "
              f"{'met' if omp <= 0.10 else '**not met**'}."]
    ev = shares.get("omp")
    if ev:
        worst = max(ev, key=ev.get)
        lines.append(f"- **Target: samples evaluated ≤ 35% of W×(D−1) on each scene** (`omp`): at most "
                     f"{ev[worst]:.0f}% ({worst}) — {'met' if ev[worst] <= 35 else '**not met**'}.")
        def bound_line(share, what, digits, over_tail):  # one ideal walk's shares, per scene
            over = [s for s in scenes if s in share and share[s] > 35]
            return (f"  {what} would evaluate " + ", ".join(f"{s} {share[s]:.{digits}f}%" for s in scenes if s in share)
                    + " in the same run" + (f": above 35% on {', '.join(over)}{over_tail}." if over else "."))
        if ideal:
            lines.append(bound_line(ideal, "An ideal max bound (each run bounded by its own cells, not a block window, "
                                    "down to blocks of 4 cells, a probe before every sample; docs/studies/SKIPPING_LIMITS.md, "
                                    "\"How far a max bound can go\")", 0, " even so"))
        if oracle:
            lines.append(bound_line(oracle, "With the same runs, an oracle that skips exactly the runs none of whose "
                                    "samples paints (what any bound at all could do; docs/studies/SKIPPING_LIMITS.md, \"Other "
                                    "bounds at the same granularity\")", 1, ""))
    return "\n".join(lines)


def accuracy_run(md):
    """The machine and commit an accuracy run names ("Machine: M. Commit: C."), or None."""
    m = re.search(r"^Machine: (.+?)\. Commit: (.+?)\.$", md, re.M)
    return (m.group(1), m.group(2)) if m else None


def accuracy_blocks(md):
    t = tables(md)
    key = next(iter(t), None)
    if key is None:
        sys.exit("readme-figures: ACCURACY.md has no table")
    head, rows = t[key][0], t[key][1:]
    col = {name: i for i, name in enumerate(head)}
    v = {r[0]: r for r in rows}
    m = re.search(r"Measured (.+?) by `make accuracy`: (\d+) seeded random poses", md)
    when, poses = (m.group(1), m.group(2)) if m else ("unknown", "?")
    where = accuracy_run(md)
    machine = f" on {where[0]}, commit `{where[1]}`" if where else ""
    # runs before the accuracy run timed its steadiness have no Spread line
    sp = re.search(r"^Spread: ([0-9.]+%) with `([^`]+)`, ([0-9.]+%) with `ybuffer`, over (\d+) checkpoints", md, re.M)
    steady = (f"; the reference frame's time spread {sp.group(1)} with `{sp.group(2)}` and {sp.group(3)} with "
              f"`ybuffer` across the run's {sp.group(4)} checkpoints") if sp else ""
    out = {}
    out["accuracy:context"] = (
        f"`retro accuracy` rendered {poses} seeded random poses of the six scenes with each "
        f"variant and compared each frame with mode `truth`, on {when}{machine}{steady} (one `make accuracy` run, "
        "published by `make publish` or `make publish-accuracy`; [`results/ACCURACY.md`](results/ACCURACY.md)). Definitions "
        "are in [`docs/ACCURACY.md`](docs/ACCURACY.md). Its times come from its own run, so "
        "compare them with each other, not with the benchmark's.")
    lines = ["| " + " | ".join(head) + " |", "|---|---|---|" + "---:|" * (len(head) - 3)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    out["accuracy:table"] = "\n".join(lines)

    def get(variant, name):
        return num(v[variant][col[name]]) if variant in v else math.nan

    ybms = "ybuffer ms/frame"
    fms = "ms/frame"
    px = "pixels differ"
    cols = "silhouette columns differ"
    say = []
    tr = get("truth", ybms) / get("exact", ybms)
    say.append(f"- **binary64 against binary32.** On `ybuffer` truth takes {fmt(tr)} the time of "
               f"exact; with the fastest kernel for each mode, {fmt(get('truth', fms) / get('exact', fms))}. "
               f"Binary32 differs from truth on {get('exact', px):.3f}% of pixels and "
               f"{get('exact', cols):.2f}% of silhouette columns.")
    if "fixed" in v:
        say.append(f"- **Integer fixed point** takes {fmt(get('fixed', ybms) / get('exact', ybms))} "
                   f"the time of binary32 on `ybuffer` and differs from truth on "
                   f"{get('fixed', px):.3f}% of pixels (binary32: {get('exact', px):.3f}%).")
    if "course" in v:
        say.append(f"- **The course's arithmetic** takes {fmt(get('course', ybms) / get('exact', ybms))} "
                   f"the time of exact on `ybuffer` and changes {get('course', px):.1f}% of the pixels.")
    for lod in ("lod 0.02",):
        if lod in v:
            say.append(f"- **A distance step of 2% of the distance** ({lod}) runs "
                       f"{fmt(get('exact', ybms) / get(lod, ybms))} as fast as exact on `ybuffer` and moves "
                       f"the silhouette in {get(lod, cols):.1f}% of the columns.")
    for peer in (k for k in v if k.startswith("peer")):
        say.append(f"- **The classic demo's algorithm** ({peer}, a peer, not a mode of retro) runs "
                   f"{fmt(get('exact', ybms) / get(peer, ybms))} as fast as exact on `ybuffer`'s time and "
                   f"moves the silhouette in {get(peer, cols):.1f}% of the columns.")
    if "half" in v:
        say.append(f"- **Half resolution** runs {fmt(get('exact', fms) / get('half', fms))} as fast "
                   f"with the fastest kernel, with {get('half', cols):.1f}% of silhouette columns moved.")
    scalar_best = min(get(k, ybms) for k in v)
    say.append(f"- **Fastest kernel against cheaper arithmetic.** Exact with the fastest kernel takes "
               f"{get('exact', fms):.3f} ms; the cheapest variant on scalar `ybuffer` takes "
               f"{scalar_best:.3f} ms.")
    out["accuracy:prose"] = "\n".join(say)
    fam_key = next((k for k in t if k.startswith("Across families")), None)
    if fam_key:
        out["accuracy:families"] = families_block(t[fam_key])
    return out


def families_block(table):
    """Both families against the continuous terrain (the mesh in binary64), from one accuracy run."""
    head, rows = table[0], table[1:]
    c = {name: i for i, name in enumerate(head)}
    lines = ["| " + " | ".join(head) + " |", "|---|---|---|---|" + "---:|" * (len(head) - 4)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    v = {r[c["variant"]]: r for r in rows}
    get = lambda k, col: num(v[k][c[col]])
    if "exact" in v and "mesh binary32" in v:
        px, sil, ms = "pixels differ", "mean silhouette error (rows)", "ms/frame"
        lines += ["", f"- **What the voxel approximation costs in accuracy.** Against the continuous terrain "
                  f"(the mesh in binary64), voxel mode exact differs on {get('exact', px):.1f}% of pixels with "
                  f"a mean silhouette error of {get('exact', sil):.3f} rows; the mesh in binary32 on "
                  f"{get('mesh binary32', px):.3f}%.",
                  f"- **What it buys in time.** Voxel exact with its fastest kernel takes {get('exact', ms):.3f} ms, "
                  f"the mesh in binary32 with its fastest kernel {get('mesh binary32', ms):.1f} ms: "
                  f"{fmt(get('mesh binary32', ms) / get('exact', ms))} the time, in this accuracy run."]
    return "\n".join(lines)


def replace(readme, blocks):
    for name, body in blocks.items():
        pat = re.compile(r"(<!-- " + re.escape(name) + r":begin -->\n).*?(<!-- "
                         + re.escape(name) + r":end -->)", re.S)
        if not pat.search(readme):
            sys.exit(f"readme-figures: README has no block {name}")
        readme = pat.sub(lambda m: m.group(1) + body + "\n" + m.group(2), readme)
    return readme


def main(argv):
    if argv[1:2] in (["-h"], ["--help"]):
        print(__doc__)
        return 0
    check = argv[1:2] == ["--check"]
    args = argv[2:] if check else argv[1:]
    if len(args) != 2 or any(a.startswith("-") for a in args):
        print("readme-figures.py: usage: readme-figures.py [--check] RESULTS_DIR README.md (--help)", file=sys.stderr)
        return 2
    results, path = args
    import os
    for f in (f"{results}/BENCH.md", f"{results}/ACCURACY.md", path):
        if not os.path.isfile(f):
            print(f"readme-figures.py: {f}: no such file", file=sys.stderr)
            return 2
    import json
    raw = os.path.exists(f"{results}/bench.json")
    blocks = bench_blocks(open(f"{results}/BENCH.md", encoding="utf-8").read(), raw,
                          json.load(open(f"{results}/bench.json", encoding="utf-8")) if raw else None)
    repo = os.path.dirname(os.path.abspath(path))
    # the build to compare the runs' objects with: RETRO_BUILD, else the repository's build/
    build = os.environ.get("RETRO_BUILD") or os.path.join(repo, "build")
    since = since_block(open(f"{results}/BENCH.md", encoding="utf-8").read(), repo,
                        f"{results}/bench-code.txt", build)
    if since is not None:
        blocks["bench:since"] = since
    else:
        print("note: git or the build cannot say whether the kernels changed after the published run "
              f"(objects compared: {build}): README's bench:since block is not checked")
    columns = readme_skipping.skip_columns_block(results)
    if columns:
        blocks["bench:skip-columns"] = columns
    accuracy = open(f"{results}/ACCURACY.md", encoding="utf-8").read()
    blocks.update(accuracy_blocks(accuracy))
    run = accuracy_run(accuracy)
    # a run of edited sources ("-dirty") has no commit to count from; since_commit refuses it
    since = since_commit(run[1], repo, f"{results}/accuracy-code.txt", build) if run else None
    if since is not None:
        blocks["accuracy:since"] = since
    else:
        print("note: the accuracy run names no clean commit git knows, or its objects cannot be compared with "
              f"{build}: README's accuracy:since block is not checked")
    old = open(path, encoding="utf-8").read()
    new = replace(old, blocks)
    if check:
        if new != old:
            import difflib
            sys.stdout.writelines(difflib.unified_diff(old.splitlines(True), new.splitlines(True),
                                                       path, "from " + results))
            print(f"FAIL: {path}'s figures differ from the run in {results} "
                  "(python3 scripts/readme-figures.py results README.md rewrites them)")
            return 1
        print(f"ok: every generated block of {path} matches {results}")
        return 0
    if new != old:
        with open(path + ".tmp", "w", encoding="utf-8") as f:
            f.write(new)
        import os
        os.replace(path + ".tmp", path)
        print(f"  GEN     {path} (figures from {results})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
