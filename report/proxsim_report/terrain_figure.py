"""terrain.png/.svg: the terrain map the robot built, seen from above, beside
the scene's truth, the error between them and the hazards, one panel under
the other along the walk (same x axis, the path walked drawn on each):
(1) the map's fused heights, and in lavender the cells known only through
free space (their surface lies below the rays that crossed them); (2) the
true heights; (3) the error elevation − truth on the cells measured; (4) the
hazards the map found (filled, by class) over the true ones in the robot's
corridor (dashed outlines). A hazard's rectangle is its extent's size
(hazards.csv size_x_m, size_y_m) centred on its centroid (x_m, y_m)."""
import numpy as np
from matplotlib import patheffects
from matplotlib.colors import ListedColormap
from matplotlib.patches import Patch, Rectangle

from .style import FREE_SPACE_COLOR, HAZARD_COLORS, HAZARD_LABELS, PATH_COLOR
from .terrain_data import height_limits

ERROR_RANGE_M = 0.05
# more hazards than this: no label each (they would hide each other), the count in the title
MAX_LABELLED_HAZARDS = 6
UNKNOWN_COLOR = "#f2f2f2"
# darker under the error, whose zero is white
UNKNOWN_ERROR_COLOR = "#c4c4c4"


def _length(v):
    if v is None:
        return "–"
    return "< 0.1 mm" if v < 1e-4 else (f"{1000 * v:.1f} mm" if v < 0.01 else f"{100 * v:.2f} cm")


def _score_line(score):
    err = score.get("elevation_error") or {}
    coverage = (score.get("corridor") or {}).get("coverage")
    return (f"{score.get('cells_measured', 0)} cells measured · RMSE {_length(err.get('rmse_m'))} · "
            f"p95 {_length(err.get('p95_m'))} · corridor coverage "
            f"{'–' if coverage is None else f'{100 * coverage:.1f} %'}")


def _draw_path(ax, path_xy):
    if path_xy is not None and len(path_xy) > 1:
        # a white halo: the path stays visible over dark heights
        ax.plot(path_xy[:, 0], path_xy[:, 1], color=PATH_COLOR, linewidth=1.0,
                path_effects=[patheffects.withStroke(linewidth=2.6, foreground="white")])


def _hazard_rectangle(h, **style):
    return Rectangle((h["x_m"] - h["size_x_m"] / 2, h["y_m"] - h["size_y_m"] / 2), h["size_x_m"], h["size_y_m"],
                     **style)


