"""terrain.png/.svg: the terrain map the robot built, seen from above, beside
the scene's truth, the error between them and the hazards, one panel under
the other along the walk: (1) the map's heights (cells known only through
free space, from above, in pale violet), (2) the true heights, (3) the error
elevation − truth on the cells measured, (4) the hazards the map found
(filled, by class) over the true ones in the corridor (dashed outlines),
with the robot's path."""
import numpy as np
from matplotlib.patches import Patch, Rectangle

from .style import HAZARD_COLORS, HAZARD_LABELS

ERROR_RANGE_M = 0.05


def _height_limits(terrain):
    values = np.concatenate([a[np.isfinite(a)].ravel() for a in (terrain.elevation, terrain.truth)] or [np.zeros(1)])
    if values.size == 0:
        return -0.1, 0.2
    lo, hi = float(np.percentile(values, 0.5)), float(np.percentile(values, 99.5))
    return (lo - 0.05, hi + 0.05) if hi - lo < 0.1 else (lo, hi)


def _score_line(score):
    err = score.get("elevation_error") or {}
    cor = score.get("corridor") or {}

    def cm(v):
        if v is None:
            return "–"
        return "< 0.1 mm" if v < 1e-4 else (f"{1000 * v:.1f} mm" if v < 0.01 else f"{100 * v:.2f} cm")

    coverage = cor.get("coverage")
    return (f"{score.get('cells_measured', 0)} cells measured · RMSE {cm(err.get('rmse_m'))} · "
            f"p95 {cm(err.get('p95_m'))} · corridor coverage "
            f"{'–' if coverage is None else f'{100 * coverage:.1f} %'}")


def terrain_figure(plt, terrain, path_xy=None):
    """The figure (four panels); path_xy: the robot's floor track (N×2) or None."""
    x_min, x_max, y_min, y_max = terrain.extent
    width, height = x_max - x_min, y_max - y_min
    panel_h = max(1.4, min(4.0, 9.0 * height / max(width, 1e-6)))
    fig, axes = plt.subplots(4, 1, figsize=(10, 4 * panel_h + 1.2), sharex=True, sharey=True,
                             constrained_layout=True)
    z_lo, z_hi = _height_limits(terrain)
    cmap = plt.get_cmap("viridis").copy()
    cmap.set_bad("#f2f2f2")
    kw = dict(origin="lower", extent=terrain.extent, interpolation="nearest", aspect="equal")

    # 1. the map: measured heights, and the cells only free space speaks for
    ax = axes[0]
    bound_only = np.where(np.isnan(terrain.elevation) & np.isfinite(terrain.upper_bound), 1.0, np.nan)
    ax.imshow(np.ma.masked_invalid(bound_only), cmap="Purples", vmin=0, vmax=4, **kw)
    image = ax.imshow(np.ma.masked_invalid(terrain.elevation), cmap=cmap, vmin=z_lo, vmax=z_hi, **kw)
    ax.set_title("the map: fused heights (pale violet: known only from free space)", fontsize=10)
    fig.colorbar(image, ax=ax, label="height (m)", shrink=0.9)

    # 2. the truth
    ax = axes[1]
    image = ax.imshow(np.ma.masked_invalid(terrain.truth), cmap=cmap, vmin=z_lo, vmax=z_hi, **kw)
    ax.set_title("the truth: highest surface below max_height_m at each cell centre", fontsize=10)
    fig.colorbar(image, ax=ax, label="height (m)", shrink=0.9)

    # 3. the error on the cells measured
    ax = axes[2]
    error = terrain.elevation.astype(np.float64) - terrain.truth
    error_cmap = plt.get_cmap("RdBu_r").copy()
    error_cmap.set_bad("#f2f2f2")
    image = ax.imshow(np.ma.masked_invalid(error), cmap=error_cmap, vmin=-ERROR_RANGE_M, vmax=ERROR_RANGE_M, **kw)
    ax.set_title("error: map − truth on the cells measured (clipped at ±5 cm)", fontsize=10)
    fig.colorbar(image, ax=ax, label="error (m)", shrink=0.9)

    # 4. the hazards found, the true ones in the corridor, the path
    ax = axes[3]
    ax.imshow(np.ma.masked_invalid(terrain.truth), cmap="Greys", vmin=z_lo - 0.5 * (z_hi - z_lo), vmax=z_hi,
              alpha=0.5, **kw)
    for h in terrain.hazards:
        color = HAZARD_COLORS.get(h["class"], "#000000")
        ax.add_patch(Rectangle((h["x_m"] - h["size_x_m"] / 2, h["y_m"] - h["size_y_m"] / 2), h["size_x_m"],
                               h["size_y_m"], facecolor=color, edgecolor=color, alpha=0.75))
        ax.annotate(f"{HAZARD_LABELS.get(h['class'], h['class'])} {100 * h['height_m']:+.0f} cm\n"
                    f"t={h['first_detection_t_s']:.2f} s, {h['distance_at_detection_m']:.2f} m ahead",
                    (h["x_m"], h["y_m"] + h["size_y_m"] / 2), fontsize=7, ha="center", va="bottom", color=color)
    for t in terrain.score.get("true_hazards") or []:
        color = HAZARD_COLORS.get(t["class"], "#000000")
        ax.add_patch(Rectangle((t["x_m"] - t["size_x_m"] / 2, t["y_m"] - t["size_y_m"] / 2), t["size_x_m"],
                               t["size_y_m"], fill=False, edgecolor=color, linestyle="--", linewidth=1.2))
    if path_xy is not None and len(path_xy) > 1:
        ax.plot(path_xy[:, 0], path_xy[:, 1], color="#333333", linewidth=1.0, label="path walked")
    handles = [Patch(facecolor=HAZARD_COLORS[c], alpha=0.75, label=f"{HAZARD_LABELS[c]} (map)") for c in HAZARD_COLORS
               if any(h["class"] == c for h in terrain.hazards)]
    handles += [Patch(fill=False, edgecolor=HAZARD_COLORS[c], linestyle="--", label=f"{HAZARD_LABELS[c]} (true)")
                for c in HAZARD_COLORS if any(t["class"] == c for t in terrain.score.get("true_hazards") or [])]
    if path_xy is not None and len(path_xy) > 1:
        handles.append(plt.Line2D([], [], color="#333333", label="path walked"))
    if handles:
        ax.legend(handles=handles, fontsize=7, loc="upper left", ncol=3)
    ax.set_title("hazards: the map's (filled) over the true ones in the corridor (dashed)", fontsize=10)
    for ax in axes:
        ax.set_ylabel("y (m)")
        ax.set_xlim(x_min, x_max)
        ax.set_ylim(y_min, y_max)
    axes[-1].set_xlabel("x (m)")
    fig.suptitle("terrain map — " + _score_line(terrain.score), fontsize=10)
    return fig
