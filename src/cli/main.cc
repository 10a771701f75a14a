// The proxsim command line (docs/cli.md):
//   proxsim run [SCENARIO.yaml] [--out DIR] [--seed N] [--threads N]
//   proxsim validate SCENARIO.yaml
//   proxsim generate SCENARIO.yaml --out WORLD.yaml  (a generated world as a plain scenario, docs/worlds.md)
//   proxsim inspect ROBOT [--json]   (a robot's links, joints and leg map, docs/robots.md)
//   proxsim plot OUT_DIR             (redraws the figures and the viewer of a run)
//   proxsim export OUT_DIR --mcap FILE (the run as an MCAP file for Foxglove, docs/foxglove.md)
//   proxsim export OUT_DIR --ros2 DIR  (the run as a ROS 2 bag, docs/ros2.md)
//   proxsim bench [--json] [--quick] (the performance suite, docs/performance.md)
//   proxsim study FILE [--shard i/N|slurm] [--out DIR], proxsim study merge DIR... --out DIR (docs/studies.md)
//   proxsim fidelity FILE [--out DIR] [--noise on|off] (a part's model against a recording, docs/fidelity.md)
// Exit codes: 0 success, 2 bad input (every problem listed, nothing written),
// 1 any other failure (an I/O error, say), with the reason on stderr.
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <memory>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/bench_suite.h"
#include "core/input_error.h"
#include "inspect_command.h"
#include "core/atomic_file.h"
#include "core/output_folder.h"
#include "output/readings_columns.h"
#include "sensors/sensor_keys.h"
#include "output/run_manifest.h"
#include "scenario/config_sections.h"
#include "scenario/scenario.h"
#include "report/mcap_export.h"
#include "report/ros2_export.h"
#include "scenario/scenario_generate.h"
#include "report/report_runner.h"
#include "run/run.h"
#include "sim/simulation.h"
#include "core/message_format.h"
#include "fidelity/fidelity_outputs.h"
#include "fidelity/fidelity_run.h"
#include "study/outcome_answers.h"
#include "study/outcome_config.h"
#include "study/outcome_runner.h"
#include "study/study_answers.h"
#include "study/study_config.h"
#include "study/study_merge.h"
#include "study/study_mpi.h"
#include "study/study_runner.h"
#include "study/study_shard.h"

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitFailure = 1;

// Set by SIGINT/SIGTERM during a run: the run stops after the current sample,
// commits its files and exits 128 + the signal number. A second signal kills.
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "written from a signal handler");

extern "C" void OnStopSignal(int signal_number) { g_stop_signal.store(signal_number); }

// While a run loads (the scenario, the robot, the meshes: seconds for a large
// file), nothing has been written: a stop signal ends the process at once,
// with the exit code a completed interruption would give. _exit is
// async-signal-safe; no destructor needs to run.
extern "C" void OnSignalWhileLoading(int signal_number) { _exit(128 + signal_number); }

void InstallLoadingHandlers() {
  struct sigaction action {};
  action.sa_handler = OnSignalWhileLoading;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void InstallStopHandlers() {
  struct sigaction action {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // the second Ctrl-C takes the default action
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int PrintInputError(const proxsim::InputError& error) {
  std::fprintf(stderr, "proxsim: %zu problem%s in the input:\n", error.problems().size(),
               error.problems().size() == 1 ? "" : "s");
  for (const std::string& problem : error.problems()) std::fprintf(stderr, "  %s\n", problem.c_str());
  return kExitBadInput;
}

proxsim::Scenario LoadScenarioArgument(const std::string& path) {
  return path.empty() ? proxsim::LoadBuiltinScenario("paper") : proxsim::LoadScenarioFile(path);
}

// --seed as text, read strictly: CLI11 turned -1 and 2^64 into 2^64 - 1
std::optional<std::uint64_t> ParseSeed(const std::string& text) {
  if (text.empty()) return std::nullopt;
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    throw proxsim::InputError("--seed: expected a whole number in [0, 18446744073709551615], got " + text);
  }
  return value;
}

// CLI11's ExistingFile, saying why a path that is there cannot be read (a
// symbolic link loop was "File does not exist")
CLI::Validator ExistingInputFile() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        struct stat info {};
        if (::stat(path.c_str(), &info) == 0) {
          return S_ISDIR(info.st_mode) ? "File is actually a directory: " + path : std::string();
        }
        if (errno == ENOENT) return "File does not exist: " + path;
        if (errno == ELOOP) return path + ": a loop of symbolic links (" + std::strerror(errno) + ")";
        return path + ": cannot be read (" + std::strerror(errno) + ")";
      },
      "FILE");
}

