"""The profile of one sensor (paper §6.2, Figs 9, 11, 13, 15): a side view along
the walking path of the world points the sensor detected, coloured by object,
over the true cross-section of the scene (grey) cut under that sensor."""
import numpy as np
from matplotlib.patches import Patch

from .cross_section import cut_scene
from .style import SECTION_EDGE, SECTION_FILL, object_color, sensor_title


def sensor_lateral(path, sensor, points_xy):
    """The sideways offset from the path where the section is cut: the median
    offset of the sensor's detected points, or of its origins."""
    xy = points_xy if len(points_xy) else sensor.p_origin[:, :2]
    xy = xy[np.all(np.isfinite(xy), axis=1)]
    if not len(xy):
        return 0.0
    return float(np.median(path.project(xy)[1]))


def draw_profile(ax, run, path, has_robot, sensor, compact=False):
    """Draws sensor's profile on ax; returns the object ids that have points."""
    prof = run.profile
    mine = prof["sensor"] == sensor.index
    pts = np.column_stack([prof["x"][mine], prof["y"][mine], prof["z"][mine]])
    obj_ids = prof["object"][mine]
    lateral = sensor_lateral(path, sensor, pts[:, :2])
    s_pts = path.project(pts[:, :2])[0] if len(pts) else np.zeros(0)
    origins = sensor.p_origin[np.all(np.isfinite(sensor.p_origin), axis=1)]
    s_org = path.project(origins[:, :2])[0] if len(origins) else np.zeros(0)

    # the window: the sensor's whole track, its reach ahead, and every point
    s_all = np.concatenate([s_pts, s_org])
    s_lo = (s_all.min() if len(s_all) else 0.0) - 0.3
    s_hi = (s_all.max() if len(s_all) else 1.0) + 0.3
    if len(s_org):
        s_hi = max(s_hi, s_org.max() + sensor.d_max_m + 0.15)
    s = np.linspace(s_lo, s_hi, 900)

    # the true cross-section, grey; the lowest it shows: the floor plane's top,
    # and every object's bottom under the path (a hole's floor, the steps'
    # feet), but not more than 1 m below the lowest top (a deep foundation)
    floor_z = -0.05
    tops, bottoms = [], []
    for cut in cut_scene(run.scene, path, s, lateral):
        if cut.wall_s is None and np.isfinite(cut.top).any():
            tops.append(np.nanmin(cut.top))
            if not cut.solid_below:
                bottoms.append(np.nanmin(cut.bottom))
        if cut.wall_s is not None:
            x0, x1 = (cut.wall_s, s_hi) if cut.wall_solid_after else (s_lo, cut.wall_s)
            ax.axvspan(x0, x1, color=SECTION_FILL, alpha=0.6, lw=0, zorder=0)
            continue
        top = cut.top
        if cut.solid_below:
            floor_z = min(floor_z, np.nanmin(top) - 0.05)
            ax.fill_between(s, top, -1e3, color=SECTION_FILL, ec=SECTION_EDGE, lw=0.8, zorder=0)
        else:
            ax.fill_between(s, cut.bottom, top, where=np.isfinite(top), color=SECTION_FILL,
                            ec=SECTION_EDGE, lw=0.8, zorder=0, interpolate=False)

    # the sensor's own track, faint, and its detections by object
    if len(origins):
        ax.plot(s_org, origins[:, 2], color="#777777", lw=0.5, alpha=0.5, zorder=1)
        if np.ptp(s_org) < 0.01 and np.ptp(origins[:, 2]) < 0.01:   # a fixed sensor: mark where it is
            ax.plot(s_org[:1], origins[:1, 2], marker=">", ms=6, color="#555555", zorder=2)
    for oid in np.unique(obj_ids):
        sel = obj_ids == oid
        ax.plot(s_pts[sel], pts[sel, 2], ls="none", marker="o", ms=1.8 if compact else 2.6,
                mew=0, color=object_color(oid), zorder=3)

    # the height shown: what the sensor saw and where it went (walls run off the top)
    z_hi = max([0.3] + ([pts[:, 2].max()] if len(pts) else []) +
               ([origins[:, 2].max() + 0.1] if len(origins) else []))
    z_lo = min([floor_z] + ([pts[:, 2].min() - 0.05] if len(pts) else []) +
               ([max(min(bottoms), min(tops) - 1.0) - 0.05] if bottoms else []))
    ax.set_xlim(s_lo, s_hi)
    ax.set_ylim(z_lo, z_hi + 0.08)
    ax.set_xlabel("distance along the path (m)" if has_robot else "x (m)")
    ax.set_ylabel("height z (m)")
    ax.set_title(sensor_title(sensor) if not compact else sensor.name, fontsize=10 if compact else 12)
    ax.grid(True, lw=0.3, alpha=0.5)
    if not len(pts):
        ax.text(0.5, 0.5, "no detections", transform=ax.transAxes, ha="center", color="#888888")
    return set(int(o) for o in np.unique(obj_ids))


def object_legend_handles(run, ids):
    names = {int(o.get("id", -1)): o.get("name", "?") for o in run.scene.get("objects", [])}
    handles = [Patch(color=object_color(i), label=names.get(i, f"object {i}")) for i in sorted(ids)]
    handles.append(Patch(color=SECTION_FILL, ec=SECTION_EDGE, label="true cross-section"))
    return handles


def profile_legend_handles(run, ids):
    from matplotlib.lines import Line2D
    handles = object_legend_handles(run, ids)
    handles.append(Line2D([], [], color="#777777", lw=0.6, label="sensor track"))
    return handles


def profile_figure(plt, run, path, has_robot, sensor):
    fig, ax = plt.subplots(figsize=(10.5, 3.6))
    # the legend goes right; 0.85 in on the left for tick labels like "-0.25" and the y-label
    fig.subplots_adjust(left=0.85 / 10.5, right=0.8, bottom=0.14, top=0.9)
    ids = draw_profile(ax, run, path, has_robot, sensor)
    ax.legend(handles=profile_legend_handles(run, ids), loc="upper left", bbox_to_anchor=(1.01, 1.0),
              fontsize=8, frameon=False)
    return fig
