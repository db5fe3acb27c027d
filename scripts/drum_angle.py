#!/usr/bin/env python3
"""The dynamic angle of repose of a rotating drum (examples/angular_drum.toml) from its
frames. A drum less than half full holds a bed shaped as a circular segment, whose chord is
the free surface, and the segment's long principal axis is parallel to its chord: in each
frame from --from seconds on, the angle is that of the long principal axis of the free
triangles (their centroids weighted by their areas), which a few grains thrown off the bed
barely move. Prints each frame's angle and their mean and spread; --png draws the last
frame with the surface: the axis' direction, through the bed's top (the 95th percentile of
the vertices along the axis' normal).
    scripts/drum_angle.py [OUT_DIR] [--from 0.6] [--png docs/images/angular_drum_surface.png]
"""
import argparse
import glob
import math
import os

import numpy as np

import tridem_experiments as tx

def bed_axis(frame):
    """The free triangles' long principal axis: (angle in degrees, unit direction, the
    bed's centroid, the surface's offset along the normal from it)."""
    free = frame["motion"] == 0
    v = frame["vertices"][free].astype(float)
    area = 0.5 * np.abs((v[:, 1, 0] - v[:, 0, 0]) * (v[:, 2, 1] - v[:, 0, 1])
                        - (v[:, 2, 0] - v[:, 0, 0]) * (v[:, 1, 1] - v[:, 0, 1]))
    c = v.mean(axis=1)
    mean = (area[:, None] * c).sum(axis=0) / area.sum()
    d = c - mean
    cov = (area[:, None, None] * d[:, :, None] * d[:, None, :]).sum(axis=0) / area.sum()
    values, vectors = np.linalg.eigh(cov)
    axis = vectors[:, np.argmax(values)]
    if axis[0] < 0:
        axis = -axis
    normal = np.array([-axis[1], axis[0]])
    top = np.percentile((v.reshape(-1, 2) - mean) @ normal, 95)
    return math.degrees(math.atan2(axis[1], axis[0])), axis, mean, top


def plot(frame, png, times, angles):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    fig, (ax, series) = plt.subplots(1, 2, figsize=(10, 4.6),
                                     gridspec_kw={"width_ratios": [1, 1.2]})
    series.plot(times, angles, ".-", lw=0.8, ms=3)
    series.axhline(np.mean(angles), color="C3", ls="--",
                   label=f"mean {np.mean(angles):.1f}° ± {np.std(angles):.1f}° (std)")
    series.set_xlabel("time (s)")
    series.set_ylabel("free-surface angle (°)")
    series.legend(fontsize=8)
    series.grid(alpha=0.3)
    free = frame["motion"] == 0
    body = frame["body"]
    colors = plt.cm.tab20((body % 20) / 19)
    ax.add_collection(PolyCollection(frame["vertices"][~free], facecolors="0.55",
                                     edgecolors="none"))
    ax.add_collection(PolyCollection(frame["vertices"][free], facecolors=colors[free],
                                     edgecolors="none"))
    angle, axis, mean, top = bed_axis(frame)
    normal = np.array([-axis[1], axis[0]])
    ends = np.array([mean + top * normal + s * axis for s in (-0.07, 0.07)])
    ax.plot(ends[:, 0], ends[:, 1], "k-", lw=1.5,
            label=f"free surface: {angle:.1f}° (t = {frame['time']:.2f} s)")
    ax.set_aspect("equal")
    ax.autoscale()
    ax.legend(loc="upper left", fontsize=8)
    fig.suptitle("Rotating drum, 2.5 rad/s counter-clockwise (examples/angular_drum.toml): "
                 "slumping, the bed's surface angle over time", fontsize=10)
    ax.set_xticks([])
    ax.set_yticks([])
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("out", nargs="?", default=os.path.join(tx.ROOT, "out", "angular_drum"))
    p.add_argument("--from", dest="start", type=float, default=0.6,
                   help="first time used, s (the bed has reached its steady rotation)")
    p.add_argument("--png", default=None)
    p.add_argument("--verbose", action="store_true", help="each frame's angle")
    a = p.parse_args()
    angles, times, last = [], [], None
    for path in sorted(glob.glob(os.path.join(a.out, "frames", "frame_*.vtu"))):
        frame = tx.read_frame(path)
        if frame["time"] < a.start:
            continue
        angle = bed_axis(frame)[0]
        angles.append(angle)
        times.append(frame["time"])
        last = frame
        if a.verbose:
            print(f"t = {frame['time']:.3f} s: surface angle {angle:.2f} deg")
    if not angles:
        raise SystemExit(f"no frame after t = {a.start} s in {a.out}/frames")
    print(f"dynamic angle of repose over {len(angles)} frames: {np.mean(angles):.2f} +- "
          f"{np.std(angles):.2f} deg (mean, std of frames)")
    # Slumping: the angle rises with the wall, then an avalanche drops it. Its turning
    # points: the angle of the bed after each avalanche and the largest it stands at.
    # A turning point is the extreme of the frames within 0.1 s either side.
    g, tt = np.array(angles), np.array(times)
    for k in range(1, len(g) - 1):
        near = g[np.abs(tt - tt[k]) <= 0.1]
        if g[k] == near.max() or g[k] == near.min():
            kind = "largest (an avalanche starts)" if g[k] == near.max() else "after an avalanche"
            print(f"  t = {times[k]:.3f} s: {g[k]:.2f} deg, {kind}")
    if a.png:
        plot(last, a.png, times, angles)
        print("wrote", a.png)


if __name__ == "__main__":
    main()