// --out: refused at once when empty (it once printed "outputs in /" and wrote nothing)
void CheckOutArgument(const std::string& out_dir) {
  if (out_dir.empty()) throw proxsim::InputError("--out: an empty path; give the folder for the outputs");
}

int Run(const std::string& scenario_path, const std::string& out_dir, const std::string& seed_text, int threads,
        bool report, const std::string& format, bool force, const std::string& mcap_path,
        const std::optional<std::string>& ros2_dir) {
  CheckOutArgument(out_dir);
  if (!mcap_path.empty()) proxsim::CheckMcapPath(mcap_path, out_dir);
  if (ros2_dir) proxsim::CheckRos2Path(*ros2_dir, out_dir);
  const std::optional<std::uint64_t> seed = ParseSeed(seed_text);
  InstallLoadingHandlers();  // a stop signal while loading ends the process at once
  proxsim::Scenario scenario = LoadScenarioArgument(scenario_path);
  if (seed) scenario.seed = *seed;
  proxsim::RunOptions options;
  options.out_dir = out_dir;
  options.threads = threads;
  options.format = format == "npy" ? proxsim::ReadingsFormat::kNpy : proxsim::ReadingsFormat::kCsv;
  options.force = force;
  options.progress = isatty(STDERR_FILENO) != 0;
  options.stop_signal = &g_stop_signal;
  options.warn = [](const std::string& warning) { std::fprintf(stderr, "proxsim: warning: %s\n", warning.c_str()); };
  options.on_loaded = InstallStopHandlers;  // from here on a stop commits what was written
  const proxsim::RunResult result = proxsim::RunScenario(scenario, options);
  if (result.interrupted) {
    const int signal_number = g_stop_signal.load();
    const auto& last = result.summary["last_sample_t_s"];
    std::fprintf(stderr,
                 "proxsim: interrupted by %s after %lld of %lld samples (last t = %s s); the files in %s/ hold "
                 "every completed sample, summary.json says \"interrupted\": true\n",
                 signal_number == SIGTERM ? "SIGTERM" : "SIGINT", result.summary["samples"].get<long long>(),
                 result.summary["samples_planned"].get<long long>(),
                 last.is_null() ? "none" : std::to_string(last.get<double>()).c_str(), out_dir.c_str());
    return 128 + signal_number;
  }

  // the summary a user reads first
  std::printf("proxsim: %s — %lld samples of %zu sensors in %.3f s wall\n", scenario.source.c_str(),
              static_cast<long long>(result.summary["samples"].get<long long>()), scenario.sensors.size(),
              result.wall_s);
  for (const auto& [name, stats] : result.summary["sensors"].items()) {
    std::printf("  %-28s %6lld detections of %lld samples", name.c_str(), stats["detections"].get<long long>(),
                stats["samples"].get<long long>());
    std::string firsts;
    for (const auto& [object, t_s] : stats["first_detection_t_s"].items()) {
      char buffer[96];
      std::snprintf(buffer, sizeof buffer, "%s%s@%.2fs", firsts.empty() ? "" : ", ", object.c_str(),
                    t_s.get<double>());
      firsts += buffer;
    }
    std::printf("%s%s\n", firsts.empty() ? "" : "  first: ", firsts.c_str());
  }
  if (const auto robot = result.summary.find("robot"); robot != result.summary.end()) {
    const auto& r = *robot;
    // how the episode ended (summary.json's outcome), or why the robot stands (its stop_reason)
    const std::string outcome = r["outcome"].get<std::string>();
    std::string motion = "still walking at the end";
    char at[48];
    std::snprintf(at, sizeof at, " at t = %.2f s", r["outcome_t_s"].get<double>());
    if (outcome == "collided") {
      const auto& first = r["collisions"].at(0);
      const std::string with = first.contains("object") ? first["object"].get<std::string>()
                                                         : "its own " + first["other_link"].get<std::string>();
      motion = "collided with " + with + " (" + first["link"].get<std::string>() + ")" + at;
    } else if (outcome == "fell") {
      motion = std::string("fell") + at + " (" + r["fall"]["reason"].get<std::string>() + ")";
    } else if (outcome == "reached_goal") {
      motion = std::string("reached its goal") + at;
    } else if (r["stopped"].get<bool>()) {
      const std::string reason = r["stop_reason"].get<std::string>();
      std::snprintf(at, sizeof at, " at t = %.2f s", r["stop_t_s"].get<double>());
      motion = reason == "strategy"      ? std::string("stopped by its strategy") + at
               : reason == "cannot_step" ? std::string("standing before a step its legs cannot take (cannot_step") + at + ")"
               : reason == "own_map"     ? std::string("standing before a step its own map shows it cannot take") + at
                                         : std::string("standing at the end of its path since ") + (at + 4);
    }
    std::printf("  robot: walked %.2f m, %s, min clearance %s m\n", r["distance_walked_m"].get<double>(), motion.c_str(),
                r["min_clearance_m"].is_null() ? "n/a" : std::to_string(r["min_clearance_m"].get<double>()).c_str());
  }
  std::printf("outputs in %s/\n", out_dir.c_str());
  std::fflush(stdout);
  // the run in Foxglove: an MCAP file of the files just written
  if (!mcap_path.empty() && proxsim::ExportMcap(out_dir, mcap_path) != 0) {
    std::fprintf(stderr, "proxsim: the run's files are complete, but its MCAP file could not be written\n");
    return kExitFailure;
  }
  // the run into a ROS 2 stack: a bag of the files just written
  if (ros2_dir && proxsim::ExportRos2(out_dir, *ros2_dir) != 0) {
    std::fprintf(stderr, "proxsim: the run's files are complete, but its ROS 2 bag could not be written\n");
    return kExitFailure;
  }
  if (!report) return 0;
  // the pictures: figures and the replay viewer, drawn from the files just written
  if (proxsim::MakeReport(out_dir) != 0) {
    std::fprintf(stderr, "proxsim: the run's files are complete, but its report could not be drawn\n");
    return kExitFailure;
  }
  std::printf("report: %s/report/index.html and %s/report/*.png\n", out_dir.c_str(), out_dir.c_str());
  return 0;
}

