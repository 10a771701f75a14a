// A user's recording of one part, for `proxsim fidelity` (docs/fidelity.md):
// a CSV in long format, one row per zone per sample (one row per sample for
// a single-zone part, whose `zone` column may be left out):
//
//   t_s,x_m,y_m,z_m,qw,qx,qy,qz,zone,d_m,valid
//   0.000,0.0,0,0.3,1,0,0,0,0,1.203,1
//
// t_s the sample's time (strictly increasing from sample to sample; a
// sample's rows share it and its pose); x_m..z_m and qw..qz the pose X_WM of
// the recorded frame M in the world (a unit quaternion, Hamilton, w first);
// zone the part's zone index (multizone.h's order); d_m the distance the part
// reported; valid 1 when the part called it a valid target (ST's status 5 or
// 9), 0 otherwise (d_m is then ignored and may be empty). Columns may come
// in any order; lines starting with '#' are comments; every sample must list
// every zone once.
//
// Frames: W world, M the recorded frame.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry.h"

namespace proxsim {

struct Recording {
  std::string source;              ///< the file, as named in messages
  int zone_count = 1;              ///< zones per sample
  std::vector<double> t_s;         ///< [sample]
  std::vector<Pose> X_WM;          ///< [sample]: the recorded frame's pose (the quaternion normalised)
  std::vector<int> first_line;     ///< [sample]: the file line of its first row, for messages
  std::vector<double> d_m;         ///< [sample · zone_count + zone]: the reported distance (NaN where not valid)
  std::vector<char> valid;         ///< [sample · zone_count + zone]

  std::size_t sample_count() const { return t_s.size(); }
};

/// Reads `path` (see above) for a part of `zone_count` zones; throws
/// InputError listing the problems (at most 20), each as
/// "FILE:LINE: column 'NAME' (N): what was expected, got what was there".
Recording LoadRecording(const std::string& path, int zone_count);

/// The same from the file's text; `source` names it in messages.
Recording ParseRecording(const std::string& text, const std::string& source, int zone_count);

}  // namespace proxsim
