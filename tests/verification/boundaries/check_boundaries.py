#!/usr/bin/python3
"""Checks of the boundary-condition cases (tests/verification/boundaries/README.md).

usage: check_boundaries.py plug RUN_DIR     mass in = mass out = 0.006 kg/s; u = 0.5 m/s everywhere
       check_boundaries.py rest RUN_DIR     velocities below 1e-8 m/s; pressure hydrostatic
"""
import csv
import glob
import os
import sys

import h5py
import numpy as np


def last(run):
    return sorted(glob.glob(os.path.join(run, "snapshot_*.h5")))[-1]


def plug(run):
    rows = list(csv.DictReader(open(os.path.join(run, "monitor.csv"))))
    inflow = float(rows[-1]["flux_inlet_gas_kg_per_s"])
    outflow = float(rows[-1]["flux_outlet_gas_kg_per_s"])
    with h5py.File(last(run)) as f:
        u = f["fields/gas_velocity_x"][:]
        w = f["fields/gas_velocity_z"][:]
    # The last x face is the outlet face, owned by the last fluid column.
    u_error = float(np.max(np.abs(u - 0.5)))
    w_error = float(np.max(np.abs(w[:-1])))  # the top row's W is the wall face: 0
    print(f"inflow {inflow:.6g} kg/s, outflow {outflow:.6g} kg/s (exact -0.006, 0.006); "
          f"max |u - 0.5| = {u_error:.2e} m/s, max |w| = {w_error:.2e} m/s")
    # Mass: to the solver tolerance (1e-4 relative); velocity: 1e-4 of the inflow speed.
    ok = abs(inflow + 0.006) < 1e-6 and abs(outflow - 0.006) < 1e-6 and u_error < 5e-5 and w_error < 5e-5
    return 0 if ok else 1


def rest(run):
    with h5py.File(last(run)) as f:
        speeds = [np.max(np.abs(f[f"fields/gas_velocity_{c}"][:])) for c in "xyz"]
        p = f["fields/gas_pressure"][:]
        xf, yf, zf = (f[f"grid/{c}_faces"][:] for c in "xyz")
    xc, yc, zc = (0.5 * (a[1:] + a[:-1]) for a in (xf, yf, zf))
    z, y, x = np.meshgrid(zc, yc, xc, indexing="ij")
    g = np.array([2.0, -3.0, -9.0])
    head = 1.2 * (g[0] * x + g[1] * y + g[2] * z)
    deviation = p - head
    spread = float(np.max(deviation) - np.min(deviation))
    print(f"largest spurious speed {max(speeds):.2e} m/s; pressure - ρ g·x varies by {spread:.2e} Pa")
    return 0 if max(speeds) < 1e-8 and spread < 1e-6 else 1


if __name__ == "__main__":
    sys.exit({"plug": plug, "rest": rest}[sys.argv[1]](sys.argv[2]))
