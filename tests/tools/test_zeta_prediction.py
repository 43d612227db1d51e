#!/usr/bin/env python3
"""tools/zeta_prediction.py: the agreement flag against hand-made zeta.csv rows, the notes for studies it cannot
use, and (given a dpdrng binary) a real CI-size study, study/ci.toml, run and reported: the tool's table, the
report's error budget and its per-round figures (the paper's Figs. 3a, 4b, 4d, 5b, 6b).

Usage: test_zeta_prediction.py SOURCE_DIR [DPDRNG SCRATCH_DIR]
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

SOURCE, DPDRNG, SCRATCH = sys.argv[1], (sys.argv[2] if len(sys.argv) > 2 else None), \
    (sys.argv[3] if len(sys.argv) > 3 else None)
TOOL = os.path.join(SOURCE, "tools", "zeta_prediction.py")

HEADER = ("generator,rounds,distribution,feed,seeding,dt,replicas,power_predicted_T_shift,power_predicted_T_shift_se,"
          "power_lags,measured_T_shift,measured_T_shift_sigma,measured_T_shift_ci_low,measured_T_shift_ci_high,"
          "integrator\n")


def run_tool(results):
    r = subprocess.run([sys.executable, TOOL, results], capture_output=True, text=True)
    return r.returncode, r.stderr


def table(results):
    with open(os.path.join(results, "zeta_prediction.csv"), newline="") as f:
        return list(csv.DictReader(f))


def study(results, name, zeta_text):
    d = os.path.join(results, name, "report")
    os.makedirs(d)
    open(os.path.join(results, name, "study.toml"), "w").close()
    if zeta_text is not None:
        with open(os.path.join(d, "zeta.csv"), "w") as f:
            f.write(zeta_text)


class HandMade(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.dir)

    def test_agreement_is_the_95_interval_of_the_difference(self):
        # Predicted -3.45 % +- 0.2 % (1 sigma) against measured -3.01 % +- 0.07 %: z = -0.44/0.212 = -2.08, a
        # failure; against -3.30 %, z = -0.71: agreement. The reference row is left out.
        study(self.dir, "w", HEADER +
              "mt19937,1,gauss,halves,stream,0.04,4,0,0.002,5,,,,,\n"
              "tea32,1,gauss,halves,distance,0.04,4,-0.0345,0.002,5,-0.0301,0.0007,-0.0315,-0.0287,\n"
              "tea32,2,gauss,halves,distance,0.04,4,-0.0345,0.002,5,-0.0330,0.0007,-0.0344,-0.0316,mvv:0.5\n")
        self.assertEqual(run_tool(self.dir)[0], 0)
        rows = table(self.dir)
        self.assertEqual([r["variant"] for r in rows], ["tea32(1)", "tea32(2)"])
        self.assertEqual(rows[0]["agreement"], "fails")
        self.assertAlmostEqual(float(rows[0]["z"]), -2.08, places=2)
        self.assertIn("measured -3.01 % against predicted -3.45 %", rows[0]["reason"])
        self.assertEqual(rows[1]["agreement"], "agrees")
        self.assertEqual(rows[1]["reason"], "")
        self.assertEqual(rows[1]["integrator"], "mvv:0.5")
        self.assertAlmostEqual(float(rows[1]["predicted_ci_low"]), -0.0345 - 1.959964 * 0.002, places=6)

    def test_large_shifts_and_missing_sides_are_named(self):
        study(self.dir, "w", HEADER +
              "tea64,1,gauss,halves,distance,0.04,3,1.43,0.05,0,20.4,0.02,20.36,20.44,\n"
              "tea64,2,gauss,halves,distance,0.04,3,,,0,0.01,0.005,0.0,0.02,\n")
        run_tool(self.dir)
        rows = table(self.dir)
        self.assertEqual(rows[0]["agreement"], "fails")
        self.assertIn("beyond 10 %", rows[0]["reason"])
        self.assertIn("lags 0", rows[0]["reason"])
        self.assertEqual(rows[1]["agreement"], "not applicable")
        self.assertIn("no effective-power prediction", rows[1]["reason"])

    def test_studies_it_cannot_use_get_one_row_saying_why(self):
        study(self.dir, "old", "generator,rounds,distribution,feed,seeding,dt,replicas,predicted_T_shift\n"
                               "tea32,1,gauss,halves,distance,0.04,3,-0.03\n")
        study(self.dir, "none", None)
        os.makedirs(os.path.join(self.dir, "not-a-study"))
        run_tool(self.dir)
        rows = {r["study"]: r for r in table(self.dir)}
        self.assertEqual(sorted(rows), ["none", "old"])
        self.assertIn("predates", rows["old"]["reason"])
        self.assertIn("no zeta.csv", rows["none"]["reason"])

    def test_bad_directory_exits_2(self):
        code, err = run_tool(os.path.join(self.dir, "missing"))
        self.assertEqual(code, 2)
        self.assertIn("RESULTS_DIR", err)


@unittest.skipUnless(DPDRNG, "no dpdrng binary given")
class CiStudy(unittest.TestCase):
    """study/ci.toml run and reported once: the tool's table, the error budget and the per-round figures."""

    @classmethod
    def setUpClass(cls):
        cls.results = SCRATCH
        shutil.rmtree(cls.results, ignore_errors=True)
        os.makedirs(cls.results)
        cls.out = os.path.join(cls.results, "ci")
        subprocess.run([DPDRNG, "study", "run", os.path.join(SOURCE, "study", "ci.toml"), "--out", cls.out,
                        "--threads", "2"], check=True, capture_output=True)
        subprocess.run([DPDRNG, "study", "report", cls.out], check=True, capture_output=True)

    def report_csv(self, name):
        with open(os.path.join(self.out, "report", name), newline="") as f:
            return list(csv.DictReader(f))

    def test_every_variant_is_judged(self):
        self.assertEqual(run_tool(self.results)[0], 0)
        rows = table(self.results)
        # 2 generators x 2 round counts x 3 feeds
        self.assertEqual(len(rows), 12)
        for r in rows:
            self.assertIn(r["agreement"], ("agrees", "fails"), r)
            self.assertNotEqual(r["predicted_T_shift"], "")
            self.assertLess(float(r["measured_ci_low"]), float(r["measured_T_shift"]))
            self.assertEqual(r["reason"] == "", r["agreement"] == "agrees", r)
        # 64TEA(1)'s several-fold heating is beyond the first-order prediction under every feed.
        for r in rows:
            if r["variant"] == "tea64(1)":
                self.assertEqual(r["agreement"], "fails", r)
                self.assertIn("beyond 10 %", r["reason"])

    def test_error_budget_adds_up_and_shows_the_integrator(self):
        rows = self.report_csv("error_budget.csv")
        kinds = {r["observable"] for r in rows}
        self.assertEqual(kinds, {"temperature_mean", "temperature_conf_mean", "temperature_x_mean",
                                 "temperature_y_mean", "temperature_z_mean"})
        self.assertEqual(len(rows), 12 * 5)
        for r in rows:
            noise, integ, total = (float(r[k]) for k in ("noise_error", "integrator_error", "variant_error"))
            self.assertAlmostEqual(noise + integ, total, delta=1e-5 * (1 + abs(total)), msg=r)
            for part in ("noise", "integrator", "variant"):
                self.assertLessEqual(float(r[part + "_ci_low"]), float(r[part + "_ci_high"]), r)
        # GW-MVV at dt 0.04 heats the reference: its configurational temperature's integrator error is above 0
        # (about +2 %) under every feed.
        for r in rows:
            if r["observable"] == "temperature_conf_mean":
                self.assertGreater(float(r["integrator_error"]), 0.0, r)

    def test_rounds_figures_hold_every_variant_with_cis(self):
        rows = self.report_csv("rounds_figures.csv")
        by_figure = {}
        for r in rows:
            by_figure.setdefault(r["figure"], []).append(r)
            self.assertLessEqual(float(r["ci_low"]), float(r["value"]), r)
            self.assertLessEqual(float(r["value"]), float(r["ci_high"]), r)
        # 4b: 3 components of 12 variants and of the 3 references; 4d: 3 of 12; 5b and 6b: 12.
        self.assertEqual(len(by_figure["4b"]), 3 * 15)
        self.assertEqual(len(by_figure["4d"]), 3 * 12)
        self.assertEqual(len(by_figure["5b"]), 12)
        self.assertEqual(len(by_figure["6b"]), 12)
        self.assertTrue(all(r["unit"] == "percent" for f in ("4d", "5b", "6b") for r in by_figure[f]))
        # 64TEA(1) with distance seeding heats the components unequally (its hash reads dx first): T_x's CI lies
        # above T_z's under the halves feed.
        comp = {r["observable"]: r for r in by_figure["4b"] if r["variant"] == "tea64(1)" and r["feed"] == "halves"}
        self.assertGreater(float(comp["temperature_x_mean"]["ci_low"]), float(comp["temperature_z_mean"]["ci_high"]))
        charts = os.listdir(os.path.join(self.out, "report", "charts"))
        for name in ("temperature_series_gauss.gp", "temperature_components_vs_rounds_gauss.gp",
                     "temperature_components_shift_vs_rounds_gauss.gp", "diffusion_shift_vs_rounds_gauss.gp",
                     "rdf_shift_vs_rounds_gauss.gp"):
            self.assertIn(name, charts)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
