"""The distance curve of one sensor (paper §6.1, Figs 8, 10, 12, 14): measured
distance over time, coloured by status, the noise-free distance beside it, and
the sensor's range limits drawn as lines."""
import numpy as np

from .run_data import STATUSES
from .style import STATUS_COLORS, STATUS_LABELS, sensor_title


OUTCOME_COLORS = {"collided": "#d62728", "fell": "#8e44ad", "stopped": "#c0392b", "refused": "#8e44ad",
                  "reached_goal": "#1e8449"}


def draw_outcome(ax, outcome):
    """Marks how the episode ended (summary.json robot.outcome) with a vertical line at its time:
    collided, fell, stopped, refused or reached_goal (time_up needs no mark)."""
    if not outcome or outcome["name"] not in OUTCOME_COLORS or outcome.get("t_s") is None:
        return
    ax.axvline(outcome["t_s"], color=OUTCOME_COLORS[outcome["name"]], lw=1.1, ls="-.", zorder=4,
               label=f"{outcome['name'].replace('_', ' ')} at {outcome['t_s']:.2f} s")


def draw_curve(ax, sensor, compact=False, outcome=None):
    """Draws sensor's distance curve on ax (compact: smaller marks, no legend), and the
    episode's outcome when given."""
    t = sensor.t_s
    # the noise-free truth, broken where nothing was within range
    ax.plot(t, sensor.d_true_m, color="#222222", lw=0.7, alpha=0.55, zorder=2,
            label="noise-free distance")
    # the measured distance: a faint line and one mark per sample, by status
    ax.plot(t, sensor.d_m, color="#5a7fa8", lw=0.5, alpha=0.35, zorder=1)
    size = 1.6 if compact else 2.4
    for status in STATUSES:
        sel = sensor.status == status
        if sel.any():
            ax.plot(t[sel], sensor.d_m[sel], ls="none", marker="o", ms=size, mew=0,
                    color=STATUS_COLORS[status], zorder=3,
                    label=f"{STATUS_LABELS[status]} ({sel.sum()})")
    ax.axhline(sensor.d_max_m, color="#b03030", ls="--", lw=0.9, zorder=0,
               label=f"d_max = {sensor.d_max_m:g} m")
    if sensor.d_min_m > 0:
        ax.axhline(sensor.d_min_m, color="#b07030", ls=":", lw=0.9, zorder=0,
                   label=f"d_min = {sensor.d_min_m:g} m")
    draw_outcome(ax, outcome)
    ax.set_ylim(0, sensor.d_max_m * 1.08)
    if len(t):
        ax.set_xlim(t.min(), max(t.max(), t.min() + 1e-3))
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("distance (m)")
    ax.set_title(sensor_title(sensor) if not compact else sensor.name, fontsize=10 if compact else 12)
    ax.grid(True, lw=0.3, alpha=0.5)
    if not len(t):
        ax.text(0.5, 0.5, "no readings", transform=ax.transAxes, ha="center", color="#888888")
    if not compact:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, markerscale=2.5, frameon=False)


def curve_figure(plt, sensor, outcome=None):
    fig, ax = plt.subplots(figsize=(10.5, 3.6))
    fig.subplots_adjust(left=0.065, right=0.8, bottom=0.14, top=0.9)   # the legend goes right
    draw_curve(ax, sensor, outcome=outcome)
    return fig
