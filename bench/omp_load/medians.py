#!/usr/bin/env python3
"""Medians of run_omp_load.sh's rounds: one row per build, load, scene, backend and wait
policy, with the load averages (uptime's first number) seen during its runs.

Usage: bench/omp_load/medians.py RUNS.tsv [RUNS.tsv ...]  (prints a Markdown table)"""
import csv
import statistics
import sys
from collections import defaultdict

groups = defaultdict(list)
order = []
for path in sys.argv[1:]:
    with open(path) as f:
        for row in csv.DictReader(f, delimiter="\t"):
            key = (row["label"], row["scene"], row["load"], row["backend"], row["policy"])
            if key not in groups:
                order.append(key)
            groups[key].append(row)

serial = {}
for key in order:
    label, scene, load, backend, _ = key
    if backend == "cpu":
        serial[(label, scene, load)] = statistics.median(float(r["s_per_step"]) for r in groups[key])

print("| build | scene | cores | backend | wait policy | runs | median s/step | vs serial (same load) | load averages seen |")
print("|---|---|---|---|---|---:|---:|---:|---|")
for key in order:
    label, scene, load, backend, policy = key
    rows = groups[key]
    med = statistics.median(float(r["s_per_step"]) for r in rows)
    loads = sorted(float(r["load1"]) for r in rows)
    ref = serial.get((label, scene, load))
    ratio = f"{med / ref:.2f}x" if ref and backend != "cpu" else ""
    print(f"| {label} | {scene} | {load} | {backend} | {policy} | {len(rows)} | "
          f"{med * 1e3:.3f} ms | {ratio} | {loads[0]:.2f}-{loads[-1]:.2f} |")
