#!/usr/bin/python3
"""The layer of jj_plug.toml at its last snapshot: mean solids x velocity against g sin θ t.

usage: check_plug.py RUN_DIR --free-slip TOLERANCE | --held-back FRACTION
  --free-slip TOL   the mass-weighted mean v_x must equal g_x t within TOL (relative), and the
                    layer must be a plug (every cell's v_x within TOL of the mean)
  --held-back F     the mean v_x must be below F × g_x t
"""
import argparse
import glob
import os
import sys

import h5py
import numpy as np

G_X = 3.990063


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run_dir")
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--free-slip", type=float)
    group.add_argument("--held-back", type=float)
    args = parser.parse_args()
    last = sorted(glob.glob(os.path.join(args.run_dir, "snapshot_*.h5")))[-1]
    with h5py.File(last, "r") as f:
        t = float(f.attrs["time"]) if "time" in f.attrs else float(f["time"][()])
        phi = f["fields/solids_fraction"][:].ravel()
        u = f["fields/solids_velocity_x"][:].ravel()
    mean = float(np.sum(phi * u) / np.sum(phi))
    expected = G_X * t
    print(f"{last}: t = {t:g} s, mass-weighted mean v_x {mean:.6f} m/s, cells {u.min():.6f}–{u.max():.6f}; "
          f"free acceleration g_x t = {expected:.6f} m/s")
    if args.free_slip is not None:
        ok = abs(mean / expected - 1) <= args.free_slip and np.all(np.abs(u / mean - 1) <= args.free_slip)
        print(f"{'PASS' if ok else 'FAIL'}: plug at g_x t within {args.free_slip:g}: "
              f"{mean / expected - 1:+.2e} (mean), {np.max(np.abs(u / mean - 1)):.2e} (cells)")
    else:
        ok = mean < args.held_back * expected
        print(f"{'PASS' if ok else 'FAIL'}: mean v_x / g_x t = {mean / expected:.4f} (bound < {args.held_back:g})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
