"""Colours and labels shared by the figures and the viewer, so that a status or
an object has the same colour in every picture."""

STATUS_COLORS = {
    "ok": "#2a9d3a",         # a detection
    "no_echo": "#9a9a9a",    # nothing within range
    "too_close": "#f28e2b",
    "grazing": "#d62728",    # incidence outside the sensor's window
    "self": "#8c56b8",       # hit the robot's own body
    "dropout": "#e7c31c",    # an echo lost to the noise model's dropout
    "crosstalk": "#17becf",  # another ultrasonic sensor's ping, read as an echo
}
STATUS_LABELS = {"ok": "detected", "no_echo": "no echo", "too_close": "too close",
                 "grazing": "grazing", "self": "self (own body)",
                 "dropout": "dropout", "crosstalk": "crosstalk (another's ping)"}
TYPE_LABELS = {"ideal": "ideal sensor", "laser": "laser range finder",
               "ultrasonic": "ultrasonic sensor", "reflectance": "reflectance (IR) sensor",
               "lookup": "lookup-table sensor"}
PAPER_TYPE_ORDER = ("ideal", "laser", "ultrasonic", "reflectance")

# objects: a qualitative palette, indexed by object id (cycled); twenty
# colours, so that the stairs course's pieces (fifteen objects) differ
_OBJECT_PALETTE = ["#1f77b4", "#ff7f0e", "#17becf", "#e377c2", "#bcbd22",
                   "#8c564b", "#2ca02c", "#9467bd", "#d62728", "#7f7f7f",
                   "#393b79", "#e7969c", "#637939", "#fdae6b", "#6baed6",
                   "#7b4173", "#b5cf6b", "#843c39", "#31a354", "#de9ed6"]
SENSOR_PALETTE = ["#1f77b4", "#e6550d", "#31a354", "#756bb1", "#c51b8a",
                  "#3182bd", "#fd8d3c", "#74c476", "#9e9ac8", "#636363"]
SECTION_FILL = "#c8c8c8"
SECTION_EDGE = "#8a8a8a"


def object_color(object_id):
    return _OBJECT_PALETTE[int(object_id) % len(_OBJECT_PALETTE)] if object_id >= 0 else "#000000"


def sensor_color(index):
    return SENSOR_PALETTE[int(index) % len(SENSOR_PALETTE)]


def sensor_title(sensor):
    return f"{sensor.name} ({TYPE_LABELS.get(sensor.type, sensor.type)})"

# the terrain map's hazard classes (terrain/hazards.h), in the figure and the viewer
HAZARD_COLORS = {"obstacle": "#d62728", "step_up": "#ff7f0e", "step_down": "#1f77b4", "hole": "#6a3d9a"}
HAZARD_LABELS = {"obstacle": "obstacle", "step_up": "step up", "step_down": "step down", "hole": "hole"}
# cells the map knows only through free space (an upper bound, no height)
FREE_SPACE_COLOR = "#c7b3e8"
# the path walked, over the terrain panels
PATH_COLOR = "#333333"
# matplotlib's viridis at 9 even stops: the viewer colours heights as the figure does
VIRIDIS_STOPS = ["#440154", "#472d7b", "#3b528b", "#2c728e", "#21918c", "#28ae80", "#5ec962", "#addc30", "#fde725"]