// The files in dir must be one run's (its manifest): a figure or an export of two runs' files would mislead.
void CheckOneRun(const std::string& dir) {
  const std::vector<std::string> problems = proxsim::RunFolderProblems(dir);
  if (problems.empty()) return;
  std::vector<std::string> lines;
  for (const std::string& problem : problems) lines.push_back(dir + "/" + problem);
  lines.push_back(dir + ": its files are not one run's; run the scenario again into this folder "
                        "(or another) to get a consistent set");
  throw proxsim::InputError(lines);
}

int Validate(const std::string& scenario_path) {
  const proxsim::Scenario scenario = proxsim::LoadScenarioFile(scenario_path);
  // the robot, its trajectory and the sensors' links, as a run would check them
  const proxsim::Simulation simulation(scenario, 1);
  // (with an MJCF scene file as the robot: how many objects it brought, and whether its floor was left out)
  const proxsim::SceneFromModel& from_model = scenario.scene_from_model;
  const std::string brought =
      from_model.objects.empty() ? "" : ", " + std::to_string(from_model.objects.size()) + " from the robot's model file";
  std::printf("%s: valid (%zu objects%s, %zu sensors, %lld samples)\n", scenario_path.c_str(),
              scenario.scene.objects.size(), brought.c_str(), scenario.sensors.size(),
              static_cast<long long>(scenario.SampleCount()));
  if (!from_model.ground_left_out.empty())
    std::printf("  the model file's ground plane '%s' is left out: the scene's own ground stands for it\n",
                from_model.ground_left_out.c_str());
  return 0;
}

