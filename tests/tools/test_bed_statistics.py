#!/usr/bin/python3
"""Tests of tools/bed-statistics on a synthetic 2-D bed whose statistics are known by construction.

A 0.2 × 1 m column of 20 × 100 cells, one cell thick. At t = 0 a bed of ε_s = 0.55 fills it to
0.5 m (H0); later snapshots have their bed surface on chosen faces, two bubbles (a 6 × 6-cell
square centred at mid-bed, a 2 × 2-cell one near the top) and an erupting void at the surface,
which is not a bubble. monitor.csv carries a pressure drop of the bed's weight per area plus a
3 Hz oscillation, on uneven steps. Run from the source root:
/usr/bin/python3 tests/tools/test_bed_statistics.py (keep the files with BAGNOLD_KEEP_TMP=1).
"""
import os
import shutil
import sys
import tempfile
import unittest

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_post_processing import read_png, run  # noqa: E402

NX, NZ = 20, 100
XF, YF, ZF = np.linspace(-0.1, 0.1, NX + 1), np.array([0.0, 0.01]), np.linspace(0.0, 1.0, NZ + 1)
TIMES = [0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0]
SURFACE = {0.0: 50, 0.25: 56, 0.5: 60, 0.75: 62, 1.0: 58, 1.25: 61, 1.5: 59, 1.75: 63, 2.0: 60}  # layers
PHI, RHO_S, G = 0.55, 2000.0, 9.81
SOLIDS_KG = RHO_S * PHI * 0.2 * 0.01 * 0.5
WEIGHT = G * SOLIDS_KG / (0.2 * 0.01)  # Pa
FREQUENCY = 3.0  # Hz
MID_SQUARE = 6  # cells a side
RHO_G = 1.2
# The probe spans z = 5 mm to 995 mm: the bed below the surface, gas above.
DECK = ("[physics]\ngravity = [0.0, 0.0, -9.81]\n[gas]\ndensity = 1.2\n[solids]\ndensity = 2000.0\n"
        "[[pressure_probe]]\nname = \"bed\"\nlower = [0.0, 0.005, 0.005]\nupper = [0.0, 0.005, 0.995]\n")


# The balance run's snapshots also carry a uniform solids velocity RISE × t and a P_s falling
# linearly from PS_FLOOR in the first layer to 0 in layer 10; its monitor the walls' shear.
RISE, PS_FLOOR, WALL_SOLIDS, WALL_GAS = 0.04, 30.0, 0.05, 0.002  # m/s², Pa, N, N


def write_snapshots(run_dir, balance=False):
    os.makedirs(run_dir, exist_ok=True)
    for step, time in enumerate(TIMES):
        phi = np.zeros((NZ, 1, NX))
        top = SURFACE[time]
        phi[:top] = PHI
        if time > 0.0:
            phi[22:22 + MID_SQUARE, 0, 5:5 + MID_SQUARE] = 0.0  # centroid z = 0.25 m, x = −0.02 m
            phi[44:46, 0, 14:16] = 0.05                          # centroid z = 0.45 m
            phi[top - 2:top, 0, 1] = 0.05                        # erupting: reaches the surface
        with h5py.File(os.path.join(run_dir, f"snapshot_{step:06d}.h5"), "w") as f:
            f.attrs.update(time=time, step=step * 100, dt=1e-3, format_version=1,
                           bagnold_version="test", title="synthetic bed", deck=DECK)
            for name, faces in (("x_faces", XF), ("y_faces", YF), ("z_faces", ZF)):
                f[f"grid/{name}"] = faces
            f["grid/cell_flags"] = np.ones((NZ, 1, NX), dtype=np.uint8)
            f["fields/solids_fraction"] = phi
            f["fields/gas_fraction"] = 1.0 - phi
            if balance:
                f["fields/solids_velocity_z"] = np.full(phi.shape, RISE * time)
                f["fields/gas_velocity_z"] = np.zeros(phi.shape)
                layers = np.clip(PS_FLOOR * (1.0 - np.arange(NZ) / 10.0), 0.0, None)
                f["fields/solids_pressure"] = np.broadcast_to(layers[:, None, None], phi.shape).copy()


