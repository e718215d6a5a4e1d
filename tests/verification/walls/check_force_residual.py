#!/usr/bin/python3
"""The monitor's `force_residual` column (each accepted step's momentum residuals against the
forces that act, whatever norm judged the step) over every step of a run.

usage: check_force_residual.py RUN_DIR --at-most BOUND | --at-least BOUND
  --at-most B   every step's value is at most B (a run judged by the force norm at tolerance B)
  --at-least B  every step's value is at least B (a norm that accepted unbalanced steps, which
                the column must show)
"""
import argparse
import csv
import os
import sys


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run_dir")
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--at-most", type=float)
    group.add_argument("--at-least", type=float)
    args = parser.parse_args()
    with open(os.path.join(args.run_dir, "monitor.csv")) as f:
        values = [float(row["force_residual"]) for row in csv.DictReader(f)]
    if not values:
        print("FAIL: no steps in monitor.csv")
        return 1
    low, high = min(values), max(values)
    print(f"{args.run_dir}: {len(values)} steps, force_residual {low:.3e} to {high:.3e}")
    ok = high <= args.at_most if args.at_most is not None else low >= args.at_least
    bound = f"at most {args.at_most:g}" if args.at_most is not None else f"at least {args.at_least:g}"
    print(f"{'PASS' if ok else 'FAIL'}: every step's force_residual {bound}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
