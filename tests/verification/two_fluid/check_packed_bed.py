#!/usr/bin/python3
"""Packed bed with moving solids, gas flowing up below minimum fluidization (packed_bed.toml).

usage: check_packed_bed.py RUN_DIR            the bed stays put; ΔP across it is Ergun's
       check_packed_bed.py RUN_DIR --inflow   the mass inflow delivers the deck's U

The gas pressure drop between the centres of the bottom cell and of the highest cell full of
bed (both cells beside every face in between at ε_s > 0.55) is compared with Ergun's, face by
face at the local ε_s (the plastic closure lets the bed's weight compress it from 0.600 at the
top to 0.608 at the bottom, which changes Ergun's gradient by 8 %), at the superficial velocity
that actually flows: the inlet's mass flux from monitor.csv over ρ_g A. Gas hydrostatics ρ_g g
is taken off. Tolerance 2 % (issue 4)."""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from snapshots import G, Snapshot, snapshot_paths  # noqa: E402

RHO_S, RHO_G, MU, D = 2500.0, 1.2, 1.8e-5, 5e-4    # as in packed_bed.toml
U_DECK = 0.1                                       # inlet gas velocity of the deck [m/s]
ERGUN_TOLERANCE = 0.02
REST_BOUND = 1e-6                                  # m/s, solids inside the bed at the end
TOP_BOUND = 0.5                                    # cells the bed's top may move
INFLOW_TOLERANCE = 1e-6                            # relative, delivered against the deck's U


def ergun_gradient(eps_s, u):
    """Ergun: −dP/dz (drag part) at solids fraction eps_s and superficial velocity u [Pa/m]."""
    eps_g = 1.0 - eps_s
    return (150.0 * MU * u * eps_s**2 / (eps_g**3 * D**2)
            + 1.75 * RHO_G * u * u * eps_s / (eps_g**3 * D))


def bed_top(snap):
    """Where the column's ε_s falls through 0.3, interpolated between cell centres [m]."""
    es, z = snap.column("solids_fraction"), snap.z_centres
    k = int(np.nonzero(es > 0.3)[0].max())
    return z[k] + (z[k + 1] - z[k]) * (es[k] - 0.3) / (es[k] - es[k + 1])


def read_monitor(run_dir):
    with open(os.path.join(run_dir, "monitor.csv")) as f:
        rows = list(csv.DictReader(f))
    return rows


def main():
    run_dir = sys.argv[1]
    snaps = [Snapshot(p) for p in snapshot_paths(run_dir)]
    first, last = snaps[0], snaps[-1]
    monitor = read_monitor(run_dir)
    inflow = -float(monitor[-1]["flux_inlet_gas_kg_per_s"])
    u = inflow / (RHO_G * last.area)
    ok = True

    if "--inflow" in sys.argv[2:]:
        error = abs(u - U_DECK) / U_DECK
        print(f"gas mass inflow {inflow:.6e} kg/s = superficial {u:.6f} m/s; the deck's "
              f"{U_DECK} m/s (ρ_g U A = {RHO_G * U_DECK * last.area:.6e} kg/s): relative error "
              f"{error:.2e} (bound {INFLOW_TOLERANCE:g})")
        print("PASS" if error < INFLOW_TOLERANCE else "FAIL")
        return 0 if error < INFLOW_TOLERANCE else 1

    es = last.column("solids_fraction")
    p = last.column("gas_pressure")
    full = np.nonzero(es > 0.55)[0]
    top = int(full.max())
    if not np.array_equal(full, np.arange(top + 1)):
        print(f"FAIL: the bed is not one block from the bottom: cells {full}")
        return 1
    z = last.z_centres
    dp = p[0] - p[top] - RHO_G * G * (z[top] - z[0])
    eps_face = 0.5 * (es[:top] + es[1:top + 1])
    ergun = float(np.sum(ergun_gradient(eps_face, u) * np.diff(z[:top + 1])))
    ergun_uniform = ergun_gradient(0.6, u) * (z[top] - z[0])
    error = abs(dp - ergun) / ergun
    print(f"superficial gas velocity through the bed {u:.6f} m/s (inlet mass flux; the deck asks "
          f"{U_DECK} m/s)")
    print(f"ΔP between z = {z[0]:.4f} and {z[top]:.4f} m (gas head off) {dp:.4f} Pa; Ergun at the "
          f"local ε_s {ergun:.4f} Pa (at ε_s = 0.6: {ergun_uniform:.4f} Pa): relative error "
          f"{error:.2e} (bound {ERGUN_TOLERANCE:g})")
    ok &= error < ERGUN_TOLERANCE

    # The bed stays put: solids at rest inside it, its top where it was, no solids through
    # any boundary, inventory kept.
    ws = last["solids_velocity_z"]
    esf = last["solids_fraction"]
    inside = (esf[:-1] > 0.3) & (esf[1:] > 0.3)
    w_bed = float(np.max(np.abs(ws[:-1][inside])))
    print(f"largest solids velocity inside the bed at t = {last.time:g} s: {w_bed:.2e} m/s "
          f"(bound {REST_BOUND:g})")
    ok &= w_bed < REST_BOUND
    moved = abs(bed_top(last) - bed_top(first))
    print(f"bed top {bed_top(first):.5f} m -> {bed_top(last):.5f} m: moved {moved * 1e3:.2f} mm "
          f"(bound {TOP_BOUND} cell = {TOP_BOUND * last.dz[top] * 1e3:.1f} mm)")
    ok &= moved < TOP_BOUND * last.dz[top]
    solids_out = max(abs(float(r[k])) for r in monitor for k in r if k.startswith("flux_")
                     and k.endswith("solids_kg_per_s"))
    drift = abs(last.solids_volume() - first.solids_volume()) / first.solids_volume()
    print(f"largest solids mass flux through any boundary {solids_out:.2e} kg/s; solids "
          f"inventory drift {drift:.2e} (bounds 0 and 1e-12)")
    ok &= solids_out == 0.0 and drift < 1e-12
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