def terrain_figure(plt, terrain, path_xy=None):
    """The figure (four panels); path_xy: the robot's floor track (N×2) or None."""
    x_min, x_max, y_min, y_max = terrain.extent
    width, height = x_max - x_min, y_max - y_min
    # panels as wide as the page, as tall as the map's aspect asks (within limits)
    panel_h = max(1.4, min(4.0, 9.0 * height / max(width, 1e-6)))
    fig, axes = plt.subplots(4, 1, figsize=(10, 4 * panel_h + 1.2), sharex=True, sharey=True,
                             constrained_layout=True)
    z_lo, z_hi = height_limits(terrain)
    # unknown cells are transparent in every layer, over the axes' own grey
    cmap = plt.get_cmap("viridis").copy()
    cmap.set_bad((0, 0, 0, 0))
    kw = dict(origin="lower", extent=terrain.extent, interpolation="nearest", aspect="equal")

    # 1. the map: measured heights, and the cells only free space speaks for
    ax = axes[0]
    bound_only = np.where(np.isnan(terrain.elevation) & np.isfinite(terrain.upper_bound), 1.0, np.nan)
    ax.imshow(np.ma.masked_invalid(bound_only), cmap=ListedColormap([FREE_SPACE_COLOR]), vmin=0, vmax=1, **kw)
    image = ax.imshow(np.ma.masked_invalid(terrain.elevation), cmap=cmap, vmin=z_lo, vmax=z_hi, **kw)
    _draw_path(ax, path_xy)
    ax.set_title("the map: fused heights (lavender: known only from free space, the surface is below)",
                 fontsize=10)
    fig.colorbar(image, ax=ax, label="height (m)", shrink=0.9)

    # 2. the truth
    ax = axes[1]
    image = ax.imshow(np.ma.masked_invalid(terrain.truth), cmap=cmap, vmin=z_lo, vmax=z_hi, **kw)
    _draw_path(ax, path_xy)
    ax.set_title("the truth: highest surface below max_height_m at each cell centre", fontsize=10)
    fig.colorbar(image, ax=ax, label="height (m)", shrink=0.9)

    # 3. the error on the cells measured
    ax = axes[2]
    error = terrain.elevation.astype(np.float64) - terrain.truth
    error_cmap = plt.get_cmap("RdBu_r").copy()
    error_cmap.set_bad((0, 0, 0, 0))
    image = ax.imshow(np.ma.masked_invalid(error), cmap=error_cmap, vmin=-ERROR_RANGE_M, vmax=ERROR_RANGE_M, **kw)
    _draw_path(ax, path_xy)
    ax.set_title("error: map − truth on the cells measured (colours clipped at ±5 cm; grey: not measured)",
                 fontsize=10)
    fig.colorbar(image, ax=ax, label="error (m)", shrink=0.9)

    # 4. the hazards found over the true ones in the corridor
    ax = axes[3]
    ax.imshow(np.ma.masked_invalid(terrain.truth), cmap="Greys", vmin=z_lo - 0.5 * (z_hi - z_lo), vmax=z_hi,
              alpha=0.5, **kw)
    true_hazards = terrain.score.get("true_hazards") or []
    for t in true_hazards:
        color = HAZARD_COLORS.get(t["class"], "#000000")
        ax.add_patch(_hazard_rectangle(t, fill=False, edgecolor=color, linestyle="--", linewidth=1.2))
    labelled = len(terrain.hazards) <= MAX_LABELLED_HAZARDS
    for h in terrain.hazards:
        color = HAZARD_COLORS.get(h["class"], "#000000")
        ax.add_patch(_hazard_rectangle(h, facecolor=color, edgecolor=color, alpha=0.75))
        if not labelled:
            continue
        ax.annotate(f"{HAZARD_LABELS.get(h['class'], h['class'])} {100 * h['height_m']:+.0f} cm\n"
                    f"t={h['first_detection_t_s']:.2f} s, {h['distance_at_detection_m']:.2f} m ahead",
                    (h["x_m"], h["y_m"] + h["size_y_m"] / 2), fontsize=7, ha="center", va="bottom", color=color)
    _draw_path(ax, path_xy)
    handles = [Patch(facecolor=HAZARD_COLORS[c], alpha=0.75, label=f"{HAZARD_LABELS[c]} (map)") for c in HAZARD_COLORS
               if any(h["class"] == c for h in terrain.hazards)]
    handles += [Patch(fill=False, edgecolor=HAZARD_COLORS[c], linestyle="--", label=f"{HAZARD_LABELS[c]} (true)")
                for c in HAZARD_COLORS if any(t["class"] == c for t in true_hazards)]
    if path_xy is not None and len(path_xy) > 1:
        handles.append(plt.Line2D([], [], color=PATH_COLOR, label="path walked"))
    if handles:
        ax.legend(handles=handles, fontsize=7, loc="upper left", ncol=3)
    ax.set_title("hazards: the map's (filled) over the true ones in the corridor (dashed)"
                 + ("" if labelled else f"; {len(terrain.hazards)} found, each in hazards.csv"), fontsize=10)

    for k, ax in enumerate(axes):
        ax.set_facecolor(UNKNOWN_ERROR_COLOR if k == 2 else UNKNOWN_COLOR)
        ax.set_ylabel("y (m)")
        ax.set_xlim(x_min, x_max)
        ax.set_ylim(y_min, y_max)
    axes[-1].set_xlabel("x (m)")
    fig.suptitle("terrain map — " + _score_line(terrain.score), fontsize=10)
    return fig
