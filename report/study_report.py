#!/usr/bin/env python3
"""A sensor-placement study's pictures and page, from the files `proxsim study`
wrote in OUT: results.csv, ranking.csv and selection.json.

  OUT/lead_heatmap.png/.svg  the mean lead distance (leading toe to the hazard at
                             its first detection, over every detection of every
                             hazard, scene and seed) as a heat map over position
                             along the link x pitch, one panel per sensor (its
                             datasheet part, else its type) and link; blank where nothing was ever detected
  OUT/pareto.png/.svg        sensor count against detection rate and mean lead
                             for the greedy sets (Pareto points marked)
  OUT/index.html             links them, with the ranking's head and the chosen set

A closed-loop study (selection.json "mode": "outcomes") is drawn by
outcome_report.py instead.

Usage: study_report.py OUT   (Debian's /usr/bin/python3 with python3-matplotlib)
"""
import csv
import html
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from proxsim_report.plotting import require_plotting  # noqa: E402

plt, np = require_plotting("study_report")
from proxsim_report.safe_files import save_figure, write_text  # noqa: E402  (never through a link)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def lead_columns(header):
    return [c for c in header if c.endswith("_lead_m")]


def sensor_of(row):
    """The sensor a candidate is: its datasheet part when it is one (an HC-SR04 and the paper's
    ultrasonic model are different sensors), else its physics type."""
    return row.get("part") or row["type"]


