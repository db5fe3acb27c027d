#!/usr/bin/env python3
"""The table of bench/compare_builds.sh: per benchmark, each build's median s/step over the
rounds and its speed against the first build."""
import glob
import json
import statistics
import sys


def medians(folder, name):
    per_bench = {}
    for path in sorted(glob.glob(f"{folder}/{name}_*.json")):
        with open(path) as f:
            for b in json.load(f)["benchmarks"]:
                if b.get("run_type") != "iteration" or "s_per_step" not in b:
                    continue
                key = b["name"].split("/iterations")[0]
                per_bench.setdefault(key, []).append(b["s_per_step"])
    return {k: statistics.median(v) for k, v in per_bench.items()}


def main():
    folder, names = sys.argv[1], sys.argv[2:]
    runs = {n: medians(folder, n) for n in names}
    base = runs[names[0]]
    print("| benchmark | " + " | ".join(f"{n} s/step" for n in names) + " | " +
          " | ".join(f"{n} speed-up" for n in names[1:]) + " |")
    print("|---" * (1 + 2 * len(names) - 1) + "|")
    for key in base:
        cells = [f"{runs[n].get(key, float('nan')) * 1e3:.4f} ms" for n in names]
        ups = [f"{base[key] / runs[n][key]:.3f}x" if key in runs[n] else "-" for n in names[1:]]
        print(f"| {key} | " + " | ".join(cells) + " | " + " | ".join(ups) + " |")


if __name__ == "__main__":
    main()
