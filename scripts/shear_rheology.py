#!/usr/bin/env python3
"""The mu(I) point of a periodic simple shear run (examples/periodic_shear.toml).

Reads a [[measure]] file (docs/output-format.md, measure_NAME.csv) and averages, over the
rows after --settle seconds, the friction coefficient mu = -sxy/syy (the shear stress over
the normal stress on planes of constant y; sxy < 0 in shear along +x with vx increasing
with y, compression positive) and the pressure P; the inertial number is
I = gamma_dot d / sqrt(P / rho), P per unit thickness (N/m) over the grains' 2D density
rho (kg/m^2 per unit thickness: the material's density). Prints one line per file:
    file  I  mu  P  rows
Plain Python (no numpy), so that it runs wherever tridem does.
"""
import argparse
import csv
import math
import sys


def rheology(path, shear_rate, diameter, density, settle):
    mus, pressures = [], []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if float(row["time"]) < settle:
                continue
            syy, sxy, p = float(row["syy"]), float(row["sxy"]), float(row["pressure"])
            if not (syy > 0 and p > 0):
                continue
            mus.append(-sxy / syy)
            pressures.append(p)
    if not mus:
        sys.exit(f"{path}: no row after t = {settle} s with a positive normal stress")
    p = sum(pressures) / len(pressures)
    mu = sum(mus) / len(mus)
    inertial = shear_rate * diameter / math.sqrt(p / density)
    return inertial, mu, p, len(mus)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("files", nargs="+", help="measure_NAME.csv of each run")
    ap.add_argument("--shear-rate", type=float, nargs="+", required=True,
                    help="the runs' shear rates, 1/s (one, or one per file)")
    ap.add_argument("--diameter", type=float, required=True, help="grain size d, m")
    ap.add_argument("--density", type=float, required=True, help="grain density, kg/m^3")
    ap.add_argument("--settle", type=float, default=0.5, help="rows before this time are skipped, s")
    args = ap.parse_args()
    rates = args.shear_rate * len(args.files) if len(args.shear_rate) == 1 else args.shear_rate
    if len(rates) != len(args.files):
        sys.exit("give one --shear-rate, or one per file")
    print("file I mu P rows")
    for path, rate in zip(args.files, rates):
        i, mu, p, n = rheology(path, rate, args.diameter, args.density, args.settle)
        print(f"{path} {i:.4g} {mu:.4g} {p:.4g} {n}")


if __name__ == "__main__":
    main()
