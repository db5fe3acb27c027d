#!/usr/bin/env python3
"""Markdown table of the CPU solver benchmark from Google Benchmark's JSON output.

Usage: cpu_bench_table.py RESULT.json [--machine-file FILE] [--notes-file FILE]

Medians are computed here from the individual repetitions (so a case run once still gets
a row); the range column gives the slowest and fastest repetition. Standard library only.
"""
import argparse
import json
import re
import statistics
import sys

NAME = re.compile(r"^dense_pile/(cpu|openmp)/n:(\d+)")


def fmt_rate(x):
    if x is None:
        return "–"
    for scale, suffix in ((1e9, "G"), (1e6, "M"), (1e3, "k")):
        if x >= scale:
            return f"{x / scale:.3g} {suffix}"
    return f"{x:.3g}"


def step_ms(rate, triangles):
    """Wall ms per step at the median rate (so that it agrees with the rate column)."""
    if not rate or not triangles:
        return "–"
    ms = 1e3 * triangles / rate
    return f"{ms:.3g}" if ms < 1000 else f"{ms:.0f}"


def collect(data):
    """{(backend, n): {"rate": [...], "sps": [...], "threads": t, "triangles": m, ...}}"""
    cases = {}
    for b in data.get("benchmarks", []):
        if b.get("run_type") != "iteration":
            continue
        m = NAME.match(b.get("run_name", b.get("name", "")))
        if not m:
            continue
        key = (m.group(1), int(m.group(2)))
        c = cases.setdefault(key, {"rate": [], "sps": [], "errors": []})
        if b.get("error_occurred"):
            c["errors"].append(b.get("error_message", "error"))
            continue
        c["rate"].append(b["tri_steps_per_s"])
        c["sps"].append(b["s_per_step"])
        c["threads"] = int(b["threads"])
        c["triangles"] = int(b["triangles"])
        c["steps_per_iter"] = int(b["steps_per_iter"])
        c["iterations"] = int(b["iterations"])
        c["first_step"] = int(b.get("first_step", 1))
        c["contacts_per_tri"] = b.get("contacts_per_tri")
    return cases


def fmt_n(n):
    e = len(str(n)) - 1
    return f"10^{e}" if n == 10**e else str(n)


def median(xs):
    return statistics.median(xs) if xs else None


def table(cases):
    sizes = sorted({n for (_, n) in cases})
    lines = [
        "| n (grains) | triangles | contacts/tri | serial tri-steps/s | serial ms/step "
        "| serial reps (range tri-steps/s) | OpenMP tri-steps/s | OpenMP ms/step | threads "
        "| OpenMP reps (range tri-steps/s) | speed-up OpenMP/serial |",
        "|---:|---:|---:|---:|---:|---|---:|---:|---:|---|---:|",
    ]
    for n in sizes:
        s = cases.get(("cpu", n), {})
        o = cases.get(("openmp", n), {})
        sr, orate = median(s.get("rate", [])), median(o.get("rate", []))
        tri = s.get("triangles") or o.get("triangles")
        cpt = s.get("contacts_per_tri") or o.get("contacts_per_tri")

        def reps(c):
            if not c.get("rate"):
                return "not run" if not c.get("errors") else "error: " + c["errors"][0]
            return f"{len(c['rate'])} ({fmt_rate(min(c['rate']))}–{fmt_rate(max(c['rate']))})"

        speedup = f"{orate / sr:.2f}×" if sr and orate else "–"
        cpt_text = f"{cpt:.2f}" if cpt is not None else "–"
        lines.append(
            f"| {fmt_n(n)} | {tri if tri else '–'} | {cpt_text} | "
            f"{fmt_rate(sr)} | {step_ms(sr, tri)} | {reps(s)} | "
            f"{fmt_rate(orate)} | {step_ms(orate, tri)} | "
            f"{o.get('threads', '–')} | {reps(o)} | {speedup} |")
    return "\n".join(lines)


def work_table(cases):
    sizes = sorted({n for (_, n) in cases})
    lines = ["| n | steps per iteration (k) | iterations per repetition | timed steps |",
             "|---:|---:|---:|---|"]
    for n in sizes:
        c = cases.get(("cpu", n)) or cases.get(("openmp", n))
        k, it, first = c.get("steps_per_iter"), c.get("iterations"), c.get("first_step")
        window = f"{first} to {first + k * it - 1}" if k and it and first else "–"
        lines.append(f"| {fmt_n(n)} | {k or '–'} | {it or '–'} | {window} |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("json")
    ap.add_argument("--machine-file", help="Markdown lines describing the machine and run")
    ap.add_argument("--notes-file", help="Markdown notes appended at the end")
    args = ap.parse_args()
    with open(args.json) as f:
        data = json.load(f)
    cases = collect(data)
    if not cases:
        sys.exit(f"{args.json}: no dense_pile result in it")
    ctx = data.get("context", {})
    out = ["# CPU solver benchmark: dense settling pile", ""]
    if args.machine_file:
        with open(args.machine_file) as f:
            out += [f.read().rstrip(), ""]
    out += [
        f"Google Benchmark context: host `{ctx.get('host_name', '?')}`, "
        f"{ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz, "
        f"compiler {ctx.get('compiler', '?')}, tridem build {ctx.get('tridem_build_type', '?')}, "
        f"load average at start of the benchmark {ctx.get('load_avg', '?')}.",
        "",
        "## Results (medians over repetitions)",
        "",
        table(cases),
        "",
        "Triangle-steps/s = triangles (grains + 3 walls) × steps / wall time; ms/step is the "
        "wall time of one step at that median rate. The range is the slowest–fastest repetition. "
        "Speed-up is the ratio of the two medians.",
        "",
        "Work per repetition, the same for both backends: a fresh `dense_pile(n)`, "
        f"{{}} untimed warm-up steps, then the timed steps:".format(
            min(c.get("first_step", 1) for c in cases.values()) - 1),
        "",
        work_table(cases),
    ]
    if args.notes_file:
        with open(args.notes_file) as f:
            out += ["", "## Notes", "", f.read().rstrip()]
    print("\n".join(out))


if __name__ == "__main__":
    main()
