#!/usr/bin/env python3
"""The curves of a biaxial test (examples/biaxial.toml) from its walls.csv: axial strain,
volumetric strain, stress ratio and the mobilised friction angle, its peak and its late-stage
mean; whether the late stage is at critical state (the volume no longer changing).
    scripts/biaxial_curves.py [OUT_DIR ...] [--png docs/images/biaxial.png] [--target 1e4]
With several output folders (samples of other seeds: scripts/write_biaxial.py --seed N),
each is summarised, the plot draws them all (the first in colour) and the last lines give
the samples' mean and spread.

Stresses are the walls' (frictionless, so principal): sigma_1 = the top and bottom walls'
mean normal force over the box's current width, sigma_3 = the side walls' over its current
height; compression positive. Strains from the faces' positions (walls.csv x, y):
axial eps_a = 1 - H/H0, volumetric eps_v = 1 - (W H)/(W0 H0) (contraction positive).
sin(phi_mob) = (sigma_1 - sigma_3) / (sigma_1 + sigma_3).
"""
import argparse
import os

import numpy as np

import tridem_experiments as tx


def curves(out):
    walls = tx.read_csv(os.path.join(out, "walls.csv"))
    xl, xr, yb, yt = tx.face_positions(walls)
    w, h = xr - xl, yt - yb
    left, right = tx.wall_series(walls, tx.LEFT), tx.wall_series(walls, tx.RIGHT)
    bottom, top = tx.wall_series(walls, tx.BOTTOM), tx.wall_series(walls, tx.TOP)
    s3 = 0.5 * (-left["fx"] + right["fx"]) / h
    s1 = 0.5 * (-bottom["fy"] + top["fy"]) / w
    c = {"time": left["time"], "w": w, "h": h, "s1": s1, "s3": s3,
         "eps_a": 1 - h / h[0], "eps_v": 1 - (w * h) / (w[0] * h[0])}
    with np.errstate(invalid="ignore", divide="ignore"):
        c["phi"] = np.degrees(np.arcsin(np.clip((s1 - s3) / (s1 + s3), -1, 1)))
    return c


def smooth(a, n):
    """Running mean over n rows (the ends over what they have)."""
    k = np.ones(n) / n
    return np.convolve(a, k, mode="same") / np.convolve(np.ones_like(a), k, mode="same")


def summary(c, target, late_from=2 / 3):
    """The numbers docs/experiments.md quotes. The servos settle first: rows from 0.5 %
    axial strain on (before that the walls close the gaps the scene starts with)."""
    loaded = c["eps_a"] > 0.005
    phi = smooth(c["phi"], 5)
    peak = int(np.argmax(np.where(loaded, phi, -np.inf)))
    eps_end = c["eps_a"][-1]
    late = c["eps_a"] >= late_from * eps_end
    slope = np.polyfit(c["eps_a"][late], c["eps_v"][late], 1)[0]   # d eps_v / d eps_a
    s3 = c["s3"][loaded]
    return {
        "peak_phi": phi[peak], "peak_eps_a": c["eps_a"][peak],
        "late_phi_mean": float(np.mean(c["phi"][late])),
        "late_phi_std": float(np.std(c["phi"][late])),
        "late_from": late_from * eps_end, "eps_end": eps_end,
        "late_dilatancy": slope, "eps_v_end": c["eps_v"][-1],
        "eps_v_min": float(np.max(c["eps_v"])),
        "s3_mean": float(np.mean(s3)), "s3_min": float(np.min(s3)), "s3_max": float(np.max(s3)),
        "s3_target": target,
        "s3_force_mean": float(np.mean((c["s3"] * c["h"] / c["h"][0])[loaded])),
    }


