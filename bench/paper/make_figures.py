#!/usr/bin/env python3
"""Tables and figures of the paper's experiments from tridem_paper_bench's JSON.

    make_figures.py BENCH.json [LATER.json ...] OUTDIR

A case in a later file replaces the case of the same name in an earlier one (a rerun of
one experiment). Writes OUTDIR/paper_tables.md and fig12.png, fig19.png, fig20.png, fig21.png,
prefilter.png (matplotlib). Every number is a median over the case's repetitions when it
has several, else the mean over its iterations; ratios are taken between cases of the one
run in BENCH.json."""
import json
import os
import statistics
import sys
from collections import defaultdict

UNIT = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def load(paths):
    runs = defaultdict(list)
    errors = {}
    context = {}
    for path in paths:
        with open(path) as f:
            data = json.load(f)
        context = context or data.get("context", {})
        names = {(b.get("run_name") or b["name"]).split("/iterations:")[0]
                 for b in data["benchmarks"]}
        for name in names:
            runs.pop(name, None)
            errors.pop(name, None)
        read_runs(data, runs, errors)
    return context, summarise(runs), errors


def read_runs(data, runs, errors):
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        name = b["run_name"] if "run_name" in b else b["name"]
        name = name.split("/iterations:")[0]
        if b.get("error_occurred"):
            errors[name] = b.get("error_message", "error")
            continue
        runs[name].append(b)


def summarise(runs):
    cases = {}
    for name, reps in runs.items():
        parts = name.split("/")
        key = {"experiment": parts[0], "backend": parts[1], "design": parts[2],
               "problem": parts[3], "n": int(parts[4][2:]), "tail": "/".join(parts[5:])}
        seconds = statistics.median(r["real_time"] * UNIT[r["time_unit"]] for r in reps)
        per_step = [r["s_per_step"] for r in reps if "s_per_step" in r]
        key["seconds"] = seconds
        key["s_per_step"] = statistics.median(per_step) if per_step else None
        key["triangles"] = int(reps[0].get("triangles", key["n"]))
        key["label"] = reps[0].get("label", "")
        cases[name] = key
    return cases


def pick(cases, **want):
    return [c for c in cases.values() if all(c[k] == v for k, v in want.items())]


def one(cases, **want):
    found = pick(cases, **want)
    return found[0] if found else None


def fmt_time(s):
    if s is None:
        return "—"
    for unit, scale in (("s", 1), ("ms", 1e-3), ("µs", 1e-6)):
        if s >= scale:
            return f"{s / scale:.3g} {unit}"
    return f"{s * 1e9:.3g} ns"


def table3(cases, errors, out):
    out.append("## Table 3: one time step of about 256 triangles\n")
    out.append("| design | triangles | GPU step | CPU step (1 core) | CPU/GPU | state up (load_state) | state down (snapshot) |")
    out.append("|---|---|---|---|---|---|---|")
    for design in ("single-domain", "decomposition-1d", "grid"):
        g = one(cases, experiment="table3", backend="cuda", design=design, tail="k:100")
        c = one(cases, experiment="table3", backend="cpu", design=design, tail="k:100")
        up = one(cases, experiment="table3", backend="cuda", design=design, tail="upload")
        down = one(cases, experiment="table3", backend="cuda", design=design, tail="download")
        ratio = f"{c['s_per_step'] / g['s_per_step']:.3g}×" if g and c else "—"
        tri = (g or c or {}).get("triangles", "—")
        out.append(f"| {design} | {tri} | {fmt_time(g and g['s_per_step'])} | "
                   f"{fmt_time(c and c['s_per_step'])} | {ratio} | {fmt_time(up and up['seconds'])} | "
                   f"{fmt_time(down and down['seconds'])} |")
    out.append("")


def plot(filename, title, xlabel, ylabel, series, logx=True, logy=True):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, xs, ys, style in series:
        if xs:
            ax.plot(xs, ys, style, label=label)
    ax.set_xscale("log" if logx else "linear")
    ax.set_yscale("log" if logy else "linear")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(filename, dpi=120)
    plt.close(fig)


def curve(cases, value="seconds", **want):
    found = sorted(pick(cases, **want), key=lambda c: c["n"])
    return [c["triangles"] for c in found], [c[value] for c in found]


def fig12(cases, out, outdir):
    out.append("## Fig. 12: speed-up of the whole job against the number of steps\n")
    out.append("The job: solver set-up (scene data to the solver, for the GPU the upload), k "
               "steps, the state back. Single-domain design; speed-up = CPU job time / GPU job time.\n")
    out.append("| triangles | k | CPU job | GPU job | speed-up |")
    out.append("|---|---|---|---|---|")
    series = []
    for n, style in ((256, "o-"), (4096, "s-")):
        ks, speedups = [], []
        for k in (1, 10, 100, 1000):
            c = one(cases, experiment="fig12", backend="cpu", n=n, tail=f"k:{k}")
            g = one(cases, experiment="fig12", backend="cuda", n=n, tail=f"k:{k}")
            if not (c and g):
                continue
            ks.append(k)
            speedups.append(c["seconds"] / g["seconds"])
            out.append(f"| {g['triangles']} | {k} | {fmt_time(c['seconds'])} | {fmt_time(g['seconds'])} | "
                       f"{speedups[-1]:.3g}× |")
        series.append((f"about {n} triangles", ks, speedups, style))
    out.append("")
    plot(os.path.join(outdir, "fig12.png"), "Fig. 12: speed-up vs steps (single-domain)",
         "steps k", "CPU time / GPU time", series)


