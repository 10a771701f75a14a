#!/usr/bin/python3
"""Checks that the report reads the same data from a run written as readings.csv
and from the same run written with `--format npy` (readings/ columns):

  /usr/bin/python3 tests/report/same_run_data.py CSV_RUN NPY_RUN

Every field of every SensorSeries must match in dtype, shape and value (NaN
where NaN, row order included), as must the scene, poses and profile. Exit 0
when identical, 1 with the differences listed, 2 when the runs are unusable
(or too plain to tell: no readings, no miss, no object). Not a unittest module
(its name does not start with test_): tests/npy_writer_test.cc makes the runs
with the real binary and calls it. Run it with Debian's /usr/bin/python3."""
import dataclasses
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "report"))
from proxsim_report.run_data import RunError, load_run  # noqa: E402


def _array_differences(where, a, b):
    if not isinstance(a, np.ndarray) or not isinstance(b, np.ndarray):
        return [f"{where}: {type(a).__name__} from the CSV, {type(b).__name__} from npy"]
    if a.dtype != b.dtype or a.shape != b.shape:
        return [f"{where}: {a.dtype}{a.shape} from the CSV, {b.dtype}{b.shape} from npy"]
    if a.dtype == object:
        wrong_type = [i for i, v in enumerate(b.flat) if type(v) is not type(a.flat[i])]
        if wrong_type:
            i = wrong_type[0]
            return [f"{where}[{i}]: {type(a.flat[i]).__name__} from the CSV, {type(b.flat[i]).__name__} from npy"]
        same = a == b
    elif a.dtype.kind == "f":
        same = (a == b) | (np.isnan(a) & np.isnan(b))
    else:
        same = a == b
    if same.all():
        return []
    i = np.argwhere(~same)[0]
    at = tuple(int(k) for k in i)
    return [f"{where}{list(at)}: {a[at]!r} from the CSV, {b[at]!r} from npy ({int((~same).sum())} differ)"]


def _differences(where, a, b):
    """What differs between two loaded values, as readable lines."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return _array_differences(where, a, b)
    if isinstance(a, dict) and isinstance(b, dict):
        if list(a) != list(b):
            return [f"{where}: keys {list(a)} from the CSV, {list(b)} from npy"]
        return [d for k in a for d in _differences(f"{where}[{k!r}]", a[k], b[k])]
    if isinstance(a, (tuple, list)) and isinstance(b, (tuple, list)) and type(a) is type(b):
        if len(a) != len(b):
            return [f"{where}: {len(a)} items from the CSV, {len(b)} from npy"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in _differences(f"{where}[{i}]", x, y)]
    if type(a) is not type(b) or a != b:
        return [f"{where}: {a!r} ({type(a).__name__}) from the CSV, {b!r} ({type(b).__name__}) from npy"]
    return []


def main(csv_dir, npy_dir):
    if not os.path.isfile(os.path.join(csv_dir, "readings.csv")):
        print(f"{csv_dir}: no readings.csv", file=sys.stderr)
        return 2
    if os.path.exists(os.path.join(npy_dir, "readings.csv")) or not os.path.isdir(os.path.join(npy_dir, "readings")):
        print(f"{npy_dir}: not an npy run (needs readings/ and no readings.csv)", file=sys.stderr)
        return 2
    try:
        from_csv, from_npy = load_run(csv_dir), load_run(npy_dir)
    except RunError as e:
        print(f"same_run_data: {e}", file=sys.stderr)
        return 2

    # a comparison that could not tell empty names or NaN from their absence proves little
    rows = sum(len(s.t_s) for s in from_csv.sensors)
    misses = sum(int((s.object == "").sum()) for s in from_csv.sensors)
    nans = sum(int(np.isnan(s.d_true_m).sum()) for s in from_csv.sensors)
    if rows == 0 or misses == 0 or misses == rows or nans == 0:
        print(f"{csv_dir}: too plain a run to compare ({rows} rows, {misses} without an object, "
              f"{nans} NaN distances)", file=sys.stderr)
        return 2

    differences = _differences("scene", from_csv.scene, from_npy.scene)
    differences += _differences("sensors", [s.name for s in from_csv.sensors], [s.name for s in from_npy.sensors])
    for a, b in zip(from_csv.sensors, from_npy.sensors):
        for f in dataclasses.fields(a):
            differences += _differences(f"{a.name}.{f.name}", getattr(a, f.name), getattr(b, f.name))
    differences += _differences("poses", from_csv.poses, from_npy.poses)
    differences += _differences("profile", from_csv.profile, from_npy.profile)
    for line in differences:
        print(line)
    if differences:
        return 1
    print(f"same data: {len(from_csv.sensors)} sensors, {rows} readings ({misses} without an object)")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
