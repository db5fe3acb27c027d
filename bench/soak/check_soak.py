#!/usr/bin/env python3
"""Checks a soak run (bench/soak/run_soak.sh): energy and momentum bounded, memory flat,
outputs complete. Standard library only (the GPU machine has no packages).

Bounds: walls are fixed and the floor's top is y = 0, so every grain's potential energy
m g y is >= 0 and the total energy E = K + P can only fall (damping, friction) from its
value E1 after the first step. Hence K <= E1 at every logged step, K + P <= E1 at the
end, and |p|^2 <= 2 M K <= 2 M E1 for the momentum p of the grains of total mass M."""
import argparse
import csv
import math
import os
import re
import sys
import tomllib

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def area(row):
    x1, y1, x2, y2, x3, y3 = (float(row[k]) for k in ("x1", "y1", "x2", "y2", "x3", "y3"))
    return 0.5 * abs((x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1))


def grains(final_csv, walls, density):
    """(mass, y) of every free grain of a final.csv."""
    with open(final_csv) as f:
        rows = [r for r in csv.DictReader(f) if int(r["id"]) >= walls]
    return [(density * area(r), float(r["y"])) for r in rows]


def energy_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def check_memory(path):
    """GPU memory must not move at all after start-up (5 s). Resident memory rises in steps
    while output buffers reach their high-water mark (the first frame, and the first
    checkpoint: its encoding of the state and the pair history, some 40 MiB here); a leak
    shows as growth after that. So the longest process (the restarted part, which writes
    many frames and checkpoints) must keep its resident memory within 4 MiB over the last
    two thirds of its life; the others are reported."""
    with open(path) as f:
        samples = list(csv.DictReader(f))
    by_pid = {}
    for s in samples:
        if int(s["seconds"]) >= 5:
            by_pid.setdefault(s["pid"], []).append(s)
    if not by_pid:
        check(False, "memory samples exist")
        return
    longest = max(by_pid, key=lambda p: len(by_pid[p]))
    for pid, mine in by_pid.items():
        gpu = [int(s["gpu_mib"]) for s in mine]
        rss = [int(s["rss_kib"]) // 1024 for s in mine]
        check(max(gpu) - min(gpu) == 0,
              f"process {pid}: GPU memory flat over {len(mine)} s ({min(gpu)}..{max(gpu)} MiB)")
        late = rss[len(rss) // 3:]
        what = (f"process {pid}: resident memory {min(rss)}..{max(rss)} MiB; over the last "
                f"{len(late)} s {min(late)}..{max(late)} MiB")
        if pid == longest:
            check(len(late) >= 60 and max(late) - min(late) <= 4,
                  what + " (flat within 4 MiB over at least 60 s)")
        else:
            print("info " + what)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scene", required=True)
    ap.add_argument("--steps", type=int, required=True)
    ap.add_argument("--run", required=True, help="output folder of the soak run")
    ap.add_argument("--step1", required=True, help="final.csv after one step")
    ap.add_argument("--memory", required=True, help="memory.csv of run_soak.sh")
    ap.add_argument("--logs", help="folder of run_soak.sh's part1.log and part2.log")
    ap.add_argument("--memory-only", action="store_true",
                    help="check only memory.csv (re-evaluating a recorded run)")
    a = ap.parse_args()
    if a.memory_only:
        check_memory(a.memory)
        print(f"{len(failures)} check(s) failed" if failures else "all memory checks passed")
        return 1 if failures else 0

    if a.logs:
        for part, code in (("part1", 130), ("part2", 0)):
            with open(os.path.join(a.logs, part + ".log")) as f:
                text = f.read()
            check(f"exit code {code} " in text, f"{part} ended with exit code {code}")

    with open(a.scene, "rb") as f:
        scene = tomllib.load(f)
    g = abs(scene["simulation"]["gravity"][1])
    every = scene["output"]["every"]
    walls = len(scene["triangle"])  # explicit triangles come first: the box
    density = next(m["density"] for m in scene["material"] if m["name"] == "sand")

    # Energy bound from the first step.
    start = grains(a.step1, walls, density)
    mass = sum(m for m, _ in start)
    k1 = float(energy_rows(os.path.join(os.path.dirname(a.step1), "energy.csv"))[-1]["kinetic"])
    e1 = k1 + sum(m * g * y for m, y in start)
    print(f"grains {len(start)}, mass {mass:.6g} kg/m, E1 = {e1:.6g} J/m")

    rows = energy_rows(os.path.join(a.run, "energy.csv"))
    steps = [int(r["step"]) for r in rows]
    expected = sorted(set(range(0, a.steps + 1, every)) | {a.steps})
    check(steps == expected, f"energy.csv has each of the {len(expected)} logged steps once, in order"
          + ("" if steps == expected else f" (got {len(steps)} rows: first differences "
             f"{[s for s in steps if s not in expected][:5]} / {[s for s in expected if s not in steps][:5]})"))
    values = [float(r[k]) for r in rows for k in r if k != "step"]
    check(all(math.isfinite(v) for v in values), "every energy.csv value is finite")
    kmax = max(float(r["kinetic"]) for r in rows)
    check(kmax <= e1, f"kinetic energy <= E1 at every logged step (max {kmax:.6g} J/m)")
    pmax = max(math.hypot(float(r["momentum_x"]), float(r["momentum_y"])) for r in rows)
    bound = math.sqrt(2 * mass * e1)
    check(pmax <= bound, f"|momentum| <= sqrt(2 M E1) = {bound:.6g} (max {pmax:.6g} kg/s)")
    end = grains(os.path.join(a.run, "final.csv"), walls, density)
    k_end = float(rows[-1]["kinetic"])
    e_end = k_end + sum(m * g * y for m, y in end)
    check(e_end <= e1, f"total energy at the end {e_end:.6g} <= E1 {e1:.6g} "
          f"(dissipated {100 * (1 - e_end / e1):.2f}%)")
    check(len(end) == len(start), f"final.csv holds all {len(start)} grains")
    check(all(y > 0 for _, y in end), "every grain ends above the floor")

    # Outputs complete.
    frames = sorted(os.listdir(os.path.join(a.run, "frames")))
    want = [f"frame_{s:09d}.vtu" for s in expected]
    check(frames == want, f"frames/ holds exactly the {len(want)} frames")
    with open(os.path.join(a.run, "tridem.pvd")) as f:
        pvd = re.findall(r'file="([^"]+)"', f.read())
    check([os.path.basename(p) for p in pvd] == want, "tridem.pvd lists each frame once, in order")
    check(os.path.getsize(os.path.join(a.run, "checkpoint.ckpt")) > 0, "checkpoint.ckpt exists")
    leftovers = [n for n in os.listdir(a.run) if "tmp" in n or n.startswith(".")]
    check(not leftovers, f"no temporary files left ({leftovers})")

    check_memory(a.memory)

    print(f"{len(failures)} check(s) failed" if failures else "all soak checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
