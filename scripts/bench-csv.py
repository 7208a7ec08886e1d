#!/usr/bin/env python3
"""Writes a benchmark run's JSON (make bench: build/results/bench.json) as CSV: one row per
case and statistic, with the case's parameters split into columns.

usage: bench-csv.py BENCH.json > bench.csv
"""
import csv
import json
import signal
import sys

signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # piped into head: stop quietly, as a C program does

if sys.argv[1:2] in (["-h"], ["--help"]):
    print(__doc__.strip())
    sys.exit(0)
if len(sys.argv) != 2 or sys.argv[1].startswith("-"):
    print("bench-csv.py: usage: bench-csv.py BENCH.json > bench.csv (--help)", file=sys.stderr)
    sys.exit(2)
try:
    with open(sys.argv[1], encoding="utf-8") as f:
        run = json.load(f)
except (OSError, ValueError) as e:
    print(f"bench-csv.py: {sys.argv[1]}: {getattr(e, 'strerror', None) or e}", file=sys.stderr)
    sys.exit(2)
out = csv.writer(sys.stdout)
out.writerow(["name", "mode_or_table", "scene", "kernel", "threads", "screen", "distance", "statistic",
              "ms_per_frame", "mpixel_per_s", "iterations", "error"])
for b in run.get("benchmarks", []):
    parts = b.get("run_name", b["name"]).split("/")
    # Matrix and sweep cases are MODE/SCENE/KERNEL/Nt/WxH/DN; the extras name their table first.
    group, scene, kernel, threads = (parts + [""] * 4)[:4]
    screen = next((p for p in parts if "x" in p and p.replace("x", "").isdigit()), "")
    dist = next((p[1:] for p in parts if p.startswith("D") and p[1:].isdigit()), "")
    out.writerow([b["name"], group, scene, kernel, threads.rstrip("t"), screen, dist,
                  b.get("aggregate_name", "repetition"), b.get("ms/frame", ""), b.get("Mpixel/s", ""),
                  b.get("iterations", ""), b.get("error_message", "")])
