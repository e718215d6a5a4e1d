#!/usr/bin/python3
"""A layer on a 24° incline (jj_plug.toml, chute_free_slip.toml): the growth of its mass-weighted
mean solids x velocity between the first and the last snapshot against g sin θ.

usage: check_plug.py RUN_DIR --free-slip TOLERANCE | --held-back FRACTION | --acceleration TOLERANCE
  --free-slip TOL     the mean v_x must grow by g_x Δt within TOL (relative), and the layer must
                      be a plug (every cell's v_x within TOL of the mean)
  --held-back F       the mean v_x must grow by less than F × g_x Δt
  --acceleration TOL  the mean v_x must grow by g_x Δt within TOL (relative); the layer may shear
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "two_fluid"))
from snapshots import Snapshot, snapshot_paths  # noqa: E402

G_X = 3.990063


def mean_velocity(snapshot):
    phi = snapshot["solids_fraction"] * snapshot.volumes
    return float(np.nansum(phi * snapshot["solids_velocity_x"]) / np.nansum(phi))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run_dir")
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--free-slip", type=float)
    group.add_argument("--held-back", type=float)
    group.add_argument("--acceleration", type=float)
    args = parser.parse_args()
    paths = snapshot_paths(args.run_dir)
    first, last = Snapshot(paths[0]), Snapshot(paths[-1])
    u = last["solids_velocity_x"].ravel()
    u = u[np.isfinite(u)]
    start, end = mean_velocity(first), mean_velocity(last)
    gain = end - start
    expected = G_X * (last.time - first.time)
    print(f"{paths[-1]}: t = {first.time:g} to {last.time:g} s, mass-weighted mean v_x "
          f"{start:.6f} to {end:.6f} m/s (cells {u.min():.6f}–{u.max():.6f}): "
          f"acceleration {gain / (last.time - first.time):.6f} m/s², free g_x = {G_X:.6f} m/s²")
    if args.held_back is not None:
        ok = gain < args.held_back * expected
        print(f"{'PASS' if ok else 'FAIL'}: gain / g_x Δt = {gain / expected:.4f} (bound < {args.held_back:g})")
        return 0 if ok else 1
    tolerance = args.free_slip if args.free_slip is not None else args.acceleration
    ok = abs(gain / expected - 1) <= tolerance
    message = f"gain at g_x Δt within {tolerance:g}: {gain / expected - 1:+.2e}"
    if args.free_slip is not None:
        ok = ok and np.all(np.abs(u / end - 1) <= tolerance)
        message += f" (mean), {np.max(np.abs(u / end - 1)):.2e} (cells, plug)"
    print(f"{'PASS' if ok else 'FAIL'}: {message}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
