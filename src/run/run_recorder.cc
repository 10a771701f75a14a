#include "run/run_recorder.h"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "core/atomic_file.h"
#include "output/poses_csv.h"
#include "output/profile_ply.h"
#include "output/run_manifest.h"
#include "output/scene_json.h"
#include "output/statistics_sink.h"
#include "output/terrain_sink.h"
#include "sim/run_summary.h"

namespace proxsim {

namespace {

// How far p_O lies inside the solid shape (negative: outside); planes count
// their z = 0 surface only, meshes have no inside here (nullopt).
std::optional<double> DepthInside(const Shape& shape, const Vec3& p_O) {
  if (const auto* box = std::get_if<Box>(&shape)) return ((box->size_m / 2) - p_O.cwiseAbs()).minCoeff();
  if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere->radius_m - p_O.norm();
  if (const auto* cylinder = std::get_if<Cylinder>(&shape)) {
    return std::min(cylinder->radius_m - p_O.head<2>().norm(), cylinder->length_m / 2 - std::abs(p_O.z()));
  }
  if (std::holds_alternative<Plane>(shape)) return -std::abs(p_O.z());
  return std::nullopt;
}

// Suspicious but legal: a sensor whose ray starts inside a scene object, or
// exactly on its surface (its rays may then hit that surface at d = 0).
std::vector<std::string> SensorsInsideObjects(const Scenario& scenario, const SampleFrame& frame) {
  constexpr double kOnSurface_m = 1e-9;
  std::vector<std::string> warnings;
  for (std::size_t s = 0; s < scenario.sensors.size() && s < frame.sensors.size(); ++s) {
    const Vec3& p_WS = frame.sensors[s].p_WS;
    for (const SceneObject& object : scenario.scene.objects) {
      const auto depth_m = DepthInside(object.shape, object.X_WO.inverse() * p_WS);
      if (!depth_m || *depth_m < -kOnSurface_m) continue;
      char where[160];
      std::snprintf(where, sizeof where, "at t = %g s its origin (%g, %g, %g) m", frame.t_s, p_WS.x(), p_WS.y(),
                    p_WS.z());
      const std::string sensor = scenario.source + ": sensor '" + scenario.sensors[s].name + "'";
      if (*depth_m > kOnSurface_m) {
        warnings.push_back(sensor + " is inside object '" + object.name + "' (" + where +
                           "); it sees that object from within");
      } else {
        warnings.push_back(sensor + " starts on the surface of object '" + object.name + "' (" + where +
                           "); its rays may hit that surface at d = 0");
      }
    }
  }
  return warnings;
}

}  // namespace

RunRecorder::RunRecorder(const Simulation& sim, const std::string& out_dir, ReadingsFormat format,
                         std::function<void(const std::string&)> warn, bool force)
    : sim_(sim), warn_(std::move(warn)) {
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
    warnings_ = SensorsInsideObjects(sim_.scenario(), frame);
    if (warn_)
      for (const std::string& warning : warnings_) warn_(warning);
  }
  for (const auto& sink : sinks_) sink->Add(frame);
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
  const std::filesystem::path out(out_dir_);
  const auto links = sim_.robot() ? sim_.robot()->LinkGeometry() : std::vector<LinkShapes>{};
  WriteFileAtomically((out / "scene.json").string(), SceneJsonText(sim_.scenario(), links));
  WriteFileAtomically((out / "summary.json").string(), summary.dump(2) + "\n");
  WriteRunManifest(out_dir_, summary["outputs"].get<std::vector<std::string>>());
  return summary;
}

}  // namespace proxsim
