#!/usr/bin/python3
"""Check periodic.toml's run: the profile against u(z) = G z (H − z) / (2 μ) and the walls' shear
in the monitor against the body force they hold, −ρ g V.

usage: check_wall_shear.py RUN_DIR

Exits 1 when the profile is off by more than 1 % of u_max or the last step's wall_shear_gas_x_N
by more than 1e-4 of ρ g V (the steady state holds to the solver's tolerance, 1e-7; the sum of
the walls' stress over the rows equals the body force exactly, the interior viscous fluxes
cancelling in pairs).
"""
import csv
import glob
import os
import sys

import h5py
import numpy as np

G, MU, RHO, VOLUME = 8.0, 1.0, 1.0, 1.0 * 0.01 * 0.1


def main(run):
    with open(os.path.join(run, "monitor.csv")) as f:
        last = list(csv.DictReader(f))[-1]
    force = float(last["wall_shear_gas_x_N"])
    expected = -G * VOLUME
    force_error = abs(force / expected - 1.0)
    snapshot = sorted(glob.glob(os.path.join(run, "snapshot_*.h5")))[-1]
    with h5py.File(snapshot, "r") as f:
        zf = f["grid/z_faces"][:]
        u = f["fields/gas_velocity_x"][:, 0, :]
    zc = 0.5 * (zf[1:] + zf[:-1])
    exact = G * (zc - zf[0]) * (zf[-1] - zc) / (2 * MU)
    profile_error = float(np.max(np.abs(u - exact[:, None]))) / (G * (zf[-1] - zf[0]) ** 2 / (8 * MU))
    print(f"walls' shear {force:.9g} N against -rho g V = {expected:.9g} N (relative {force_error:.2e}); "
          f"largest |u - u_exact| / u_max = {profile_error:.2e}")
    return 0 if force_error < 1e-4 and profile_error < 0.01 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
