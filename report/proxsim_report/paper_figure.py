"""The paper's comparison (Figs 8–15 side by side): one column per sensor type
(ideal, laser, ultrasonic, reflectance), the distance curve above the profile."""
from .curve_figure import OUTCOME_COLORS, draw_curve
from .figure_legend import fit_bottom_legend
from .profile_figure import draw_profile, object_legend_handles
from .run_data import STATUSES
from .style import PAPER_TYPE_ORDER, STATUS_COLORS, STATUS_LABELS, TYPE_LABELS


def paper_sensors(sensors):
    """The first sensor of each of the paper's types, in the paper's order; or,
    when the run has none of them, its first four sensors."""
    picked = []
    for kind in PAPER_TYPE_ORDER:
        s = next((s for s in sensors if s.type == kind), None)
        if s is not None:
            picked.append(s)
    return picked or list(sensors[:4])


def paper_figure(plt, run, path, has_robot):
    from matplotlib.lines import Line2D
    cols = paper_sensors(run.sensors)
    n = max(len(cols), 1)
    # margins in inches, so that one or two columns keep their y-labels
    width_in, plots_in = 4.3 * n, 6.2
    fig, axes = plt.subplots(2, n, figsize=(width_in, plots_in), squeeze=False)
    ids = set()
    for j, sensor in enumerate(cols):
        draw_curve(axes[0, j], sensor, compact=True, outcome=run.outcome)
        ids |= draw_profile(axes[1, j], run, path, has_robot, sensor, compact=True)
        axes[0, j].set_title(f"{TYPE_LABELS.get(sensor.type, sensor.type)}\n{sensor.name}", fontsize=10)
        axes[1, j].set_title(f"profile: {sensor.name}", fontsize=10)
    status_handles = [Line2D([], [], ls="none", marker="o", color=STATUS_COLORS[s], label=STATUS_LABELS[s])
                      for s in STATUSES
                      if s not in ("dropout", "crosstalk") or any((sensor.status == s).any() for sensor in cols)]
    status_handles.append(Line2D([], [], color="#222222", lw=0.8, label="noise-free"))
    status_handles.append(Line2D([], [], color="#b03030", ls="--", lw=0.9, label="d_max"))
    status_handles.append(Line2D([], [], color="#777777", lw=0.6, label="sensor track"))
    if run.outcome and run.outcome["name"] in OUTCOME_COLORS:
        status_handles.append(Line2D([], [], color=OUTCOME_COLORS[run.outcome["name"]], ls="-.", lw=1.1,
                                     label=f"{run.outcome['name'].replace('_', ' ')} at {run.outcome['t_s']:.2f} s"))
    legend_in = fit_bottom_legend(fig, status_handles + object_legend_handles(run, ids))
    # the legend's rows below the plots: the figure grows by them
    title_in, xlabel_in = 0.95, 0.55
    height_in = plots_in + legend_in + 0.1
    fig.set_size_inches(width_in, height_in)
    # fixed margins: a layout engine costs seconds here, and the grid is regular
    fig.subplots_adjust(left=0.75 / width_in, right=1 - 0.12 / width_in, top=1 - title_in / height_in,
                        bottom=(legend_in + 0.1 + xlabel_in) / height_in, hspace=0.5, wspace=0.28)
    fig.suptitle("Distance curves (top) and profiles (bottom) per sensor type" if n > 1 else
                 "Distance curve (top) and profile (bottom)", fontsize=13 if n > 1 else 11)
    return fig
