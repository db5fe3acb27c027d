#!/usr/bin/env python3
"""Google Benchmark JSON files of one machine merged into one: the first file's context and
every file's benchmarks, in order. Files that do not exist are left out (a run that did not
finish); with none left nothing is written.

usage: merge_bench_json.py OUT_JSON IN_JSON...
"""
import json
import os
import sys


def main():
    out, inputs = sys.argv[1], [p for p in sys.argv[2:] if os.path.exists(p)]
    if not inputs:
        return 1
    merged = json.load(open(inputs[0]))
    for path in inputs[1:]:
        merged["benchmarks"] += json.load(open(path))["benchmarks"]
    json.dump(merged, open(out, "w"), indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
