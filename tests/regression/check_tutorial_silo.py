#!/usr/bin/python3
"""Checks a run of the tutorial's silo (cases/tutorial/silo-2d.toml, docs/tutorial.md).

usage: check_tutorial_silo.py RUN_DIR

Fails unless: solids leave through the outlet (its solids flux positive over the last 0.02 s of
the run, and at least 1 g gone), none leaves through the top, the solids inventory changes from
row to row by −Σ flux × dt (mass conserved, to 1e-8 of the inventory: the monitor prints 10 digits), and the last
snapshot holds the outlet's face velocities pointing out of the domain (docs/output.md,
"Openings").
"""
import csv
import glob
import os
import sys

import h5py
import numpy as np


def main():
    run = sys.argv[1]
    with open(os.path.join(run, "monitor.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["time"]) for r in rows])
    dt = np.array([float(r["dt"]) for r in rows])
    m = np.array([float(r["inventory_solids_kg"]) for r in rows])
    out = np.array([float(r["flux_outlet_solids_kg_per_s"]) for r in rows])
    top = np.array([float(r["flux_top_solids_kg_per_s"]) for r in rows])
    walls = np.array([float(r["flux_walls_solids_kg_per_s"]) for r in rows])
    failures = []
    late = t > t[-1] - 0.02
    rate = float(np.sum(out[late] * dt[late]) / np.sum(dt[late]))
    if not rate > 0:
        failures.append(f"no solids leave through the outlet at the end (mean flux {rate:.3g} kg/s)")
    gone = m[0] + out[0] * dt[0] - m[-1]  # the inventory before the first row, less the last
    if not gone > 1e-3:
        failures.append(f"only {gone * 1e3:.3g} g of solids left the silo")
    if np.max(np.abs(top)) > 0 or np.max(np.abs(walls)) > 0:
        failures.append("solids cross the top or the walls")
    drift = np.abs(np.diff(m) + (out[1:] + top[1:] + walls[1:]) * dt[1:])
    allowed = 1e-8 * np.abs(m[1:])  # the printed digits: about 1e-10 relative
    if np.any(drift > allowed):
        k = int(np.argmax(drift - allowed)) + 1
        failures.append(f"mass not conserved at t = {t[k]:.6g} s: the inventory changed by "
                        f"{m[k] - m[k - 1]:.6g} kg, the fluxes say {-(out[k] + top[k] + walls[k]) * dt[k]:.6g}")
    last = sorted(glob.glob(os.path.join(run, "snapshot_*.h5")))[-1]
    with h5py.File(last, "r") as f:
        names = [str(n) for n in f["openings"].attrs["region_names"]]
        region = f["openings/region"][:]
        outflow = f["openings/solids_outflow_velocity"][:][region == names.index("outlet")]
        if len(outflow) != 4 or not np.all(outflow > 0):
            failures.append(f"the outlet's 4 faces should carry solids outward: {outflow}")
    print(f"t = {t[-1]:.4g} s: {gone * 1e3:.2f} g left through the outlet, {rate * 1e3:.1f} g/s "
          f"over the last 0.02 s; mass balance worst {np.max(drift):.2e} kg; outlet face velocities "
          f"{np.min(outflow):.3g} to {np.max(outflow):.3g} m/s")
    for text in failures:
        print("FAIL: " + text)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
