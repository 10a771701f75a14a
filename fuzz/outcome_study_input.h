// An outcome study file a fuzz input stands for (fuzz/fuzz_outcome_study.cc,
// replayed by FuzzRegressionTest.OutcomeStudy): the input's bytes written as
// study.yaml in a private temporary folder, beside a small base scenario
// `walker.yaml` the study may name (`base: walker.yaml`) and a detection
// study's `ranking.csv` (`combine: {from: ranking.csv}`), then loaded as
// `proxsim study` loads it. Any input must load or be refused with an
// InputError naming the fault.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "study/outcome_config.h"

namespace proxsim {

inline OutcomeStudyConfig LoadFuzzedOutcomeStudy(std::string_view bytes) {
  static const std::filesystem::path dir = [] {
    const auto path = std::filesystem::temp_directory_path() / ("proxsim_fuzz_outcome_" + std::to_string(getpid()));
    std::filesystem::create_directories(path);
    std::ofstream(path / "walker.yaml")
        << "proxsim: 1\nduration_s: 4\nrate_hz: 20\n"
           "robot: {model: builtin:biped, path: {waypoints_m: [[0, 0], [2, 0]]}}\n"
           "sensors:\n  - {name: s, type: ideal, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.2]}}\n";
    std::ofstream(path / "ranking.csv")
        << "rank,candidate,type,part,link,along_m,forward_m,pitch_deg,yaw_deg,detection_rate,detection_rate_ci95,"
           "lead_mean_m,lead_ci95_m,false_alarms_mean,self_share,grazing_share,floor_coverage\n"
           "1,laser@left_tibia:z-0.35:x0.06:p15:y0,laser,,left_tibia,-0.35,0.06,15,0,1,0,0.5,0,0,0,0,0.5\n"
           "2,vl53l0x@right_tibia:z-0.25:x0.06:p0:y0,laser,vl53l0x,right_tibia,-0.25,0.06,0,0,1,0,0.4,0,0,0,0,0.5\n";
    return path;
  }();
  const std::filesystem::path study = dir / "study.yaml";
  std::ofstream(study, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return LoadOutcomeStudyFile(study.string());
}

}  // namespace proxsim
