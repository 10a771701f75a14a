#!/usr/bin/env python3
"""Walks a built-in strategy over generated worlds with `proxsim run` and counts
the outcomes (summary.json robot.outcome); prints every run that did not end as
expected, then the counts. The figures in docs/strategies.md and docs/terrain.md
(issue 26) come from it.

  rooms:   scripts/measure_generated.py rooms --seeds 1 500 [--no-people]
           (difficulty 0.5, 10 x 10 m, the sensors and strategy of
           data/scenarios/circumvent_obstacle.yaml, stride 0.6 m, 40 s)
  courses: scripts/measure_generated.py courses --element hole --difficulty 1 --seeds 1 100
           [--stride 0.5] [--max-drop 0.08]
           (length 8 m, that element only, the knee mounting of
           data/scenarios/hole_stop_rule.yaml, the stop rule, 8 s, each seed
           starting up to 0.9 m back)

--proxsim (default build/release/proxsim), --jobs (default 2).
"""
import argparse
import collections
import json
import os
import re
import shutil
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLE = os.path.join(ROOT, "data", "scenarios", "circumvent_obstacle.yaml")
KNEE_SENSORS = """sensors:
  - {name: laser_left, type: laser, link: left_tibia, pose: &knee {xyz_m: [0.08, 0, -0.08], rpy_deg: [0, 35, 0]}}
  - {name: laser_right, type: laser, link: right_tibia, pose: *knee}
  - {name: reflectance_left, type: reflectance, link: left_tibia, pose: *knee}
  - {name: reflectance_right, type: reflectance, link: right_tibia, pose: *knee}
"""


def room(seed, args):
    example = open(EXAMPLE).read()
    strategy = re.search(r"^  strategy: .*$", example, re.M).group(0)
    people = ", people: [0, 0]" if args.no_people else ""
    return (f"proxsim: 1\nseed: 1\nduration_s: 40.0\nrate_hz: 100\nscene:\n"
            f"  generate: {{kind: room, difficulty: 0.5, seed: {seed}{people}}}\n"
            f"robot:\n  model: builtin:biped\n  gait: {{stride_m: 0.6, period_s: 1.2}}\n{strategy}\n"
            + example[example.index("\nsensors:") + 1:])


def course(seed, args):
    drop = f", max_drop_m: {args.max_drop}" if args.max_drop > 0 else ""
    start_x = -0.09 * ((seed * 37) % 10)
    return (f"proxsim: 1\nseed: 1\nduration_s: 8.0\nrate_hz: 100\nscene:\n"
            f"  generate: {{kind: course, length_m: 8, elements: [{args.element}], seed: {seed}, "
            f"difficulty: {args.difficulty:.2f}}}\n"
            f"robot:\n  model: builtin:biped\n  start: {{xyz_m: [{start_x:.2f}, 0, 0], yaw_deg: 0}}\n"
            f"  gait: {{stride_m: {args.stride:.2f}, period_s: 1.2}}\n  strategy: {{name: stop{drop}}}\n"
            + KNEE_SENSORS)


def run(seed, args):
    folder = tempfile.mkdtemp(prefix="proxsim-measure-")
    try:
        scenario = os.path.join(folder, "scenario.yaml")
        with open(scenario, "w") as f:
            f.write(room(seed, args) if args.kind == "rooms" else course(seed, args))
        subprocess.run([args.proxsim, "run", scenario, "--out", os.path.join(folder, "out"), "--no-report"],
                       capture_output=True, check=False)
        with open(os.path.join(folder, "out", "summary.json")) as f:
            robot = json.load(f)["robot"]
        return seed, robot["outcome"], robot.get("outcome_t_s"), robot.get("outcome_detail")
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("kind", choices=["rooms", "courses"])
    parser.add_argument("--seeds", nargs=2, type=int, default=[1, 100], metavar=("FIRST", "LAST"))
    parser.add_argument("--no-people", action="store_true", help="rooms: people: [0, 0]")
    parser.add_argument("--element", default="hole", help="courses: the one element (hole, gap, ...)")
    parser.add_argument("--difficulty", type=float, default=0.5, help="courses: in [0, 1]")
    parser.add_argument("--stride", type=float, default=0.5, help="courses: gait stride, m")
    parser.add_argument("--max-drop", type=float, default=0.0, help="courses: the stop rule's max_drop_m (0: the legs')")
    parser.add_argument("--proxsim", default=os.path.join(ROOT, "build", "release", "proxsim"))
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    expected = "reached_goal" if args.kind == "rooms" else "stopped"
    with ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda seed: run(seed, args), range(args.seeds[0], args.seeds[1] + 1)))
    for seed, outcome, t_s, detail in results:
        if outcome != expected:
            print(f"seed {seed}: {outcome} at {t_s} s: {detail}")
    counts = collections.Counter(outcome for _, outcome, _, _ in results)
    print(f"{len(results)} runs: " + ", ".join(f"{name} {n}" for name, n in counts.most_common()))


if __name__ == "__main__":
    main()