def write_monitor(run_dir, probes=("bed",), wall_shear=False):
    rng = np.random.default_rng(3)
    dts = rng.uniform(0.8e-3, 1.2e-3, 2600)
    t = np.cumsum(dts)
    keep = t <= 2.0
    t, dts = t[keep], dts[keep]
    dp = WEIGHT * (1.0 + 0.02 * np.sin(2 * np.pi * FREQUENCY * t))
    names = ["time", "dt", "inventory_solids_kg"] + [f"dp_{p}" for p in probes]
    walls = [WALL_GAS, WALL_SOLIDS] if wall_shear else []
    if wall_shear:
        names += ["wall_shear_gas_z_N", "wall_shear_solids_z_N"]
    with open(os.path.join(run_dir, "monitor.csv"), "w") as f:
        f.write(",".join(names) + "\n")
        for i in range(len(t)):
            f.write(",".join(f"{v:.17g}" for v in [t[i], dts[i], SOLIDS_KG] + [dp[i]] * len(probes) + walls) + "\n")
    return t, dts, dp


def last_lines(out):
    values = {}
    for line in out.splitlines():
        if " = " in line and line.split(" = ")[0].isidentifier():
            key, value = line.split(" = ")
            values[key] = float(value)
    return values


class BedStatistics(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="bagnold_bed_")
        cls.run_dir = os.path.join(cls.tmp, "run")
        write_snapshots(cls.run_dir)
        cls.t, cls.dt, cls.dp = write_monitor(cls.run_dir)

    @classmethod
    def tearDownClass(cls):
        if os.environ.get("BAGNOLD_KEEP_TMP"):
            print(f"kept {cls.tmp}", file=sys.stderr)
        else:
            shutil.rmtree(cls.tmp)

    def statistics(self, *args, run_dir=None):
        code, out, err = run("bed-statistics", run_dir or self.run_dir, *args)
        self.assertEqual(code, 0, err)
        self.assertNotIn("Traceback", err)
        return last_lines(out), out

    def test_known_statistics(self):
        values, out = self.statistics("--darton", "0.25,0.06")
        self.assertEqual(values["bed_height_H0_m"], 0.5)
        window = [SURFACE[t] * 0.01 / 0.5 for t in TIMES if t >= 0.5]
        self.assertAlmostEqual(values["mean_expansion_H_over_H0"], np.mean(window), places=5)
        self.assertEqual(values["bubbles_per_snapshot"], 2.0)  # not the erupting void
        square = MID_SQUARE * 0.01
        self.assertAlmostEqual(values["mid_bed_bubble_diameter_m"], np.sqrt(4 * square ** 2 / np.pi), places=5)
        keep = (self.t > 0.5) & (self.t <= 2.0)
        mean = np.sum(self.dp[keep] * self.dt[keep]) / np.sum(self.dt[keep])
        self.assertAlmostEqual(values["mean_pressure_drop_Pa"], mean, places=2)
        self.assertAlmostEqual(values["pressure_drop_over_weight"], mean / WEIGHT, places=6)
        # Between 5 and 995 mm: each snapshot's layers' mean ε_s (the bubbles lower it).
        between = []
        for t in (t for t in TIMES if t >= 0.5):
            top, column = SURFACE[t] * 0.01, []
            solids = PHI * (top - 0.005) * 0.2 - 0.06 * 0.06 * PHI - 0.02 * 0.02 * (PHI - 0.05) \
                - 0.02 * 0.01 * (PHI - 0.05)  # ε_s · area in the x–z plane, less the voids
            solids_per_width = solids / 0.2
            between.append(G * (RHO_S * solids_per_width + RHO_G * (0.99 - solids_per_width)))
        # (the key lines carry 6 significant digits)
        self.assertLess(abs(values["weight_between_probe_ends_Pa"] / np.mean(between) - 1.0), 1e-5)
        self.assertLess(abs(values["pressure_drop_over_weight_between"] * np.mean(between) / mean - 1.0), 1e-5)
        self.assertLessEqual(abs(values["dominant_frequency_Hz"] - FREQUENCY), 1.0 / 1.5)
        darton = 0.54 * 0.19 ** 0.4 * 0.25 ** 0.8 / G ** 0.2
        self.assertIn(f"D = {darton:.4g} m", out)

    def test_momentum_balance(self):
        # Without the walls' shear in monitor.csv there is no balance.
        values, _ = self.statistics()
        self.assertTrue(np.isnan(values["momentum_balance_residual"]))
        run_dir = os.path.join(self.tmp, "balance")
        write_snapshots(run_dir, balance=True)
        write_monitor(run_dir, wall_shear=True)
        values, out = self.statistics(run_dir=run_dir)
        area = 0.2 * 0.01
        self.assertAlmostEqual(values["wall_support_Pa"], (WALL_SOLIDS + WALL_GAS) / area, places=4)
        # P_s at 5 mm (the first layer's centre) less that at 995 mm.
        self.assertAlmostEqual(values["solids_pressure_difference_Pa"], PS_FLOOR, places=4)
        # The z-momentum of the solids between the probe's heights (from 5 mm: half the first
        # layer) at 2 s less that at 0.5 s (the window's snapshots), over 1.5 s.
        def solids_kg(t):
            top = SURFACE[t] * 0.01
            per_width = PHI * (top - 0.005) * 0.2 - 0.06 * 0.06 * PHI - 0.02 * 0.02 * (PHI - 0.05) \
                - 0.02 * 0.01 * (PHI - 0.05)
            return RHO_S * per_width * 0.01
        change = (solids_kg(2.0) * RISE * 2.0 - solids_kg(0.5) * RISE * 0.5) / 1.5 / area
        self.assertLess(abs(values["momentum_change_Pa"] / change - 1.0), 1e-5)
        expected = (values["mean_pressure_drop_Pa"] + PS_FLOOR + (WALL_SOLIDS + WALL_GAS) / area - change
                    - values["weight_between_probe_ends_Pa"]) / values["weight_between_probe_ends_Pa"]
        self.assertAlmostEqual(values["momentum_balance_residual"], expected, places=5)
        self.assertIn("momentum balance between the probe's ends", out)

    def test_window_and_thresholds(self):
        values, _ = self.statistics("--start", "1.0", "--end", "1.5")
        self.assertAlmostEqual(values["mean_expansion_H_over_H0"], (0.58 + 0.61 + 0.59) / 1.5, places=5)
        # A bubble threshold below the small bubble's 0.05 leaves only the mid-bed square.
        values, _ = self.statistics("--bubble-threshold", "0.01")
        self.assertEqual(values["bubbles_per_snapshot"], 1.0)
        # A mid-bed band of ±0.25 m takes in the small bubble (centroid 0.45 m) too.
        values, _ = self.statistics("--mid-band", "0.5")
        both = 0.5 * (np.sqrt(4 * 0.06 ** 2 / np.pi) + np.sqrt(4 * 0.02 ** 2 / np.pi))
        self.assertAlmostEqual(values["mid_bed_bubble_diameter_m"], both, places=5)

    def test_figures(self):
        folder = os.path.join(self.tmp, "figures")
        self.statistics("--figures", folder)
        for name in ("bed-height.png", "pressure-drop.png", "solids-fraction.png"):
            read_png(self, os.path.join(folder, name))

    def test_bad_inputs(self):
        code, _, err = run("bed-statistics", os.path.join(self.tmp, "missing"))
        self.assertEqual(code, 1)
        self.assertIn("does not exist", err)
        code, _, err = run("bed-statistics", self.run_dir, "--start", "5")
        self.assertEqual(code, 1)
        self.assertIn("no snapshot in the window", err)
        code, _, err = run("bed-statistics", self.run_dir, "--probe", "riser")
        self.assertEqual(code, 1)
        self.assertIn("dp_riser", err)
        two = os.path.join(self.tmp, "two_probes")
        write_snapshots(two)
        write_monitor(two, probes=("bed", "freeboard"))
        code, _, err = run("bed-statistics", two)
        self.assertEqual(code, 1)
        self.assertIn("choose one with --probe", err)
        self.assertNotIn("Traceback", err)
        values, _ = self.statistics("--probe", "freeboard", run_dir=two)
        self.assertTrue(np.isfinite(values["mean_pressure_drop_Pa"]))


if __name__ == "__main__":
    unittest.main()
