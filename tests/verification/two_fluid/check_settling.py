#!/usr/bin/python3
"""Settling column (settling_column.toml): solids mass conserved over the run, the final bed as
high as the inventory packed at the closure's limit, and no cell packed beyond what the bed's
weight can compress the plastic closure to.   usage: check_settling.py RUN_DIR"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from snapshots import G, Snapshot, snapshot_paths  # noqa: E402

RHO_S, RHO_G, MU, D = 2500.0, 1.2, 1.8e-5, 5e-4  # as in settling_column.toml
PACKED = 0.6                               # ε_s* = 1 − ε_g* of the plastic closure
A, N = 1e24, 10.0                          # P_s = A (ε_s − ε_s*)^n
MASS_DRIFT_BOUND = 1e-12                   # relative; measured 3.5e-16 (round-off)
PACKING_MARGIN = 1e-4                      # on ε_s above the compression by the bed's weight


def main():
    snaps = [Snapshot(p) for p in snapshot_paths(sys.argv[1])]
    first, last = snaps[0], snaps[-1]
    ok = True

    # 1. Solids mass over the whole run (every snapshot, full double precision).
    m0 = first.solids_volume() * RHO_S
    drift = max(abs(s.solids_volume() * RHO_S - m0) for s in snaps) / m0
    print(f"solids mass {m0:.12e} kg at t = 0; largest relative drift over {len(snaps)} "
          f"snapshots to t = {last.time:g} s: {drift:.2e} (bound {MASS_DRIFT_BOUND:g})")
    ok &= drift < MASS_DRIFT_BOUND

    # 2. Bed height: where the column's ε_s falls through ε_s*/2, interpolated between cell
    # centres, against inventory / ε_s*.
    es = last.column("solids_fraction")
    z = last.z_centres
    inventory = last.solids_volume() / last.area  # m of solids per unit area
    expected = inventory / PACKED
    top = int(np.nonzero(es > 0.5 * PACKED)[0].max())
    if top + 1 >= len(es):
        print("FAIL: no free surface: the column is full")
        return 1
    half = 0.5 * PACKED
    height = z[top] + (z[top + 1] - z[top]) * (es[top] - half) / (es[top] - es[top + 1])
    cell = float(last.dz[top])
    print(f"bed height {height:.5f} m, expected inventory/ε_s* = {inventory:.5f}/{PACKED} = "
          f"{expected:.5f} m: off by {abs(height - expected) * 1e3:.2f} mm "
          f"(bound one cell, {cell * 1e3:.1f} mm)")
    ok &= abs(height - expected) < cell

    # 3. Packing. The plastic limit is soft: the bed's buoyant weight per area W is carried by
    # P_s at the bottom, so at rest ε_s there is ε_s* + (W/A)^(1/n). The final state may not
    # exceed that plus a margin of 1e-4 in ε_s (P_s = 1.13 W).
    weight = (RHO_S - RHO_G) * G * inventory
    limit = PACKED + (weight / A) ** (1.0 / N)
    bound = limit + PACKING_MARGIN
    print(f"bed weight per area W = {weight:.1f} Pa -> ε_s where P_s = W: {limit:.6f}; "
          f"final largest ε_s {es.max():.6f} (P_s = {A * (es.max() - PACKED) ** N / weight:.3f} W; "
          f"bound {bound:.6f})")
    ok &= es.max() < bound
    # While the bed forms it also stops the falling suspension: the momentum flux
    # ρ_s ε_s0 v (v + c) with v the hindered settling speed (Ergun drag, closed box:
    # β s = ε_s ε_g (ρ_s − ρ_g) g, v = ε_g s) and c = ε_s0 v / (ε_s* − ε_s0) the rise of the bed
    # front. Over the run the bound is P_s = 1.5 (W + that).
    e0 = float(np.nansum(first["solids_fraction"] * first.volumes) / np.sum(first.volumes))
    eg = 1.0 - e0
    lin = 150.0 * e0**2 * MU / (eg * D**2)
    quad = 1.75 * e0 * RHO_G / D
    slip = (-lin + np.sqrt(lin**2 + 4 * quad * e0 * eg * (RHO_S - RHO_G) * G)) / (2 * quad)
    v = eg * slip
    c = e0 * v / (PACKED - e0)
    impact = RHO_S * e0 * v * (v + c)
    run_bound = PACKED + (1.5 * (weight + impact) / A) ** (1.0 / N)
    run_max = max(float(np.nanmax(s["solids_fraction"])) for s in snaps)
    print(f"hindered settling speed {v:.3f} m/s, bed front {c:.3f} m/s, impact {impact:.1f} Pa "
          f"= {impact / weight:.2f} W; largest ε_s over the run {run_max:.6f} "
          f"(P_s = {A * (run_max - PACKED) ** N / weight:.3f} W; bound {run_bound:.6f}, "
          f"P_s = {1.5 * (weight + impact) / weight:.2f} W)")
    ok &= run_max < run_bound
    below = es[:top]
    print(f"bed cells under the surface cell: ε_s in [{below.min():.6f}, {below.max():.6f}] "
          f"(must be ≥ ε_s* = {PACKED})")
    ok &= bool(np.all(below >= PACKED))

    # 4. The bed has settled: solids at rest inside it (faces with solids on both sides).
    ws = last["solids_velocity_z"]
    esf = last["solids_fraction"]
    inside = (esf[:-1] > 0.5 * PACKED) & (esf[1:] > 0.5 * PACKED)
    w_bed = float(np.max(np.abs(ws[:-1][inside])))
    print(f"largest solids velocity inside the bed at t = {last.time:g} s: {w_bed:.2e} m/s "
          f"(bound 1e-6)")
    ok &= w_bed < 1e-6

    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
