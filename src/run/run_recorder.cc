#include "run/run_recorder.h"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "core/atomic_file.h"
#include "output/measurements_npy.h"
#include "output/poses_csv.h"
#include "output/profile_ply.h"
#include "output/run_manifest.h"
#include "output/scene_json.h"
#include "output/statistics_sink.h"
#include "output/terrain_sink.h"
#include "scene/shape_inside.h"
#include "sim/run_summary.h"

namespace proxsim {

namespace {

// Suspicious but legal: a sensor whose ray starts inside a scene object, or
// exactly on its surface (its rays may then hit that surface at d = 0), or
// inside the link it is fixed on (its rays then see only that link, `self`).
// A sensor on its link's surface is how sensors are mounted: no warning.
std::vector<std::string> SensorsInsideObjects(const Simulation& sim, const SampleFrame& frame) {
  constexpr double kOnSurface_m = 1e-9;
  // A sensor mounted on its link's surface, at a point computed from the
  // link's float mesh vertices (`proxsim inspect` reports them), may land a
  // few 1e-8 m inside it: only deeper than this is inside.
  constexpr double kOnLinkSurface_m = 1e-4;
  // within this of its link's surface, a sensor whose axis goes into the link sees only it
  constexpr double kNearLinkSurface_m = 2e-3;
  constexpr double kFacingStep_m = 1e-3;
  const Scenario& scenario = sim.scenario();
  std::vector<std::string> warnings;
  for (std::size_t s = 0; s < scenario.sensors.size() && s < frame.sensors.size(); ++s) {
    const Vec3& p_WS = frame.sensors[s].p_WS;
    char where[160];
    std::snprintf(where, sizeof where, "at t = %g s its origin (%g, %g, %g) m", frame.t_s, p_WS.x(), p_WS.y(),
                  p_WS.z());
    const std::string sensor = scenario.source + ": sensor '" + scenario.sensors[s].name + "'";
    for (const SceneObject& object : scenario.scene.objects) {
      const double depth_m = DepthInside_m(object.shape, object.X_WO.inverse() * p_WS);
      if (depth_m < -kOnSurface_m) continue;
      if (depth_m > kOnSurface_m) {
        warnings.push_back(sensor + " is inside object '" + object.name + "' (" + where +
                           "); it sees that object from within");
      } else {
        warnings.push_back(sensor + " starts on the surface of object '" + object.name + "' (" + where +
                           "); its rays may hit that surface at d = 0");
      }
    }
    // its own link, at its pose of this sample (a sensor that sees through the robot does not mind)
    const int link = sim.rig().sensor_link(s);
    if (link < 0 || sim.robot() == nullptr || !scenario.sensors[s].see_robot) continue;
    const RobotLink& robot_link = sim.robot()->model().link(link);
    const Pose X_LW = sim.robot()->X_WL(link).inverse();
    const Vec3 p_LS = X_LW * p_WS;
    // a step along its axis from its origin, to tell a sensor on the surface
    // facing into the link from one facing out of it
    const Vec3 p_L_ahead = p_LS + kFacingStep_m * (X_LW.linear() * frame.sensors[s].dir_W);
    for (const LinkShape& shape : robot_link.shapes) {
      const Pose X_OL = shape.X_LO.inverse();
      const double depth_m = DepthInside_m(shape.shape, X_OL * p_LS);
      if (depth_m > kOnLinkSurface_m) {
        warnings.push_back(sensor + " is inside its own link '" + robot_link.name + "' (" + where +
                           "); it sees that link from within (echoes `self`); move it out to the link's surface "
                           "(`proxsim inspect` lists where it is)");
        break;  // one line per sensor and link
      }
      if (depth_m > -kNearLinkSurface_m && DepthInside_m(shape.shape, X_OL * p_L_ahead) > 0) {
        warnings.push_back(sensor + " sits within 2 mm of the surface of its own link '" + robot_link.name +
                           "', facing into it (" + where +
                           "): its axis meets the link at once (echoes `self`); turn it out, or move it a few "
                           "millimetres proud of the surface");
        break;
      }
    }
  }
  return warnings;
}

}  // namespace

RunRecorder::RunRecorder(const Simulation& sim, const std::string& out_dir, ReadingsFormat format,
                         std::function<void(const std::string&)> warn, bool force)
    : sim_(sim), warn_(std::move(warn)), mounting_(sim.scenario(), sim.world().object_names()) {
  if (!out_dir.empty()) {
    folder_ = std::make_shared<OutputFolder>(out_dir, ClaimOptions{.command = "run", .force = force});
    out_dir_ = folder_->path();
    TrackCommitsUnder(out_dir_);  // the manifest lists exactly the files this run commits
  }
  const Scenario& scenario = sim.scenario();
  const std::vector<std::string>& object_names = sim.world().object_names();
  const std::filesystem::path out(out_dir_);
  // the sinks in the order summary.json lists their files
  if (!out_dir_.empty()) {
    // the folder holds one run: the previous run's files go (the user's own stay)
    RemovePreviousRun(out_dir_);
    sinks_.push_back(MakeReadingsSink(format, out_dir_, scenario, object_names));
    sinks_.push_back(std::make_unique<ProfilePlyWriter>((out / "profile.ply").string()));
    if (sim.robot()) sinks_.push_back(std::make_unique<PosesCsvWriter>((out / "poses.csv").string(), *sim.robot()));
    if (sim.robot() && sim.robot_state()) {
      sinks_.push_back(std::make_unique<JointsCsvWriter>((out / "joints.csv").string(), sim.robot()->model(),
                                                         *sim.robot_state()));
    }
    if (ObjectPosesCsvWriter::Needed(scenario.scene)) {
      sinks_.push_back(std::make_unique<ObjectPosesCsvWriter>((out / "objects_poses.csv").string(), scenario.scene));
    }
    // what parts report beside their reading: zones' targets, beams' echoes
    for (const auto kind : {MeasurementsNpyWriter::Kind::kZones, MeasurementsNpyWriter::Kind::kEchoes})
      if (MeasurementsNpyWriter::Needed(scenario, kind))
        sinks_.push_back(std::make_unique<MeasurementsNpyWriter>(out_dir_, scenario, kind));
  }
  if (sim.terrain_map()) {
    sinks_.push_back(std::make_unique<TerrainSink>(*sim.terrain_map(), sim.world().caster(),
                                                   out_dir_.empty() ? "" : (out / "terrain").string()));
  }
  sinks_.push_back(std::make_unique<StatisticsSink>(scenario, object_names));
}

RunRecorder::~RunRecorder() {
  if (!out_dir_.empty()) StopTrackingCommits(out_dir_);
}

void RunRecorder::Add(const SampleFrame& frame) {
  ++samples_;
  last_t_s_ = frame.t_s;
  if (frame.sample == 0) {
    warnings_ = SensorsInsideObjects(sim_, frame);
    if (warn_)
      for (const std::string& warning : warnings_) warn_(warning);
  }
  for (const auto& sink : sinks_) sink->Add(frame);
  mounting_.Add(frame);
}

nlohmann::json RunRecorder::Summary(bool interrupted) const {
  nlohmann::json summary = {{"proxsim", 1},
                            {"versions", VersionsJson()},
                            {"inputs", InputsJson(sim_.scenario())},
                            {"samples", samples_},
                            {"interrupted", interrupted},
                            {"outputs", nlohmann::json::array()},
                            {"terrain", nullptr}};
  for (const auto& sink : sinks_) sink->AddToSummary(summary);
  for (const char* file : {"scene.json", "summary.json", "timings.json"}) summary["outputs"].push_back(file);
  summary["warnings"] = warnings_;
  for (const std::string& warning : mounting_.Warnings()) summary["warnings"].push_back(warning);
  if (interrupted) {
    // the files hold every sample up to and including this one
    summary["samples_planned"] = sim_.sample_count();
    summary["last_sample_t_s"] = samples_ > 0 ? nlohmann::json(last_t_s_) : nlohmann::json(nullptr);
  }
  if (sim_.robot()) summary["robot"] = RobotOutcomeJson(sim_);
  return summary;
}

nlohmann::json RunRecorder::Finish(bool interrupted) {
  if (out_dir_.empty()) return Summary(interrupted);
  // the sinks' files first: the summary reports them (the terrain map its score)
  for (const auto& sink : sinks_) sink->Commit();
  const nlohmann::json summary = Summary(interrupted);
  if (warn_)
    for (const std::string& warning : mounting_.Warnings()) warn_(warning);
  const std::filesystem::path out(out_dir_);
  const auto links = sim_.robot() ? sim_.robot()->LinkGeometry() : std::vector<LinkShapes>{};
  WriteFileAtomically((out / "scene.json").string(), SceneJsonText(sim_.scenario(), links));
  WriteFileAtomically((out / "summary.json").string(), summary.dump(2) + "\n");
  WriteRunManifest(out_dir_, summary["outputs"].get<std::vector<std::string>>());
  return summary;
}

}  // namespace proxsim
