#!/usr/bin/python3
"""The monitor's `force_residual` column (each accepted step's momentum residuals against the
forces that act, whatever norm judged the step) over every step of a run.

usage: check_force_residual.py RUN_DIR --force-norm | --at-least BOUND
  --force-norm  a run judged by the force norm: every step's value is at most its `residual` (the
                largest of all its normalized residuals, of which the momentum ones are this
                column's) and equal to it to 1e-9 in at least one step
  --at-least B  every step's value is at least B (a norm that accepted steps judged on a state
                with its forces unbalanced, which the column must show)
"""
import argparse
import csv
import os
import sys


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run_dir")
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--force-norm", action="store_true")
    group.add_argument("--at-least", type=float)
    args = parser.parse_args()
    with open(os.path.join(args.run_dir, "monitor.csv")) as f:
        rows = [(float(row["force_residual"]), float(row["residual"])) for row in csv.DictReader(f)]
    if not rows:
        print("FAIL: no steps in monitor.csv")
        return 1
    values = [v for v, _ in rows]
    print(f"{args.run_dir}: {len(values)} steps, force_residual {min(values):.3e} to {max(values):.3e}")
    if args.force_norm:
        within = all(v <= r * (1 + 1e-9) for v, r in rows)
        equal = sum(1 for v, r in rows if abs(v - r) <= 1e-9 * r)
        ok = within and equal > 0
        print(f"{'PASS' if ok else 'FAIL'}: force_residual at most the judged residual in every step "
              f"({within}), equal to it in {equal} of {len(rows)}")
    else:
        ok = min(values) >= args.at_least
        print(f"{'PASS' if ok else 'FAIL'}: every step's force_residual at least {args.at_least:g}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
