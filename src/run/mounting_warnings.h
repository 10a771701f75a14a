// Mounting mistakes a run reveals only as it goes, said at its end (the
// run's output and summary.json's `warnings`), each naming the sensor:
//  - every reading it took was `self`: it sees only the robot's own body
//    (the link and the nearest distance are named: a sensor placed at a
//    surface point and tilted into its own shin reads it at a fraction of a
//    millimetre);
//  - all of its mounting angles are below 2π in magnitude, one at least is
//    not 0, and it never detected anything: radians typed into `rpy_deg`?
// (A sensor whose origin lies inside a scene object or its own link is said
// at the first sample: run_recorder.cc.)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scenario/scenario.h"
#include "sim/sample_frame.h"

namespace proxsim {

class MountingWatch {
 public:
  /// `object_names`: the world's objects, scene objects then robot links (World::object_names).
  MountingWatch(const Scenario& scenario, const std::vector<std::string>& object_names);

  /// Tallies one sample's readings.
  void Add(const SampleFrame& frame);

  /// The warnings the samples so far give, in sensor order.
  std::vector<std::string> Warnings() const;

 private:
  struct Tally {
    std::int64_t sampled = 0;   // readings taken (not `not_sampled`)
    std::int64_t self = 0;      // of them `self`
    std::int64_t detected = 0;  // of them detections
    double nearest_self_m = 0;  // the nearest `self` echo's true distance
    std::int32_t self_object = -1;  // its object
  };
  const Scenario& scenario_;
  const std::vector<std::string>& object_names_;
  std::vector<Tally> tallies_;
};

}  // namespace proxsim
