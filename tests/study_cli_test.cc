// `proxsim study` through the real CLI: the shipped example's answers and
// figures; the same files whatever ran it (1 thread, 2 threads, 2 MPI ranks);
// a study killed with SIGKILL and resumed gives the same files without
// redoing a job; bad study files list every problem before any run.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>

#include "cli_helpers.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::ReadCsv;
using testing::ReadFile;
using testing::RunCommand;
using testing::RunProxsim;

const std::string kTibiaStudy = std::string(PROXSIM_SOURCE_DIR) + "/data/studies/tibia_placement.yaml";
// as root, mpirun needs these; under the ASan preset, OpenMPI's own plug-ins
// leak at exit (unloaded modules, not proxsim's memory): leak checks stay on
// for every run of this file but the ranks'
constexpr const char* kStudyMpiEnv =
    "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 ";

std::size_t LineCount(const fs::path& path) {
  std::ifstream in(path);
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

class StudyCliTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = FreshDir("study_cli"); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(StudyCliTest, TheExampleRanksPicksThreePartsAndDrawsIt) {
  const auto out = dir_ / "example";
  const auto result = RunProxsim("study " + kTibiaStudy + " --out " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  // 4 types x 2 links x 3 positions x 3 pitches, in 4 scenes with 3 seeds
  EXPECT_EQ(ReadCsv(out / "results.csv").rows.size(), 72u * 4u * 3u);
  EXPECT_EQ(ReadCsv(out / "ranking.csv").rows.size(), 72u);
  const auto selection = nlohmann::json::parse(ReadFile(out / "selection.json"));
  ASSERT_EQ(selection["chosen"].size(), 3u);
  for (const auto& pick : selection["chosen"]) {
    EXPECT_FALSE(pick["added"].get<std::string>().starts_with("ideal@")) << "select.types excludes the ideal sensor";
  }
  // the obstacle in three variants and the stairs course's steps up and down, each with three seeds
  EXPECT_EQ(selection["items"], 15);
  for (const char* file : {"lead_heatmap.png", "lead_heatmap.svg", "pareto.png", "pareto.svg", "index.html"}) {
    EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
  }
  EXPECT_NE(ReadFile(out / "index.html").find("ranking.csv"), std::string::npos);
}

// A datasheet part is a sensor of its own: an HC-SR04 and the paper's
// ultrasonic model share a physics type but not a row key or a heat-map panel.
TEST_F(StudyCliTest, CandidatesAreKeyedByTheirPartNotOnlyTheirType) {
  fs::create_directories(dir_);
  const auto study = dir_ / "parts.yaml";
  std::ofstream(study) << "proxsim_study: 1\n"
                          "base: " << PROXSIM_SOURCE_DIR << "/data/scenarios/paper_dining_room.yaml\n"
                          "candidates:\n"
                          "  axes: {type: [ultrasonic, hc_sr04, vl53l0x], link: left_tibia, along_m: [-0.35, -0.25],\n"
                          "         forward_m: 0.06, pitch_deg: [0, 15]}\n"
                          "scenes: [{name: room, builtin: dining_room}]\n"
                          "seeds: [1]\n"
                          "hazards: [obstacle]\n";
  const auto out = dir_ / "parts";
  const auto result = RunProxsim("study " + study.string() + " --out " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::map<std::string, std::set<std::string>> parts_by_type;
  for (const auto& row : ReadCsv(out / "ranking.csv").rows) parts_by_type[row.at("type")].insert(row.at("part"));
  EXPECT_EQ(parts_by_type["ultrasonic"], (std::set<std::string>{"", "hc_sr04"}));
  EXPECT_EQ(parts_by_type["laser"], (std::set<std::string>{"vl53l0x"}));
  for (const auto& row : ReadCsv(out / "results.csv").rows)
    EXPECT_EQ(row.at("part").empty(), row.at("candidate").starts_with("ultrasonic@")) << row.at("candidate");
  // the heat map: one panel per part (or model) and link
  const std::string svg = ReadFile(out / "lead_heatmap.svg");
  for (const char* panel : {"hc_sr04 on left_tibia", "ultrasonic on left_tibia", "vl53l0x on left_tibia"})
    EXPECT_NE(svg.find(panel), std::string::npos) << panel;
}

TEST_F(StudyCliTest, FilesAreByteIdenticalWithOneThreadTwoThreadsAndTwoMpiRanks) {
  const std::string common = "study " + kTibiaStudy + " --no-report --out ";
  ASSERT_EQ(RunProxsim(common + (dir_ / "t1").string() + " --threads 1").exit_code, 0);
  ASSERT_EQ(RunProxsim(common + (dir_ / "t2").string() + " --threads 2").exit_code, 0);
  std::vector<std::string> outs = {"t2"};
  if (RunCommand("command -v mpirun").exit_code == 0) {
    const auto mpi = RunCommand(std::string(kStudyMpiEnv) + "mpirun --oversubscribe -x ASAN_OPTIONS -np 2 " + PROXSIM_BINARY + " " + common +
                                (dir_ / "mpi2").string() + " --threads 1");
    ASSERT_EQ(mpi.exit_code, 0) << mpi.output;
    EXPECT_NE(mpi.output.find("1 thread x 2 ranks"), std::string::npos) << mpi.output;
    outs.push_back("mpi2");
  } else {
    std::printf("[ SKIPPED PART ] mpirun not found: the 2-rank comparison did not run (scripts/install-deps.sh installs openmpi-bin)\n");
  }
  for (const std::string& out : outs) {
    for (const char* file : {"results.csv", "ranking.csv", "selection.json"}) {
      EXPECT_EQ(ReadFile(dir_ / out / file), ReadFile(dir_ / "t1" / file)) << out << "/" << file;
    }
  }
}

// A study long enough to be killed in the middle: 24 jobs of one scene and seed each.
const std::string kLongStudy =
    "proxsim_study: 1\nbase: " + std::string(PROXSIM_SOURCE_DIR) + "/data/scenarios/paper_dining_room.yaml\n"
    "candidates:\n  axes:\n    type: [laser, ultrasonic, reflectance]\n    link: left_tibia\n"
    "    along_m: -0.35\n    forward_m: 0.06\n    pitch_deg: [0, 15]\n"
    "seeds: {from: 1, to: 24}\nhazards: [obstacle]\n";

TEST_F(StudyCliTest, KilledWithSigkillAndResumedGivesTheSameFilesWithoutRedoingAJob) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "long.yaml") << kLongStudy;
  const std::string study = (dir_ / "long.yaml").string();
  ASSERT_EQ(RunProxsim("study " + study + " --no-report --threads 1 --out " + (dir_ / "whole").string()).exit_code, 0);
  const std::size_t jobs = LineCount(dir_ / "whole" / "journal.jsonl") - 1;
  ASSERT_EQ(jobs, 24u);

  // start it again and kill it once a few jobs are journaled
  const fs::path cut = dir_ / "cut";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string out = cut.string();
    execl(PROXSIM_BINARY, PROXSIM_BINARY, "study", study.c_str(), "--no-report", "--threads", "1", "--out",
          out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline &&
         !(fs::exists(cut / "journal.jsonl") && LineCount(cut / "journal.jsonl") >= 4)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the study finished before it could be killed: make it longer";
  const std::size_t journaled = LineCount(cut / "journal.jsonl") - 1;
  ASSERT_GE(journaled, 3u);
  ASSERT_LT(journaled, jobs);
  EXPECT_FALSE(fs::exists(cut / "results.csv"));

  const auto resumed = RunProxsim("study " + study + " --no-report --threads 1 --resume --out " + cut.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("already done (resumed)"), std::string::npos) << resumed.output;
  for (const char* file : {"results.csv", "ranking.csv", "selection.json"}) {
    EXPECT_EQ(ReadFile(cut / file), ReadFile(dir_ / "whole" / file)) << file;
  }
  // every job journaled once: none redone, none lost
  std::ifstream journal(cut / "journal.jsonl");
  std::string line;
  std::getline(journal, line);  // the study's fingerprint
  std::set<std::size_t> seen;
  while (std::getline(journal, line)) EXPECT_TRUE(seen.insert(nlohmann::json::parse(line).at("job").get<std::size_t>()).second);
  EXPECT_EQ(seen.size(), jobs);
}

TEST_F(StudyCliTest, ResumingAnotherStudysJournalIsRefused) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "long.yaml") << kLongStudy;
  const std::string out = (dir_ / "out").string();
  ASSERT_EQ(RunProxsim("study " + (dir_ / "long.yaml").string() + " --no-report --out " + out).exit_code, 0);
  const auto other = RunProxsim("study " + kTibiaStudy + " --no-report --resume --out " + out);
  EXPECT_EQ(other.exit_code, 2) << other.output;
  EXPECT_NE(other.output.find("belongs to another study"), std::string::npos) << other.output;
}

