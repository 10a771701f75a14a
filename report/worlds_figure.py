"""Draws generated worlds (docs/worlds.md) from the scenarios `proxsim generate` writes:
rooms seen from above and courses seen from the side, at three difficulties.

Usage: python3 report/worlds_figure.py PROXSIM_BINARY OUT.png
Every shape is drawn from the written scenario's own numbers (boxes, cylinders,
spheres; people at their start; the robot's path), nothing is invented here.
"""
import math
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import yaml  # noqa: E402

DIFFICULTIES = [0.0, 0.5, 1.0]


def generate(binary, generate_map, folder):
    source = os.path.join(folder, "in.yaml")
    out = os.path.join(folder, "out.yaml")
    with open(source, "w") as f:
        f.write("proxsim: 1\nscene:\n  generate: " + generate_map + "\nrobot: {model: builtin:biped}\n"
                "sensors:\n  - {name: s, type: ideal, link: left_tibia}\n")
    subprocess.run([binary, "generate", source, "--out", out], check=True, capture_output=True)
    with open(out) as f:
        return yaml.safe_load(f)


def draw_room(ax, world):
    for obj in world["scene"]["objects"]:
        albedo = float(obj.get("material", {}).get("albedo", 0.6))
        if "person" in obj:
            (x, y) = obj["motion"]["waypoints_m"][0]
            (x1, y1) = obj["motion"]["waypoints_m"][1]
            ax.plot([x, x1], [y, y1], color="tab:red", lw=0.8, ls="--")
            ax.add_patch(plt.Circle((x, y), 0.25, color="tab:red"))
            continue
        if "box" in obj:
            sx, sy, _ = obj["box"]["size_m"]
            cx, cy, _ = obj["pose"]["xyz_m"]
            ax.add_patch(plt.Rectangle((cx - sx / 2, cy - sy / 2), sx, sy, color=str(1 - albedo * 0.8)))
        elif "cylinder" in obj or "sphere" in obj:
            r = obj["cylinder"]["radius_m"] if "cylinder" in obj else obj["sphere"]["radius_m"]
            cx, cy, _ = obj["pose"]["xyz_m"]
            ax.add_patch(plt.Circle((cx, cy), r, color=str(1 - albedo * 0.8)))
    path = world["robot"]["path"]["waypoints_m"]
    ax.plot([p[0] for p in path], [p[1] for p in path], color="tab:blue", lw=1.5)
    ax.plot(path[0][0], path[0][1], "o", color="tab:blue")
    ax.plot(path[-1][0], path[-1][1], "*", color="tab:blue", ms=10)
    ax.set_aspect("equal")
    ax.set_xlim(-1.3, 9.3)
    ax.set_ylim(-5.3, 5.3)


def draw_course(ax, world):
    for obj in world["scene"]["objects"]:
        if "box" not in obj:
            continue
        sx, sy, sz = obj["box"]["size_m"]
        cx, cy, cz = obj["pose"]["xyz_m"]
        pitch = math.radians(obj["pose"].get("rpy_deg", [0, 0, 0])[1])
        if cy - sy / 2 > 0 or cy + sy / 2 < 0:  # the row at y = 0 (box fields)
            continue
        # the box's side outline in x-z (pitched about y)
        corners = [(-sx / 2, -sz / 2), (sx / 2, -sz / 2), (sx / 2, sz / 2), (-sx / 2, sz / 2)]
        pts = [(cx + u * math.cos(pitch) + w * math.sin(pitch), cz - u * math.sin(pitch) + w * math.cos(pitch))
               for u, w in corners]
        color = "0.55" if obj.get("ground", False) else "tab:red"
        ax.add_patch(plt.Polygon(pts, color=color, lw=0))
    ax.set_xlim(-1, 21)
    ax.set_ylim(-1.2, 1.2)
    ax.set_aspect("equal")


def main():
    binary, out_png = sys.argv[1], sys.argv[2]
    fig, axes = plt.subplots(2, 3, figsize=(15, 8.5), gridspec_kw={"height_ratios": [2.2, 1]})
    with tempfile.TemporaryDirectory() as folder:
        for col, d in enumerate(DIFFICULTIES):
            room = generate(binary, "{kind: room, seed: 7, difficulty: %g}" % d, folder)
            draw_room(axes[0][col], room)
            n = sum(1 for o in room["scene"]["objects"] if "person" in o)
            axes[0][col].set_title("room, seed 7, difficulty %g: %d objects, %d people"
                                   % (d, len(room["scene"]["objects"]), n), fontsize=9)
            course = generate(binary, "{kind: course, seed: 7, difficulty: %g}" % d, folder)
            draw_course(axes[1][col], course)
            axes[1][col].set_title("course, seed 7, difficulty %g (side view at y = 0; holes red)" % d, fontsize=9)
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)


if __name__ == "__main__":
    main()
