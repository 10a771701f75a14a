#!/usr/bin/python3
"""Draws a finished proxsim run's figures and writes its 3D replay viewer.

  /usr/bin/python3 report/make_report.py OUT --viewer-bundle build/release/viewer/viewer.js

reads OUT/{scene.json, readings.csv or readings/ (--format npy), poses.csv, profile.ply, terrain/}
and writes OUT/report/:
  curve_<sensor>.png/.svg     distance curve per sensor (paper Figs 8, 10, 12, 14)
  profile_<sensor>.png/.svg   profile per sensor (paper Figs 9, 11, 13, 15)
  paper_figures.png/.svg      the four sensor types side by side
  terrain.png/.svg            the terrain map, the truth, the error and the hazards (runs with a robot)
  index.html, data.js, viewer.js   the replay viewer (opens from disk)
Run it with Debian's /usr/bin/python3 (python3-matplotlib, python3-numpy).
Exit codes: 0 done, 2 bad input (missing files), 3 matplotlib or numpy missing.
"""
import argparse
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def _import_plotting():
    try:
        import matplotlib
        import numpy  # noqa: F401
    except ImportError as e:
        sys.stderr.write(f"make_report: {e}; this script needs matplotlib and numpy "
                         f"(Debian: apt-get install python3-matplotlib python3-numpy, "
                         f"and run it with /usr/bin/python3, not {sys.executable})\n")
        sys.exit(3)
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    plt.rcParams.update({"svg.fonttype": "none", "figure.dpi": 100, "savefig.dpi": 130,
                         "axes.titleweight": "bold"})
    return plt


_JOBS = []   # figure jobs, inherited by forked workers, which run them by index


def _run_job(i):
    _JOBS[i]()


def _safe(name):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name)


def main(argv=None):
    ap = argparse.ArgumentParser(description="Draws a proxsim run's figures and writes its replay viewer.")
    ap.add_argument("out_dir", help="a finished run's output directory")
    ap.add_argument("--viewer-bundle", help="the built viewer.js to copy into OUT/report/")
    ap.add_argument("--no-svg", action="store_true", help="write PNG only")
    args = ap.parse_args(argv)

    if not os.path.isdir(args.out_dir):
        sys.stderr.write(f"make_report: {args.out_dir}: no such run directory\n")
        return 2
    if args.viewer_bundle and not os.path.isfile(args.viewer_bundle):
        sys.stderr.write(f"make_report: viewer bundle {args.viewer_bundle} not found "
                         f"(build the 'proxsim_viewer' target: cmake --build --preset release)\n")
        return 2
    plt = _import_plotting()
    from proxsim_report.curve_figure import curve_figure
    from proxsim_report.paper_figure import paper_figure
    from proxsim_report.profile_figure import profile_figure
    from proxsim_report.run_data import RunError, load_run
    from proxsim_report.safe_files import save_figure
    from proxsim_report.terrain_data import load_terrain
    from proxsim_report.terrain_figure import terrain_figure
    from proxsim_report.viewer_page import write_viewer
    from proxsim_report.walk_path import path_of_run

    start = time.monotonic()
    try:
        run = load_run(args.out_dir)
    except RunError as e:
        sys.stderr.write(f"make_report: {e}\n")
        return 2
    except (ValueError, KeyError, TypeError, IndexError, AttributeError, UnicodeDecodeError) as e:
        # a file that is not what proxsim writes (a garbage scene.json, a t_s of 1e309): its name, no traceback
        sys.stderr.write(f"make_report: {args.out_dir}: not a run's files proxsim can read "
                         f"({type(e).__name__}: {e}); run the scenario again into this folder\n")
        return 2
    report_dir = os.path.join(args.out_dir, "report")
    os.makedirs(report_dir, exist_ok=True)
    path, has_robot = path_of_run(run)
    formats = ("png",) if args.no_svg else ("png", "svg")

    def save(fig, stem):
        for ext in formats:
            save_figure(fig, os.path.join(report_dir, f"{stem}.{ext}"))
        plt.close(fig)

    # one job per figure, shared by up to two forked workers (the machine's cores)
    jobs = []
    if run.sensors:   # the longest job first
        jobs.append((lambda: paper_figure(plt, run, path, has_robot), "paper_figures"))
    terrain = load_terrain(args.out_dir)
    if terrain is not None:
        track = path.xy if has_robot else None
        jobs.append((lambda: terrain_figure(plt, terrain, track), "terrain"))
    for sensor in run.sensors:
        jobs.append((lambda s=sensor: curve_figure(plt, s, run.outcome), f"curve_{_safe(sensor.name)}"))
        jobs.append((lambda s=sensor: profile_figure(plt, run, path, has_robot, s),
                     f"profile_{_safe(sensor.name)}"))
    _JOBS[:] = [(lambda j=j: save(j[0](), j[1])) for j in jobs]
    workers = min(2, os.cpu_count() or 1)
    if workers > 1 and len(_JOBS) > 2:
        import multiprocessing
        with multiprocessing.get_context("fork").Pool(workers) as pool:
            pool.map(_run_job, range(len(_JOBS)), chunksize=1)
    else:
        for i in range(len(_JOBS)):
            _run_job(i)
    if args.viewer_bundle:
        try:
            write_viewer(run, report_dir, args.viewer_bundle, terrain)
        except RunError as e:
            sys.stderr.write(f"make_report: {e}\n")
            return 2
    print(f"make_report: {len(run.sensors)} sensors drawn into {report_dir} "
          f"in {time.monotonic() - start:.1f} s"
          + ("" if args.viewer_bundle else " (no viewer: pass --viewer-bundle)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
