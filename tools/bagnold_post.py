"""Shared reading and analysis for the post-processing tools (discharge-rate, plot-mass, plot-slice).

Reads only a run's output directory (docs/output.md): monitor.csv and snapshot_NNNNNN.h5.
Not a script: the tools import it with their own folder on sys.path.

Steady window (steady_window): the monitor's per-step rate is averaged over blocks of
BLOCK = 0.05 s laid back from the last monitored time (a partial block at the start is dropped;
each step's value holds over its [t - dt, t], so uneven steps weigh by their length). The
reference level is the mean of the trailing --window-min seconds of blocks, and those blocks must
all lie within ±tolerance (default 5 %) of it, or the series is not steady at its end. Walking
back from the end, the window grows by one block while the block mean stays within ±tolerance of
the reference; the first block outside the band (the end of the transient) stops it. The window
is therefore the longest trailing run of 0.05 s blocks that all agree with the final level to
within the tolerance. A band on block means, not on a running mean, because a running mean
swallows part of the transient before it leaves the band and biases the rate by up to the
tolerance; here any block that differs by more than the tolerance is excluded. The window must
last at least --window-min seconds and the run must end while the discharge is steady (use
--until to cut off a tail, e.g. the bin running empty).
"""
import glob
import os
import re
import shlex
import subprocess
import sys

import numpy as np

BLOCK = 0.05  # s, block length for block means and the spread
# `bagnold run`'s last line: steps, redone steps, outer iterations per step, wall seconds.
RUN_SUMMARY = re.compile(r"after (\d+) steps \((\d+) redone\), ([\d.]+) outer iterations per step, "
                         r"([\d.]+) s wall")


class PostError(Exception):
    """A user-facing error: the tools print it and exit 1."""