TEST_F(StudyCliTest, AJournalLineOfTheWrongShapeIsAnInputErrorNotAnOutOfBoundsRead) {
  // issue 23 (c): a line with another study's number of metrics once read past
  // the end of a vector (study_answers.cc) on --resume
  fs::create_directories(dir_);
  std::ofstream(dir_ / "long.yaml") << kLongStudy;
  const std::string study = (dir_ / "long.yaml").string();
  const fs::path out = dir_ / "out";
  ASSERT_EQ(RunProxsim("study " + study + " --no-report --threads 2 --out " + out.string()).exit_code, 0);
  const std::string whole = ReadFile(out / "journal.jsonl");
  const std::string fingerprint = whole.substr(0, whole.find('\n') + 1);
  const char* const kBadLines[] = {
      R"({"job": 0, "metrics": []})",
      R"({"job": 0, "metrics": [{"h": [], "n": 1, "fa": 0, "self": 0, "graze": 0, "floor": 0}]})",
      R"({"job": 100000, "metrics": []})",
      R"({"job": -1, "metrics": []})",
      R"([1, 2, 3])",
  };
  for (const char* line : kBadLines) {
    SCOPED_TRACE(line);
    std::ofstream(out / "journal.jsonl", std::ios::trunc) << fingerprint << line << "\n";
    const auto resumed = RunProxsim("study " + study + " --no-report --threads 1 --resume --out " + out.string());
    EXPECT_EQ(resumed.exit_code, 2) << resumed.output;
    EXPECT_NE(resumed.output.find("journal.jsonl:2: journal line"), std::string::npos) << resumed.output;
  }
}

