#include "study/outcome_runner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <yaml-cpp/yaml.h>

#include "core/input_error.h"
#include "sim/simulation.h"

namespace proxsim {

namespace {

using nlohmann::json;
constexpr double kRunNaN = std::numeric_limits<double>::quiet_NaN();

[[noreturn]] void Bad(const std::string& what) { throw InputError("journal line: " + what); }

// Journal numbers are bounded as a run can make them: times and distances in
// [0, kMaxJournalValue], a clearance within ±kMaxJournalValue (a line saying
// reached_goal at t = -1e308 was once taken as a run's result).
constexpr double kMaxJournalValue = 1e9;

double NumberOrNaN(const json& value, const std::string& where, const char* name, double min = 0) {
  if (value.is_null()) return kRunNaN;
  if (!value.is_number()) Bad(where + ": " + name + ": expected a number, got " + value.dump());
  const double number = value.get<double>();
  if (!(number >= min && number <= kMaxJournalValue)) {
    Bad(where + ": " + name + ": expected a number in [" + (min < 0 ? "-1e9" : "0") + ", 1e9], got " + value.dump());
  }
  return number;
}

// What identifies an outcome study's journal: its sets, strategies and worlds.
std::string Fingerprint(const OutcomeStudyConfig& study) {
  std::string text = "outcomes;";
  for (const SensorSet& set : study.sets) text += set.name + "=" + set.sensors_yaml + ";";
  for (const StrategyChoice& s : study.strategies) text += s.label + "=" + s.yaml + ";";
  for (const WorldFamily& f : study.families) text += f.name + "=" + f.document_yaml + ";";
  for (const OutcomeStudyConfig::Job& j : study.jobs) text += std::to_string(j.family) + ":" + std::to_string(j.seed) + ";";
  return StudyFingerprint("outcomes-" + std::to_string(study.sets.size()) + "x" +
                              std::to_string(study.strategies.size()) + "x" + std::to_string(study.jobs.size()),
                          text);
}

// The episode of a loaded scenario, walked to its end on `world` (built from the same scene and robot).
OutcomeRun RunLoaded(Scenario scenario, const std::shared_ptr<World>& world) {
  Simulation sim(std::move(scenario), 1, world);
  // the goal ends the episode: nothing after it changes the outcome
  while (!sim.done() && !sim.robot_outcome().reached_goal) sim.Step();
  OutcomeRun run;
  const Simulation::Outcome outcome = sim.outcome();
  run.outcome = outcome.kind;
  run.outcome_t_s = outcome.t_s;
  const RobotKnowledge* robot = sim.observation().robot;
  run.walked_m = robot != nullptr ? robot->distance_walked_m : 0.0;
  run.straight_m = kRunNaN;
  if (const auto& config = sim.scenario().robot; config && !config->waypoints_m.empty()) {
    run.straight_m = (config->waypoints_m.back() - config->start_xyz_m.head<2>()).norm();
  }
  const double clearance = sim.robot_outcome().min_clearance_m;
  run.min_clearance_m = std::isfinite(clearance) ? clearance : kRunNaN;
  return run;
}

// one job: the world generated and built once, the reference walk, then every run on it
OutcomeJob RunJob(const OutcomeStudyConfig& study, std::size_t job) {
  const std::string& source = study.families[study.jobs[job].family].source;
  // the world and each run as documents: the values their replay texts hold
  // (WorldText, RunScenarioText), never written out and parsed back
  YAML::Node world = WorldNode(study, job);
  OutcomeJob result;
  // the reference walk: blind, no strategy, legs that refuse an unsafe step,
  // the episode ended by the first collision. Refused: the path cannot be
  // walked; collided: something stands in the straight way (a generated
  // room's blockers, a person) — either way a stop before it is a success.
  // Its scenario builds the world (bodies, acceleration structures) that
  // every set and strategy then runs on, in turn
  Scenario reference_scenario = LoadScenarioNode(RunNodeFromWorld(world, nullptr, nullptr, true), source);
  const std::shared_ptr<World> built = BuildWorld(reference_scenario, 1);
  const OutcomeRun reference = RunLoaded(std::move(reference_scenario), built);
  result.way_through = reference.outcome != OutcomeKind::kRefused && reference.outcome != OutcomeKind::kCollided;
  if (!result.way_through) {
    result.hazard_m = reference.walked_m;
    result.stop_window_m = reference.outcome == OutcomeKind::kRefused ? kStopBeforeHazard_m : kStopBeforeObstacle_m;
  }
  for (const SensorSet& set : study.sets) {
    for (const StrategyChoice& strategy : study.strategies) {
      // (the last run takes the world itself, uncopied)
      const bool last = &set == &study.sets.back() && &strategy == &study.strategies.back();
      result.runs.push_back(RunLoaded(
          LoadScenarioNode(last ? RunNodeFromWorld(std::move(world), &set, &strategy, false)
                                : RunNodeFromWorld(world, &set, &strategy, false),
                           source),
          built));
    }
  }
  return result;
}

}  // namespace

bool IsSuccess(const OutcomeRun& run, const OutcomeJob& job) {
  if (run.outcome == OutcomeKind::kReachedGoal) return true;
  return !job.way_through && (run.outcome == OutcomeKind::kStopped || run.outcome == OutcomeKind::kRefused) &&
         run.walked_m >= job.hazard_m - job.stop_window_m;
}

OutcomeRun RunEpisode(const std::string& scenario_text, const std::string& source) {
  Scenario scenario = LoadScenarioText(scenario_text, source);
  const std::shared_ptr<World> world = BuildWorld(scenario, 1);
  return RunLoaded(std::move(scenario), world);
}

json OutcomeJobJson(const OutcomeJob& job) {
  json runs = json::array();
  for (const OutcomeRun& r : job.runs) runs.push_back({OutcomeName(r.outcome), r.outcome_t_s, r.walked_m, r.straight_m, r.min_clearance_m});
  return {{"way", job.way_through}, {"hazard_m", job.hazard_m}, {"window_m", job.stop_window_m}, {"runs", runs}};
}

OutcomeJob ParseOutcomeJob(const json& metrics, std::size_t runs_per_job, const std::string& where) {
  if (!metrics.is_object()) Bad(where + ": expected an object {\"way\", \"runs\"}");
  const auto way = metrics.find("way");
  const auto hazard = metrics.find("hazard_m");
  const auto runs = metrics.find("runs");
  if (way == metrics.end() || !way->is_boolean()) Bad(where + ": expected \"way\": true or false");
  if (hazard == metrics.end() || !hazard->is_number()) Bad(where + ": expected \"hazard_m\": a number");
  NumberOrNaN(*hazard, where, "hazard_m");
  const auto window = metrics.find("window_m");
  if (window == metrics.end() || !window->is_number() || !std::isfinite(window->get<double>()) ||
      window->get<double>() < 0)
    Bad(where + ": expected \"window_m\": a number >= 0");
  if (runs == metrics.end() || !runs->is_array() || runs->size() != runs_per_job) {
    Bad(where + ": expected " + std::to_string(runs_per_job) + " runs (sets x strategies; a line of another study?)");
  }
  OutcomeJob job;
  job.way_through = way->get<bool>();
  job.hazard_m = hazard->get<double>();
  job.stop_window_m = window->get<double>();
  for (const json& r : *runs) {
    const std::optional<OutcomeKind> kind =
        r.is_array() && r.size() == 5 && r[0].is_string() ? OutcomeFromName(r[0].get<std::string>()) : std::nullopt;
    if (!kind) Bad(where + ": a run is not [outcome, outcome_t_s, walked_m, straight_m, min_clearance_m]: " + r.dump());
    job.runs.push_back({*kind, NumberOrNaN(r[1], where, "outcome_t_s"),
                        NumberOrNaN(r[2], where, "walked_m"), NumberOrNaN(r[3], where, "straight_m"),
                        NumberOrNaN(r[4], where, "min_clearance_m", -kMaxJournalValue)});
  }
  return job;
}

JobSet OutcomeJobSet(const OutcomeStudyConfig& study) {
  JobSet set;
  set.jobs = study.jobs.size();
  set.runs_per_job = study.runs_per_job();
  set.fingerprint = Fingerprint(study);
  std::vector<std::string> files{study.source};
  for (const WorldFamily& f : study.families)
    if (std::ranges::find(files, f.source) == files.end()) files.push_back(f.source);
  set.digest = StudyDigest(set.fingerprint, files);
  set.mode = "outcomes";
  set.study_file = study.source;
  set.check = [&study](const json& line) -> std::size_t {
    if (!line.is_object()) Bad("expected an object {\"job\": ..., \"metrics\": {...}}");
    const auto job = line.find("job");
    if (job == line.end() || !job->is_number_unsigned() || job->get<std::uint64_t>() >= study.jobs.size())
      Bad("job: expected a job index below " + std::to_string(study.jobs.size()));
    const auto metrics = line.find("metrics");
    if (metrics == line.end()) Bad("job " + job->dump() + ": no 'metrics'");
    ParseOutcomeJob(*metrics, study.runs_per_job(), "job " + job->dump());
    return job->get<std::size_t>();
  };
  set.header = std::to_string(study.sets.size()) + " sets x " + std::to_string(study.strategies.size()) +
               " strategies x " + std::to_string(study.jobs.size()) + " worlds = " +
               std::to_string(study.runs_per_job() * study.jobs.size()) +
               " runs (closed loop; a job: one world, every set with every strategy)";
  return set;
}

OutcomeResults OutcomeResultsFromJournal(const OutcomeStudyConfig& study, const std::map<std::size_t, json>& lines) {
  OutcomeResults results(study.jobs.size());
  for (const auto& [job, line] : lines)
    results[job] = ParseOutcomeJob(line.at("metrics"), study.runs_per_job(), "job " + std::to_string(job));
  return results;
}

OutcomeResults RunOutcomeStudy(const OutcomeStudyConfig& study, const StudyOptions& options, bool* is_writer) {
  StudyMpi mpi;  // a no-op unless started by mpirun with more than one rank

  // every family's first world with every set, built before any run: every
  // problem listed at once (a link the robot lacks, a bad generate key)
  {
    std::vector<std::string> problems;
    std::vector<bool> checked(study.families.size(), false);
    for (std::size_t job = 0; job < study.jobs.size(); ++job) {
      const std::size_t family = study.jobs[job].family;
      if (checked[family]) continue;
      checked[family] = true;
      const std::string& name = study.families[family].name;
      try {
        const std::string world = WorldText(study, job);
        const std::string& source = study.families[family].source;
        const std::shared_ptr<World> built =
            BuildWorld(LoadScenarioText(RunTextFromWorld(world, nullptr, nullptr, true), source), 1);
        for (const SensorSet& set : study.sets) {
          try {
            const Simulation sim(
                LoadScenarioText(RunTextFromWorld(world, &set, &study.strategies.front(), false), source), 1, built);
          } catch (const InputError& error) {
            for (const std::string& p : error.problems())
              problems.push_back(study.source + ": set '" + set.name + "' in world '" + name + "': " + p);
          }
        }
      } catch (const InputError& error) {
        for (const std::string& p : error.problems()) problems.push_back(study.source + ": world '" + name + "': " + p);
      }
    }
    if (!problems.empty()) throw InputError(problems);
  }

  JobSet set = OutcomeJobSet(study);
  const int threads = WorkerThreads(options.threads, mpi);
  for (int t = 0; t < threads; ++t)
    set.workers.push_back([&study](std::size_t job) { return OutcomeJobJson(RunJob(study, job)); });
  const std::map<std::size_t, json> lines = RunJobs(set, options, mpi, is_writer);
  if (!*is_writer || options.slice) return {};
  return OutcomeResultsFromJournal(study, lines);
}

}  // namespace proxsim
