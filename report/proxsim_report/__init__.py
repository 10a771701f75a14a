"""proxsim's report: figures (matplotlib) and the 3D replay viewer's data, drawn
from a finished run's output files. Entry point: report/make_report.py."""
