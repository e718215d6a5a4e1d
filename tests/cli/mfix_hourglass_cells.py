#!/usr/bin/python3
"""MFIX's 2-D hourglass deck (cases/hourglass/mfix-hourglass.toml): `bagnold check` passes and
reports as many fluid cells as the three quadrics give at the cell centres, counted here from
their formulas alone (a cell is fluid where the piece whose z range holds its centre has f < 0).

Usage: mfix_hourglass_cells.py BAGNOLD DECK
"""
import re
import subprocess
import sys

LOWER_JOINT, UPPER_JOINT = 0.128158, 0.271842


def fluid(x, z):
    """Whether (x, z) is fluid: f < 0 for every piece whose range contains z (joints: both)."""
    pieces = []
    if LOWER_JOINT <= z <= UPPER_JOINT:  # hyperbola: a 5 cm throat at z = 0.20 m
        pieces.append(1600.0 * (x - 0.10) ** 2 - 1500.0 * (z - 0.20) ** 2 - 1.0)
    if UPPER_JOINT <= z <= 0.40:  # upper circle, radius 0.10 m
        pieces.append((x - 0.10) ** 2 + (z - 0.339194) ** 2 - 0.01)
    if 0.0 <= z <= LOWER_JOINT:  # lower circle, radius 0.10 m
        pieces.append((x - 0.10) ** 2 + (z - 0.060806) ** 2 - 0.01)
    return all(f < 0.0 for f in pieces)


def expected_fluid_cells(nx=40, nz=80, width=0.20, height=0.40):
    dx, dz = width / nx, height / nz
    return sum(fluid((i + 0.5) * dx, (k + 0.5) * dz) for i in range(nx) for k in range(nz))


def main():
    bagnold, deck = sys.argv[1], sys.argv[2]
    expected = expected_fluid_cells()
    result = subprocess.run([bagnold, "check", deck], capture_output=True, text=True)
    output = result.stdout + result.stderr
    if result.returncode != 0:
        sys.exit(f"bagnold check exited {result.returncode}:\n{output}")
    match = re.search(r"cells: (\d+) fluid", output)
    if not match:
        sys.exit(f"no 'cells: N fluid' line in the output of check:\n{output}")
    found = int(match.group(1))
    if found != expected:
        sys.exit(f"check reports {found} fluid cells; the quadrics give {expected}")
    print(f"{found} fluid cells, as the quadrics give")


if __name__ == "__main__":
    main()
