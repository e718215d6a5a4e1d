#!/usr/bin/python3
"""Tests of tools/discharge-rate, tools/plot-mass and tools/plot-slice on synthetic run directories.

Builds, in a temporary directory, a monitor.csv with a known transient followed by a steady solids
discharge of 165 g/s plus noise, and small HDF5 snapshots in the layout of docs/output.md, then runs
the tools as a user does. Run from the source root: /usr/bin/python3 tests/tools/test_post_processing.py
(keep the temporary directory with BAGNOLD_KEEP_TMP=1).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOLS = os.path.join(ROOT, "tools")
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable

STEADY = 0.165  # kg/s
OVERSHOOT, TAU_RISE, TAU_PEAK = 0.060, 0.02, 0.05  # kg/s, s, s
NOISE = 0.008  # kg/s per step (about 5 %)
END = 1.5  # s
REGIONS = ("orifice", "top", "walls")


def synthetic_rate(t):
    """Known solids flux through the orifice: a rise from 0 with an overshoot, then 165 g/s."""
    x = t / TAU_PEAK
    return STEADY * (1.0 - np.exp(-t / TAU_RISE)) + OVERSHOOT * x * np.exp(1.0 - x)


def transient_end(tolerance=0.05):
    """Last time the noise-free rate is more than `tolerance` away from the steady value."""
    t = np.linspace(0.0, END, 150001)
    off = np.abs(synthetic_rate(t) - STEADY) > tolerance * STEADY
    return float(t[np.nonzero(off)[0][-1]])


def write_monitor(run_dir, end=END, rate=synthetic_rate, seed=1, columns=None):
    """monitor.csv with uneven steps (0.5 to 1.5 ms); inventory = initial mass - integral of the flux."""
    rng = np.random.default_rng(seed)
    dts = rng.uniform(0.5e-3, 1.5e-3, int(2 * end / 1e-3) + 10)
    t = np.cumsum(dts)
    keep = t <= end
    t, dts = t[keep], dts[keep]
    flux = rate(t - 0.5 * dts) + NOISE * rng.standard_normal(len(t))
    solids = 1.16 - np.cumsum(flux * dts)
    gas = 1.9e-3 - 1e-6 * t
    names = columns or (["time", "dt", "iterations", "residual", "inventory_gas_kg", "inventory_solids_kg"]
                        + [f"flux_{r}_{p}_kg_per_s" for r in REGIONS for p in ("gas", "solids")])
    os.makedirs(run_dir, exist_ok=True)
    with open(os.path.join(run_dir, "monitor.csv"), "w") as f:
        f.write(",".join(names) + "\n")
        for i in range(len(t)):
            values = {"time": t[i], "dt": dts[i], "iterations": 4 + i % 3, "residual": 1e-7,
                      "inventory_gas_kg": gas[i], "inventory_solids_kg": solids[i],
                      "flux_orifice_gas_kg_per_s": 1e-5, "flux_orifice_solids_kg_per_s": flux[i],
                      "flux_top_gas_kg_per_s": -1e-5, "flux_top_solids_kg_per_s": 0.0,
                      "flux_walls_gas_kg_per_s": 0.0, "flux_walls_solids_kg_per_s": 0.0}
            f.write(",".join(f"{values[n]:.17g}" for n in names) + "\n")
    return t, flux, solids


def write_snapshots(run_dir, times=(0.0, 0.5, 1.0, 1.5)):
    """Small snapshots of a bin-like domain: 4 x 4 x 20 cm, 8 x 8 x 40 cells, a wedge of blocked
    cells at the bottom (NaN in the fields) and a falling solids level."""
    nx, ny, nz = 8, 8, 40
    xf, yf, zf = np.linspace(0, 0.04, nx + 1), np.linspace(0, 0.04, ny + 1), np.linspace(0, 0.2, nz + 1)
    xc, zc = 0.5 * (xf[1:] + xf[:-1]), 0.5 * (zf[1:] + zf[:-1])
    Z, Y, X = np.meshgrid(zc, 0.5 * (yf[1:] + yf[:-1]), xc, indexing="ij")
    fluid = Z > 0.02 + 0.5 * np.abs(X - 0.02)  # funnel: blocked below the wedge
    flags = np.where(fluid, 1, 0).astype(np.uint8)
    os.makedirs(run_dir, exist_ok=True)
    for step, time in enumerate(times):
        level = 0.15 - 0.05 * time
        eps = np.where(Z < level, 0.58, 0.02) * (1.0 - 0.3 * np.exp(-((X - 0.02) / 0.006) ** 2) * time / 1.5)
        fields = {"solids_fraction": eps, "gas_fraction": 1.0 - eps,
                  "gas_pressure": 101325.0 + 2500 * 9.81 * eps * (0.2 - Z),
                  "solids_velocity_z": -0.1 * time * np.exp(-((X - 0.02) / 0.008) ** 2)}
        with h5py.File(os.path.join(run_dir, f"snapshot_{step:06d}.h5"), "w") as f:
            f.attrs.update(time=time, step=step * 500, dt=1e-3, format_version=1,
                           bagnold_version="test", title="synthetic bin")
            for name, faces in (("x_faces", xf), ("y_faces", yf), ("z_faces", zf)):
                f[f"grid/{name}"] = faces
            f["grid/cell_flags"] = flags
            for name, value in fields.items():
                f[f"fields/{name}"] = np.where(fluid, value, np.nan)
                f[f"fields/{name}"].attrs["centering"] = "z_face" if name.endswith("_z") else "cell"


def run(tool, *args):
    """Runs a tool; returns (exit status, stdout, stderr)."""
    result = subprocess.run([PYTHON, os.path.join(TOOLS, tool), *map(str, args)],
                            capture_output=True, text=True, cwd=ROOT, timeout=300)
    return result.returncode, result.stdout, result.stderr


def read_png(test, path):
    test.assertTrue(os.path.isfile(path), f"{path} was not written")
    test.assertGreater(os.path.getsize(path), 10000, f"{path} is suspiciously small")
    image = plt.imread(path)
    test.assertEqual(image.ndim, 3)
    test.assertGreater(image.shape[0], 200)
    test.assertGreater(image.shape[1], 200)
    test.assertGreater(float(np.std(image[..., :3])), 0.01, f"{path} is blank")
    return image


class PostProcessing(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="bagnold_tools_")
        cls.run_dir = os.path.join(cls.tmp, "run")
        cls.t, cls.flux, cls.solids = write_monitor(cls.run_dir)
        write_snapshots(cls.run_dir)

    @classmethod
    def tearDownClass(cls):
        if os.environ.get("BAGNOLD_KEEP_TMP"):
            print(f"kept {cls.tmp}", file=sys.stderr)
        else:
            shutil.rmtree(cls.tmp)

    def assert_fails(self, tool, *args, message):
        code, out, err = run(tool, *args)
        self.assertNotEqual(code, 0, f"{tool} {args} should fail; stdout:\n{out}")
        self.assertRegex(err, message, f"{tool} {args}: unexpected message")
        self.assertNotIn("Traceback", err)
        return err

    # discharge-rate ---------------------------------------------------------------------------

    def discharge(self, *args):
        code, out, err = run("discharge-rate", self.run_dir, *args)
        self.assertEqual(code, 0, err)
        return out

    def test_discharge_rate(self):
        out = self.discharge()
        last = out.rstrip("\n").split("\n")[-1]
        self.assertRegex(last, r"^discharge_rate_g_per_s = [0-9.eE+-]+$")
        rate = float(last.split(" = ")[1])
        print(f"\ndischarge rate {rate} g/s (synthetic {STEADY * 1e3} g/s, "
              f"{100 * (rate / (STEADY * 1e3) - 1):+.3f} %)", file=sys.stderr)
        self.assertLess(abs(rate / (STEADY * 1e3) - 1.0), 0.005)

        window = re.search(r"window: start ([0-9.]+) s, end ([0-9.]+) s, duration ([0-9.]+) s", out)
        self.assertIsNotNone(window, out)
        start, end, duration = map(float, window.groups())
        print(f"window {start} to {end} s; transient ends at {transient_end():.4f} s", file=sys.stderr)
        self.assertGreaterEqual(start, transient_end() - 0.05)  # at most one block into the 5 % tail
        self.assertLess(start, transient_end() + 0.15)          # and not far after it
        self.assertAlmostEqual(end, self.t[-1], delta=1e-4)  # printed to 0.1 ms
        self.assertAlmostEqual(duration, end - start, places=3)

        spread = re.search(r"std ([0-9.]+) g/s .*min ([0-9.]+) g/s, max ([0-9.]+) g/s", out)
        self.assertIsNotNone(spread, out)
        std, low, high = map(float, spread.groups())
        self.assertTrue(0 < std < 0.05 * rate and low < rate < high, out)

        inventory = float(re.search(r"-d\(inventory_solids\)/dt over the window = ([0-9.]+) g/s", out).group(1))
        print(f"inventory cross-check {inventory} g/s", file=sys.stderr)
        self.assertLess(abs(inventory / rate - 1.0), 0.005)
        self.assertIn("discharge-rate", out.split("\n")[0])  # the reproducing command

    def test_discharge_rate_until_and_options(self):
        out = self.discharge("--until", 1.0, "--window-min", 0.3, "--region", "orifice")
        rate = float(out.rstrip().split("\n")[-1].split(" = ")[1])
        self.assertLess(abs(rate / (STEADY * 1e3) - 1.0), 0.005)
        self.assertRegex(out, r"end 1\.0000 s|end 0\.99\d\d s")
        self.assertIn("--until 1.0", out.split("\n")[0])

    def test_discharge_rate_torn_last_line(self):
        """A running job's monitor may end in a half-written row: it is skipped."""
        torn = os.path.join(self.tmp, "torn_run")
        os.makedirs(torn, exist_ok=True)
        shutil.copy(os.path.join(self.run_dir, "monitor.csv"), torn)
        with open(os.path.join(torn, "monitor.csv"), "a") as f:
            f.write("1.5011,0.0012,4,1e-0")
        code, out, err = run("discharge-rate", torn)
        self.assertEqual(code, 0, err)
        self.assertEqual(out.rstrip().split("\n")[-1], self.discharge().rstrip().split("\n")[-1])

    def test_discharge_rate_bad_inputs(self):
        missing = os.path.join(self.tmp, "no_such_run")
        self.assert_fails("discharge-rate", missing, message="does not exist")
        empty = os.path.join(self.tmp, "empty_run")
        os.makedirs(empty, exist_ok=True)
        self.assert_fails("discharge-rate", empty, message="no monitor.csv")
        self.assert_fails("discharge-rate", self.run_dir, "--region", "nozzle",
                          message="no column 'flux_nozzle_solids_kg_per_s'.*orifice, top, walls")
        short = os.path.join(self.tmp, "short_run")
        write_monitor(short, end=0.15)
        self.assert_fails("discharge-rate", short, message="too short")
        ramp = os.path.join(self.tmp, "ramp_run")
        write_monitor(ramp, rate=lambda t: 0.1 * t)
        self.assert_fails("discharge-rate", ramp, message="not steady at the end")
        no_flux = os.path.join(self.tmp, "no_flux_run")
        write_monitor(no_flux, columns=["time", "dt", "iterations", "residual", "inventory_gas_kg",
                                        "inventory_solids_kg"])
        self.assert_fails("discharge-rate", no_flux, message="no column")
        header_only = os.path.join(self.tmp, "header_only")
        os.makedirs(header_only, exist_ok=True)
        with open(os.path.join(header_only, "monitor.csv"), "w") as f:
            f.write("time,dt,inventory_solids_kg,flux_orifice_solids_kg_per_s\n")
        self.assert_fails("discharge-rate", header_only, message="no rows")
        self.assert_fails("discharge-rate", self.run_dir, "--window-min", "abc", message="invalid float")

    def test_help(self):
        for tool in ("discharge-rate", "plot-mass", "plot-slice"):
            code, out, err = run(tool, "--help")
            self.assertEqual(code, 0, err)
            self.assertIn("usage:", out)
        self.assertIn("Steady window", run("discharge-rate", "--help")[1])

    # plot-mass --------------------------------------------------------------------------------

    def test_plot_mass(self):
        png = os.path.join(self.tmp, "mass.png")
        code, out, err = run("plot-mass", self.run_dir, "--output", png)
        self.assertEqual(code, 0, err)
        read_png(self, png)
        self.assertIn("plot-mass", out)
        self.assertRegex(out, r"window: start [0-9.]+ s")
        # Default output name, inside the run directory.
        code, out, err = run("plot-mass", self.run_dir)
        self.assertEqual(code, 0, err)
        read_png(self, os.path.join(self.run_dir, "mass.png"))

    def test_plot_mass_bad_inputs(self):
        self.assert_fails("plot-mass", os.path.join(self.tmp, "no_such_run"), message="does not exist")
        self.assert_fails("plot-mass", self.run_dir, "--region", "nozzle", message="no column")
        self.assert_fails("plot-mass", self.run_dir, "--output", os.path.join(self.tmp, "mass.pdf"),
                          message=r"\.png")

    # plot-slice -------------------------------------------------------------------------------

    def test_plot_slice(self):
        png = os.path.join(self.tmp, "slice.png")
        code, out, err = run("plot-slice", self.run_dir, "--times", "0,0.5,1.0", "--output", png)
        self.assertEqual(code, 0, err)
        read_png(self, png)
        self.assertIn("plot-slice", out)
        self.assertIn("snapshot_000002.h5", out)  # t = 1.0
        png2 = os.path.join(self.tmp, "slice_x.png")
        code, out, err = run("plot-slice", self.run_dir, "--times", "1.4", "--field", "gas_pressure",
                             "--axis", "x", "--at", "0.01", "--output", png2)
        self.assertEqual(code, 0, err)
        read_png(self, png2)
        self.assertIn("snapshot_000003.h5", out)  # nearest to 1.4 is 1.5
        code, out, err = run("plot-slice", self.run_dir, "--times", "1.0", "--range=-0.25,0.1",
                             "--output", png2)
        self.assertEqual(code, 0, err)
        self.assertIn("colour scale -0.25 to 0.1", out)

    def test_plot_slice_bad_inputs(self):
        out = os.path.join(self.tmp, "bad.png")
        self.assert_fails("plot-slice", self.run_dir, "--times", "0,0.5", "--field", "vorticity",
                          "--output", out, message="no field 'vorticity'.*solids_fraction")
        self.assert_fails("plot-slice", self.run_dir, "--times", "0,5.0", "--output", out,
                          message="outside the run")
        self.assert_fails("plot-slice", self.run_dir, "--times", "-1", "--output", out,
                          message="outside the run")
        self.assert_fails("plot-slice", self.run_dir, "--times", "zero", "--output", out,
                          message="--times")
        self.assert_fails("plot-slice", self.run_dir, "--times", "0", "--at", "0.5", "--output", out,
                          message="outside the domain")
        self.assert_fails("plot-slice", self.run_dir, "--times", "0", "--axis", "z", "--output", out,
                          message="invalid choice")
        self.assert_fails("plot-slice", self.run_dir, "--times", "0", "--range", "0.6", "--output", out,
                          message="--range wants MIN,MAX")
        self.assert_fails("plot-slice", self.run_dir, "--times", "0", "--range", "0.6,0", "--output", out,
                          message="MIN < MAX")
        self.assert_fails("plot-slice", os.path.join(self.tmp, "empty_run2"), "--times", "0",
                          message="does not exist")
        os.makedirs(os.path.join(self.tmp, "no_snapshots"), exist_ok=True)
        self.assert_fails("plot-slice", os.path.join(self.tmp, "no_snapshots"), "--times", "0",
                          message="no snapshot")
        self.assertFalse(os.path.exists(out))


