#!/usr/bin/python3
"""Tests of tools/chute-1d, the 1-D steady inclined-layer solver (report App. C Eqs. 41-49).

1. Bagnold limit. With very stiff particles (k = 1e12 N/m for 1 mm beads, so γ̂ ~ 1e-7) the
   steady-shear rheology is the pure inertial-number law p = ρ_s (γ̇ d)² α_inert/(φ_c - φ)²,
   η = η_hard(I). η = tan θ is uniform, so I* and φ* = φ_c - sqrt(α_inert) I* are uniform and the
   profile is Bagnold's: γ̇ = (I*/d) sqrt(φ* g cos θ (H - y)),
   v(y) = v(0) + (2/3)(I*/d) sqrt(φ* g cos θ) (H^1.5 - (H - y)^1.5).
2. Slip base: v(0) against Eq. 48, ν(0)/(ρ_s d) F(tan θ), with F written out here.
3. The default (soft, k = 1e5 N/m) profile against Bagnold's own C++ closure: at sampled heights
   the `steady-shear` rheometer (tests/unit/models/rheometer_table, path in argv[1] or
   $RHEOMETER_TABLE) must give back the overburden pressure and η = tan θ.
4. Depth and inventory inputs agree; refusals (μ_w < 0.33, tan θ ≤ η_s) exit 1 with the reason.

Run from anywhere: /usr/bin/python3 tests/tools/test_chute_1d.py [RHEOMETER_TABLE]
"""
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOL = os.path.join(ROOT, "tools", "chute-1d")
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
RHEOMETER = os.environ.get("RHEOMETER_TABLE", "")

G = 9.81
D, RHO = 1e-3, 2500.0
# App. A, μ = 0.5: φ_c = 0.587, η_s = 0.382 (Table I-II); α_inert, I_0, α_1, β_1 (Table II).
PHI_C, ETA_S, ALPHA_INERT, I0, ALPHA_1, BETA_1 = 0.587, 0.382, 0.021, 0.32, 0.37, 1.5


def run(*arguments, expect=0):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "profile.csv")
        result = subprocess.run([PYTHON, TOOL, *arguments, "--output", out],
                                capture_output=True, text=True, timeout=60)
        if result.returncode != expect:
            raise AssertionError(f"exit {result.returncode}, expected {expect}:\n"
                                 f"{result.stdout}\n{result.stderr}")
        profile = np.genfromtxt(out, delimiter=",", names=True) if expect == 0 else None
    return profile, result.stdout + result.stderr


def bagnold_inertial_number(theta):
    """I* from η_s + α_1/((I_0/I)^β_1 + 1) = tan θ."""
    return I0 * (ALPHA_1 / (math.tan(theta) - ETA_S) - 1.0) ** (-1.0 / BETA_1)


def apparent_slip(tan_theta, wall_friction, friction=0.5, restitution=0.8):
    """F(η) of App. C, Eqs. 13-15, 19, 22, 26-28, 31, written out independently."""
    x = (tan_theta - ETA_S) / (wall_friction + 0.33 - ETA_S)
    i_surf = 1.55 * x ** (2 / 3) / (1 - x) ** 5.25
    e_eff = restitution - 1.5 * friction * math.exp(-3 * friction)
    m_prime = 23.4 * (1 - e_eff**2) * math.atan(6 * (wall_friction / ETA_S - 1))
    m = 1 / (1 - math.exp(-6 * friction)) ** 2
    i_layer = m_prime * (tan_theta - ETA_S)
    return i_surf + m * i_layer + i_layer


