#!/usr/bin/env python3
"""Writes examples/biaxial.toml and examples/biaxial_grains.csv: a biaxial test of angular
grains at constant confining stress (docs/experiments.md, "A biaxial test").

1. Consolidation (run here, into out/biaxial_prepare): random convex polygons generated
   loose in a box of four flat frictionless walls, no gravity; the left, right and top walls
   are servos at the confining stress, the bottom is fixed. The grains' friction is low
   while they pack (a denser sample, one that shows a peak), and local damping settles them.
2. The test (the scene written): the packing read back by an [[import]] (final.csv's
   grains), the walls put on its outline; the side walls hold the confining stress over the
   sample's current height (servos with length_between = [bottom, top]), the top wall moves down at a constant speed, the bottom stays; grains now at their test
   friction. scripts/biaxial_curves.py turns its walls.csv into the curves.

Deterministic (seeded). Rerun after editing the parameters below:
    scripts/write_biaxial.py          (about 2 minutes of one core)
    scripts/write_biaxial.py --seed 3 --dest DIR   (another sample: DIR/biaxial.toml)
"""
import argparse
import os
import sys

import tridem_experiments as tx

SEED = 7
WIDTH, HEIGHT = 0.09, 0.18       # the sample after consolidation, about, m
LOOSE = 1.3                      # the generated box is this much larger on each side
SIZES = (0.008, 0.012)           # grain sizes (equal-area diameter), uniform by number, m
CONFINING = 1e4                  # sigma_3, Pa (N/m per m of wall)
PENALTY = 1e7                    # Pa: stiffness over stress 1000, rigid grains
DENSITY = 2650.0
FRICTION_PREPARE, FRICTION_TEST = 0.1, 0.5
INERTIAL = 1e-3                  # quasi-static: I = strain rate * d / sqrt(sigma_3 / rho)
AXIAL_STRAIN = 0.20              # how far the top wall compresses, of the height
GAIN = 1e-4                      # servos while consolidating, m/s per N/m (docs/experiments.md:
GAIN_TEST = 4e-4                 # how to choose); while testing: the side walls lag their
                                 # target by their speed / gain, 1.5 % here
MAX_SPEED = 0.05                 # m/s, while testing
PREPARE_SPEED = 0.1              # m/s, the top wall while consolidating; the side walls at
                                 # the speed that closes the box in the same time
PREPARE_TIME = 1.0               # s, for the example's size (longer in proportion for a larger box)
SAFETY = 0.9                     # of the per-body critical step (docs/model.md)

MATERIALS = f"""[[material]]
name = "grain"
density = {DENSITY}
penalty = {PENALTY:g}
friction = {{friction}}
restitution = 0.5

[[material]]
name = "wall"                    # frictionless: the box's faces carry principal stresses
density = 7800.0
penalty = {PENALTY:g}
friction = 0.0
restitution = 1.0                # the contacts' dashpots against a servo (mean 0.75) are
                                 # what limit its gain
"""


def servo(direction, length, max_speed=MAX_SPEED, gain=GAIN_TEST):
    """A servo holding the confining stress over `length`: a fixed length (m), or a pair of
    wall ids whose gap it follows (length_between: the stress over the current length)."""
    over = (f"length_between = [{length[0]}, {length[1]}]" if isinstance(length, tuple)
            else f"length = {length:.9g}")
    return (f'motion = "prescribed"\nprogram = {{ kind = "servo", direction = {direction}, '
            f"stress = {CONFINING:g}, {over}, gain = {gain:g}, "
            f"max_speed = {max_speed:g} }}")