def time_vs_n(cases, out, outdir, experiment, title, filename, lines):
    series = []
    out.append(f"## {title}\n")
    header = "| triangles | " + " | ".join(label for label, _ in lines) + " |"
    out.append(header)
    out.append("|" + "---|" * (len(lines) + 1))
    rows = defaultdict(dict)
    for label, want in lines:
        xs, ys = curve(cases, experiment=experiment, **want)
        series.append((label, xs, ys, "o-" if want.get("backend") == "cuda" else "s--"))
        for x, y in zip(xs, ys):
            rows[x][label] = y
    for x in sorted(rows):
        out.append(f"| {x} | " + " | ".join(fmt_time(rows[x].get(label)) for label, _ in lines) + " |")
    out.append("")
    plot(os.path.join(outdir, filename), title, "triangles", "time for 100 steps, s", series)


def fig20_lines(cases):
    shapes = sorted({c["design"] for c in pick(cases, experiment="fig20")
                     if c["design"].startswith("decomposition-2d")})
    return [(f"GPU {s}", {"backend": "cuda", "design": s}) for s in shapes] + \
           [("GPU grid", {"backend": "cuda", "design": "grid"})]


def prefilter(cases, out, outdir):
    out.append("## The bounding-box pre-filter (§4)\n")
    out.append("Time per step with the pre-filter on and off; ratio > 1: the pre-filter helps.\n")
    out.append("| backend | design | packing | triangles | pre-filter on | off | off/on | grid |")
    out.append("|---|---|---|---|---|---|---|---|")
    bars = []
    for backend in ("cuda", "cpu"):
        for design in ("single-domain", "decomposition-2d"):
            for problem in ("sparse", "medium", "dense"):
                for on in pick(cases, experiment="prefilter", backend=backend, design=design,
                               problem=problem):
                    off = one(cases, experiment="prefilter", backend=backend,
                              design=design + "-noprefilter", problem=problem, n=on["n"])
                    grid = one(cases, experiment="prefilter", backend=backend, design="grid",
                               problem=problem, n=on["n"])
                    ratio = off["s_per_step"] / on["s_per_step"] if off else None
                    out.append(f"| {backend} | {design} | {problem} | {on['triangles']} | "
                               f"{fmt_time(on['s_per_step'])} | {fmt_time(off and off['s_per_step'])} | "
                               f"{'—' if ratio is None else f'{ratio:.3g}×'} | "
                               f"{fmt_time(grid and grid['s_per_step'])} |")
                    if ratio is not None:
                        bars.append((f"{backend} {design}\n{problem} n={on['triangles']}", ratio))
    out.append("")
    if bars:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(max(7, 0.7 * len(bars)), 4.5))
        ax.bar(range(len(bars)), [b[1] for b in bars])
        ax.axhline(1, color="k", lw=0.8)
        ax.set_xticks(range(len(bars)))
        ax.set_xticklabels([b[0] for b in bars], rotation=60, ha="right", fontsize=7)
        ax.set_ylabel("time without / with pre-filter")
        ax.set_title("Does the bounding-box pre-filter help?")
        fig.tight_layout()
        fig.savefig(os.path.join(outdir, "prefilter.png"), dpi=120)
        plt.close(fig)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    context, cases, errors = load(sys.argv[1:-1])
    outdir = sys.argv[-1]
    os.makedirs(outdir, exist_ok=True)
    out = [f"# The paper's experiments on {context.get('gpu', '?')} and {context.get('cpu_model', '?')}\n",
           f"From {', '.join(f'`{os.path.basename(p)}`' for p in sys.argv[1:-1])} "
           f"({context.get('date', '?')}); made by "
           "bench/paper/make_figures.py. CPU = one core (the serial solver).\n"]
    table3(cases, errors, out)
    fig12(cases, out, outdir)
    time_vs_n(cases, out, outdir, "fig19", "Fig. 19: 100 steps against n, 1D decomposition",
              "fig19.png", [("GPU 1D", {"backend": "cuda", "design": "decomposition-1d"}),
                            ("CPU 1D", {"backend": "cpu", "design": "decomposition-1d"}),
                            ("GPU grid", {"backend": "cuda", "design": "grid"}),
                            ("CPU grid", {"backend": "cpu", "design": "grid"})])
    time_vs_n(cases, out, outdir, "fig20", "Fig. 20: 2D decompositions of different shapes (GPU)",
              "fig20.png", fig20_lines(cases))
    time_vs_n(cases, out, outdir, "fig19", "Fig. 21: 1D against 2D decomposition",
              "fig21.png", [("GPU 1D", {"backend": "cuda", "design": "decomposition-1d"}),
                            ("GPU 2D", {"backend": "cuda", "design": "decomposition-2d"}),
                            ("CPU 1D", {"backend": "cpu", "design": "decomposition-1d"}),
                            ("CPU 2D", {"backend": "cpu", "design": "decomposition-2d"})])
    prefilter(cases, out, outdir)
    if errors:
        out.append("## Cases that did not run\n")
        for name, why in sorted(errors.items()):
            out.append(f"- `{name}`: {why}")
        out.append("")
    with open(os.path.join(outdir, "paper_tables.md"), "w") as f:
        f.write("\n".join(out))
    print("\n".join(out))


if __name__ == "__main__":
    main()
