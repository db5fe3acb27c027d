#!/usr/bin/env python3
"""mu(I) of angular grains in periodic simple shear (Lees-Edwards): writes one run per
packing fraction (scripts/write_shear_flow.py, grains shrunk by area scale s^2), runs them
(several at once), and from each measure_cell.csv takes the steady state (shear strain
from STEADY_FROM on): mu = -sxy/syy and I = shear_rate d / sqrt(P / rho), P the pressure.
    scripts/shear_flow_mu_i.py [--jobs 2] [--no-run | --write-only] [--png docs/images/shear_flow_mu_i.png]
Runs go to out/shear_flow_runs/s2_<scale2>/ (--no-run: only read what is there;
--write-only: only write the scenes, e.g. to run them elsewhere with tridem run).
sxy is the symmetric part (sxy + syx)/2 of the Love-Weber tensor; the two differ by the
grains' unbalanced torques.
"""
import argparse
import os
import subprocess

import numpy as np

import tridem_experiments as tx
import write_shear_flow as wsf

SCALES2 = (0.995, 0.985, 0.975, 0.96, 0.945, 0.93, 0.90, 0.86)
STEADY_FROM = 3.0   # shear strain


def run_dir(s2):
    return os.path.join(tx.ROOT, "out", "shear_flow_runs", f"s2_{s2:.3f}")


def write_all():
    for s2 in SCALES2:
        os.makedirs(run_dir(s2), exist_ok=True)
        wsf.write(s2, os.path.join(run_dir(s2), "scene.toml"),
                  os.path.join(run_dir(s2), "grains.csv"), run_dir(s2))


def run_all(jobs):
    pending = [s2 for s2 in SCALES2]
    running = []
    while pending or running:
        while pending and len(running) < jobs:
            s2 = pending.pop(0)
            d = run_dir(s2)
            log = open(os.path.join(d, "run.log"), "w")
            running.append((subprocess.Popen(
                [tx.tridem_binary(), "run", os.path.join(d, "scene.toml"), "--out", d,
                 "--backend", "cpu", "--quiet"], stdout=log, stderr=subprocess.STDOUT), s2))
        proc, s2 = running.pop(0)
        if proc.wait() != 0:
            print(f"s2 = {s2}: tridem failed, see {run_dir(s2)}/run.log")


def steady(s2, d, phi):
    path = os.path.join(run_dir(s2), "measure_cell.csv")
    if not os.path.exists(path):
        return None
    m = tx.read_csv(path)
    strain = wsf.SHEAR_RATE * m["time"]
    keep = strain >= STEADY_FROM
    if keep.sum() < 3:
        return None
    # mu and I of the mean stresses (ratios of means: a row's syy can be near 0 in the
    # loosest flows); the spreads are the rows' own.
    sxy = 0.5 * (m["sxy"] + m["syx"])[keep]
    syy, p = m["syy"][keep], m["pressure"][keep]
    inertial = wsf.SHEAR_RATE * d / np.sqrt(np.mean(p) / wsf.write_biaxial.DENSITY)
    return {"phi": phi, "mu": float(-np.mean(sxy) / np.mean(syy)),
            "mu_std": float(np.std(-sxy / syy)), "I": float(inertial),
            "I_std": float(np.std(wsf.SHEAR_RATE * d / np.sqrt(np.abs(p) / wsf.write_biaxial.DENSITY))),
            "P": float(np.mean(p)),
            "z": float(np.mean(m["coordination"][keep])), "rows": int(keep.sum()),
            "strain_end": float(strain[-1])}


def plot(points, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
    i = np.array([p["I"] for p in points])
    ax[0].errorbar(i, [p["mu"] for p in points], xerr=[p["I_std"] for p in points],
                   yerr=[p["mu_std"] for p in points], fmt="o", capsize=3)
    ax[0].set_xscale("log")
    ax[0].set_xlabel("inertial number I = γ̇ d / √(P/ρ)")
    ax[0].set_ylabel("μ = −σxy / σyy")
    ax[1].plot([p["phi"] for p in points], i, "s", color="C1")
    ax[1].set_yscale("log")
    ax[1].set_xlabel("packing fraction φ (constant volume)")
    ax[1].set_ylabel("I")
    for a in ax:
        a.grid(alpha=0.3, which="both")
    fig.suptitle(f"Periodic simple shear (Lees-Edwards) of angular grains, γ̇ = "
                 f"{wsf.SHEAR_RATE:g} /s, steady state from γ = {STEADY_FROM:g}", fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--no-run", action="store_true")
    p.add_argument("--write-only", action="store_true")
    p.add_argument("--png", default=None)
    a = p.parse_args()
    if not a.no_run:
        write_all()
        if a.write_only:
            return
        run_all(a.jobs)
    rows, w, h = wsf.consolidated()
    points = []
    print("s^2    phi     I (+- std)          mu (+- std)       P (Pa)    Z    rows  strain")
    for s2 in SCALES2:
        grains = wsf.shrunk(rows, s2, h)
        r = steady(s2, wsf.grain_size(grains), wsf.packing_fraction(grains, w, h))
        if r is None:
            print(f"{s2:.3f}  no steady rows in {run_dir(s2)}")
            continue
        points.append(r)
        print(f"{s2:.3f}  {r['phi']:.4f}  {r['I']:.4g} (+- {r['I_std']:.2g})  "
              f"{r['mu']:.4f} (+- {r['mu_std']:.3f})  {r['P']:9.4g}  {r['z']:.2f}  "
              f"{r['rows']:4d}  {r['strain_end']:.2f}")
    if len(points) >= 2:
        b, mu0 = np.polyfit([r["I"] for r in points], [r["mu"] for r in points], 1)
        print(f"straight line through the points: mu = {mu0:.3f} + {b:.3f} I")
    if a.png and points:
        plot(points, a.png)
        print("wrote", a.png)


if __name__ == "__main__":
    main()
