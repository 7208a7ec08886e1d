"""The README's figures of issue 18's measurements, for readme-figures.py: occlusion skipping at
a large frame (BENCH.md's table), the share of samples evaluated along each column
(skip-columns.csv and .txt, written by scripts/skip-columns.sh in the same `make bench`) and the
submission's spread across runs. Each returns None when its run lacks the data, so a run made
before the measurement existed leaves the README's block as it is."""
import os
import re
import sys

if __name__ == "__main__":
    sys.exit("readme_skipping.py is a module of readme-figures.py, not a program: "
             "python3 scripts/readme-figures.py --help")


def verdict(ok):
    return "met" if ok else "**not met**"


def times(cell):
    return float(cell.replace("×", ""))


def skip_large_block(t):
    """omp with and without skipping at 1920×1080, D 4000, and the 4× target."""
    key = next((k for k in t if k.startswith("Occlusion skipping at a large frame")), None)
    if key is None:
        return None
    head, rows = t[key][0], t[key][1:]
    geo = next((r for r in rows if r[0].startswith("geomean")), None)
    if geo is None:
        return None
    what = key[len("Occlusion skipping at a large frame"):].strip().strip("()")
    ratio = times(geo[head.index("ratio")])
    turn = ("; in turn: the median ratio of pairs of the two frames timed one after the other after the run, "
            "with its quartiles" if "in turn" in head else "")
    lines = [f"At a large frame ({what}), median ms per frame with the kernel's default skipping "
             f"and with it off (`--no-skip`), timed side by side in the same run{turn}:", "",
             "| " + " | ".join(head) + " |", "|---|" + "--:|" * (len(head) - 1)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    per = [times(r[head.index("ratio")]) for r in rows if r is not geo and r[head.index("ratio")] != "–"]
    turn = geo[head.index("in turn")] if "in turn" in head else "–"
    beside = f"; timed in turn, {turn}" if turn.endswith("×") else ""
    lines += ["", f"- **Target: at 1920×1080, D 4000, `omp` at least 4× faster than without skipping** "
              f"(geometric mean over the scenes): {ratio:.2f}× ({min(per):.2f}× to {max(per):.2f}× per scene"
              f"{beside}) — {verdict(ratio >= 4)}."]
    return "\n".join(lines)


def skip_columns_block(results):
    """The share of samples ybuffer evaluates along each column, with skipping and without."""
    csv, txt = f"{results}/skip-columns.csv", f"{results}/skip-columns.txt"
    if not (os.path.exists(csv) and os.path.exists(txt)):
        return None
    stats = open(txt, encoding="utf-8").read()
    frame = re.search(r"^frame: (.*)$", stats, re.M).group(1)
    total = {k: int(re.search(rf"^{k}: (\d+)", stats, re.M).group(1)) for k in ("samples", "evaluated", "painting")}
    lines = open(csv, encoding="utf-8").read().splitlines()
    if lines[0] != "column,samples,evaluated,painting,evaluated_noskip,painting_noskip":
        raise SystemExit(f"readme-figures: {csv}: unexpected header {lines[0]!r}")
    rows = [[int(x) for x in line.split(",")] for line in lines[1:]]
    sums = [sum(r[i] for r in rows) for i in range(1, 6)]
    # the columns must add up to the frame's totals printed beside them, or the files disagree
    if sums[:3] != [total["samples"], total["evaluated"], total["painting"]]:
        raise SystemExit(f"readme-figures: {csv} does not add up to {txt}'s totals")
    share = lambda i: [100.0 * r[i] / r[1] for r in rows if r[1]]
    ev, ns, pt = share(2), share(4), share(3)
    mean = lambda i: 100.0 * sums[i - 1] / sums[0]
    return (f"On the benchmark's frame of {frame} (`results/skip-columns.csv`, "
            f"{len(rows)} columns), `ybuffer` with skipping evaluates {mean(2):.1f}% of the samples "
            f"({min(ev):.1f}% to {max(ev):.1f}% per column), without skipping {mean(4):.1f}% "
            f"({min(ns):.1f}% to {max(ns):.1f}%); {mean(3):.1f}% of them paint "
            f"({min(pt):.1f}% to {max(pt):.1f}%), the same samples either way. So skipping evaluates "
            f"{sums[1] / sums[2]:.1f} samples per sample that paints, where the full walk evaluates "
            f"{sums[3] / sums[2]:.1f}.")


def submission_spread(header, row):
    """The sentence on the submission's spread across runs on one scene, or "" without the column."""
    if "submission spread" not in header or row[header.index("submission spread")] == "–":
        return ""
    spread = float(row[header.index("submission spread")].rstrip("%"))
    runs = int(row[header.index("runs")])
    return (f" Its spread across {runs} runs on {row[0]} (max − min over the median): {spread:.1f}% — "
            f"{verdict(spread <= 15 and runs >= 10)} (target: at most 15% across 10 runs).")
