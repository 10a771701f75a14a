"""The report's terrain map (terrain_data, terrain_figure, the viewer's map
layer) on a small terrain/ folder written here with values worked out by
hand: the cells' places follow meta.json's contract, the cells are listed in
the order they were first measured, the error panel is elevation − truth,
a hazard is marked at the map's surface; and make_report draws terrain.png
and .svg for a run that has terrain/ and none for a run without it.
Run: /usr/bin/python3 -m unittest discover -s tests/report"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "report"))
from proxsim_report.terrain_data import height_limits, load_terrain, measured_cells  # noqa: E402
from proxsim_report.viewer_page import terrain_viewer_data  # noqa: E402

NAN = np.nan
R = 0.5
ORIGIN = (1.0, -1.0)
# 2 rows (y) × 3 columns (x); cell (i, j) covers x0 + j·r .. and y0 + i·r ..
ELEVATION = np.array([[0.0, 0.2, NAN], [NAN, 0.01, -0.3]], dtype=np.float32)
TRUTH = np.array([[0.0, 0.15, 0.0], [0.0, 0.0, -0.3]], dtype=np.float32)
UPPER = np.array([[NAN, NAN, -0.1], [0.4, NAN, NAN]], dtype=np.float32)
FIRST_T = np.array([[0.3, 0.1, NAN], [NAN, 0.3, 0.2]], dtype=np.float32)
HAZARDS = [{"class": "obstacle", "x_m": 1.75, "y_m": -0.75, "size_x_m": 0.5, "size_y_m": 0.5, "height_m": 0.2,
            "first_detection_t_s": 0.1, "distance_at_detection_m": 0.9},
           {"class": "hole", "x_m": 2.25, "y_m": -0.25, "size_x_m": 0.5, "size_y_m": 0.5, "height_m": -0.3,
            "first_detection_t_s": 0.2, "distance_at_detection_m": 0.7}]


def write_terrain(out):
    folder = os.path.join(out, "terrain")
    os.makedirs(folder)
    with open(os.path.join(folder, "meta.json"), "w") as f:
        json.dump({"resolution_m": R, "origin_xy_m": list(ORIGIN), "shape": [2, 3]}, f)
    arrays = {"elevation": ELEVATION, "variance": np.where(np.isnan(ELEVATION), NAN, 1e-4).astype(np.float32),
              "upper_bound": UPPER, "truth": TRUTH, "first_update_t_s": FIRST_T}
    for name, a in arrays.items():
        np.save(os.path.join(folder, f"{name}.npy"), a)
    with open(os.path.join(folder, "hazards.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(HAZARDS[0]))
        w.writeheader()
        w.writerows(HAZARDS)
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump({"terrain": {"cells_measured": 4, "elevation_error": {"rmse_m": 0.026, "p95_m": 0.045},
                               "corridor": {"coverage": 0.5}, "true_hazards": []}}, f)


class TerrainDataTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        write_terrain(self.tmp.name)
        self.terrain = load_terrain(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_no_folder_no_map(self):
        with tempfile.TemporaryDirectory() as out:
            self.assertIsNone(load_terrain(out))

    def test_reads_the_arrays_the_hazards_and_the_score(self):
        t = self.terrain
        np.testing.assert_array_equal(t.elevation, ELEVATION)
        self.assertEqual(t.extent, (1.0, 2.5, -1.0, 0.0))
        self.assertEqual([h["class"] for h in t.hazards], ["obstacle", "hole"])
        self.assertEqual(t.hazards[1]["height_m"], -0.3)
        self.assertEqual(t.score["cells_measured"], 4)

    def test_measured_cells_are_the_cell_centres_in_the_order_first_measured(self):
        x, y, z, t = measured_cells(self.terrain)
        # (i, j, t): (0, 1, 0.1), (1, 2, 0.2), then at 0.3 (0, 0) before (1, 1)
        np.testing.assert_allclose(t, [0.1, 0.2, 0.3, 0.3], rtol=1e-6)
        np.testing.assert_allclose(x, [1.75, 2.25, 1.25, 1.75])
        np.testing.assert_allclose(y, [-0.75, -0.25, -0.75, -0.25])
        np.testing.assert_allclose(z, [0.2, -0.3, 0.0, 0.01], rtol=1e-6)

    def test_the_height_scale_spans_map_and_truth(self):
        lo, hi = height_limits(self.terrain)
        self.assertAlmostEqual(lo, np.percentile(np.r_[ELEVATION[~np.isnan(ELEVATION)], TRUTH.ravel()], 0.5), 5)
        self.assertGreater(hi, 0.19)

    def test_viewer_layer_lists_cells_and_marks_hazards_at_the_maps_surface(self):
        d = terrain_viewer_data(self.terrain)
        self.assertEqual(d["t"], [0.1, 0.2, 0.3, 0.3])
        self.assertEqual(len(d["x"]), 4)
        # the obstacle's extent holds cell (0, 1), height 0.2; the hole's cell
        # (1, 2), height −0.3, and nothing else measured
        self.assertEqual([h["z"] for h in d["hazards"]], [0.2, -0.3])
        self.assertEqual(d["hazards"][0]["t"], 0.1)
        self.assertEqual(len(d["colorStops"]), 9)
        self.assertIsNone(terrain_viewer_data(None))


class TerrainFigureTest(unittest.TestCase):
    def test_four_panels_and_the_error_is_elevation_minus_truth(self):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from proxsim_report.terrain_figure import terrain_figure
        with tempfile.TemporaryDirectory() as out:
            write_terrain(out)
            fig = terrain_figure(plt, load_terrain(out), np.array([[1.0, -0.5], [2.5, -0.5]]))
        panels = [ax for ax in fig.axes if ax.get_label() != "<colorbar>"]
        self.assertEqual(len(panels), 4)
        error = panels[2].images[0].get_array()
        np.testing.assert_allclose(error.filled(NAN), ELEVATION - TRUTH, rtol=1e-6)
        # the hazards panel: one filled rectangle per map hazard, at its centroid
        filled = [p for p in panels[3].patches if p.get_fill()]
        self.assertEqual(len(filled), 2)
        self.assertEqual(filled[0].get_xy(), (1.5, -1.0))
        plt.close(fig)


class MakeReportTerrainTest(unittest.TestCase):
    def run_script(self, *args):
        return subprocess.run([sys.executable, *args], capture_output=True, text=True, cwd=ROOT)

    def test_terrain_figure_only_for_a_run_with_a_map(self):
        with tempfile.TemporaryDirectory() as out:
            self.assertEqual(self.run_script("tests/data/report_sample/make_sample.py", out).returncode, 0)
            r = self.run_script("report/make_report.py", out, "--no-svg")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertNotIn("terrain.png", os.listdir(os.path.join(out, "report")))
            with open(os.path.join(out, "summary.json")) as f:
                summary = json.load(f)
            os.remove(os.path.join(out, "summary.json"))
            write_terrain(out)
            with open(os.path.join(out, "summary.json")) as f:
                summary["terrain"] = json.load(f)["terrain"]
            with open(os.path.join(out, "summary.json"), "w") as f:
                json.dump(summary, f)
            r = self.run_script("report/make_report.py", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            files = os.listdir(os.path.join(out, "report"))
            self.assertIn("terrain.png", files)
            self.assertIn("terrain.svg", files)


if __name__ == "__main__":
    unittest.main()
