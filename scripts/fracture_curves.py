#!/usr/bin/env python3
"""The curves of the bonded specimens of docs/fracture.md from their runs' walls.csv and
energy.csv: the Brazilian disc's platen force against its travel (with the force at which
sigma_t = 2F/(pi D) equals f_t), the rectangle's stress against its platen strain in
uniaxial compression (with the bonds' Mohr-Coulomb unconfined strength), and the energy
budget of three-point bending over time.
    scripts/fracture_curves.py DISC_OUT COMPRESSION_OUT BENDING_OUT [--png FILE]
The runs are those of examples/brazilian_disc.toml, uniaxial_compression.toml and
three_point_bending.toml (tridem run SCENE --out DIR). The moving platen or nose is the
wall with a velocity; the stress is the mean of the two platens' |fy| over the width.
"""
import argparse
import math
import os

import numpy as np

import tridem_experiments as tx

F_T = 8e6                      # the granite's tensile strength, Pa
COHESION, PHI = 25e6, math.radians(35)
DISC_DIAMETER = 0.05
WIDTH, HEIGHT = 0.02, 0.04     # the compressed rectangle


def walls_of(out):
    walls = tx.read_csv(os.path.join(out, "walls.csv"))
    ids = sorted(set(int(i) for i in walls["id"]))
    return {i: tx.wall_series(walls, i) for i in ids}


def moving(walls):
    return next(w for w in walls.values() if np.any(w["vy"] != 0))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("disc")
    p.add_argument("compression")
    p.add_argument("bending")
    p.add_argument("--png", default=None)
    a = p.parse_args()

    disc = moving(walls_of(a.disc))
    travel_disc = disc["y"][0] - disc["y"]
    force_disc = np.abs(disc["fy"])
    f_peak = force_disc.max()
    print(f"Brazilian disc: peak platen force {f_peak:.4g} N/m, sigma_t = 2F/(pi D) = "
          f"{2 * f_peak / (math.pi * DISC_DIAMETER):.4g} Pa = "
          f"{2 * f_peak / (math.pi * DISC_DIAMETER) / F_T:.3f} f_t")

    walls = walls_of(a.compression)
    top = moving(walls)
    stress = 0.5 * sum(np.abs(w["fy"]) for w in walls.values()) / WIDTH
    strain = (top["y"][0] - top["y"]) / HEIGHT
    ucs = 2 * COHESION * math.cos(PHI) / (1 - math.sin(PHI))
    k = int(np.argmax(stress))
    print(f"compression: peak {stress[k]:.4g} Pa ({stress[k] / F_T:.3f} f_t, "
          f"{stress[k] / ucs:.3f} of the unconfined strength {ucs:.4g} Pa) at platen strain "
          f"{strain[k]:.3g}")

    e = tx.read_csv(os.path.join(a.bending, "energy.csv"))
    held = e["kinetic"] + e["elastic"]
    lost = e["dissipated_damping"] + e["dissipated_friction"] + e["dissipated_local"]
    fracture = e["dissipated_fracture"]
    gap = e["wall_work"] - (held + lost + fracture)
    print(f"three-point bending: work {e['wall_work'][-1]:.4g} J/m; the budget closes to "
          f"{abs(gap).max() / max(e['wall_work'][-1], 1e-300):.2e} of it; fracture "
          f"{fracture[-1]:.4g} J/m")
    if not a.png:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    ax[0].plot(travel_disc * 1e6, force_disc / 1e3, color="C0")
    ax[0].axhline(F_T * math.pi * DISC_DIAMETER / 2 / 1e3, color="C3", ls="--", lw=0.8,
                  label="2F/(πD) = f_t")
    ax[0].set_xlabel("top platen travel (µm)")
    ax[0].set_ylabel("platen force (kN/m)")
    ax[0].set_title("Brazilian disc, 2.5 mm mesh", fontsize=9)
    ax[0].legend(fontsize=8)
    ax[1].plot(strain * 100, stress / 1e6, color="C0")
    ax[1].axhline(ucs / 1e6, color="C3", ls="--", lw=0.8, label="bonds' unconfined strength")
    ax[1].axhline(F_T / 1e6, color="0.5", ls=":", lw=0.8, label="f_t")
    ax[1].set_xlabel("platen strain (%)")
    ax[1].set_ylabel("stress (MPa)")
    ax[1].set_title("uniaxial compression, 20 × 40 mm, 2.5 mm mesh", fontsize=9)
    ax[1].legend(fontsize=8)
    t = e["time"] * 1e3
    ax[2].plot(t, e["wall_work"], color="k", label="work of the supports and nose")
    ax[2].plot(t, held + lost + fracture, color="C1", ls="--", label="kinetic + elastic + dissipated")
    ax[2].plot(t, fracture, color="C3", label="dissipated by fracture")
    ax[2].plot(t, e["dissipated_local"], color="C2", label="local damping")
    ax[2].set_xlabel("time (ms)")
    ax[2].set_ylabel("energy (J/m)")
    ax[2].set_title("three-point bending: the energy budget", fontsize=9)
    ax[2].legend(fontsize=8)
    for x in ax:
        x.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    print("wrote", a.png)


if __name__ == "__main__":
    main()
