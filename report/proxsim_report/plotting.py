"""matplotlib (headless) and numpy for a report script, or its exit code 3:
the C++ runner (src/report/report_runner.cc) reads 3 as "install
python3-matplotlib python3-numpy" and says so."""
import sys


def require_plotting(script):
    """(pyplot, numpy) with matplotlib's Agg backend; exits 3 naming `script` when either is missing."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy as np
    except ImportError:
        print(f"{script}: needs python3-matplotlib and python3-numpy", file=sys.stderr)
        sys.exit(3)
    return plt, np
