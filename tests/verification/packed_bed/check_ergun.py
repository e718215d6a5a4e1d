#!/usr/bin/python3
"""Fixed packed bed: the pressure gradient in the bed against the Ergun equation, and the
interstitial velocity U/ε_g.   usage: check_ergun.py RUN_DIR"""
import glob
import os
import sys

import h5py
import numpy as np

MU, RHO, U, EPS_S, D = 1.8e-5, 1.2, 0.1, 0.6, 1e-3  # as in fixed_bed.toml


def main():
    eps_g = 1.0 - EPS_S
    ergun = 150 * MU * U * EPS_S**2 / (eps_g**3 * D**2) + 1.75 * RHO * U**2 * EPS_S / (eps_g**3 * D)
    with h5py.File(sorted(glob.glob(os.path.join(sys.argv[1], "snapshot_*.h5")))[-1], "r") as f:
        p = f["fields/gas_pressure"][:, 0, 0]
        w = f["fields/gas_velocity_z"][:, 0, 0]
        zf = f["grid/z_faces"][:]
    zc = 0.5 * (zf[1:] + zf[:-1])
    inside = (zc > 0.07) & (zc < 0.13)  # away from the bed's ends
    gradient = -np.polyfit(zc[inside], p[inside], 1)[0]
    error = abs(gradient - ergun) / ergun
    interstitial = float(np.max(np.abs(w[inside] - U / eps_g))) / (U / eps_g)
    print(f"dP/dz in the bed {gradient:.6f} Pa/m, Ergun {ergun:.6f} Pa/m, relative error {error:.2e}; "
          f"interstitial velocity off U/ε_g by {interstitial:.2e} (relative)")
    return 0 if error < 0.02 and interstitial < 1e-6 else 1


if __name__ == "__main__":
    sys.exit(main())
