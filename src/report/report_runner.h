// Draws a finished run's figures and writes its 3D replay viewer, by running
// the report script that ships with proxsim (report/make_report.py, matplotlib)
// with Debian's /usr/bin/python3, as a child process.
#pragma once

#include <string>

namespace proxsim {

/// Draws the figures and writes the viewer for a finished run in out_dir; returns 0 on success, else prints why to stderr and returns non-zero.
int MakeReport(const std::string& out_dir);

/// Draws a finished study's figures and its HTML page (report/study_report.py); 0 on success.
int MakeStudyReport(const std::string& out_dir);

/// Draws a fidelity comparison's figure, OUT/fidelity.png (report/fidelity_report.py); 0 on success.
int MakeFidelityReport(const std::string& out_dir);

}  // namespace proxsim
