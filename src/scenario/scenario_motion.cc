// An object's `motion` key (docs/worlds.md, "Moving objects"): waypoints at a
// speed, a constant velocity, or a trajectory file, exactly one of them; and
// the `person` shape key's parameters. A trajectory file is read here, so a
// missing file or a time that does not increase is reported with the
// scenario's other problems before anything runs.
#include <fstream>
#include <sstream>

#include "core/nearest_key.h"
#include "core/text_fields.h"
#include "scenario/scenario_sections.h"
#include "scene/person.h"

namespace proxsim {

namespace {

constexpr const char* kTrajectoryColumns[] = {"t_s", "x_m", "y_m", "z_m", "yaw_deg"};

// waypoints_m: [[x, y], ...], at least two
std::vector<Vec2> ReadWaypoints(YamlReader& reader, const Field& field) {
  std::vector<Vec2> waypoints;
  const auto items = reader.List(field, "a list of at least two waypoints [x, y] in metres");
  if (!items) return waypoints;
  for (const Field& item : *items) {
    if (const auto xy = reader.Numbers(item, 2, Coordinate(), "[x, y] in metres")) waypoints.emplace_back((*xy)[0], (*xy)[1]);
  }
  return waypoints;
}

// the rows of a trajectory CSV: a header naming the five columns (any order), then numbers
void ReadTrajectoryFile(YamlReader& reader, const Field& field, const std::string& path, Motion& motion) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string line;
  int line_no = 0;
  std::vector<std::string> header;
  while (std::getline(text, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    header = SplitCsvLine(line);
    break;
  }
  int column[5];
  for (int c = 0; c < 5; ++c) {
    const auto found = std::find(header.begin(), header.end(), kTrajectoryColumns[c]);
    column[c] = found == header.end() ? -1 : static_cast<int>(found - header.begin());
    if (column[c] < 0) {
      reader.Fail(field, path + ":" + std::to_string(line_no) + ": missing column '" + kTrajectoryColumns[c] +
                             "' (expected a header t_s,x_m,y_m,z_m,yaw_deg)");
      return;
    }
  }
  while (std::getline(text, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::vector<std::string> cells = SplitCsvLine(line);
    const std::string where = path + ":" + std::to_string(line_no) + ": ";
    if (cells.size() != header.size()) {
      reader.Fail(field, where + std::to_string(cells.size()) + " cells, expected " + std::to_string(header.size()));
      return;
    }
    double v[5];
    for (int c = 0; c < 5; ++c) {
      if (!ParseFiniteNumber(cells[column[c]], &v[c])) {
        reader.Fail(field, where + "column '" + kTrajectoryColumns[c] + "': '" + cells[column[c]] +
                               "' is not a finite number");
        return;
      }
    }
    if (!motion.trajectory.empty() && !(v[0] > motion.trajectory.back().t_s)) {
      reader.Fail(field, where + "t_s " + cells[column[0]] +
                             " is not after the previous row's; times must strictly increase");
      return;
    }
    motion.trajectory.push_back({v[0], Vec3(v[1], v[2], v[3]), DegToRad(v[4])});
  }
  if (motion.trajectory.size() < 2) reader.Fail(field, path + ": expected at least two data rows after the header");
}

}  // namespace

std::optional<Motion> ReadMotion(YamlReader& reader, const Field& field, const std::filesystem::path& base_dir) {
  if (!field) return std::nullopt;
  const auto map = reader.Map(field, {"waypoints_m", "speed_m_s", "mode", "start_s", "velocity_m_s", "trajectory"});
  if (!map) return std::nullopt;
  Motion motion;
  const int kinds = map->Has("waypoints_m") + map->Has("velocity_m_s") + map->Has("trajectory");
  if (kinds != 1) {
    reader.Fail(field, "expected exactly one of waypoints_m, velocity_m_s or trajectory, got " +
                           std::to_string(kinds));
    return std::nullopt;
  }
  // the keys that only waypoints take
  for (const char* key : {"speed_m_s", "mode", "start_s"}) {
    if (map->Has(key) && !map->Has("waypoints_m")) reader.Fail((*map)[key], std::string(key) + " is for waypoints_m only");
  }

  if (const Field waypoints = (*map)["waypoints_m"]) {
    motion.kind = Motion::Kind::kWaypoints;
    motion.waypoints_m = ReadWaypoints(reader, waypoints);
    motion.speed_m_s = reader.Number((*map)["speed_m_s"], PositiveNumber("m/s")).value_or(motion.speed_m_s);
    motion.start_s = reader.Number((*map)["start_s"], NonNegativeNumber("s")).value_or(motion.start_s);
    if (const auto mode = reader.String((*map)["mode"])) {
      const auto& names = MotionModeNames();
      const auto found = std::find(names.begin(), names.end(), *mode);
      if (found != names.end()) {
        motion.mode = static_cast<MotionMode>(found - names.begin());
      } else {
        const auto nearest = NearestKey(*mode, names);
        reader.Fail((*map)["mode"], "unknown mode '" + *mode + "' (" +
                                        (nearest ? "did you mean '" + *nearest + "'? " : "") +
                                        "expected loop, back_and_forth or once)");
      }
    }
    for (const std::string& problem : MotionProblems(motion)) reader.Fail(waypoints, problem);
  } else if (const Field velocity = (*map)["velocity_m_s"]) {
    motion.kind = Motion::Kind::kVelocity;
    motion.velocity_m_s =
        reader.Vector3(velocity, NumberIn(-100, 100, "m/s"), "[vx, vy, vz] in m/s").value_or(Vec3::Zero());
  } else if (const Field trajectory = (*map)["trajectory"]) {
    motion.kind = Motion::Kind::kTrajectory;
    const auto text = reader.String(trajectory);
    if (!text) return std::nullopt;
    motion.trajectory_file = *text;
    const std::filesystem::path path = ResolveScenarioPath(base_dir, *text);
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
      reader.Fail(trajectory, "expected the path of a trajectory CSV file (t_s,x_m,y_m,z_m,yaw_deg; relative paths "
                              "start from the scenario's folder), but '" + path.string() + "' is not a file");
      return std::nullopt;
    }
    ReadTrajectoryFile(reader, trajectory, path.string(), motion);
  }
  // a motion that cannot be followed (already reported) is none
  if (!MotionProblems(motion).empty()) return std::nullopt;
  return motion;
}

double ReadPersonHeight(YamlReader& reader, const Field& field) {
  constexpr double kDefaultHeight_m = 1.75;
  const auto map = reader.Map(field, {"height_m"});
  if (!map) return kDefaultHeight_m;
  return reader.Number((*map)["height_m"], NumberIn(kPersonMinHeight_m, kPersonMaxHeight_m, "m"))
      .value_or(kDefaultHeight_m);
}

}  // namespace proxsim