TEST_F(StudyCliTest, TwoStudiesIntoOneFolderAtOnceTheSecondFailsNamingTheFirst) {
  // issue 23 (h): both once exited 0, their journals spliced
  fs::create_directories(dir_);
  std::ofstream(dir_ / "long.yaml") << kLongStudy;
  const std::string study = (dir_ / "long.yaml").string();
  const fs::path out = dir_ / "out";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string out_arg = out.string();
    const int null_fd = open("/dev/null", O_WRONLY);
    dup2(null_fd, STDOUT_FILENO);
    dup2(null_fd, STDERR_FILENO);
    execl(PROXSIM_BINARY, PROXSIM_BINARY, "study", study.c_str(), "--no-report", "--threads", "1", "--out",
          out_arg.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline && !fs::exists(out / "journal.jsonl"))
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const auto second = RunProxsim("study " + study + " --no-report --threads 1 --out " + out.string());
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the first study failed";
  EXPECT_EQ(second.exit_code, 2) << second.output;
  EXPECT_NE(second.output.find("in use by pid " + std::to_string(pid) + ": proxsim study"), std::string::npos)
      << second.output;
  EXPECT_EQ(LineCount(out / "journal.jsonl"), 25u) << "one study's 24 jobs and its fingerprint, nothing spliced";
}

