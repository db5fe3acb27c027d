#!/usr/bin/env python3
"""Writes examples/angular_drum.toml: angular grains (random convex polygons of 4 to 7
sides, as [[body]] polygon blocks) in a rotating drum (a ring of 2 x 60 triangles, one
prescribed body turned about its centre by a rotation program). Deterministic (seeded); rerun it after editing
the parameters below:  scripts/write_angular_drum.py > examples/angular_drum.toml
"""
import math
import random

SEED = 13
DRUM_RADIUS = 0.1      # inner radius, m
RING = 0.01            # ring thickness, m
SEGMENTS = 60          # trapezoids of the ring, two triangles each
OMEGA = 2.5            # rad/s, counter-clockwise
GRAIN_RADIUS = 0.0045  # mean circumradius of a grain, m
PITCH = 0.0115         # lattice spacing of the grains' centres (> the largest grain), m
FILL_TOP = 0.01        # grains below this height (drum centre at 0), m
DURATION = 2.1         # simulated time, s
SAFETY = 0.9           # of the per-body critical step
FRAME_EVERY = 2500     # steps between frames (about 9e-6 s each): 0.02 s, for the
                       # surface angle over time (scripts/drum_angle.py)

rnd = random.Random(SEED)


def point(x, y):
    return f"[{x:.6f}, {y:.6f}]"


def grain(cx, cy):
    """A convex polygon: n corners at jittered angles on an ellipse of random aspect."""
    n = rnd.randint(4, 7)
    r = GRAIN_RADIUS * rnd.uniform(0.8, 1.2)
    aspect = rnd.uniform(0.7, 1.0)  # minor / major axis
    turn = rnd.uniform(0, 2 * math.pi)
    step = 2 * math.pi / n
    angles = [k * step + rnd.uniform(-0.3, 0.3) * step for k in range(n)]
    corners = []
    for a in angles:
        x, y = r * math.cos(a), r * aspect * math.sin(a)
        corners.append((cx + x * math.cos(turn) - y * math.sin(turn),
                        cy + x * math.sin(turn) + y * math.cos(turn)))
    return corners


def main():
    print(f"""# Angular grains in a rotating drum: {{count}} random convex polygons (4 to 7 sides, each a
# rigid body of triangles) in a drum that turns counter-clockwise at {OMEGA} rad/s. The bed
# rises with the wall and avalanches down its free surface. Written by
# scripts/write_angular_drum.py (edit the parameters there, not here).
#   tridem run examples/angular_drum.toml --backend cpu
#   tridem render out/angular_drum --color body
# The automatic step is {SAFETY} x the bound tridem proves for each body (docs/model.md, "The
# time step"); flat members on the grains' outlines set it.

[simulation]
time = {DURATION}               # s
safety = {SAFETY}
gravity = [0.0, -9.81]

[output]
dir = "out/angular_drum"
every = {FRAME_EVERY}
contacts = false

[[material]]
name = "gravel"
density = 2650.0
penalty = 1e6
friction = 0.6
restitution = 0.3

[[material]]
name = "steel"
density = 7800.0
penalty = 1e6
friction = 0.6
restitution = 0.3

# The drum: one prescribed body, a ring of {SEGMENTS} trapezoids, turned about its centre
# (the origin) by a rotation program: its pose is the exact rotation at each time.
[[body]]
material = "steel"
motion = "prescribed"
program = {{ kind = "rotation", center = [0.0, 0.0], angular_velocity = {OMEGA} }}""")
    members = []
    for k in range(SEGMENTS):
        a0, a1 = 2 * math.pi * k / SEGMENTS, 2 * math.pi * (k + 1) / SEGMENTS
        p = [(rad * math.cos(a), rad * math.sin(a))
             for rad, a in ((DRUM_RADIUS, a0), (DRUM_RADIUS, a1),
                            (DRUM_RADIUS + RING, a1), (DRUM_RADIUS + RING, a0))]
        members.append(f"[{point(*p[0])}, {point(*p[1])}, {point(*p[2])}]")
        members.append(f"[{point(*p[0])}, {point(*p[2])}, {point(*p[3])}]")
    print("triangles = [\n  " + ",\n  ".join(members) + "]")

    count = 0
    rows = int(2 * DRUM_RADIUS / PITCH) + 1
    for j in range(rows):
        for i in range(rows):
            cx = -DRUM_RADIUS + (i + 0.5 + 0.5 * (j % 2)) * PITCH
            cy = -DRUM_RADIUS + (j + 0.5) * PITCH
            if cy > FILL_TOP or math.hypot(cx, cy) > DRUM_RADIUS - 1.5 * GRAIN_RADIUS * 1.2:
                continue
            corners = grain(cx, cy)
            print(f'\n[[body]]\nmaterial = "gravel"\npolygon = [' +
                  ", ".join(point(*c) for c in corners) + "]")
            count += 1
    return count


if __name__ == "__main__":
    import io
    import sys
    buffer = io.StringIO()
    stdout, sys.stdout = sys.stdout, buffer
    n = main()
    sys.stdout = stdout
    sys.stdout.write(buffer.getvalue().replace("{count}", str(n), 1))
