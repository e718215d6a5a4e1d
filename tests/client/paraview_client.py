#!/usr/bin/python3
"""The client test: a short run opened in ParaView as a user would (docs/paraview.md).

usage: paraview_client.py BAGNOLD DECK RUN_DIR

Runs DECK for a few steps into RUN_DIR, reads what its snapshots hold with h5py, then opens
RUN_DIR/run.xmf in pvpython (under xvfb-run -a) with check_in_paraview.py, which checks the
bounds, the time steps, the fields, the cell-centred velocity vectors (components and
magnitudes against the h5py reads) and the openings' face velocities, renders a slice to
PNG (the packed fill must show in it) and traces stream lines of both vectors (Stream Tracer
must return lines with points). Exits 77 (CTest's SKIP_RETURN_CODE) with a message when pvpython or xvfb-run is missing.
"""
import glob
import json
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

SKIP = 77


def expectations(run_dir):
    snapshots = sorted(glob.glob(os.path.join(run_dir, "snapshot_*.h5")))
    times, fields = [], None
    for path in snapshots:
        with h5py.File(path, "r") as f:
            times.append(float(f.attrs["time"]))
    with h5py.File(snapshots[-1], "r") as f:
        faces = [f["grid/" + a + "_faces"][:] for a in "xyz"]
        fields = sorted(f["fields"])
        vectors = {}
        for name in ("gas_velocity", "solids_velocity"):
            v = f["fields/" + name][:]  # (nz, ny, nx, 3), C order: x fastest, as VTK's cells
            vectors[name] = v.reshape(-1, 3).tolist()
            # The vector is the mean of the two staggered faces along each axis (fluid cells).
            staggered = f["fields/" + name + "_x"][:]
            fluid = f["grid/cell_flags"][:] == 1
            interior = fluid[:, :, 1:] & fluid[:, :, :-1]
            mean = 0.5 * (staggered[:, :, 1:] + staggered[:, :, :-1])
            if not np.allclose(v[:, :, 1:, 0][interior], mean[interior], rtol=0, atol=1e-15):
                raise SystemExit(f"FAIL: {name}[..., 0] is not the mean of {name}_x on its two faces")
        openings = {name: f["openings/" + name][:].tolist()
                    for name in ("solids_velocity", "solids_outflow_velocity", "region")}
    bounds = [float(b) for a in faces for b in (a[0], a[-1])]
    return {"times": times, "bounds": bounds, "fields": fields, "vectors": vectors,
            "openings": openings, "cells": int(np.prod([len(a) - 1 for a in faces]))}


def main():
    bagnold, deck, run_dir = sys.argv[1:4]
    pvpython, xvfb = shutil.which("pvpython"), shutil.which("xvfb-run")
    if not pvpython or not xvfb:
        missing = " and ".join(n for n, p in (("pvpython", pvpython), ("xvfb-run", xvfb)) if not p)
        print(f"SKIP: {missing} not found; install Debian's python3-paraview and xvfb (tools/setup --tests)")
        return SKIP
    shutil.rmtree(run_dir, ignore_errors=True)
    subprocess.run([bagnold, "run", deck, "--set", "run.end_time=0.02",
                    "--set", "output.snapshot_interval=0.01", "--set", f"output.directory={run_dir}"],
                   check=True, stdout=subprocess.DEVNULL)
    expected = expectations(run_dir)
    expected_path = os.path.join(run_dir, "expected.json")
    with open(expected_path, "w") as out:
        json.dump(expected, out)
    png = os.path.join(run_dir, "slice.png")
    check = os.path.join(os.path.dirname(os.path.abspath(__file__)), "check_in_paraview.py")
    # A loaded machine's X server sometimes refuses pvpython's connection before it has read
    # anything ("bad X server connection", abort): that is the display, not the run, so retry.
    for attempt in range(1, 4):
        result = subprocess.run([xvfb, "-a", pvpython, "--force-offscreen-rendering", check,
                                 os.path.join(run_dir, "run.xmf"), expected_path, png],
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        sys.stdout.write(result.stdout)
        if result.returncode == 0 or "bad X server connection" not in result.stdout:
            break
        print(f"pvpython could not connect to the X server (attempt {attempt} of 3)")
    if result.returncode != 0:
        print(f"FAIL: pvpython exited with {result.returncode}")
        return 1
    if not os.path.exists(png) or os.path.getsize(png) < 4000:
        print(f"FAIL: {png} missing or too small to show the slice")
        return 1
    with open(png, "rb") as f:
        if f.read(8) != b"\x89PNG\r\n\x1a\n":
            print(f"FAIL: {png} is not a PNG")
            return 1
    import matplotlib.image
    pixels = matplotlib.image.imread(png)[:, :, :3]
    # The packed fill (ε_s ≈ 0.58, the top of the 0-0.6 range) shows dark red, the empty upper
    # bin (0) dark blue; the slender bin covers about 2 % of the picture.
    red = (pixels[:, :, 0] > 0.45) & (pixels[:, :, 1] < 0.25) & (pixels[:, :, 2] < 0.25)
    blue = (pixels[:, :, 2] > 0.45) & (pixels[:, :, 0] < 0.3) & (pixels[:, :, 1] < 0.3)
    if red.mean() < 0.003 or blue.mean() < 0.003:
        print(f"FAIL: {png} does not show the fill and the empty bin above it "
              f"({100 * red.mean():.2f} % red, {100 * blue.mean():.2f} % blue pixels)")
        return 1
    print(f"{png}: {os.path.getsize(png)} bytes, {100 * red.mean():.2f} % of it the packed fill, "
          f"{100 * blue.mean():.2f} % the empty bin")
    return 0


if __name__ == "__main__":
    sys.exit(main())