TEST_F(StudyCliTest, AStudyTooLargeIsRefusedBeforeAnythingIsBuilt) {
  // issue 23 (m): 1.9 million candidates ended in std::bad_alloc; the size is now counted first
  fs::create_directories(dir_);
  const std::string base = "proxsim_study: 1\nbase: " + std::string(PROXSIM_SOURCE_DIR) +
                           "/data/scenarios/paper_dining_room.yaml\n";
  std::ofstream(dir_ / "huge.yaml") << base << "candidates:\n  axes:\n    type: [laser, ultrasonic]\n"
                                    << "    link: left_tibia\n    along_m: {from: -0.4, to: 0, step: 0.0004}\n"
                                    << "    pitch_deg: {from: 0, to: 94, step: 0.1}\n";
  const auto huge = RunCommand("timeout -s KILL 60 " + std::string(PROXSIM_BINARY) + " study " +
                               (dir_ / "huge.yaml").string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(huge.exit_code, 2) << huge.output;
  EXPECT_NE(huge.output.find("the axes make 1.884e+06 candidates (2 types x 1 links x 1001"), std::string::npos) << huge.output;
  EXPECT_NE(huge.output.find("--allow-large"), std::string::npos) << huge.output;
  EXPECT_FALSE(fs::exists(dir_ / "out"));

  // 100 candidates x 1 scene x 20000 seeds = 2e6 runs
  std::ofstream(dir_ / "many_runs.yaml") << base << "candidates:\n  axes:\n    type: laser\n    link: left_tibia\n"
                                         << "    pitch_deg: {from: 0, to: 99, step: 1}\n"
                                         << "seeds: {from: 1, to: 20000}\n";
  const auto runs = RunCommand("timeout -s KILL 60 " + std::string(PROXSIM_BINARY) + " study " +
                               (dir_ / "many_runs.yaml").string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(runs.exit_code, 2) << runs.output;
  EXPECT_NE(runs.output.find("= 2000000 runs; expected at most 1000000 (pass --allow-large"), std::string::npos)
      << runs.output;
}

TEST_F(StudyCliTest, BadStudiesListEveryProblemBeforeAnyRun) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "bad.yaml")
      << "proxsim_study: 1\nbase: " << PROXSIM_SOURCE_DIR << "/data/scenarios/paper_dining_room.yaml\n"
      << "candidates:\n  axes:\n    type: [laser, sonar]\n    link: left_tibia\n    colour: red\n    pitch_deg: []\n"
      << "    along_m: {from: -0.1, to: -0.3}\n"
      << "scenes:\n  - {name: fine, builtin: dining_room}\n  - {name: missing, scenario: no_such_scene.yaml}\n"
      << "  - {name: odd, builtin: moon}\n";
  const auto bad = RunProxsim("study " + (dir_ / "bad.yaml").string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  for (const char* problem : {"colour", "sonar", "empty list", "empty range", "no_such_scene.yaml", "moon"}) {
    EXPECT_NE(bad.output.find(problem), std::string::npos) << problem << " not reported in:\n" << bad.output;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "no run may start";

  std::ofstream(dir_ / "empty.yaml") << "proxsim_study: 1\nbase: " << PROXSIM_SOURCE_DIR
                                     << "/data/scenarios/paper_dining_room.yaml\ncandidates: {list: []}\n";
  const auto empty = RunProxsim("study " + (dir_ / "empty.yaml").string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(empty.exit_code, 2) << empty.output;
  EXPECT_NE(empty.output.find("no candidate"), std::string::npos) << empty.output;

  std::ofstream(dir_ / "wrong_link.yaml") << "proxsim_study: 1\nbase: " << PROXSIM_SOURCE_DIR
                                          << "/data/scenarios/paper_dining_room.yaml\n"
                                          << "candidates: {axes: {type: laser, link: [left_tibia, left_wing]}}\n";
  const auto link = RunProxsim("study " + (dir_ / "wrong_link.yaml").string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(link.exit_code, 2) << link.output;
  EXPECT_NE(link.output.find("left_wing"), std::string::npos) << link.output;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "journal.jsonl")) << "no run may start";

  // a hazard no scene holds would measure nothing
  std::ofstream(dir_ / "no_hazard.yaml") << "proxsim_study: 1\nbase: " << PROXSIM_SOURCE_DIR
                                         << "/data/scenarios/paper_dining_room.yaml\n"
                                         << "candidates: {axes: {type: laser, link: left_tibia}}\n"
                                         << "hazards: [obstacle, unicorn]\n";
  const auto hazard = RunProxsim("study " + (dir_ / "no_hazard.yaml").string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(hazard.exit_code, 2) << hazard.output;
  EXPECT_NE(hazard.output.find("'unicorn' begins the name of no object"), std::string::npos) << hazard.output;
  EXPECT_EQ(hazard.output.find("'obstacle'"), std::string::npos) << hazard.output;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "journal.jsonl")) << "no run may start";
}

}  // namespace
}  // namespace proxsim
