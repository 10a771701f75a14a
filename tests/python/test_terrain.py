"""The terrain map's files (OUT/terrain/, the contract of issue 14) read back
with NumPy, its score recomputed from them, and the map a script sees."""
import csv
import json
import math
import os

import numpy as np

import proxsim
from conftest import run_cli

ARRAYS = ("elevation", "variance", "upper_bound", "truth", "first_update_t_s", "last_update_t_s")


def test_the_files_hold_the_map_and_the_truth_and_the_summary_scores_them(tmp_path):
    out = tmp_path / "run"
    assert run_cli("run", "--no-report", "--out", str(out)).returncode == 0
    terrain = out / "terrain"
    meta = json.loads((terrain / "meta.json").read_text())
    assert meta["resolution_m"] == 0.02
    ny, nx = meta["shape"]
    arrays = {name: np.load(terrain / f"{name}.npy") for name in ARRAYS}
    hits = np.load(terrain / "hits.npy")
    for name, a in arrays.items():
        assert a.shape == (ny, nx) and a.dtype == np.float32, name
    assert hits.dtype == np.uint32
    elevation, truth = arrays["elevation"], arrays["truth"]
    measured = ~np.isnan(elevation)
    # a cell has a height exactly when points were fused into it, and a variance with it
    np.testing.assert_array_equal(measured, hits > 0)
    np.testing.assert_array_equal(measured, ~np.isnan(arrays["variance"]))
    # the floor is at 0 under the robot's path; the obstacle (x 2.4-2.6, |y| <= 0.15) 0.15 high
    x0, y0 = meta["origin_xy_m"]
    r = meta["resolution_m"]

    def cell(x, y):
        return int(math.floor((y - y0) / r)), int(math.floor((x - x0) / r))

    assert truth[cell(1.0, 0.0)] == 0.0
    assert abs(truth[cell(2.5, 0.0)] - 0.15) < 1e-6
    # the summary's error, recomputed from the arrays
    both = measured & ~np.isnan(truth)
    error = np.abs(elevation[both].astype(np.float64) - truth[both])
    score = json.loads((out / "summary.json").read_text())["terrain"]
    assert score["elevation_error"]["cells"] == int(both.sum())
    assert math.isclose(score["elevation_error"]["rmse_m"], math.sqrt(np.mean(error ** 2)), rel_tol=1e-6)
    assert math.isclose(score["elevation_error"]["p95_m"], float(np.percentile(error, 95)), rel_tol=1e-5, abs_tol=1e-9)
    assert score["cells_measured"] == int(measured.sum())
    # free space's bounds against the truth, recounted
    upper = arrays["upper_bound"].astype(np.float64)
    bounded = ~np.isnan(upper) & ~np.isnan(truth)
    assert score["upper_bound"]["cells"] == int(bounded.sum()) > 0
    assert score["upper_bound"]["below_truth"] == int((upper[bounded] < truth[bounded] - 0.05).sum())
    # the floor measured along the walk, flat within a centimetre (short of the
    # obstacle: the cells just before its face hold the face's points)
    x_centres = x0 + (np.arange(nx) + 0.5) * r
    floor = measured & (truth == 0.0) & (x_centres < 2.3)[np.newaxis, :]
    assert floor.sum() > 60 and np.all(np.abs(elevation[floor]) < 0.01)
    # the hazards: the obstacle, found before the robot stood still
    with open(terrain / "hazards.csv") as f:
        rows = list(csv.DictReader(f))
    assert rows and rows[0]["class"] == "obstacle"
    stop_t_s = json.loads((out / "summary.json").read_text())["robot"]["stop_t_s"]
    assert float(rows[0]["first_detection_t_s"]) < stop_t_s
    assert 2.35 < float(rows[0]["x_m"]) < 2.65


def test_a_script_reads_the_map_the_robot_builds():
    with proxsim.Simulation.builtin("paper") as sim:
        first_hazard_t_s = None
        while not sim.done:
            obs = sim.step()
            if first_hazard_t_s is None and sim.terrain_map()["hazards"]:
                first_hazard_t_s = obs["t_s"]
        m = sim.terrain_map()
    assert m["resolution_m"] == 0.02
    assert m["elevation"].dtype == np.float32 and m["elevation"].shape == m["hits"].shape
    assert (m["hits"] > 0).sum() == (~np.isnan(m["elevation"])).sum() > 60
    assert m["hazards"][0]["class"] == "obstacle"
    assert m["hazards"][0]["first_detection_t_s"] == first_hazard_t_s


def test_no_map_without_a_robot():
    with proxsim.Simulation(os.path.join(os.path.dirname(__file__), "..", "..", "data", "scenarios",
                                         "world_sensors_demo.yaml")) as sim:
        sim.step()
        assert sim.terrain_map() is None
        assert sim.summary()["terrain"] is None