def prepare(out, width=WIDTH, height=HEIGHT, seed=SEED):
    """Consolidates a packing of about width x height at the confining stress into `out`
    (its final.csv: the four walls, ids 0-3, then the grains)."""
    w0, h0 = width * LOOSE, height * LOOSE
    walls = tx.box_walls(w0, h0, "wall", {
        tx.LEFT: servo("[1, 0]", height, PREPARE_SPEED * 0.5 * width / height, GAIN),
        tx.RIGHT: servo("[-1, 0]", height, PREPARE_SPEED * 0.5 * width / height, GAIN),
        tx.TOP: servo("[0, -1]", width, PREPARE_SPEED, GAIN)})
    scene = f"""# Consolidation of the biaxial sample (scripts/write_biaxial.py writes and runs it).
[simulation]
time = {PREPARE_TIME * max(1.0, height / HEIGHT):g}
safety = {SAFETY}
local_damping = 0.3

[output]
dir = "{out}"
every = 0
energy_every = 5000
contacts = false

{MATERIALS.format(friction=FRICTION_PREPARE)}
{walls}
[[generate]]
kind = "polygons"
material = "grain"
region = [[0.002, 0.002], [{w0 - 0.002:.9g}, {h0 - 0.002:.9g}]]
sides = [5, 7]
aspect_ratio = [1, 1.4]
angularity = 0.4
size = [{SIZES[0]}, {SIZES[1]}]
packing_fraction = 0.42
seed = {seed}
"""
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "scene.toml")
    # The same scene run to its end before gives the same packing (deterministic).
    if os.path.exists(os.path.join(out, "final.csv")) and os.path.exists(path):
        with open(path) as f:
            if f.read() == scene:
                return
    with open(path, "w") as f:
        f.write(scene)
    tx.run(path, out, "--backend", "cpu")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--seed", type=int, default=SEED, help="the grains' draws")
    p.add_argument("--dest", default=os.path.join(tx.ROOT, "examples"),
                   help="folder of biaxial.toml and biaxial_grains.csv")
    p.add_argument("--scale", type=float, default=1.0, help="the sample's sides, x WIDTH, HEIGHT")
    p.add_argument("--axial-strain", type=float, default=AXIAL_STRAIN,
                   help="how far the top wall compresses, of the height (a critical state: "
                        "0.4 with --scale 2, docs/experiments.md)")
    a = p.parse_args()
    name = "biaxial_prepare" + ("" if a.seed == SEED else f"_seed{a.seed}") + \
        ("" if a.scale == 1 else f"_scale{a.scale:g}")
    out = os.path.join(tx.ROOT, "out", name)
    prepare(out, WIDTH * a.scale, HEIGHT * a.scale, a.seed)
    os.makedirs(a.dest, exist_ok=True)
    shifted, w, h = tx.packing_at_origin(tx.read_csv(os.path.join(out, "final.csv")))
    d = 0.5 * (SIZES[0] + SIZES[1])
    rate = INERTIAL / (d * (DENSITY / CONFINING) ** 0.5)   # axial strain rate, 1/s
    speed = rate * h
    duration = a.axial_strain / rate
    walls = tx.box_walls(w, h, "wall", {
        # The side walls hold sigma_3 over the sample's current height, the gap between
        # the bottom and top walls, as the top comes down.
        tx.LEFT: servo("[1, 0]", (tx.BOTTOM, tx.TOP)),
        tx.RIGHT: servo("[-1, 0]", (tx.BOTTOM, tx.TOP)),
        tx.TOP: f'motion = "prescribed"\nvelocity = [0.0, {-speed:.9g}]'})
    bodies = len({r["body"] for r in shifted})
    tx.write_grains_csv(os.path.join(a.dest, "biaxial_grains.csv"), shifted)
    scene = f"""# A biaxial test of angular grains at constant confining stress: {bodies} random convex
# polygons (5 to 7 sides, rigid bodies of triangles), consolidated at {CONFINING:g} Pa in a box of
# four frictionless walls (examples/biaxial_grains.csv), then compressed by the top wall at
# a constant speed while the side walls hold the confining stress over the current height
# (servos, length_between = [bottom, top]) and the bottom stays. No gravity. Written by
# scripts/write_biaxial.py (edit the parameters there).
#   tridem run examples/biaxial.toml --backend cpu
#   scripts/biaxial_curves.py out/biaxial      (curves, friction angles: docs/experiments.md)
# Box {w:.4f} m x {h:.4f} m; axial strain rate {rate:.3g} /s (inertial number {INERTIAL:g}:
# quasi-static) to {a.axial_strain:g} axial strain. walls.csv's x, y give the box's faces: each
# wall's face is {tx.WALL_THICKNESS / 3:.6g} m from its centroid (a third of its thickness).

[simulation]
time = {duration:.6g}
safety = {SAFETY}

[output]
dir = "out/biaxial"
every = 0
energy_every = 1000
contacts = false

{MATERIALS.format(friction=FRICTION_TEST)}
{walls}
[[import]]
file = "biaxial_grains.csv"
material = "grain"
keep_overlaps = true          # the consolidated packing's contacts overlap a little
"""
    with open(os.path.join(a.dest, "biaxial.toml"), "w") as f:
        f.write(scene)
    print(f"{bodies} grains, box {w:.4f} x {h:.4f} m, top wall at {speed:.4g} m/s for "
          f"{duration:.3g} s")


if __name__ == "__main__":
    sys.exit(main())