class CompareMonitors(unittest.TestCase):
    """tools/compare-monitors: each column against its largest |value|, a vector's components
    against the vector's."""

    def write(self, folder, rows):
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(folder, "monitor.csv"), "w") as f:
            f.write("time,dt,wall_shear_solids_x_N,wall_shear_solids_y_N,wall_shear_solids_z_N\n")
            for row in rows:
                f.write(",".join(f"{v:.17g}" for v in row) + "\n")

    def test_round_off_in_a_vector_component(self):
        with tempfile.TemporaryDirectory() as tmp:
            a, b, c = (os.path.join(tmp, n) for n in "abc")
            self.write(a, [[0.1, 0.1, 2.0, 1e-16, -30.0], [0.2, 0.1, 2.5, -2e-16, -31.0]])
            # y is zero but for round-off in both: its difference is measured against |z|.
            self.write(b, [[0.1, 0.1, 2.0, -3e-16, -30.0], [0.2, 0.1, 2.5, 1e-16, -31.0]])
            code, out, _ = run("compare-monitors", a, b, "--tolerance", "1e-9")
            self.assertEqual(code, 0, out)
            # A difference of 1e-3 of the vector in one component fails.
            self.write(c, [[0.1, 0.1, 2.0, 0.031, -30.0], [0.2, 0.1, 2.5, 0.0, -31.0]])
            code, out, _ = run("compare-monitors", a, c, "--tolerance", "1e-4")
            self.assertEqual(code, 1, out)
            self.assertIn("FAIL", out)


if __name__ == "__main__":
    unittest.main(verbosity=2)
