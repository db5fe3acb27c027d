#!/usr/bin/env python3
"""The hopper whose gate opens (examples/hopper_gate.toml): three frames (before, while and
after the gate slides away) and the gate's load over time from walls.csv.
    scripts/hopper_gate_plot.py [OUT_DIR] [--png docs/images/hopper_gate.png]
The gate is particle id 4 (the scene's fifth [[triangle]]).
"""
import argparse
import glob
import os

import numpy as np

import tridem_experiments as tx

GATE = 4
TIMES = (0.45, 0.68, 0.95)   # s: settled on the closed gate, opening, discharging


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("out", nargs="?", default=os.path.join(tx.ROOT, "out", "hopper_gate"))
    p.add_argument("--png", default=None)
    a = p.parse_args()
    gate = tx.wall_series(tx.read_csv(os.path.join(a.out, "walls.csv")), GATE)
    for t in (0.34, 0.45, 0.57, 0.68, 0.80, 1.0):
        k = int(np.argmin(abs(gate["time"] - t)))
        print(f"t = {gate['time'][k]:.3f} s: gate fy = {gate['fy'][k]:.1f} N/m, "
              f"x = {gate['x'][k]:.4f} m")
    if not a.png:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    frames = sorted(glob.glob(os.path.join(a.out, "frames", "frame_*.vtu")))
    times = [tx.read_frame(f)["time"] for f in frames]
    fig = plt.figure(figsize=(13, 4))
    for i, t in enumerate(TIMES):
        frame = tx.read_frame(frames[int(np.argmin(abs(np.array(times) - t)))])
        ax = fig.add_subplot(1, 4, i + 1)
        free = frame["motion"] == 0
        ax.add_collection(PolyCollection(frame["vertices"][~free], facecolors="0.6",
                                         edgecolors="none"))
        ax.add_collection(PolyCollection(frame["vertices"][free], facecolors="C0",
                                         edgecolors="none"))
        ax.set_xlim(-0.5, 0.5)
        ax.set_ylim(-0.85, 0.75)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(f"t = {frame['time']:.2f} s", fontsize=9)
    ax = fig.add_subplot(1, 4, 4)
    ax.plot(gate["time"], -gate["fy"], color="C3")
    ax.axvline(0.5, color="0.6", ls="--", lw=0.8)
    ax.axvline(0.725, color="0.6", ls=":", lw=0.8)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("load on the gate, −fy (N/m)")
    ax.set_title("gate moves at 0.5 s, orifice open at 0.725 s", fontsize=9)
    ax.grid(alpha=0.3)
    fig.suptitle("A hopper whose gate opens (examples/hopper_gate.toml)", fontsize=10)
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    print("wrote", a.png)


if __name__ == "__main__":
    main()
