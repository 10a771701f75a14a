#include "run/run_recorder.h"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "core/atomic_file.h"
#include "output/npy_writer.h"
#include "output/poses_csv.h"
#include "output/profile_ply.h"
#include "output/readings_csv.h"
#include "output/run_manifest.h"
#include "output/scene_json.h"
#include "sim/run_statistics.h"
#include "sim/run_summary.h"
#include "terrain/octomap_recorder.h"
#include "terrain/terrain_files.h"

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

struct RunRecorder::Writers {
  std::optional<ReadingsCsvWriter> readings_csv;
  std::optional<NpyReadingsWriter> readings_npy;
  std::optional<ProfilePlyWriter> profile;
  std::optional<PosesCsvWriter> poses;
  std::optional<OctomapRecorder> octomap;
  std::optional<RunStatistics> statistics;
};

RunRecorder::RunRecorder(const Simulation& sim, const std::string& out_dir, ReadingsFormat format,
                         std::function<void(const std::string&)> warn)
    : sim_(sim), out_dir_(out_dir), format_(format), warn_(std::move(warn)), writers_(std::make_unique<Writers>()) {
  writers_->statistics.emplace(sim.scenario().sensors.size());
  if (out_dir_.empty()) return;
  std::filesystem::create_directories(out_dir_);
  // the folder holds one run: the previous run's files go (the user's own stay)
  RemovePreviousRun(out_dir_);
  const std::filesystem::path out(out_dir_);
  const Scenario& scenario = sim.scenario();
  const std::vector<std::string>& object_names = sim.world().object_names();
  if (format_ == ReadingsFormat::kNpy) {
    writers_->readings_npy.emplace((out / "readings").string(), scenario, object_names);
  } else {
    writers_->readings_csv.emplace((out / "readings.csv").string(), scenario, object_names);
  }
  writers_->profile.emplace((out / "profile.ply").string());
  if (sim.robot()) writers_->poses.emplace((out / "poses.csv").string(), sim.robot()->model());
  if (sim.terrain_map()) writers_->octomap.emplace(sim.terrain_map()->config().resolution_m);
}

RunRecorder::~RunRecorder() = default;

void RunRecorder::Add(const SampleFrame& frame) {
  ++samples_;
  last_t_s_ = frame.t_s;
  if (frame.sample == 0) {
    warnings_ = SensorsInsideObjects(sim_.scenario(), frame);
    if (warn_)
      for (const std::string& warning : warnings_) warn_(warning);
  }
  writers_->statistics->Add(frame);
  for (const SensorSample& sample : frame.sensors) profile_points_ += sample.reading.detected() ? 1 : 0;
  if (out_dir_.empty()) return;
  if (writers_->readings_npy) writers_->readings_npy->Append(frame); else writers_->readings_csv->Append(frame);
  writers_->profile->Append(frame);
  if (writers_->poses) writers_->poses->Append(frame.t_s, sim_.robot()->X_WL());
  if (writers_->octomap) {
    for (const RayEvidence& evidence : sim_.terrain_map()->last_evidence()) writers_->octomap->Add(evidence);
  }
}

nlohmann::json RunRecorder::Summary(bool interrupted) const {
  // the map scored as it stands, no files written
  const TerrainMap* map = sim_.terrain_map();
  return SummaryWith(interrupted, map ? RecordTerrain(*map, sim_.world().caster(), "", nullptr) : nlohmann::json(nullptr));
}

nlohmann::json RunRecorder::SummaryWith(bool interrupted, nlohmann::json terrain) const {
  const bool npy = format_ == ReadingsFormat::kNpy;
  const Scenario& scenario = sim_.scenario();
  std::vector<std::string> sensor_names;
  for (const SensorConfig& sensor : scenario.sensors) sensor_names.push_back(sensor.name);
  nlohmann::json summary = {
      {"proxsim", 1},
      {"versions", VersionsJson()},
      {"inputs", InputsJson(scenario)},
      {"samples", samples_},
      {"interrupted", interrupted},
      {"profile_points", profile_points_},
      {"sensors", writers_->statistics->ToJson(sensor_names, sim_.world().object_names())},
      {"outputs", {npy ? "readings/" : "readings.csv", "profile.ply", "scene.json", "summary.json", "timings.json"}}};
  summary["warnings"] = warnings_;
  if (interrupted) {
    // the files hold every sample up to and including this one
    summary["samples_planned"] = sim_.sample_count();
    summary["last_sample_t_s"] = samples_ > 0 ? nlohmann::json(last_t_s_) : nlohmann::json(nullptr);
  }
  if (sim_.robot()) {
    summary["robot"] = RobotOutcomeJson(sim_);
    summary["outputs"].push_back("poses.csv");
  }
  summary["terrain"] = std::move(terrain);
  if (sim_.terrain_map()) summary["outputs"].push_back("terrain/");
  return summary;
}

nlohmann::json RunRecorder::Finish(bool interrupted) {
  if (out_dir_.empty()) return Summary(interrupted);
  // terrain/ and its score first: the summary reports it
  const TerrainMap* map = sim_.terrain_map();
  const std::filesystem::path terrain_dir = std::filesystem::path(out_dir_) / "terrain";
  nlohmann::json terrain = map ? RecordTerrain(*map, sim_.world().caster(), terrain_dir.string(),
                                               writers_->octomap ? &*writers_->octomap : nullptr)
                               : nlohmann::json(nullptr);
  const nlohmann::json summary = SummaryWith(interrupted, std::move(terrain));
  if (writers_->readings_npy) writers_->readings_npy->Commit(); else writers_->readings_csv->Commit();
  writers_->profile->Commit();
  if (writers_->poses) writers_->poses->Commit();
  const Scenario& scenario = sim_.scenario();
  const std::filesystem::path out(out_dir_);
  const auto links = sim_.robot() ? sim_.robot()->LinkGeometry() : std::vector<LinkShapes>{};
  WriteFileAtomically((out / "scene.json").string(), SceneJsonText(scenario, links));
  WriteFileAtomically((out / "summary.json").string(), summary.dump(2) + "\n");
  WriteRunManifest(out_dir_, summary["outputs"].get<std::vector<std::string>>());
  return summary;
}

}  // namespace proxsim
