#include "study/study_runner.h"

#include <algorithm>
#include <map>
#include <memory>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "study/study_journal.h"
#include "study/study_mpi.h"

namespace proxsim {

namespace {

using nlohmann::json;

// ----- a job's metrics as JSON (the journal and the MPI messages)

// What makes a journal belong to this study: the candidates, variants, seeds, hazards.
std::string Fingerprint(const StudyConfig& study) {
  std::string text;
  for (const Candidate& c : study.candidates) text += c.id + ";";
  for (const SceneVariant& v : study.variants) text += v.name + ";";
  for (std::uint64_t s : study.seeds) text += std::to_string(s) + ";";
  for (const std::string& h : study.hazards) text += h + ";";
  return StudyFingerprint(std::to_string(study.candidates.size()) + "c" + std::to_string(study.variants.size()) + "v" +
                              std::to_string(study.seeds.size()) + "s" + std::to_string(study.hazards.size()) + "h",
                          text);
}

JournalShape ShapeOf(const StudyConfig& study) {
  return {study.variants.size() * study.seeds.size(), study.candidates.size(), study.hazards.size()};
}

// ----- one worker's simulations: a world per variant, built once, reset per job

class Worker {
 public:
  Worker(const StudyConfig& study) : study_(study) {}

  std::vector<RunMetrics> Run(std::size_t job) {
    const std::size_t variant = job / study_.seeds.size();
    const std::uint64_t seed = study_.seeds[job % study_.seeds.size()];
    Simulation& sim = SimulationOf(variant);
    sim.Reset(seed);
    RunMetricsRecorder metrics(sim, study_.hazards);
    while (!sim.done()) {
      sim.Step();
      metrics.Add();
    }
    return metrics.Finish();
  }

  Simulation& SimulationOf(std::size_t variant) {
    auto& sim = simulations_[variant];
    if (!sim) sim = std::make_unique<Simulation>(ScenarioOf(study_, variant), 1);
    return *sim;
  }

  static Scenario ScenarioOf(const StudyConfig& study, std::size_t variant) {
    Scenario scenario = study.variants[variant].scenario;
    scenario.source = study.source + " (scene " + study.variants[variant].name + ")";
    for (const Candidate& c : study.candidates) {
      scenario.sensors.push_back(c.sensor);
      scenario.sensors.back().spec.ambient_klux = scenario.scene.ambient_klux;  // the variant's light
    }
    return scenario;
  }

 private:
  const StudyConfig& study_;
  std::map<std::size_t, std::unique_ptr<Simulation>> simulations_;
};

}  // namespace

JobSet StudyJobSet(const StudyConfig& study) {
  const std::size_t jobs = study.variants.size() * study.seeds.size();
  JobSet set;
  set.jobs = jobs;
  set.runs_per_job = study.candidates.size();
  set.fingerprint = Fingerprint(study);
  // the study file and the scenario files its variants came from: an edit of
  // the base (its timing, its robot) changes the answers, not the fingerprint
  std::vector<std::string> files{study.source};
  for (const SceneVariant& v : study.variants)
    if (std::ranges::find(files, v.scenario.source) == files.end()) files.push_back(v.scenario.source);
  set.digest = StudyDigest(set.fingerprint, files);
  set.mode = "detection";
  set.study_file = study.source;
  set.check = [shape = ShapeOf(study)](const json& line) { return ParseJournalLine(line, shape).job; };
  set.header = std::to_string(study.candidates.size()) + " candidates x " + std::to_string(study.variants.size()) +
               " scenes x " + std::to_string(study.seeds.size()) + " seeds = " +
               std::to_string(jobs * study.candidates.size()) + " runs in " + std::to_string(jobs) +
               " jobs (a job: one scene and seed, every candidate)";
  return set;
}

StudyResults StudyResultsFromJournal(const StudyConfig& study, const std::map<std::size_t, json>& lines) {
  StudyResults results(study.variants.size(), std::vector<std::vector<RunMetrics>>(study.seeds.size()));
  for (const auto& [job, line] : lines) {
    results[job / study.seeds.size()][job % study.seeds.size()] = ParseJournalLine(line, ShapeOf(study)).metrics;
  }
  return results;
}

StudyResults RunStudy(const StudyConfig& study, const StudyOptions& options, bool* is_writer) {
  StudyMpi mpi;  // a no-op unless started by mpirun with more than one rank

  // every variant's world, built before any run: a candidate on a link the
  // robot lacks fails here, with every problem listed
  std::vector<std::unique_ptr<Worker>> workers;
  const int threads = WorkerThreads(options.threads, mpi);
  for (int t = 0; t < threads; ++t) workers.push_back(std::make_unique<Worker>(study));
  {
    std::vector<std::string> problems;
    std::vector<bool> hazard_found(study.hazards.size(), false);
    for (std::size_t v = 0; v < study.variants.size(); ++v) {
      try {
        const World& world = workers[0]->SimulationOf(v).world();
        for (std::size_t h = 0; h < study.hazards.size(); ++h)
          if (NamesAHazard(world, study.hazards[h])) hazard_found[h] = true;
      } catch (const InputError& error) {
        problems.insert(problems.end(), error.problems().begin(), error.problems().end());
      }
    }
    // a hazard no scene holds would be measured as never seen by any mounting
    for (std::size_t h = 0; problems.empty() && h < study.hazards.size(); ++h) {
      if (!hazard_found[h]) {
        problems.push_back(study.source + ": hazards: '" + study.hazards[h] +
                           "' begins the name of no object in any scene variant: nothing to measure for it");
      }
    }
    if (!problems.empty()) throw InputError(problems);
  }

  JobSet set = StudyJobSet(study);
  for (auto& worker : workers)
    set.workers.push_back([w = worker.get()](std::size_t job) { return JournalMetricsJson(w->Run(job)); });
  const std::map<std::size_t, json> lines = RunJobs(set, options, mpi, is_writer);
  if (!*is_writer || options.slice) return {};
  return StudyResultsFromJournal(study, lines);
}

}  // namespace proxsim
