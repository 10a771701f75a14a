#!/usr/bin/env python3
"""The figure of a fidelity comparison, from the files `proxsim fidelity`
wrote in OUT: fidelity.json (the tables) and fidelity_pairs.csv (each
recorded reading beside the model's). docs/fidelity.md says what they hold.

  OUT/fidelity.png   four panels: the model's distance against the
                     recorded one (both valid), coloured by ring of zones;
                     the median error and the p90 of |error| as a fraction
                     of the recorded distance, by range band, one line per
                     ring; the median relative error of each zone on the
                     part's grid (multi-zone parts); the validity confusion
                     by range band

Usage: fidelity_report.py OUT   (Debian's /usr/bin/python3 with python3-matplotlib)
Exit 3 without matplotlib or numpy, 2 when OUT's files cannot be read.
"""
import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from proxsim_report.plotting import require_plotting  # noqa: E402

plt, np = require_plotting("fidelity_report")
from proxsim_report.safe_files import save_figure  # noqa: E402  (never through a link)
from proxsim_report.style import SENSOR_PALETTE  # noqa: E402  (the report's colours)

# the confusion's four cells, as fidelity_stats.h names them
CONFUSION = [("both_valid", "both valid", "#2a9d3a"), ("recorded_only", "recording only", "#f28e2b"),
             ("simulated_only", "model only", "#1f77b4"), ("both_invalid", "both invalid", "#9a9a9a")]


def read_inputs(out):
    with open(os.path.join(out, "fidelity.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "fidelity_pairs.csv"), newline="") as f:
        pairs = list(csv.DictReader(f))
    return summary, pairs


def rows_of(summary, table):
    return [r for r in summary["tables"] if r["table"] == table]


def scatter_panel(ax, pairs):
    """The model's distance against the recorded one, where both are valid."""
    both = [p for p in pairs if p["recorded_valid"] == "1" and p["simulated_valid"] == "1"]
    rings = sorted({int(p["ring"]) for p in both})
    top = 0.0
    for ring in rings:
        x = [float(p["recorded_d_m"]) for p in both if int(p["ring"]) == ring]
        y = [float(p["simulated_d_m"]) for p in both if int(p["ring"]) == ring]
        top = max([top] + x + y)
        ax.scatter(x, y, s=4, alpha=0.5, color=SENSOR_PALETTE[ring % len(SENSOR_PALETTE)], label=f"ring {ring}")
    ax.plot([0, top], [0, top], color="#333333", linewidth=0.8, label="model = recording")
    ax.set_xlabel("recorded distance (m)")
    ax.set_ylabel("model's distance (m)")
    ax.set_title("Readings both call valid", fontsize=9)
    ax.legend(fontsize=7, markerscale=3)


def band_panel(ax, summary):
    """Median and p90 |error| relative to the recorded distance, by band, one line per ring."""
    bands = [r for r in rows_of(summary, "band") if r["band"] >= 0]
    names = [r["band_name"] for r in bands]
    for ring_row in rows_of(summary, "ring"):
        ring = ring_row["ring"]
        colour = SENSOR_PALETTE[ring % len(SENSOR_PALETTE)]
        cells = {r["band"]: r for r in rows_of(summary, "ring_band") if r["ring"] == ring}
        median = [100 * cells[b["band"]]["median_rel_error"] if b["band"] in cells and
                  cells[b["band"]]["median_rel_error"] is not None else np.nan for b in bands]
        p90 = [100 * cells[b["band"]]["p90_abs_rel_error"] if b["band"] in cells and
               cells[b["band"]]["p90_abs_rel_error"] is not None else np.nan for b in bands]
        ax.plot(range(len(bands)), p90, "o-", color=colour, label=f"ring {ring}: p90 |error|")
        ax.plot(range(len(bands)), median, "s--", color=colour, alpha=0.7, label=f"ring {ring}: median error")
    ax.axhline(0, color="#333333", linewidth=0.6)
    ax.set_xticks(range(len(bands)), names, rotation=20, fontsize=8)
    ax.set_xlabel("range band (recorded distance)")
    ax.set_ylabel("% of the recorded distance")
    ax.set_title("Error (model − recording) by range band and ring", fontsize=9)
    ax.legend(fontsize=6, ncol=2)


def zone_panel(ax, summary):
    """The median relative error of each zone, laid out as the part's grid (row 0 at the top)."""
    zones = summary["sensor"].get("zones")
    if not zones:
        ax.axis("off")
        ax.text(0.5, 0.5, "a single-zone part:\nno zone grid", ha="center", va="center")
        return
    nx, ny = zones
    grid = np.full((ny, nx), np.nan)
    for r in rows_of(summary, "zone"):
        if r["median_rel_error"] is not None:
            grid[r["zone"] // nx, r["zone"] % nx] = 100 * r["median_rel_error"]
    limit = max(1.0, float(np.nanmax(np.abs(grid)))) if np.isfinite(grid).any() else 1.0
    image = ax.imshow(grid, cmap="RdBu_r", vmin=-limit, vmax=limit)
    for row in range(ny):
        for column in range(nx):
            if np.isfinite(grid[row, column]) and nx * ny <= 64:
                ax.text(column, row, f"{grid[row, column]:+.1f}", ha="center", va="center", fontsize=6)
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_title(f"Median error by zone, % ({nx}x{ny}; row 0 at the top, column 0 on the left\n"
                 "seen along the sensor's axis)", fontsize=9)
    plt.colorbar(image, ax=ax, fraction=0.046, label="%")


def validity_panel(ax, summary):
    """How the readings' validity compares, by range band (stacked counts)."""
    bands = rows_of(summary, "band")
    bottom = np.zeros(len(bands))
    for key, label, colour in CONFUSION:
        counts = np.array([b[key] for b in bands], dtype=float)
        ax.bar(range(len(bands)), counts, bottom=bottom, color=colour, label=label)
        bottom += counts
    for k, b in enumerate(bands):
        if b["validity_agreement"] is not None:
            ax.text(k, bottom[k], f"{b['validity_agreement']:.2f}", ha="center", va="bottom", fontsize=7)
    ax.set_xticks(range(len(bands)), [b["band_name"] for b in bands], rotation=20, fontsize=8)
    ax.set_xlabel("range band (recorded distance; invalid: the recording says so)")
    ax.set_ylabel("readings")
    ax.set_title("Validity: confusion counts and agreement by range band", fontsize=9)
    ax.legend(fontsize=7)


def main():
    if len(sys.argv) != 2:
        print("usage: fidelity_report.py OUT", file=sys.stderr)
        return 2
    out = sys.argv[1]
    try:
        summary, pairs = read_inputs(out)
    except (OSError, ValueError, KeyError) as e:
        print(f"fidelity_report: cannot read the comparison's files in {out}: {e}", file=sys.stderr)
        return 2
    sensor = summary["sensor"]
    fig, axes = plt.subplots(2, 2, figsize=(12, 9), constrained_layout=True)
    scatter_panel(axes[0][0], pairs)
    band_panel(axes[0][1], summary)
    zone_panel(axes[1][0], summary)
    validity_panel(axes[1][1], summary)
    noise = "on" if summary["simulate_noise"] else "off"
    fig.suptitle(f"{sensor['name']} ({sensor['part'] or sensor['type']}) against {summary['recording']}: "
                 f"{summary['samples']} samples, model noise {noise}", fontsize=10)
    save_figure(fig, os.path.join(out, "fidelity.png"), dpi=110)
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