def plot(c, s, png, others=(), name="the example", scene="examples/biaxial.toml"):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
    e = 100 * c["eps_a"]
    for k, o in enumerate(others):
        label = f"{len(others)} other samples" if k == 0 else None
        ax[0].plot(100 * o["eps_a"], smooth(o["phi"], 5), lw=0.7, color="0.75", label=label)
        ax[1].plot(100 * o["eps_a"], 100 * o["eps_v"], lw=0.7, color="0.75", label=label)
    ax[0].plot(e, smooth(c["phi"], 5), color="C0", label=f"{name} (running mean, 5 rows)")
    ax[0].axhline(s["late_phi_mean"], color="C3", ls="--",
                  label=f"its late mean {s['late_phi_mean']:.1f}°")
    ax[0].plot(100 * s["peak_eps_a"], s["peak_phi"], "o", color="C1",
               label=f"its peak {s['peak_phi']:.1f}°")
    ax[0].set_xlabel("axial strain ε_a (%)")
    ax[0].set_ylabel("mobilised friction angle φ (°)")
    ax[0].legend(fontsize=7, loc="lower right")
    ax[1].plot(e, 100 * c["eps_v"], color="C2", label=name)
    ax[1].set_xlabel("axial strain ε_a (%)")
    ax[1].set_ylabel("volumetric strain ε_v (%, contraction +)")
    ax[1].axhline(0, color="0.8", lw=0.5)
    ax[1].legend(fontsize=7)
    ax[2].plot(e, c["s1"] / s["s3_target"], label="σ1 (top, bottom)")
    ax[2].plot(e, c["s3"] / s["s3_target"], label="σ3 (sides): force / current height")
    ax[2].plot(e, c["s3"] * c["h"] / c["h"][0] / s["s3_target"], ls=":",
               label="σ3 × H/H0: force / initial height")
    ax[2].set_xlabel("axial strain ε_a (%)")
    ax[2].set_ylabel(f"stress / confining target {s['s3_target']:g} Pa")
    ax[2].legend(fontsize=7)
    for a in ax:
        a.grid(alpha=0.3)
    fig.suptitle("Biaxial test of angular grains at constant confining stress "
                 f"({scene})", fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def report(s):
    print(f"axial strain to {100 * s['eps_end']:.2f} %")
    print(f"peak friction angle {s['peak_phi']:.2f} deg at axial strain "
          f"{100 * s['peak_eps_a']:.2f} %")
    print(f"late stage (axial strain {100 * s['late_from']:.1f}-{100 * s['eps_end']:.1f} %): "
          f"friction angle {s['late_phi_mean']:.2f} +- {s['late_phi_std']:.2f} deg (std of rows)")
    print(f"volumetric strain: largest contraction {100 * s['eps_v_min']:.2f} %, at the end "
          f"{100 * s['eps_v_end']:.2f} %; late-stage d(eps_v)/d(eps_a) = "
          f"{s['late_dilatancy']:.3f} (0 at critical state; negative: still dilating)")
    print(f"confining stress sigma_3 (force / current height): mean {s['s3_mean']:.4g} Pa, "
          f"range {s['s3_min']:.4g}-{s['s3_max']:.4g} (target {s['s3_target']:g}); "
          f"force / initial height (a fixed-length servo would hold it): mean {s['s3_force_mean']:.4g}")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("out", nargs="*", default=[os.path.join(tx.ROOT, "out", "biaxial")])
    p.add_argument("--png", default=None, help="plot to this PNG (e.g. docs/images/biaxial.png)")
    p.add_argument("--target", type=float, default=1e4, help="the servos' stress, Pa")
    p.add_argument("--name", default="the example", help="the first sample's name in the legends")
    p.add_argument("--scene", default="examples/biaxial.toml", help="the scene named in the title")
    a = p.parse_args()
    samples = [curves(out) for out in a.out]
    sums = [summary(c, a.target) for c in samples]
    for out, s in zip(a.out, sums):
        print(f"== {out}")
        report(s)
    if len(sums) > 1:
        for key, what in (("peak_phi", "peak friction angle"),
                          ("late_phi_mean", "late-stage friction angle")):
            v = np.array([s[key] for s in sums])
            print(f"{len(v)} samples: {what} {v.mean():.2f} +- {v.std():.2f} deg "
                  f"(mean, std of samples; {v.min():.2f}-{v.max():.2f})")
    if a.png:
        plot(samples[0], sums[0], a.png, samples[1:], a.name, a.scene)
        print("wrote", a.png)


if __name__ == "__main__":
    main()
