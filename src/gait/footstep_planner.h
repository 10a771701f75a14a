// Where the swing foot lands: a foothold on the ground profile ahead
// (gait/terrain_profile.h), as close as it can be to where the gait's curves
// would put the heel, with the sole flat on one level segment — heel and toe
// both on it, kept `margin_m` from its edges, so nothing of the sole
// overhangs — within the step lengths the legs take and the height
// (gait.max_step_m) they climb or descend. A foothold that would overhang an
// edge is moved along the path: back (a shorter step) or forward (a longer
// one), whichever is nearer the curves' heel.
//
// Two steps of look-ahead: of the footholds within reach, the nearest one
// from which the next two steps also find footholds is chosen (else one with
// one step ahead, else the nearest), so that the robot shortens its steps
// before a hole it can step over instead of landing too far from it.
//
// The step planner then checks the swing that will leave the chosen
// foothold (gait_steps.h, "Uneven ground"); when it would not clear the
// ground, it takes the next of PlanFootholds' other choices.
//
// When no foothold is within reach, the reason names what is ahead: a step
// up or down higher than max_step_m, a gap wider than a step can cross, or
// no level ground.
#pragma once

#include <string>
#include <vector>

#include "gait/terrain_profile.h"

namespace proxsim {

/// What the legs can do in one step.
struct FootholdLimits {
  double sole_length_m = 0.26;  ///< heel to toe
  double margin_m = 0.01;       ///< kept between either end of the sole and its segment's edges
  double min_step_m = 0.15;     ///< shortest step, heel to heel along the line
  double max_step_m = 0.6;      ///< longest step (one stride)
  double max_rise_m = 0.3;      ///< highest step up or down (gait.max_step_m)
};

/// A foothold, or why there is none.
struct Foothold {
  bool found = false;
  double s_heel_m = 0;  ///< the heel along the profile's line
  double z_m = 0;       ///< the tread's height
  std::size_t segment = 0;
  std::string reason;   ///< when not found: one line for a person
};

/// The foothold for a swing heel whose stance heel is at s_stance_m on a tread
/// at z_stance_m, nearest s_nominal_m (where the curves would put it).
Foothold PlanFoothold(const TerrainProfile& profile, double s_stance_m, double z_stance_m, double s_nominal_m,
                      const FootholdLimits& limits);

/// Up to `count` footholds for the same step, in the order to try them:
/// PlanFoothold's first, then the others within reach — those with the most
/// steps of look-ahead first, each set nearest s_nominal_m first — at least
/// spacing_m (> 0) apart. When none is within reach: one, not found, with the reason.
std::vector<Foothold> PlanFootholds(const TerrainProfile& profile, double s_stance_m, double z_stance_m,
                                   double s_nominal_m, const FootholdLimits& limits, double spacing_m,
                                   std::size_t count);

}  // namespace proxsim