def parse_numbers(text, option):
    """The numbers of a comma-separated command-line value, e.g. `--times 0,0.5,1`."""
    try:
        numbers = [float(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise PostError(f"{option} wants comma-separated numbers, not '{text}'")
    if not numbers:
        raise PostError(f"{option} is empty")
    return numbers


def command_line():
    """The reproducing command, as the user typed it (program path as invoked)."""
    return " ".join(shlex.quote(a) for a in sys.argv)


def run_tool(main):
    """Runs main() and turns PostError into a message on stderr and exit status 1."""
    try:
        return main()
    except PostError as error:
        print(f"{os.path.basename(sys.argv[0])}: error: {error}", file=sys.stderr)
        return 1


def check_run_dir(run_dir):
    if not os.path.exists(run_dir):
        raise PostError(f"run directory '{run_dir}' does not exist")
    if not os.path.isdir(run_dir):
        raise PostError(f"'{run_dir}' is not a directory (give the run's output directory)")


def read_monitor(run_dir):
    """monitor.csv as {column: float64 array}. Rows that do not parse (a torn last line of a
    running job) are skipped."""
    check_run_dir(run_dir)
    path = os.path.join(run_dir, "monitor.csv")
    if not os.path.isfile(path):
        raise PostError(f"no monitor.csv in '{run_dir}'")
    with open(path) as f:
        header = f.readline().strip()
        if not header:
            raise PostError(f"{path} is empty")
        names = [n.strip() for n in header.split(",")]
        rows = []
        for line in f:
            parts = line.strip().split(",")
            if len(parts) != len(names):
                continue
            try:
                rows.append([float(p) for p in parts])
            except ValueError:
                continue
    if "time" not in names:
        raise PostError(f"{path} has no 'time' column (columns: {', '.join(names)})")
    data = np.array(rows, dtype=float).reshape(len(rows), len(names))
    columns = {n: data[:, i] for i, n in enumerate(names)}
    if "dt" not in columns and len(rows) > 0:
        t = columns["time"]
        columns["dt"] = np.diff(np.concatenate(([t[0] - (t[1] - t[0]) if len(t) > 1 else 0.0], t)))
    return columns, path


def column(columns, name, path):
    if name not in columns:
        fluxes = sorted({n[len("flux_"):-len("_solids_kg_per_s")] for n in columns
                         if n.startswith("flux_") and n.endswith("_solids_kg_per_s")})
        hint = f"; regions in this run: {', '.join(fluxes)}" if fluxes else ""
        raise PostError(f"{path} has no column '{name}'{hint}")
    return columns[name]


def solids_rates(columns, path, region, until=None):
    """(t_end, dt, flux [kg/s], inventory [kg], rows kept) per step, through `until` if given."""
    t = column(columns, "time", path)
    dt = column(columns, "dt", path)
    flux = column(columns, f"flux_{region}_solids_kg_per_s", path)
    inventory = column(columns, "inventory_solids_kg", path)
    keep = np.isfinite(t) & np.isfinite(dt) & np.isfinite(flux)
    if until is not None:
        keep &= t <= until + 1e-12
    return t[keep], dt[keep], flux[keep], inventory[keep], keep


def block_means(t, dt, values, block=BLOCK):
    """Means of a per-step series over blocks of `block` seconds laid back from t[-1].
    Each value holds over its step [t - dt, t]. Returns (edges, means), edges ascending,
    len(edges) = len(means) + 1; a partial block at the start is dropped."""
    if len(t) == 0:
        return np.array([]), np.array([])
    starts = t - dt
    # Cumulative integral at the step ends, piecewise linear within each step.
    knots = np.concatenate(([starts[0]], t))
    cumulative = np.concatenate(([0.0], np.cumsum(values * dt)))
    nblocks = int(np.floor((t[-1] - starts[0]) / block + 1e-9))
    edges = t[-1] - block * np.arange(nblocks, -1, -1)
    integral = np.interp(edges, knots, cumulative)
    return edges, np.diff(integral) / block


def steady_window(t, dt, rate, window_min=0.2, tolerance=0.05, block=BLOCK):
    """The steady window of a per-step rate series (see the module docstring).
    Returns a dict: start, end, duration, mean, std, min, max (of the block means in the window),
    blocks, reference, first_block (index into edges/means), edges, means."""
    if window_min <= 0 or tolerance <= 0:
        raise PostError("--window-min and --tolerance must be positive")
    edges, means = block_means(t, dt, rate, block)
    span = (t[-1] - (t[0] - dt[0])) if len(t) else 0.0
    nref = int(np.ceil(window_min / block - 1e-9))
    if len(means) < nref + 1:
        raise PostError(f"the series covers {span:.3g} s, too short for a steady window of "
                        f"--window-min {window_min:g} s after a transient "
                        f"(needs more than {(nref + 1) * block:.3g} s of {block:g} s blocks)")
    reference = float(np.mean(means[-nref:]))
    if not reference > 0:
        raise PostError(f"no outflow: the mean rate over the last {window_min:g} s is "
                        f"{reference * 1e3:.4g} g/s")
    band = tolerance * reference
    inside = np.abs(means - reference) <= band
    if not inside[-nref:].all():
        worst = float(np.max(np.abs(means[-nref:] - reference)) / reference)
        raise PostError(f"not steady at the end of the series: over the last {window_min:g} s the "
                        f"{block:g} s block means differ from their mean by up to {100 * worst:.1f} % "
                        f"(tolerance {100 * tolerance:g} %); run longer, or cut a tail with --until")
    first = len(means) - nref
    while first > 0 and inside[first - 1]:
        first -= 1
    window = means[first:]
    start, end = float(edges[first]), float(edges[-1])
    return dict(start=start, end=end, duration=end - start, mean=float(np.mean(window)),
                std=float(np.std(window, ddof=1)) if len(window) > 1 else 0.0,
                min=float(np.min(window)), max=float(np.max(window)), blocks=len(window),
                reference=reference, first_block=first, edges=edges, means=means,
                tolerance=tolerance, block=block,
                note="" if first > 0 else "no transient detected: every full block is within the band")


def inventory_rate(t, inventory, start, end):
    """-d(inventory)/dt averaged over [start, end]: the inventory drop over the window / duration."""
    if not np.isfinite(inventory).all():
        raise PostError("inventory_solids_kg has non-finite values")
    i0 = np.interp(start, t, inventory)
    i1 = np.interp(end, t, inventory)
    return float((i0 - i1) / (end - start))


def discharge(run_dir, region="orifice", window_min=0.2, tolerance=0.05, until=None):
    """Everything discharge-rate prints and plot-mass draws."""
    columns, path = read_monitor(run_dir)
    if len(columns["time"]) == 0:
        raise PostError(f"{path} has a header but no rows")
    t, dt, flux, inventory, keep = solids_rates(columns, path, region, until)
    if len(t) < 2:
        raise PostError(f"{path} has fewer than 2 usable rows")
    window = steady_window(t, dt, flux, window_min, tolerance)
    window["inventory_rate"] = inventory_rate(t, inventory, window["start"], window["end"])
    # All regions' solids fluxes: what the inventory change must balance.
    total = np.zeros_like(t)
    regions = []
    for name in columns:
        if name.startswith("flux_") and name.endswith("_solids_kg_per_s"):
            regions.append(name[len("flux_"):-len("_solids_kg_per_s")])
            total += np.nan_to_num(columns[name][keep])
    edges, totals = block_means(t, dt, total)
    window["all_regions_rate"] = float(np.mean(totals[window["first_block"]:]))
    window["regions"] = regions
    return dict(t=t, dt=dt, flux=flux, inventory=inventory, window=window, path=path)


def solids_mass_balance(columns):
    """|inventory(end) + ∫ outflow dt − inventory(0)| / inventory(0) from monitor columns (all
    regions' solids fluxes; the first row is after the first step)."""
    dt = columns["dt"]
    outflow = sum(columns[n] for n in columns if n.startswith("flux_") and n.endswith("_solids_kg_per_s"))
    inventory = columns["inventory_solids_kg"]
    initial = inventory[0] + outflow[0] * dt[0]
    return abs(inventory[-1] + float(np.sum(outflow * dt)) - initial) / initial


def run_bagnold(bagnold, deck, ranks, sets):
    """`mpirun -np RANKS BAGNOLD run DECK --overwrite --set ...` (root allowed), output captured.
    The tools run each case fresh into a directory of its own, so a rerun replaces it (--keep)."""
    command = ["mpirun", "--oversubscribe", "-np", str(ranks), bagnold, "run", deck, "--overwrite"]
    for s in sets:
        command += ["--set", s]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return subprocess.run(command, capture_output=True, text=True, env=env)


def failure_line(text):
    """Why a `bagnold run` failed: its "bagnold run: failed: ..." line (on stderr, which the
    tools capture apart from stdout), else the output's last line."""
    lines = [l for l in text.strip().splitlines() if l.strip()]
    failed = [l for l in lines if l.startswith("bagnold run: failed:")]
    return failed[-1] if failed else (lines[-1] if lines else "no output")


def list_snapshots(run_dir):
    """[(time, path)] of the run's snapshots, in time order."""
    import h5py

    check_run_dir(run_dir)
    paths = sorted(glob.glob(os.path.join(run_dir, "snapshot_*.h5")))
    if not paths:
        raise PostError(f"no snapshot_*.h5 in '{run_dir}'")
    result = []
    for p in paths:
        try:
            with h5py.File(p, "r") as f:
                result.append((float(f.attrs["time"]), p))
        except (OSError, KeyError) as error:
            raise PostError(f"cannot read the time of {p}: {error}")
    return sorted(result)


def nearest_snapshots(snapshots, times):
    """The snapshot nearest each requested time; refuses times outside the run (more than half
    the median snapshot interval before the first or after the last snapshot)."""
    stamps = np.array([s[0] for s in snapshots])
    slack = 0.5 * float(np.median(np.diff(stamps))) if len(stamps) > 1 else 1e-9
    chosen = []
    for want in times:
        if want < stamps[0] - slack or want > stamps[-1] + slack:
            raise PostError(f"time {want:g} s is outside the run: its snapshots span "
                            f"{stamps[0]:g} to {stamps[-1]:g} s")
        chosen.append(snapshots[int(np.argmin(np.abs(stamps - want)))])
    return chosen