def heatmap(results, out):
    """Mean lead over along_m x pitch_deg, one panel per (part or type, link)."""
    leads = lead_columns(results[0].keys())
    panels = sorted({(sensor_of(r), r["link"]) for r in results})
    along = sorted({float(r["along_m"]) for r in results})
    pitch = sorted({float(r["pitch_deg"]) for r in results})
    cols = min(4, len(panels))
    rows = (len(panels) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(3.6 * cols, 2.9 * rows + 0.6), squeeze=False,
                             constrained_layout=True)
    image = None
    all_values = [float(r[c]) for r in results for c in leads if r[c] != ""]
    vmin, vmax = (min(all_values), max(all_values)) if all_values else (0.0, 1.0)
    for k, (sensor_type, link) in enumerate(panels):
        ax = axes[k // cols][k % cols]
        grid = np.full((len(pitch), len(along)), np.nan)
        for i, p in enumerate(pitch):
            for j, a in enumerate(along):
                values = [float(r[c]) for r in results for c in leads
                          if sensor_of(r) == sensor_type and r["link"] == link and float(r["pitch_deg"]) == p
                          and float(r["along_m"]) == a and r[c] != ""]
                if values:
                    grid[i, j] = np.mean(values)
        image = ax.imshow(grid, origin="lower", aspect="auto", cmap="viridis", vmin=vmin, vmax=vmax,
                          extent=None)
        ax.set_xticks(range(len(along)), [f"{a:g}" for a in along], fontsize=8)
        ax.set_yticks(range(len(pitch)), [f"{p:g}" for p in pitch], fontsize=8)
        ax.set_title(f"{sensor_type} on {link}", fontsize=9)
        ax.set_xlabel("position along the link z (m)", fontsize=8)
        ax.set_ylabel("pitch (deg)", fontsize=8)
        for i in range(len(pitch)):
            for j in range(len(along)):
                if np.isfinite(grid[i, j]):
                    ax.text(j, i, f"{grid[i, j] + 0.0:.2f}".replace("-0.00", "0.00"), ha="center", va="center", fontsize=7, color="white")
    for k in range(len(panels), rows * cols):
        axes[k // cols][k % cols].axis("off")
    if image is not None:
        fig.colorbar(image, ax=axes, shrink=0.8, label="mean lead distance (m)")
    fig.suptitle("Lead distance at first detection (blank: never detected)", fontsize=11)
    for ext in ("png", "svg"):
        save_figure(fig, os.path.join(out, f"lead_heatmap.{ext}"), dpi=120)
    plt.close(fig)


def pareto(selection, out):
    front = selection["pareto_front"]
    n = [p["sensors"] for p in front]
    rate = [p["detection_rate"] for p in front]
    lead = [p["mean_lead_m"] if p["mean_lead_m"] is not None else np.nan for p in front]
    fig, ax = plt.subplots(figsize=(6.4, 4.0), constrained_layout=True)
    ax.plot(n, rate, "o-", color="#1f77b4", label="detection rate")
    for x, y, p in zip(n, rate, front):
        if p["pareto"]:
            ax.plot([x], [y], "o", ms=11, mfc="none", mec="#d62728")
    ax.set_xlabel("number of sensors (greedy set)")
    ax.set_ylabel("share of hazards detected", color="#1f77b4")
    ax.set_ylim(0, 1.05)
    ax.set_xticks(n)
    twin = ax.twinx()
    twin.plot(n, lead, "s--", color="#2ca02c", label="mean lead (m)")
    twin.set_ylabel("mean lead distance (m)", color="#2ca02c")
    ax.set_title("Sensor count against detection and lead (red rings: Pareto points)", fontsize=10)
    for ext in ("png", "svg"):
        save_figure(fig, os.path.join(out, f"pareto.{ext}"), dpi=120)
    plt.close(fig)


def page(ranking, selection, out):
    def table(rows, keys):
        head = "".join(f"<th>{html.escape(k)}</th>" for k in keys)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(str(r.get(k, '')))}</td>" for k in keys) + "</tr>"
                       for r in rows)
        return f"<table><tr>{head}</tr>{body}</table>"

    chosen = [{"sensors": p["sensors"], "added": p["added"], "detection rate": f"{p['detection_rate']:.3f}",
               "mean lead (m)": "" if p["mean_lead_m"] is None else f"{p['mean_lead_m']:.3f}"}
              for p in selection["chosen"]]
    text = f"""<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>proxsim study</title>
<style>body{{font-family:sans-serif;margin:2em;max-width:1100px}} table{{border-collapse:collapse;font-size:13px}}
td,th{{border:1px solid #ccc;padding:3px 6px}} img{{max-width:100%}}</style></head><body>
<h1>Sensor-placement study</h1>
<p>Files: <a href="results.csv">results.csv</a> (one row per run), <a href="ranking.csv">ranking.csv</a>,
<a href="selection.json">selection.json</a>.</p>
<h2>The best {selection['k']} sensors</h2>
<p>{html.escape(selection['objective'])}; {html.escape(selection['why_greedy'])}. {selection['items']} items.</p>
{table(chosen, ["sensors", "added", "detection rate", "mean lead (m)"])}
<h2>Sensor count against detection and lead</h2><img src="pareto.png" alt="Pareto front">
<h2>Lead distance over position and pitch</h2><img src="lead_heatmap.png" alt="lead heat maps">
<h2>Ranking of single mountings (first 20)</h2>
{table(ranking[:20], ["rank", "candidate", "detection_rate", "detection_rate_ci95", "lead_mean_m", "lead_ci95_m",
                      "false_alarms_mean", "self_share", "grazing_share", "floor_coverage"])}
</body></html>
"""
    write_text(os.path.join(out, "index.html"), text)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    out = sys.argv[1]
    # the same files draw the same figures, byte for byte (a merged study's as
    # a single run's, docs/studies.md): SVG ids from a fixed salt rather than
    # a random one, and the SVG date fixed (matplotlib reads SOURCE_DATE_EPOCH)
    plt.rcParams["svg.hashsalt"] = "proxsim-study"
    os.environ.setdefault("SOURCE_DATE_EPOCH", "0")
    with open(os.path.join(out, "selection.json")) as f:
        if json.load(f).get("mode") == "outcomes":
            # a closed-loop study: its own figures (outcome_report.py, beside this file)
            import outcome_report
            outcome_report.draw(out)
            print(f"study_report: figures and index.html in {out}")
            return
    results = read_csv(os.path.join(out, "results.csv"))
    ranking = read_csv(os.path.join(out, "ranking.csv"))
    with open(os.path.join(out, "selection.json")) as f:
        selection = json.load(f)
    if results:
        heatmap(results, out)
    pareto(selection, out)
    page(ranking, selection, out)
    print(f"study_report: figures and index.html in {out}")


if __name__ == "__main__":
    main()
