"""Unit tests of the report's geometry (walking path, true cross-section) and
loading, with expected values worked out by hand; plus make_report on a
synthetic run (files written) and on bad input (exit 2).
Run: /usr/bin/python3 -m unittest discover -s tests/report"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "report"))
from proxsim_report.cross_section import cut_object  # noqa: E402
from proxsim_report.walk_path import WalkPath  # noqa: E402

X_AXIS = WalkPath(np.array([[0.0, 0.0], [1.0, 0.0]]))


def quat_rpy(roll, pitch, yaw):
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return [cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy]


class WalkPathTest(unittest.TestCase):
    def test_projects_onto_an_l_shaped_path(self):
        path = WalkPath(np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0]]))
        s, lateral = path.project(np.array([[2.5, 1.0], [1.0, 0.3], [-1.0, 0.0]]))
        np.testing.assert_allclose(s, [3.0, 1.0, -1.0])
        np.testing.assert_allclose(lateral, [-0.5, 0.3, 0.0])   # left of the walk is positive

    def test_point_at_inverts_project(self):
        path = WalkPath(np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0]]))
        np.testing.assert_allclose(path.point_at(np.array([3.0, 1.0]), 0.5), [[1.5, 1.0], [1.0, 0.5]])


    def test_simplify_keeps_corners_and_drops_sway(self):
        from proxsim_report.walk_path import simplify
        x = np.linspace(0, 4, 401)
        sway = np.column_stack([x, 0.01 * np.sin(8 * x)])             # 1 cm sway on a straight walk
        np.testing.assert_allclose(simplify(sway, 0.03), sway[[0, -1]])
        corner = np.array([[0, 0], [1, 0], [2, 0], [2, 1], [2, 2.0]])
        np.testing.assert_allclose(simplify(corner, 0.03), [[0, 0], [2, 0], [2, 2]])


class CrossSectionTest(unittest.TestCase):
    s = np.linspace(0.0, 4.0, 4001)   # 1 mm steps

    def at(self, cut, s0):
        k = int(round(s0 * 1000))
        return cut.bottom[k], cut.top[k]

    def test_box_is_cut_to_its_height_over_its_length(self):
        box = {"name": "b", "id": 1, "shape": "box", "size_m": [0.2, 0.4, 0.1], "xyz_m": [2.0, 0.0, 0.05],
               "quat_wxyz": [1, 0, 0, 0]}
        cut = cut_object(box, X_AXIS, self.s)
        np.testing.assert_allclose(self.at(cut, 2.0), [0.0, 0.1], atol=1e-9)
        self.assertTrue(np.isnan(cut.top[int(2.2 * 1000)]))
        hit = self.s[np.isfinite(cut.top)]
        self.assertAlmostEqual(hit.min(), 1.9, delta=1.5e-3)
        self.assertAlmostEqual(hit.max(), 2.1, delta=1.5e-3)

    def test_yawed_square_box_is_cut_along_its_diagonal(self):
        box = {"name": "b", "shape": "box", "size_m": [0.2, 0.2, 0.3], "xyz_m": [1.0, 0.0, 0.15],
               "quat_wxyz": quat_rpy(0, 0, math.radians(45))}
        hit = self.s[np.isfinite(cut_object(box, X_AXIS, self.s).top)]
        self.assertAlmostEqual(hit.max() - hit.min(), 0.2 * math.sqrt(2), delta=2e-3)

    def test_sphere_outline_is_a_circle(self):
        ball = {"name": "s", "shape": "sphere", "radius_m": 0.2, "xyz_m": [1.0, 0.0, 0.5]}
        cut = cut_object(ball, X_AXIS, self.s)
        np.testing.assert_allclose(self.at(cut, 1.0), [0.3, 0.7], atol=1e-9)
        h = math.sqrt(0.2 ** 2 - 0.1 ** 2)
        np.testing.assert_allclose(self.at(cut, 1.1), [0.5 - h, 0.5 + h], atol=1e-9)

    def test_lying_cylinder_outline_is_a_circle(self):
        log = {"name": "c", "shape": "cylinder", "radius_m": 0.1, "length_m": 1.0, "xyz_m": [3.0, 0.0, 0.1],
               "quat_wxyz": quat_rpy(math.radians(90), 0, 0)}   # axis along y, across the path
        cut = cut_object(log, X_AXIS, self.s)
        np.testing.assert_allclose(self.at(cut, 3.0), [0.0, 0.2], atol=1e-9)
        h = math.sqrt(0.1 ** 2 - 0.05 ** 2)
        np.testing.assert_allclose(self.at(cut, 3.05), [0.1 - h, 0.1 + h], atol=1e-9)

    def test_standing_cylinder_is_cut_between_its_caps(self):
        post = {"name": "p", "shape": "cylinder", "radius_m": 0.1, "length_m": 1.0, "xyz_m": [2.0, 0.05, 0.5]}
        cut = cut_object(post, X_AXIS, self.s)
        np.testing.assert_allclose(self.at(cut, 2.0), [0.0, 1.0], atol=1e-9)
        hit = self.s[np.isfinite(cut.top)]
        self.assertAlmostEqual(hit.max() - hit.min(), 2 * math.sqrt(0.1 ** 2 - 0.05 ** 2), delta=2e-3)

    def test_tilted_plane_height_and_solid_side(self):
        ramp = {"name": "ramp", "shape": "plane", "xyz_m": [0, 0, 0.2],
                "quat_wxyz": quat_rpy(0, math.radians(-10), 0)}   # rises along +x
        cut = cut_object(ramp, X_AXIS, self.s)
        self.assertTrue(cut.solid_below)
        self.assertAlmostEqual(self.at(cut, 2.0)[1], 0.2 + 2.0 * math.tan(math.radians(10)), places=9)

    def test_vertical_plane_is_a_wall_crossing(self):
        wall = {"name": "w", "shape": "plane", "xyz_m": [2.5, 0, 0],
                "quat_wxyz": quat_rpy(0, math.radians(-90), 0)}   # faces -x: solid beyond x = 2.5
        cut = cut_object(wall, X_AXIS, self.s)
        self.assertAlmostEqual(cut.wall_s, 2.5, delta=2e-3)
        self.assertTrue(cut.wall_solid_after)

    def test_lateral_offset_selects_what_is_cut(self):
        box = {"name": "b", "shape": "box", "size_m": [0.2, 0.2, 0.1], "xyz_m": [1.0, 0.5, 0.05]}
        self.assertIsNone(cut_object(box, X_AXIS, self.s, lateral=0.0))
        self.assertIsNotNone(cut_object(box, X_AXIS, self.s, lateral=0.5))

    def test_mesh_tetrahedron_top_and_bottom(self):
        tet = {"name": "m", "shape": "mesh", "xyz_m": [1.0, 0.0, 0.0],
               "vertices_m": [[-0.5, -0.5, 0], [0.5, -0.5, 0], [0, 0.5, 0], [0, 0, 1]],
               "triangles": [[0, 1, 2], [0, 1, 3], [1, 2, 3], [2, 0, 3]]}
        cut = cut_object(tet, X_AXIS, self.s)
        bottom, top = self.at(cut, 1.0)
        self.assertAlmostEqual(bottom, 0.0, places=9)
        self.assertAlmostEqual(top, 1.0, places=9)


class ReadingsFormatTest(unittest.TestCase):
    """Which readings a run is read from: readings.csv, or the npy columns in
    readings/ (their equality with the CSV is tests/npy_writer_test.cc's, on
    real runs, through same_run_data.py)."""

    def folder(self, files, outputs=None):
        out = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, out)
        for name in files:
            if name.endswith("/"):
                os.makedirs(os.path.join(out, name))
            else:
                open(os.path.join(out, name), "w").close()
        if outputs is not None:
            with open(os.path.join(out, "summary.json"), "w") as f:
                json.dump({"outputs": outputs}, f)
        return out

    def test_the_summary_names_the_run_s_own_readings_over_a_stale_file(self):
        from proxsim_report.run_data import _readings_format
        both = ["readings.csv", "readings/"]
        self.assertEqual(_readings_format(self.folder(both, ["readings/", "scene.json"])), "npy")
        self.assertEqual(_readings_format(self.folder(both, ["readings.csv", "scene.json"])), "csv")

    def test_without_a_summary_the_csv_comes_first(self):
        from proxsim_report.run_data import _readings_format
        self.assertEqual(_readings_format(self.folder(["readings.csv", "readings/"])), "csv")
        self.assertEqual(_readings_format(self.folder(["readings/"])), "npy")
        self.assertEqual(_readings_format(self.folder([])), "csv")   # whose error names readings.csv

    def test_a_missing_or_short_column_is_named(self):
        from proxsim_report.run_data import RunError, load_run
        out = self.folder(["readings/"], ["readings/"])
        with open(os.path.join(out, "scene.json"), "w") as f:
            json.dump({"sensors": []}, f)
        with self.assertRaisesRegex(RunError, "columns.json"):
            load_run(out)
        with open(os.path.join(out, "readings", "columns.json"), "w") as f:
            json.dump({"rows": 2, "sensors": ["s"], "columns": [{"name": "sensor", "dtype": "<i4", "codes": "sensors"},
                                                                {"name": "t_s", "dtype": "<f8"}]}, f)
        with self.assertRaisesRegex(RunError, "sensor.npy"):
            load_run(out)
        np.save(os.path.join(out, "readings", "sensor.npy"), np.zeros(1, dtype="<i4"))
        with self.assertRaisesRegex(RunError, "sensor.npy: shape \\(1,\\), but columns.json says 2 rows"):
            load_run(out)


class MakeReportTest(unittest.TestCase):
    def run_script(self, *args):
        return subprocess.run([sys.executable, *args], capture_output=True, text=True, cwd=ROOT)

    def test_draws_a_run_without_robot_and_loads_it_consistently(self):
        from proxsim_report.run_data import load_run
        with tempfile.TemporaryDirectory() as out:
            self.assertEqual(self.run_script("tests/data/report_sample/make_sample.py", out, "--no-robot").returncode, 0)
            run = load_run(out)
            self.assertEqual(run.poses, {})
            detected = sum(int(s.detected.sum()) for s in run.sensors)
            self.assertEqual(detected, len(run.profile["x"]))
            sky = next(s for s in run.sensors if s.name == "laser_sky")
            self.assertFalse(sky.detected.any())
            self.assertTrue(np.isnan(sky.d_true_m).all())
            r = self.run_script("report/make_report.py", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            files = set(os.listdir(os.path.join(out, "report")))
            for name in ("paper_figures.png", "paper_figures.svg", "curve_laser_sky.png", "profile_laser_sky.svg"):
                self.assertIn(name, files)

    def test_bad_input_exits_2_with_a_message(self):
        with tempfile.TemporaryDirectory() as out:
            r = self.run_script("report/make_report.py", out)
            self.assertEqual(r.returncode, 2)
            self.assertIn("scene.json", r.stderr)
            r = self.run_script("report/make_report.py", out, "--viewer-bundle", os.path.join(out, "nope.js"))
            self.assertEqual(r.returncode, 2)
            self.assertIn("viewer bundle", r.stderr)


class FigureLayoutTest(unittest.TestCase):
    """On the synthetic walk: the paper figure of one, two or four sensors keeps
    its y-labels and its legend inside the figure, and a profile over a course
    of boxes shows the bottom of the hole under the path."""

    @classmethod
    def setUpClass(cls):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from proxsim_report.run_data import load_run
        from proxsim_report.walk_path import path_of_run
        cls.plt = plt
        cls.out = tempfile.mkdtemp()
        r = subprocess.run([sys.executable, "tests/data/report_sample/make_sample.py", cls.out],
                           capture_output=True, text=True, cwd=ROOT)
        assert r.returncode == 0, r.stderr
        cls.walk = load_run(cls.out)
        cls.path, cls.has_robot = path_of_run(cls.walk)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.out)

    def test_one_two_or_four_sensors_keep_labels_and_legend_inside(self):
        import copy
        from proxsim_report.paper_figure import paper_figure
        for n in (1, 2, 4):
            run = copy.copy(self.walk)
            run.sensors = self.walk.sensors[:n]
            fig = paper_figure(self.plt, run, self.path, self.has_robot)
            fig.canvas.draw()
            renderer = fig.canvas.get_renderer()
            W, H = fig.bbox.width, fig.bbox.height
            artists = [ax.yaxis.label for ax in fig.axes] + list(fig.legends) + [fig._suptitle]
            for artist in artists:
                box = artist.get_window_extent(renderer)
                with self.subTest(sensors=n, artist=str(artist)[:40]):
                    self.assertGreaterEqual(box.x0, 0)
                    self.assertGreaterEqual(box.y0, 0)
                    self.assertLessEqual(box.x1, W)
                    self.assertLessEqual(box.y1, H)
            self.plt.close(fig)

    def test_the_profile_shows_the_hole_bottom(self):
        import copy
        from proxsim_report.profile_figure import draw_profile

        def box(name, i, x0, x1, z0, z1):
            return {"name": name, "id": i, "shape": "box", "size_m": [x1 - x0, 4.0, z1 - z0],
                    "xyz_m": [(x0 + x1) / 2, 0.0, (z0 + z1) / 2], "quat_wxyz": [1, 0, 0, 0]}
        run = copy.copy(self.walk)
        run.scene = dict(self.walk.scene)
        run.scene["objects"] = [box("floor", 0, -5, 3, -0.5, 0), box("hole_bottom", 1, 3, 3.5, -0.6, -0.5),
                                box("floor_after", 2, 3.5, 20, -0.5, 0)]
        fig, ax = self.plt.subplots()
        draw_profile(ax, run, self.path, self.has_robot, run.sensors[0])
        self.assertLessEqual(ax.get_ylim()[0], -0.6)
        self.assertGreater(ax.get_ylim()[0], -0.7)
        self.plt.close(fig)


if __name__ == "__main__":
    unittest.main()
