#!/usr/bin/python3
"""Fails when a run's discharge rate over a fixed window departs from a reference.

usage: check_discharge_rate.py RUN_DIR --window START END --reference G_PER_S --tolerance REL

The rate is the dt-weighted mean of the monitor's flux_orifice_solids_kg_per_s over the steps
ending in (START, END] (tools/discharge-rate's block mean, on a fixed window so a short run is
compared like for like).
"""
import argparse
import os
import sys

import numpy as np

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "tools"))
import bagnold_post as post  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run_dir")
    parser.add_argument("--window", type=float, nargs=2, required=True, metavar=("START", "END"))
    parser.add_argument("--reference", type=float, required=True, help="g/s")
    parser.add_argument("--tolerance", type=float, required=True, help="relative")
    args = parser.parse_args()
    columns, path = post.read_monitor(args.run_dir)
    t, dt = columns["time"], columns["dt"]
    start, end = args.window
    inside = (t > start + 1e-12) & (t <= end + 1e-12)
    if t[-1] < end - 1e-9 or not inside.any():
        print(f"FAIL: {path} ends at t = {t[-1]:.4g} s, before the window [{start}, {end}] s")
        return 1
    flux = columns["flux_orifice_solids_kg_per_s"][inside]
    rate = 1e3 * float(np.sum(flux * dt[inside]) / np.sum(dt[inside]))
    deviation = rate / args.reference - 1.0
    verdict = "PASS" if abs(deviation) <= args.tolerance else "FAIL"
    print(f"{verdict}: discharge rate over {start}–{end} s {rate:.2f} g/s against the reference "
          f"{args.reference:.2f} g/s: {100 * deviation:+.2f} % (bound ±{100 * args.tolerance:g} %)")
    return 0 if verdict == "PASS" else 1


if __name__ == "__main__":
    sys.exit(main())
