#!/usr/bin/env python3
"""Writes wall_vl53l5cx.csv: a SYNTHESISED recording of a VL53L5CX (8x8 zones)
facing a flat white wall, for `proxsim fidelity` (docs/fidelity.md).

NOT MEASURED ON HARDWARE. Every reading is computed here by closed-form
geometry from the datasheet's figures, independently of proxsim (nothing of
proxsim is imported or run), and made noisy with a seeded Gaussian. It is the
command's example and its test; a team judging the model should record its
own part on its own bench and compare with that.

Geometry. The wall is the plane x = WALL_X_M facing -x (white, 88 %
reflectance, in the dark). The sensor stands at (WALL_X_M - d, 0, SENSOR_Z_M)
with its axis (+x) turned by a yaw psi about +z: d is its perpendicular
distance from the wall, psi the angle between its axis and the wall's normal.
Its 8x8 zones split its 45 deg x 45 deg square field of view into equal cells
of the image plane x = 1 (u = y/x, v = z/x each across +-tan 22.5 deg; zone =
row*8 + column, row 0 at the top (+z), column 0 on the left (+y) seen along
+x: ST's SPAD grid behind the lens, UM2884's zone order). A zone's centre
direction in the sensor frame is (1, u, v); turned by psi it meets the wall at
    t = d * |(1, u, v)| / (cos psi - u sin psi)        (along the ray)
and the part reports the distance along its own axis of that point (ST's
chips convert radial to perpendicular on the chip: SENSOR_FACTS, ST's forum)
    reading = t / |(1, u, v)| = d / (cos psi - u sin psi).
Head-on (psi = 0) every zone reads d.

Noise. DS13754 Table 19 gives the 8x8 ranging accuracy for a white target in
the dark as +-5 % (201-4000 mm). It is read here as the bound that about 95 %
of readings fall within: a Gaussian of sigma = 2.5 % of the reading (an
assumption: ST does not say which quantile its figure is; proxsim's own
sensor model reads the same figure as sigma, docs/sensors.md), then rounded
to the millimetre the ULD API reports. Seeded (SEED): the file is the same on
every machine (Python's random.Random is specified to be reproducible).

Validity. DS13754 Table 18: a white 88 % target in the dark is ranged to
3.5 m by the centre zones and 3.1 m by the corner zones (8x8, 90 % detection
rate). A zone is valid (ST status 5) here when the wall point on its centre
direction lies within 3.1 m along that direction, the shorter figure, for
every zone; the datasheet gives head-on ranges only, so the wall's incidence
is not taken into account. Beyond it the zone is written invalid (valid 0,
d_m empty; ST would report status 255).

Usage: python3 data/fidelity/make_wall_recording.py [OUT.csv]
(default: wall_vl53l5cx.csv beside this script). Needs Python 3 only.
"""
import math
import os
import random
import sys

SEED = 20261129
WALL_X_M = 3.0
SENSOR_Z_M = 0.5
DISTANCES_M = (0.3, 0.5, 0.8, 1.2, 1.6, 2.0)   # perpendicular distance to the wall
YAWS_DEG = (0.0, 20.0, 40.0)                    # the sensor's axis from the wall's normal
SAMPLES_PER_POSE = 3
RATE_HZ = 15.0                                  # the VL53L5CX's 8x8 ranging frequency
ZONES = 8
HALF_FOV_DEG = 22.5
ACCURACY = 0.05                                 # DS13754 Table 19, 8x8, white, dark
SIGMA = ACCURACY / 2.0                          # read as a 95 % bound (see above)
MAX_RANGE_M = 3.1                               # DS13754 Table 18, 8x8 white dark, corner zones


def zone_centre_uv(zone):
    """(u, v) of a zone's centre on the image plane x = 1."""
    row, column = divmod(zone, ZONES)
    half = math.tan(math.radians(HALF_FOV_DEG))
    u = half * (1.0 - (2 * column + 1) / ZONES)   # column 0 on the left (+y)
    v = half * (1.0 - (2 * row + 1) / ZONES)      # row 0 at the top (+z)
    return u, v


def zone_reading(d_m, yaw_deg, zone):
    """(perpendicular reading, distance along the zone's centre direction) of the wall, m."""
    u, v = zone_centre_uv(zone)
    psi = math.radians(yaw_deg)
    facing = math.cos(psi) - u * math.sin(psi)    # the ray's x component in the world, times |(1, u, v)|
    perpendicular_m = d_m / facing
    along_ray_m = perpendicular_m * math.sqrt(1.0 + u * u + v * v)
    return perpendicular_m, along_ray_m


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                            "wall_vl53l5cx.csv")
    rng = random.Random(SEED)
    lines = [
        "# SYNTHESISED, NOT MEASURED: a VL53L5CX (8x8) facing a flat white wall, computed by closed-form",
        "# geometry from the datasheet (DS13754) by data/fidelity/make_wall_recording.py, independently of",
        "# proxsim; noise: Gaussian sigma = 2.5 % of the reading (the +-5 % accuracy read as a 95 % bound),",
        f"# seed {SEED}, rounded to 1 mm; valid when the wall lies within 3.1 m along the zone's centre.",
        "# Use your own bench recording to judge the model. Columns: docs/fidelity.md.",
        "t_s,x_m,y_m,z_m,qw,qx,qy,qz,zone,d_m,valid",
    ]
    sample = 0
    for yaw_deg in YAWS_DEG:
        half_yaw = math.radians(yaw_deg) / 2.0
        qw, qz = math.cos(half_yaw), math.sin(half_yaw)   # a turn about +z
        for d_m in DISTANCES_M:
            for _ in range(SAMPLES_PER_POSE):
                t_s = sample / RATE_HZ
                pose = f"{t_s:.6f},{WALL_X_M - d_m:.6f},0,{SENSOR_Z_M},{qw:.12f},0,0,{qz:.12f}"
                for zone in range(ZONES * ZONES):
                    perpendicular_m, along_ray_m = zone_reading(d_m, yaw_deg, zone)
                    noisy_m = perpendicular_m * (1.0 + SIGMA * rng.gauss(0.0, 1.0))
                    if along_ray_m <= MAX_RANGE_M:
                        lines.append(f"{pose},{zone},{round(noisy_m * 1000) / 1000:.3f},1")
                    else:
                        lines.append(f"{pose},{zone},,0")
                sample += 1
    with open(out, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{out}: {sample} samples x {ZONES * ZONES} zones")


if __name__ == "__main__":
    main()
