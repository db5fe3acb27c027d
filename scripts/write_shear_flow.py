#!/usr/bin/env python3
"""Writes a periodic simple shear flow (Lees-Edwards) of angular grains: examples/
shear_flow.toml and examples/shear_flow_grains.csv by default (docs/experiments.md,
"Simple shear in a periodic cell").

The grains are a packing consolidated by scripts/write_biaxial.py's box of servo walls
(into out/shear_flow_prepare, once), each grain then shrunk about its centroid by a factor
s: the packing fraction is the consolidated one times s^2, and at constant volume it is what
sets the inertial number. The cell is the box the packing filled; every grain starts on the
shear profile vx = shear_rate * (y - y_mid) (the generators cannot give per-grain velocities).
    scripts/write_shear_flow.py                      (the example, s^2 = SCALE2 below)
    scripts/write_shear_flow.py --scale2 0.95 --out DIR   (DIR/scene.toml, DIR/grains.csv)
"""
import argparse
import math
import os

import numpy as np

import tridem_experiments as tx
import write_biaxial

SIDE = 0.12              # the consolidated square, about, m
SEED = 11
SHEAR_RATE = 4.0         # 1/s
STRAIN = 8.0             # shear strain of the run
SCALE2 = 0.93            # the example's area scale s^2 of the grains
MEASURE_EVERY = 2000     # steps


def consolidated():
    out = os.path.join(tx.ROOT, "out", "shear_flow_prepare")
    if not os.path.exists(os.path.join(out, "final.csv")):
        write_biaxial.prepare(out, SIDE, SIDE, SEED)
    return tx.packing_at_origin(tx.read_csv(os.path.join(out, "final.csv")))


def shrunk(rows, scale2, height):
    """Each body shrunk about its centroid by sqrt(scale2), on the shear profile."""
    s = math.sqrt(scale2)
    bodies = {}
    for r in rows:
        bodies.setdefault(r["body"], []).append(r)
    out = []
    for members in bodies.values():
        area = cx = cy = 0.0
        for r in members:
            a = tx.triangle_area(r)
            area += a
            cx += a * (r["x1"] + r["x2"] + r["x3"]) / 3
            cy += a * (r["y1"] + r["y2"] + r["y3"]) / 3
        cx, cy = cx / area, cy / area
        for r in members:
            q = dict(r)
            for k in "123":
                q["x" + k] = cx + s * (r["x" + k] - cx)
                q["y" + k] = cy + s * (r["y" + k] - cy)
            q["vx"], q["vy"], q["omega"] = SHEAR_RATE * (cy - 0.5 * height), 0.0, 0.0
            out.append(q)
    return out


def grain_size(rows):
    """Mean equal-area diameter of the bodies, m."""
    areas = {}
    for r in rows:
        areas[r["body"]] = areas.get(r["body"], 0.0) + tx.triangle_area(r)
    return float(np.mean([2 * math.sqrt(a / math.pi) for a in areas.values()]))


def packing_fraction(grains, w, h):
    """The grains' area over the cell's: the packing fraction the run keeps (constant
    volume). measure_cell.csv's is lower: it counts only the parts of triangles inside the
    cell, and a body's members may lie outside it (it wraps by its centroid)."""
    return sum(tx.triangle_area(r) for r in grains) / (w * h)


def write(scale2, scene_path, grains_path, out_dir):
    rows, w, h = consolidated()
    grains = shrunk(rows, scale2, h)
    tx.write_grains_csv(grains_path, grains, extra=("vx", "vy", "omega"))
    phi = packing_fraction(grains, w, h)
    d = grain_size(grains)
    bodies = len({r["body"] for r in grains})
    scene = f"""# A periodic simple shear flow (Lees-Edwards) of {bodies} angular grains (random convex polygons,
# rigid bodies of triangles) at constant volume: packing fraction {phi:.4f}, shear rate
# {SHEAR_RATE:g} /s, to a shear strain of {STRAIN:g}. The grains ({os.path.basename(grains_path)}) are a packing
# consolidated in a box, each shrunk about its centroid (area x {scale2:g}) and started on
# the shear profile. Written by scripts/write_shear_flow.py (edit the parameters there);
# scripts/shear_flow_mu_i.py runs several packing fractions and plots mu(I).
#   tridem run examples/shear_flow.toml --backend cpu
# Mean grain size (equal-area diameter) {d:.6f} m; measure_cell.csv's stress gives
# mu = -sxy/syy and I = shear_rate d / sqrt(pressure / density).

[simulation]
time = {STRAIN / SHEAR_RATE:g}
safety = {write_biaxial.SAFETY}
periodic_x = [0.0, {w:.12g}]
periodic_y = [0.0, {h:.12g}]
shear_rate = {SHEAR_RATE:g}

[output]
dir = "{out_dir}"
every = 0
energy_every = {MEASURE_EVERY}
contacts = false

[[material]]
name = "grain"
density = {write_biaxial.DENSITY}
penalty = {write_biaxial.PENALTY:g}
friction = {write_biaxial.FRICTION_TEST}
restitution = 0.5

[[import]]
file = "{os.path.relpath(grains_path, os.path.dirname(scene_path))}"
material = "grain"
keep_overlaps = true

[[measure]]
name = "cell"
region = [[0.0, 0.0], [{w:.12g}, {h:.12g}]]
"""
    with open(scene_path, "w") as f:
        f.write(scene)
    return {"phi": phi, "d": d, "bodies": bodies, "w": w, "h": h}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--scale2", type=float, default=SCALE2)
    p.add_argument("--out", default=None, help="a folder for scene.toml and grains.csv")
    a = p.parse_args()
    if a.out is None:
        ex = os.path.join(tx.ROOT, "examples")
        info = write(a.scale2, os.path.join(ex, "shear_flow.toml"),
                     os.path.join(ex, "shear_flow_grains.csv"), "out/shear_flow")
    else:
        os.makedirs(a.out, exist_ok=True)
        info = write(a.scale2, os.path.join(a.out, "scene.toml"),
                     os.path.join(a.out, "grains.csv"), a.out)
    print(f"{info['bodies']} grains, cell {info['w']:.4f} x {info['h']:.4f} m, packing "
          f"fraction {info['phi']:.4f}, mean size {info['d']:.5f} m")


if __name__ == "__main__":
    main()