class BagnoldLimit(unittest.TestCase):
    ANGLE, DEPTH = 25.0, 0.02  # 20 d

    def test_no_slip_profile_is_bagnolds(self):
        theta = math.radians(self.ANGLE)
        profile, _ = run("--angle", str(self.ANGLE), "--depth", str(self.DEPTH), "--stiffness", "1e12")
        i_star = bagnold_inertial_number(theta)
        phi_star = PHI_C - math.sqrt(ALPHA_INERT) * i_star
        y = profile["y"]
        depth_below = self.DEPTH - y
        scale = (i_star / D) * math.sqrt(phi_star * G * math.cos(theta))
        rate = scale * np.sqrt(depth_below)
        velocity = (2 / 3) * scale * (self.DEPTH**1.5 - depth_below**1.5)
        v_surface = velocity[-1]
        # φ* = 0.5664; the harmonic blend's share p_inert/p_int ~ 1e-8 here, the quadrature ~1e-6.
        pressure = RHO * phi_star * G * math.cos(theta) * depth_below
        errors = {"phi": np.max(np.abs(profile["phi"] - phi_star)),
                  "velocity": np.max(np.abs(profile["velocity_x"] - velocity)) / v_surface,
                  "shear_rate": np.max(np.abs(profile["shear_rate"] - rate)) / rate[0],
                  "pressure": np.max(np.abs(profile["pressure"] - pressure)) / pressure[0]}
        self.assertLess(errors["phi"], 1e-5)
        self.assertLess(errors["velocity"], 1e-4)
        self.assertLess(errors["shear_rate"], 1e-4)
        self.assertLess(errors["pressure"], 1e-5)
        self.assertEqual(profile["velocity_x"][0], 0.0)
        print(f"\nBagnold limit: v_surface {profile['velocity_x'][-1]:.6f} m/s (exact {v_surface:.6f}); "
              "largest errors: " + ", ".join(f"{k} {v:.1e}" for k, v in errors.items()))

    def test_slip_base_follows_eq48(self):
        theta = math.radians(self.ANGLE)
        profile, text = run("--angle", str(self.ANGLE), "--depth", str(self.DEPTH), "--stiffness", "1e12",
                            "--base", "slip", "--wall-friction", "0.5")
        i_star = bagnold_inertial_number(theta)
        phi_star = PHI_C - math.sqrt(ALPHA_INERT) * i_star
        base_pressure = RHO * phi_star * G * math.cos(theta) * self.DEPTH
        base_rate = i_star * math.sqrt(base_pressure / RHO) / D
        viscosity = math.tan(theta) * base_pressure / base_rate  # ν(0) = τ(0)/γ̇(0)
        slip = viscosity / (RHO * D) * apparent_slip(math.tan(theta), 0.5)  # Eq. 48
        self.assertAlmostEqual(profile["velocity_x"][0] / slip, 1.0, delta=1e-5)
        no_slip, _ = run("--angle", str(self.ANGLE), "--depth", str(self.DEPTH), "--stiffness", "1e12")
        # The slip shifts the whole profile: the rheology is local and the stresses unchanged.
        shifted = profile["velocity_x"] - profile["velocity_x"][0]
        self.assertLess(np.max(np.abs(shifted - no_slip["velocity_x"])), 1e-8)  # CSV: 11 digits of ~5 m/s
        self.assertIn("slip velocity", text)
        print(f"\nslip base: v(0) {profile['velocity_x'][0]:.6f} m/s (Eq. 48: {slip:.6f})")

    def test_no_flow_below_yield_and_refused_wall_friction(self):
        _, text = run("--angle", "20", "--depth", "0.02", expect=1)  # tan 20° = 0.364 < 0.382
        self.assertIn("eta_s", text)
        _, text = run("--angle", "25", "--depth", "0.02", "--base", "slip", "--wall-friction", "0.2",
                      expect=2)
        self.assertIn("0.33", text)


class SoftParticles(unittest.TestCase):
    def test_depth_and_inventory_agree(self):
        by_depth, text = run("--angle", "24", "--depth", "0.03")
        inventory = float(text.split("inventory")[1].split()[0])
        by_mass, _ = run("--angle", "24", "--inventory", repr(inventory))
        self.assertAlmostEqual(by_mass["y"][-1] / 0.03, 1.0, delta=1e-5)
        self.assertAlmostEqual(by_mass["velocity_x"][-1] / by_depth["velocity_x"][-1], 1.0, delta=1e-4)

    def test_profile_satisfies_bagnolds_steady_shear_closure(self):
        if not (RHEOMETER and os.path.exists(RHEOMETER)):
            self.skipTest("rheometer_table not given")
        angle = 24.0
        profile, _ = run("--angle", str(angle), "--depth", "0.05")
        tan_theta = math.tan(math.radians(angle))
        for index in np.linspace(0, len(profile) - 20, 6).astype(int):
            phi, rate, pressure = profile["phi"][index], profile["shear_rate"][index], profile["pressure"][index]
            out = subprocess.run([RHEOMETER, "steady-shear", "--phi", repr(phi), "--shear-rate", repr(rate),
                                  "--set", "solids.friction=0.5", "--set", "solids.diameter=1e-3",
                                  "--set", "solids.density=2500", "--set", "solids.stiffness=1e5",
                                  "--set", "min_strain_rate=0", "--set", "max_viscosity=1e300"],
                                 capture_output=True, text=True, check=True).stdout.strip().splitlines()
            row = dict(zip(out[0].split(","), out[1].split(",")))
            row = {key: float(row[key]) for key in ("pressure", "stress_ratio")}
            self.assertAlmostEqual(row["pressure"] / pressure, 1.0, delta=1e-6, msg=f"y index {index}")
            self.assertAlmostEqual(row["stress_ratio"], tan_theta, delta=1e-7, msg=f"y index {index}")


if __name__ == "__main__":
    if len(sys.argv) > 1 and not sys.argv[1].startswith("-"):
        RHEOMETER = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=2)
