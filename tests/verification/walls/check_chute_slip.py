#!/usr/bin/python3
"""The chute with sidewalls (cases/chute/sidewalls-slip.toml, also sidewalls.toml's start) at its
last snapshot: the layer still moves, with no secondary flow and no pressure spike.

usage: check_chute_slip.py RUN_DIR --end-time T --min-speed V

Fails (exit 1) unless the last snapshot is at T (the run did not stall before it), the
mass-weighted mean v_x is at least V (the layer is still carried on its slip, not collapsed
into the ~0.5-0.7 m/s sliding plug the no-slip start falls into), the cross-stream velocities
|v_y|, |v_z| are below 0.01 m/s and P_s nowhere exceeds 3 times the layer's weight per unit
area (rho_s g cos(theta) x inventory: 3 x 384 Pa). Reverting the slip start (back to the
no-slip profile) fails on the speed within 1 s, or stalls.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "two_fluid"))
from snapshots import Snapshot, snapshot_paths  # noqa: E402

WEIGHT = 2500.0 * 8.961980 * 0.570771 * 0.03  # ρ_s g cos θ φ̄ H [Pa], chute-1d's column


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run_dir")
    parser.add_argument("--end-time", type=float, required=True)
    parser.add_argument("--min-speed", type=float, required=True)
    args = parser.parse_args()
    last = Snapshot(snapshot_paths(args.run_dir)[-1])
    t = last.time
    phi, vx, vy, vz = (last[name] for name in ("solids_fraction", "solids_velocity_x",
                                               "solids_velocity_y", "solids_velocity_z"))
    p = last["solids_pressure"]
    mean = float(np.sum(phi * vx) / np.sum(phi))
    cross = float(max(np.max(np.abs(vy)), np.max(np.abs(vz))))
    largest_p = float(np.max(p))
    print(f"t = {t:g} s: mean v_x {mean:.4f} m/s, largest |v_y|, |v_z| {cross:.3g} m/s, "
          f"largest P_s {largest_p:.4g} Pa (weight {WEIGHT:.4g} Pa)")
    failures = []
    if abs(t - args.end_time) > 1e-6 * max(1.0, args.end_time):
        failures.append(f"last snapshot at t = {t:g} s, not {args.end_time:g} s")
    if not mean >= args.min_speed:
        failures.append(f"mean v_x {mean:.4f} m/s below {args.min_speed:g} m/s")
    if not cross < 0.01:
        failures.append(f"cross-stream velocity {cross:.3g} m/s (secondary flow)")
    if not largest_p < 3.0 * WEIGHT:
        failures.append(f"P_s {largest_p:.4g} Pa above 3 x the weight")
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