// the scenario's generated world written out as a plain scenario, checked
// as a run would read it from where it is written
int Generate(const std::string& scenario_path, const std::string& out_path) {
  if (const std::string problem = proxsim::ReplaceableFileProblem(out_path); !problem.empty())
    throw proxsim::InputError("--out " + problem);
  std::error_code error;
  if (!std::filesystem::is_regular_file(scenario_path, error))
    throw proxsim::InputError(scenario_path + ": cannot read the scenario file: no such file");
  std::ifstream file(scenario_path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  const std::string world = proxsim::GeneratedScenarioText(text.str(), scenario_path, out_path);
  const proxsim::Scenario scenario = proxsim::LoadScenarioText(world, out_path);
  const proxsim::Simulation simulation(scenario, 1);
  proxsim::WriteFileAtomically(out_path, world);
  std::printf("%s: written from %s (%zu objects)\n", out_path.c_str(), scenario_path.c_str(),
              scenario.scene.objects.size());
  return 0;
}

// A slice of a study run (--shard): its journal and record written, the answers left to `study merge`
int SliceDone(const std::string& study_path, const std::string& out_dir, const proxsim::StudySlice& slice) {
  std::printf("proxsim study: %s — slice %s done in %s/ (journal.jsonl, %s); when every slice is done: "
              "proxsim study merge SLICE_DIR... --out DIR\n",
              study_path.c_str(), slice.Name().c_str(), out_dir.c_str(), proxsim::kSliceRecordName);
  return 0;
}

// `mode: outcomes`: the answers from every job's results (a single run's, or the merged slices'), printed and drawn
int AnswerOutcomeStudy(const proxsim::OutcomeStudyConfig& study, const proxsim::OutcomeResults& results,
                       const std::string& study_path, const std::string& out_dir, const std::string& folder_path,
                       bool report) {
  const nlohmann::json selection = proxsim::WriteOutcomeAnswers(study, results, folder_path);
  std::printf("proxsim study: %s — %zu closed-loop runs\n", study_path.c_str(), study.runs_per_job() * study.jobs.size());
  for (std::size_t i = 0; i < std::min<std::size_t>(5, selection["ranking"].size()); ++i) {
    const auto& row = selection["ranking"][i];
    const std::string perception =
        row["perception_score"].is_null()
            ? std::string()
            : proxsim::FormatNumbers(", perception %.2f", row["perception_score"].get<double>());
    // the strategy with the values tuned for this set (tune:), as its variant is named
    const std::string tuned = row["tuned"].get<std::string>();
    const std::string strategy = row["strategy"].get<std::string>() + (tuned.empty() ? "" : "[" + tuned + "]");
    std::printf("  %-40s %-12s success %.3f [%.3f, %.3f]%s%s%s\n", row["set"].get<std::string>().c_str(),
                strategy.c_str(), row["success_rate"].get<double>(),
                row["success_ci95"][0].get<double>(), row["success_ci95"][1].get<double>(), perception.c_str(),
                row["price_usd"].is_null() ? "" : proxsim::FormatNumbers(", $%.2f", row["price_usd"].get<double>()).c_str(),
                row["baseline"].is_null() ? "" : " (baseline)");
  }
  for (const auto& warning : selection["warnings"]) std::printf("warning: %s\n", warning.get<std::string>().c_str());
  if (const auto& lowest = selection["lowest_expected_cost"]; !lowest.is_null()) {
    std::printf("lowest expected cost per run: %s with %s, $%.3f a run\n", lowest["set"].get<std::string>().c_str(),
                lowest["strategy"].get<std::string>().c_str(), lowest["expected_cost_per_run_usd"].get<double>());
  }
  const auto& cheapest = selection["cheapest_reaching_target"];
  if (cheapest.is_null()) {
    std::printf("no priced set reaches the target success rate %.3f\n", study.target_success);
  } else {
    std::printf("cheapest reaching %.3f: %s with %s, $%.2f, success %.3f\n", study.target_success,
                cheapest["set"].get<std::string>().c_str(), cheapest["strategy"].get<std::string>().c_str(),
                cheapest["price_usd"].get<double>(), cheapest["success_rate"].get<double>());
  }
  std::printf("outputs in %s/ (results.csv, ranking.csv, pairs.csv, selection.json, failures.csv, episodes.jsonl)\n",
              out_dir.c_str());
  std::fflush(stdout);
  if (!report) return 0;
  if (proxsim::MakeStudyReport(out_dir) != 0) {
    std::fprintf(stderr, "proxsim: the study's files are complete, but its figures could not be drawn\n");
    return kExitFailure;
  }
  std::printf("report: %s/index.html\n", out_dir.c_str());
  return 0;
}

// `mode: outcomes`: sensor sets with strategies, closed loop, ranked by how often the robot gets through
int OutcomeStudy(const std::string& study_path, const proxsim::StudyOptions& options, bool report, bool allow_large) {
  const proxsim::OutcomeStudyConfig study = proxsim::LoadOutcomeStudyFile(study_path, allow_large);
  bool writer = false;
  std::shared_ptr<proxsim::OutputFolder> folder;  // locked until the answers and figures are written
  proxsim::StudyOptions run_options = options;
  run_options.folder = &folder;
  const proxsim::OutcomeResults results = proxsim::RunOutcomeStudy(study, run_options, &writer);
  if (!writer) return 0;  // an MPI worker rank: rank 0 writes everything
  if (options.slice) return SliceDone(study_path, options.out_dir, *options.slice);
  return AnswerOutcomeStudy(study, results, study_path, options.out_dir, folder->path(), report);
}

// a placement study: the answers from every job's metrics (a single run's, or the merged slices'), printed and drawn
int AnswerStudy(const proxsim::StudyConfig& study, const proxsim::StudyResults& results, const std::string& study_path,
                const std::string& out_dir, const std::string& folder_path, bool report) {
  const nlohmann::json selection = proxsim::WriteStudyAnswers(study, results, folder_path);
  std::printf("proxsim study: %s — %zu runs\n", study_path.c_str(),
              study.candidates.size() * study.variants.size() * study.seeds.size());
  std::printf("best %d sensors (greedy, hazards covered then lead, over %zu items):\n", study.select_sensors,
              selection["items"].get<std::size_t>());
  for (const auto& pick : selection["chosen"]) {
    std::printf("  %-48s detection rate %.3f, mean lead %s m\n", pick["added"].get<std::string>().c_str(),
                pick["detection_rate"].get<double>(),
                pick["mean_lead_m"].is_null() ? "n/a" : std::to_string(pick["mean_lead_m"].get<double>()).c_str());
  }
  if (selection["chosen"].size() < static_cast<std::size_t>(study.select_sensors)) {
    std::printf("  (no further sensor detects another hazard or sees one farther ahead)\n");
  }
  std::printf("outputs in %s/ (results.csv, ranking.csv, selection.json)\n", out_dir.c_str());
  std::fflush(stdout);
  if (!report) return 0;
  if (proxsim::MakeStudyReport(out_dir) != 0) {
    std::fprintf(stderr, "proxsim: the study's files are complete, but its figures could not be drawn\n");
    return kExitFailure;
  }
  std::printf("report: %s/index.html\n", out_dir.c_str());
  return 0;
}

int Study(const std::string& study_path, const std::string& out_dir, int threads, bool resume, bool report,
          bool force, bool allow_large, const std::string& shard) {
  CheckOutArgument(out_dir);
  proxsim::StudyOptions options{
      .out_dir = out_dir, .threads = threads, .resume = resume, .progress = true, .force = force};
  if (!shard.empty())
    options.slice = proxsim::ParseStudySlice(shard, [](const char* name) { return std::getenv(name); });
  if (proxsim::IsOutcomeStudyFile(study_path)) return OutcomeStudy(study_path, options, report, allow_large);
  const proxsim::StudyConfig study = proxsim::LoadStudyFile(study_path, allow_large);
  bool writer = false;
  std::shared_ptr<proxsim::OutputFolder> folder;  // locked until the answers and figures are written
  options.folder = &folder;
  const proxsim::StudyResults results = proxsim::RunStudy(study, options, &writer);
  if (!writer) return 0;  // an MPI worker rank: rank 0 writes everything
  if (options.slice) return SliceDone(study_path, out_dir, *options.slice);
  return AnswerStudy(study, results, study_path, out_dir, folder->path(), report);
}

// `study merge`: the slices checked and joined into the study's journal, then
// the answers written by the very code a single run's go through
int MergeStudy(const std::vector<std::string>& slice_dirs, const std::string& out_dir, bool report, bool force) {
  CheckOutArgument(out_dir);
  const std::vector<proxsim::SliceRecord> slices = proxsim::ReadStudySlices(slice_dirs);
  const std::string& study_path = slices.front().study_file;
  std::shared_ptr<proxsim::OutputFolder> folder;  // locked until the answers and figures are written
  const proxsim::StudyOptions options{.out_dir = out_dir, .force = force, .folder = &folder};
  // read from its absolute path (the slices' working folders are not ours);
  // the answers then echo it as the slices' command line named it, as a
  // single run invoked that way does (a failure's replay file). The slices
  // ran it, so its size was accepted then.
  const std::string& given = slices.front().study_file_given;
  if (proxsim::IsOutcomeStudyFile(study_path)) {
    proxsim::OutcomeStudyConfig study = proxsim::LoadOutcomeStudyFile(study_path, true);
    const auto lines = proxsim::MergeStudySlices(proxsim::OutcomeJobSet(study), slices, options);
    study.source = given;
    return AnswerOutcomeStudy(study, proxsim::OutcomeResultsFromJournal(study, lines), given, out_dir,
                              folder->path(), report);
  }
  proxsim::StudyConfig study = proxsim::LoadStudyFile(study_path, true);
  const auto lines = proxsim::MergeStudySlices(proxsim::StudyJobSet(study), slices, options);
  study.source = given;
  return AnswerStudy(study, proxsim::StudyResultsFromJournal(study, lines), given, out_dir, folder->path(), report);
}

// `fidelity`: the inputs checked before the folder is claimed (bad input writes nothing),
// then the replay, the files, the summary and the figure
int Fidelity(const std::string& path, const std::string& out_dir, const std::string& noise, int threads, bool report,
             bool force) {
  CheckOutArgument(out_dir);
  const std::optional<bool> simulate_noise = noise.empty() ? std::nullopt : std::optional<bool>(noise == "on");
  const proxsim::FidelityInputs inputs = proxsim::LoadFidelityInputs(path, simulate_noise);
  const proxsim::OutputFolder folder(out_dir, {.command = "fidelity", .force = force, .ours = "fidelity.json"});
  const proxsim::FidelityComparison comparison = proxsim::CompareFidelity(inputs, threads);
  proxsim::WriteFidelityOutputs(folder.path(), inputs.config, inputs.recording, comparison.replayed,
                                comparison.compared, comparison.rows);
  std::fputs(proxsim::FidelitySummary(inputs, comparison).c_str(), stdout);
  std::printf("outputs in %s/ (fidelity.json, fidelity_stats.csv, fidelity_pairs.csv)\n", out_dir.c_str());
  std::fflush(stdout);
  if (!report) return 0;
  if (proxsim::MakeFidelityReport(folder.path()) != 0) {
    std::fprintf(stderr, "proxsim: the comparison's files are complete, but its figure could not be drawn\n");
    return kExitFailure;
  }
  std::printf("figure: %s/fidelity.png\n", out_dir.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"proxsim — proximity sensors on a walking biped, by ray casting"};
  app.require_subcommand(1);
  app.set_version_flag("--version", PROXSIM_VERSION);

  std::string scenario_path, out_dir = "proxsim-out";
  std::string seed;  // parsed by ParseSeed: CLI11 wraps -1 and 2^64 round
  int threads = 1;
  CLI::App* run = app.add_subcommand("run", "run a scenario (default: the paper's experiment)");
  run->add_option("scenario", scenario_path, "scenario YAML file; none runs the built-in paper experiment")
      ->check(ExistingInputFile());
  run->add_option("--out", out_dir, "output folder")->capture_default_str();
  run->add_option("--seed", seed, "seed of the sensor noise, 0 to 2^64-1 (overrides the scenario's)");
  bool run_force = false;
  run->add_flag("--force", run_force,
                "write into a non-empty folder that holds no previous run (its files are never removed)");
  run->add_option("--threads", threads, "ray-casting threads")->check(CLI::Range(1, 256))->capture_default_str();
  bool no_report = false;
  run->add_flag("--no-report", no_report, "skip the figures and the viewer (the data files are still written)");
  std::string format = "csv";
  std::string run_mcap;
  run->add_option("--mcap", run_mcap, "also write the run as an MCAP file for Foxglove (docs/foxglove.md)");
  // optional, not a string: `--ros2 ''` must be refused, not taken for "no bag"
  std::optional<std::string> run_ros2;
  run->add_option("--ros2", run_ros2, "also write the run as a ROS 2 bag into this new folder (docs/ros2.md)");
  run->add_option("--format", format, "readings as readings.csv, or as one .npy per column in readings/ (large runs)")
      ->check(CLI::IsMember({"csv", "npy"}))
      ->capture_default_str();

  bool bench_json = false, bench_quick = false;
  CLI::App* bench = app.add_subcommand("bench", "race proxsim against bare Embree, Bullet and MuJoCo (a few minutes)");
  bench->add_flag("--json", bench_json, "print one JSON object with every figure (keys: docs/performance.md)");
  bench->add_flag("--quick", bench_quick, "fewer rays and a shorter heavy run: a smoke test");
  std::string bench_from;
  bench->add_option("--from", bench_from, "print the Markdown tables of a run saved with --json, without running")
      ->check(CLI::ExistingFile);
  std::string bench_only = "all";
  bench->add_option("--only", bench_only,
                    "run one part: rays (the engines), e2e (paper and heavy runs), robots (the H1 against the biped), "
                    "study (placement studies, MPI), outcomes (closed-loop studies on generated rooms, MPI), terrain (planning footsteps on the stairs course), map "
                    "(the terrain map's cost per sample), python (co-simulation and VecWalkEnv from Python) or worlds "
                    "(moving objects, generating worlds)")
      ->check(CLI::IsMember({"all", "rays", "e2e", "robots", "study", "outcomes", "terrain", "map", "python", "worlds"}))
      ->capture_default_str();

  std::string plot_dir;
  CLI::App* plot = app.add_subcommand("plot", "redraw the figures and the viewer of a finished run");
  plot->add_option("out", plot_dir, "the run's output folder")->required()->check(CLI::ExistingDirectory);

  std::string export_dir;
  std::optional<std::string> export_mcap, export_ros2;
  CLI::App* export_command =
      app.add_subcommand("export", "write a finished run as an MCAP file for Foxglove and/or a ROS 2 bag");
  export_command->add_option("out", export_dir, "the run's output folder")->required()->check(CLI::ExistingDirectory);
  export_command->add_option("--mcap", export_mcap, "the MCAP file to write (docs/foxglove.md)");
  export_command->add_option("--ros2", export_ros2, "the new folder to write the ROS 2 bag into (docs/ros2.md)");

  std::string study_path, study_out = "study-out";
  int study_threads = 0;
  bool study_resume = false, study_no_report = false;
  CLI::App* study = app.add_subcommand("study", "rank sensor mountings over scene variants and seeds (mpirun: over ranks)");
  study->add_option("study", study_path, "study YAML file (see data/studies/)");
  study->add_option("--out", study_out, "output folder")->capture_default_str();
  study->add_option("--threads", study_threads, "worker threads (default: every core; 1 per rank under mpirun)")
      ->check(CLI::Range(0, 256));
  study->add_flag("--resume", study_resume, "finish a study that was stopped, keeping the runs it had finished");
  study->add_flag("--no-report", study_no_report, "skip the figures and the HTML page");
  bool study_force = false, study_allow_large = false;
  study->add_flag("--force", study_force,
                  "write into a non-empty folder that holds no previous study (its files are never removed)");
  study->add_flag("--allow-large", study_allow_large,
                  "run a study beyond the size bounds (10000 candidates, 1000000 runs; docs/studies.md)");
  std::string study_shard;
  study->add_option("--shard", study_shard,
                    "run only slice i of N of the jobs (i/N, counted from 1), or slurm: the slice of this Slurm "
                    "job array task (SLURM_ARRAY_TASK_ID); then `study merge` the slices' folders");
  // `study merge DIR... --out DIR`: a subcommand of study, so the study file is not required with it
  std::vector<std::string> merge_dirs;
  std::string merge_out = "study-out";
  bool merge_no_report = false, merge_force = false;
  CLI::App* merge = study->add_subcommand(
      "merge", "put the slices of one study (study --shard) back together: the answers of a single run, byte for byte");
  merge->add_option("slices", merge_dirs, "every slice's output folder")->required();
  merge->add_option("--out", merge_out, "output folder of the merged study")->capture_default_str();
  merge->add_flag("--no-report", merge_no_report, "skip the figures and the HTML page");
  merge->add_flag("--force", merge_force,
                  "write into a non-empty folder that holds no previous study (its files are never removed)");

  std::string fidelity_path, fidelity_out = "fidelity-out", fidelity_noise;
  int fidelity_threads = 1;
  bool fidelity_no_report = false, fidelity_force = false;
  CLI::App* fidelity = app.add_subcommand(
      "fidelity", "compare a part's model with your own recording of it: errors by zone and range band, and a figure");
  fidelity->add_option("file", fidelity_path, "fidelity YAML file: scene, sensor, recording (docs/fidelity.md)")
      ->required()
      ->check(ExistingInputFile());
  fidelity->add_option("--out", fidelity_out, "output folder")->capture_default_str();
  fidelity->add_option("--noise", fidelity_noise, "the model's noise: on or off (default: the file's simulate_noise)")
      ->check(CLI::IsMember({"on", "off"}));
  fidelity->add_option("--threads", fidelity_threads, "ray-casting threads")->check(CLI::Range(1, 256))->capture_default_str();
  fidelity->add_flag("--no-report", fidelity_no_report, "skip the figure (the data files are still written)");
  fidelity->add_flag("--force", fidelity_force,
                     "write into a non-empty folder that holds no previous comparison (its files are never removed)");

  std::string validate_path;
  CLI::App* validate = app.add_subcommand("validate", "check a scenario and list every problem");
  validate->add_option("scenario", validate_path, "scenario YAML file")->required();

  std::string generate_path, generate_out;
  CLI::App* generate = app.add_subcommand("generate", "write a scenario's generated world (scene.generate) as a plain scenario");
  generate->add_option("scenario", generate_path, "scenario YAML file with scene: {generate: ...}")->required();
  generate->add_option("--out", generate_out, "the scenario file to write")->required();

  std::string inspect_target;
  bool inspect_json = false;
  CLI::App* inspect = app.add_subcommand(
      "inspect", "list a robot's links, sizes, joints and limits, and suggest its leg map and shank sensor spots");
  inspect->add_option("robot", inspect_target, "a URDF file, a scenario file (its robot) or builtin:biped")->required();
  inspect->add_flag("--json", inspect_json, "print one JSON object (keys: docs/robots.md)");

  CLI::App* columns = app.add_subcommand("columns", "print the readings' columns (name, type, unit, meaning) as a Markdown table");
  bool columns_sensor_keys = false;
  columns->add_flag("--sensor-keys", columns_sensor_keys,
                    "print every key a sensor takes in a scenario (type and unit, default, meaning) instead");
  std::string columns_keys;
  columns->add_option("--keys", columns_keys,
                      "print the keys of a scenario section (type and unit, default, meaning) instead: " +
                          [] {
                            std::string names;
                            for (const std::string& name : proxsim::ConfigSectionNames())
                              names += (names.empty() ? "" : ", ") + name;
                            return names;
                          }())
      ->check([](const std::string& name) {
        return proxsim::ConfigSectionParams(name) ? std::string() : "not a section with declared keys";
      });

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitBadInput;
  }

  try {
    if (*run) return Run(scenario_path, out_dir, seed, threads, !no_report, format, run_force, run_mcap, run_ros2);
    if (*bench && !bench_from.empty()) {
      std::string report;
      // a regular file only: a FIFO would block the read for ever
      if (std::error_code ec; !std::filesystem::is_regular_file(bench_from, ec))
        throw proxsim::InputError(bench_from + ": not a regular file; expected the output of `proxsim bench --json`");
      try {
        std::ifstream saved(bench_from);
        report = proxsim::bench::BenchReport(nlohmann::json::parse(saved));
      } catch (const nlohmann::json::exception& error) {
        throw proxsim::InputError(bench_from + ": not the output of `proxsim bench --json` (" + error.what() + ")");
      }
      std::fputs(report.c_str(), stdout);
      return 0;
    }
    if (*bench) {
      const nlohmann::json result = proxsim::bench::RunBench(
          {.quick = bench_quick,
           .progress = true,
           .rays = bench_only == "all" || bench_only == "rays",
           .end_to_end = bench_only == "all" || bench_only == "e2e",
           .robots = bench_only == "all" || bench_only == "robots",
           .study = bench_only == "all" || bench_only == "study",
           .outcomes = bench_only == "all" || bench_only == "outcomes",
           .terrain = bench_only == "all" || bench_only == "terrain",
           .map = bench_only == "all" || bench_only == "map",
           .python = bench_only == "all" || bench_only == "python",
           .worlds = bench_only == "all" || bench_only == "worlds"});
      const bool whole = bench_only == "all";
      std::fputs(bench_json || !whole ? (result.dump(2) + "\n").c_str() : proxsim::bench::BenchReport(result).c_str(),
                 stdout);
      return 0;
    }
    if (*plot) {
      CheckOneRun(plot_dir);
      // redrawing replaces report/: hold the folder against a run into it meanwhile
      const proxsim::OutputFolder folder(plot_dir, {.command = "plot", .create = false, .check_contents = false});
      // the script's 2 is a run file it cannot read: bad input, as the C++ readers'
      const int status = proxsim::MakeReport(plot_dir);
      return status == 0 ? 0 : status == 2 ? 2 : kExitFailure;
    }
    if (*export_command) {
      if (!export_mcap && !export_ros2) throw proxsim::InputError("export: give --mcap FILE, --ros2 DIR or both");
      CheckOneRun(export_dir);
      if (export_mcap) proxsim::CheckMcapPath(*export_mcap, export_dir);
      if (export_ros2) proxsim::CheckRos2Path(*export_ros2, export_dir);
      // hold the folder against a run into it while its files are read
      const proxsim::OutputFolder folder(export_dir, {.command = "export", .create = false, .check_contents = false});
      int code = export_mcap ? proxsim::ExportMcap(export_dir, *export_mcap) : 0;
      if (code == 0 && export_ros2) code = proxsim::ExportRos2(export_dir, *export_ros2);
      // the two writers give bad input the same code
      static_assert(proxsim::kMcapExportBadInput == proxsim::kRos2ExportBadInput);
      return code == 0 ? 0 : code == proxsim::kMcapExportBadInput ? kExitBadInput : kExitFailure;
    }
    if (*fidelity)
      return Fidelity(fidelity_path, fidelity_out, fidelity_noise, fidelity_threads, !fidelity_no_report, fidelity_force);
    if (*validate) return Validate(validate_path);
    if (*generate) return Generate(generate_path, generate_out);
    if (*inspect) return proxsim::InspectCommand(inspect_target, inspect_json);
    if (*columns && !columns_keys.empty()) {
      std::fputs(proxsim::ParamsMarkdown(*proxsim::ConfigSectionParams(columns_keys)).c_str(), stdout);
      return 0;
    }
    if (*columns) {
      std::fputs(columns_sensor_keys ? proxsim::SensorKeysMarkdown().c_str() : proxsim::ReadingsColumnsMarkdown().c_str(),
                 stdout);
      return 0;
    }
    if (*study && *merge) return MergeStudy(merge_dirs, merge_out, !merge_no_report, merge_force);
    if (*study) {
      if (study_path.empty()) {
        throw proxsim::InputError(
            "study: no study file given; expected `proxsim study FILE` or `proxsim study merge DIR... --out DIR`");
      }
      return Study(study_path, study_out, study_threads, study_resume, !study_no_report, study_force,
                   study_allow_large, study_shard);
    }
  } catch (const proxsim::InputError& error) {
    const int code = PrintInputError(error);
    proxsim::AbortMpiJobAfterFailure(code);  // every rank of a study's MPI job ends with it
    return code;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "proxsim: error: %s\n", error.what());
    proxsim::AbortMpiJobAfterFailure(kExitFailure);
    return kExitFailure;
  }
  return 0;
}
