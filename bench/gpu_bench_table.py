#!/usr/bin/env python3
"""Markdown table of a GPU benchmark run: serial, OpenMP and CUDA solvers on dense_pile(n).

usage: gpu_bench_table.py CPU_JSON GPU_JSON [--header TEXT]
Medians over repetitions (Google Benchmark's *_median aggregates, or the only run);
speed-ups are ratios of medians measured in the same run on the same machine.
"""
import json
import sys
from collections import defaultdict


def medians(path):
    data = json.load(open(path))
    runs = defaultdict(list)
    for b in data["benchmarks"]:
        if b.get("error_occurred"):
            continue
        name = b["run_name"] if "run_name" in b else b["name"]
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        runs[name.split("/iterations")[0]].append(b)
    out = {}
    for name, bs in runs.items():
        agg = [b for b in bs if b.get("aggregate_name") == "median"]
        b = agg[0] if agg else bs[0]
        reps = len([x for x in bs if x.get("run_type") != "aggregate"]) or b.get("repetitions", 1)
        out[name] = dict(b, reps=reps)
    return data["context"], out


def fmt_rate(x):
    return f"{x / 1e6:.3g} M" if x < 1e9 else f"{x / 1e9:.3g} G"


def main():
    cpu_ctx, cpu = medians(sys.argv[1])
    gpu_ctx, gpu = medians(sys.argv[2])
    allr = {**cpu, **gpu}
    sizes = sorted({int(k.split("n:")[1]) for k in allr if k.startswith("dense_pile/")})
    print(f"GPU: {gpu_ctx.get('gpu', '?')}; CPU: {cpu_ctx.get('cpu_model', '?')}, "
          f"{cpu_ctx.get('omp_max_threads', '?')} OpenMP threads; tridem {gpu_ctx.get('tridem_version', '?')}, "
          f"{gpu_ctx.get('date', '')}\n")
    print("| n | triangles | serial | OpenMP | CUDA double | CUDA float | double vs serial | double vs OpenMP | float vs serial | float vs OpenMP |")
    print("|---:|---:|---|---|---|---|---:|---:|---:|---:|")
    for n in sizes:
        def cell(v):
            b = allr.get(f"dense_pile/{v}/n:{n}")
            if not b:
                return "–", None
            r = b["tri_steps_per_s"]
            return f"{fmt_rate(r)} ({b['s_per_step'] * 1e3:.3g} ms, {b['reps']}×)", r
        cells = {v: cell(v) for v in ("cpu", "openmp", "cuda", "cuda-float")}
        tri = next((allr[k]["triangles"] for k in allr if k.endswith(f"/n:{n}") and "triangles" in allr[k]), n)

        def ratio(a, b):
            x, y = cells[a][1], cells[b][1]
            return f"{x / y:.0f}×" if x and y else "–"
        print(f"| {n:.0e} | {int(tri)} | {cells['cpu'][0]} | {cells['openmp'][0]} | {cells['cuda'][0]} | "
              f"{cells['cuda-float'][0]} | {ratio('cuda', 'cpu')} | {ratio('cuda', 'openmp')} | "
              f"{ratio('cuda-float', 'cpu')} | {ratio('cuda-float', 'openmp')} |")
    print("\nTriangle-steps per second (median), in parentheses milliseconds per step and repetitions.\n")
    frames = [k for k in gpu if k.startswith("frame")]
    if frames:
        print("| output frame | n | ms per frame | state bytes | contacts | GB/s of state |")
        print("|---|---:|---:|---:|---:|---:|")
        for k in sorted(frames, key=lambda k: (k.split("/")[1], int(k.split("n:")[1]), k)):
            b = gpu[k]
            s = b["s_per_frame"]
            print(f"| {k.split('/n:')[0]} | {int(b['triangles'])} | {s * 1e3:.3g} | {int(b['state_bytes'])} | "
                  f"{int(b['contacts'])} | {b['state_bytes'] / s / 1e9:.2f} |")
        print("\nA frame copies 9 arrays of n (position, angle, velocities, forces) from the GPU into a host "
              "Snapshot in double precision; with contacts it also copies the pair list and results and "
              "keeps the touching pairs.")


if __name__ == "__main__":
    main()
