#!/usr/bin/env python3
"""Sums an Nsight Compute source page (--page source --print-source sass --csv) by opcode:
warp-level executions and stall samples, largest first. Usage: sass_opcode_table.py FILE.csv"""
import csv
import sys
from collections import defaultdict


def number(text):
    try:
        return float(text.replace(",", ""))
    except ValueError:
        return 0.0


def main(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f)]
    header_at = next(i for i, r in enumerate(rows) if "Source" in r)
    header = rows[header_at]
    source = header.index("Source")
    executed = next((i for i, h in enumerate(header) if "Instructions Executed" in h), None)
    if executed is None:
        sys.exit(f"no executed-instructions column in {header}")
    samples = next((i for i, h in enumerate(header) if h.startswith("Warp Stall Sampling (All")), None)
    by_op = defaultdict(lambda: [0.0, 0.0])
    for r in rows[header_at + 1:]:
        if len(r) <= executed:
            continue
        text = r[source].strip()
        if not text:
            continue
        op = text.split()[0]
        if op.startswith("@"):
            op = text.split()[1]
        op = op.split(".")[0]
        by_op[op][0] += number(r[executed])
        if samples is not None:
            by_op[op][1] += number(r[samples])
    total_exec = sum(v[0] for v in by_op.values()) or 1
    total_samp = sum(v[1] for v in by_op.values()) or 1
    print(f"{'opcode':<10} {'executed':>14} {'share':>7} {'stall samples':>14} {'share':>7}")
    for op, (e, s) in sorted(by_op.items(), key=lambda kv: -kv[1][0]):
        print(f"{op:<10} {e:>14.0f} {100 * e / total_exec:>6.1f}% {s:>14.0f} {100 * s / total_samp:>6.1f}%")


if __name__ == "__main__":
    main(sys.argv[1])
