#!/usr/bin/python3
"""Bed at rest in a closed box (bed_at_rest.toml): after the bed has taken up its weight
(t ≥ 0.5 s) the solids in the bed and the gas everywhere stay at rest.

usage: check_bed_at_rest.py RUN_DIR

Bounds (measured over t = 0.5 … 1 s, 1 rank: solids 3.4e-11 m/s, gas 8.2e-10 m/s):
  solids velocity, every component, at faces with solids on both sides (ε_s > 0.3): 1e-8 m/s;
  gas velocity, every face: 1e-7 m/s;
  solids volume flux ε_s,upwind u_s through every face: 1e-8 m/s.
The last matters at the bed's free surface: the face between the top bed cell and the empty
cell above has a solids velocity of its own (≈ 0.16 m/s downward, the free-fall balance of
gravity, drag and a half-empty control volume), but nothing upwind of it to carry, so its
flux is zero. That velocity is reported, not bounded."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from snapshots import Snapshot, snapshot_paths  # noqa: E402

SOLIDS_BOUND, GAS_BOUND, FLUX_BOUND = 1e-8, 1e-7, 1e-8
SINCE = 0.5


def face_pairs(field, axis):
    """(owner, neighbour) values across the + face along axis, periodic wrap in x and y."""
    return field, np.roll(field, -1, axis=axis)


def main():
    snaps = [Snapshot(p) for p in snapshot_paths(sys.argv[1])]
    worst_s = worst_g = worst_flux = surface = 0.0
    for s in snaps:
        if s.time < SINCE - 1e-9:
            continue
        es = s["solids_fraction"]
        for axis, name in ((2, "x"), (1, "y"), (0, "z")):
            us, ug = s["solids_velocity_" + name], s["gas_velocity_" + name]
            own, nb = face_pairs(es, axis)
            if axis == 0:  # no wrap in z: the top row's faces are the wall
                own, nb, us, ug = own[:-1], nb[:-1], us[:-1], ug[:-1]
            both = (own > 0.3) & (nb > 0.3)
            worst_s = max(worst_s, float(np.max(np.abs(us[both]), initial=0.0)))
            worst_g = max(worst_g, float(np.nanmax(np.abs(ug))))
            upwind = np.where(us >= 0.0, own, nb)
            worst_flux = max(worst_flux, float(np.nanmax(np.abs(upwind * us))))
            surface = max(surface, float(np.nanmax(np.abs(us[~both]))))
    ok = worst_s < SOLIDS_BOUND and worst_g < GAS_BOUND and worst_flux < FLUX_BOUND
    print(f"t ≥ {SINCE} s: largest solids velocity in the bed {worst_s:.2e} m/s (bound {SOLIDS_BOUND:g}); "
          f"largest gas velocity {worst_g:.2e} m/s (bound {GAS_BOUND:g}); largest solids volume flux "
          f"{worst_flux:.2e} m/s (bound {FLUX_BOUND:g}); solids velocity at the free surface "
          f"{surface:.3f} m/s (not bounded)")
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
