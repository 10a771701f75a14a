// No data lost, and the same bytes every time (docs/trust.md):
//  - SIGINT / SIGTERM during `proxsim run` stops after the current sample with
//    every file committed and consistent, summary.json marked interrupted, exit
//    130 / 143;
//  - an unwritable folder and a full disk are clear errors, with no file under
//    its final name and no temporary file left behind;
//  - the default run gives byte-identical files with --threads 1, 2 and 8, and
//    so does a run with enough beam rays for the work to be shared out.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"
#include "core/atomic_file.h"

extern char** environ;

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::ReadFile;
using testing::RunProxsim;

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

std::size_t FieldCount(const std::string& line) { return static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1; }

std::vector<fs::path> TemporaryFiles(const fs::path& dir) {
  std::vector<fs::path> found;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.ends_with(".tmp") || name.ends_with(".body")) found.push_back(entry.path());
  }
  return found;
}

// Starts `proxsim run SCENARIO --out OUT --no-report`, waits until its loop is
// writing, lets it run `after`, sends `signal_number`, and returns its exit code.
int RunAndSignal(const std::string& scenario, const fs::path& out, int signal_number, std::chrono::milliseconds after) {
  const fs::path log = out.string() + ".log";
  const std::string out_arg = out.string();
  std::vector<std::string> args = {PROXSIM_BINARY, "run", scenario, "--out", out_arg, "--no-report"};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, PROXSIM_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;

  // the loop writes readings.csv.tmp from its first sample on
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(out / "readings.csv.tmp") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(after);
  kill(pid, signal_number);

  int status = 0;
  const auto wait_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > wait_deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      ADD_FAILURE() << "proxsim did not stop within 60 s of the signal";
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::cerr << ReadFile(log);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// The files of an interrupted run: complete, consistent with each other and
// with summary.json.
void ExpectCompleteInterruptedRun(const fs::path& out) {
  ASSERT_TRUE(fs::exists(out / "summary.json"));
  const auto summary = nlohmann::json::parse(ReadFile(out / "summary.json"));
  EXPECT_TRUE(summary["interrupted"].get<bool>());
  const auto samples = summary["samples"].get<long long>();
  EXPECT_GT(samples, 0);
  EXPECT_LT(samples, summary["samples_planned"].get<long long>());
  const double last_t_s = summary["last_sample_t_s"].get<double>();
  EXPECT_TRUE(TemporaryFiles(out).empty());

  // readings.csv: closed (ends with a newline), every row whole, last row at the last sample time
  const std::string readings = ReadFile(out / "readings.csv");
  ASSERT_FALSE(readings.empty());
  EXPECT_EQ(readings.back(), '\n');
  const auto rows = Lines(readings);
  ASSERT_GE(rows.size(), 2u);
  for (const std::string& row : rows) ASSERT_EQ(FieldCount(row), FieldCount(rows[0])) << row;
  EXPECT_DOUBLE_EQ(std::stod(rows.back().substr(0, rows.back().find(','))), last_t_s);
  const auto sensors = summary["inputs"]["sensors"].size();
  EXPECT_EQ(static_cast<long long>(rows.size() - 1), samples * static_cast<long long>(sensors));

  // profile.ply: as many vertex lines as its header says, as the summary says
  const auto ply = Lines(ReadFile(out / "profile.ply"));
  long long declared = -1;
  std::size_t header_end = 0;
  for (std::size_t i = 0; i < ply.size(); ++i) {
    if (ply[i].rfind("element vertex ", 0) == 0) declared = std::stoll(ply[i].substr(15));
    if (ply[i] == "end_header") {
      header_end = i;
      break;
    }
  }
  ASSERT_GT(header_end, 0u);
  EXPECT_EQ(static_cast<long long>(ply.size() - header_end - 1), declared);
  EXPECT_EQ(declared, summary["profile_points"].get<long long>());

  // poses.csv: whole rows up to the same last sample
  if (fs::exists(out / "poses.csv")) {
    const auto poses = Lines(ReadFile(out / "poses.csv"));
    ASSERT_GE(poses.size(), 2u);
    for (const std::string& row : poses) ASSERT_EQ(FieldCount(row), FieldCount(poses[0])) << row;
    EXPECT_DOUBLE_EQ(std::stod(poses.back().substr(0, poses.back().find(','))), last_t_s);
  }
}

const std::string kLongWalk = std::string(PROXSIM_TEST_DATA_DIR) + "/cli/long_walk.yaml";

TEST(RunIntegrityTest, SigintStopsCleanlyWithEveryFileCommitted) {
  const auto out = FreshDir("sigint");
  EXPECT_EQ(RunAndSignal(kLongWalk, out, SIGINT, std::chrono::milliseconds(500)), 130);
  ExpectCompleteInterruptedRun(out);
}

TEST(RunIntegrityTest, SigtermStopsCleanlyWithEveryFileCommitted) {
  const auto out = FreshDir("sigterm");
  EXPECT_EQ(RunAndSignal(kLongWalk, out, SIGTERM, std::chrono::milliseconds(300)), 143);
  ExpectCompleteInterruptedRun(out);
}

TEST(RunIntegrityTest, CompleteRunSaysItWasNotInterrupted) {
  const auto out = FreshDir("not_interrupted");
  const auto result = RunProxsim("run " + std::string(PROXSIM_TEST_DATA_DIR) + "/cli/world_closed_form.yaml --out " +
                                 out.string() + " --no-report");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto summary = nlohmann::json::parse(ReadFile(out / "summary.json"));
  EXPECT_FALSE(summary["interrupted"].get<bool>());
  EXPECT_FALSE(summary.contains("samples_planned"));
}

TEST(RunIntegrityTest, UnwritableFolderIsAClearErrorWithNothingWritten) {
  // a path below a regular file cannot be a folder, even for root
  const auto parent = FreshDir("not_a_folder");
  { std::ofstream(parent) << "a file\n"; }
  const fs::path out = parent / "out";
  const auto result = RunProxsim("run " + std::string(PROXSIM_TEST_DATA_DIR) + "/cli/world_closed_form.yaml --out " +
                                 out.string() + " --no-report");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("proxsim: error:"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find(out.string()), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(out));
  fs::remove(parent);
}

TEST(AtomicFileTest, FullDiskIsAnErrorAndLeavesNoFile) {
  // a file-size limit of 1 MiB stands for a full disk (NAME.tmp can no longer
  // be a link to /dev/full: AtomicFile never writes through a link): every
  // write past it fails (EFBIG) once flushed
  const auto dir = FreshDir("full_disk");
  fs::create_directories(dir);
  const fs::path path = dir / "readings.csv";
  struct rlimit saved {};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto saved_handler = signal(SIGXFSZ, SIG_IGN);
  struct rlimit small = saved;
  small.rlim_cur = 1 << 20;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  try {
    AtomicFile file(path.string());
    file.Write(std::string(3 << 20, 'x'));  // more than the buffer: fails in Write or in Commit
    file.Commit();
    ADD_FAILURE() << "writing past the limit did not throw";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("File too large"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(path.string() + ".tmp"), std::string::npos) << error.what();
  }
  setrlimit(RLIMIT_FSIZE, &saved);
  signal(SIGXFSZ, saved_handler);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(fs::symlink_status(path.string() + ".tmp")));
  fs::remove_all(dir);
}

TEST(AtomicFileTest, APlantedLinkUnderTheTemporaryNameIsRefusedNotFollowed) {
  // issue 23 (e): summary.json.tmp planted as a link made the run overwrite its target
  const auto dir = FreshDir("planted_link");
  fs::create_directories(dir);
  { std::ofstream(dir / "precious.txt") << "the user's\n"; }
  fs::create_symlink(dir / "precious.txt", dir / "summary.json.tmp");
  EXPECT_THROW(WriteFileAtomically((dir / "summary.json").string(), "{}\n"), std::runtime_error);
  EXPECT_EQ(ReadFile(dir / "precious.txt"), "the user's\n");
  // a link under the final name is replaced, its target untouched
  fs::remove(dir / "summary.json.tmp");
  fs::create_symlink(dir / "precious.txt", dir / "summary.json");
  WriteFileAtomically((dir / "summary.json").string(), "{}\n");
  EXPECT_FALSE(fs::is_symlink(dir / "summary.json"));
  EXPECT_EQ(ReadFile(dir / "precious.txt"), "the user's\n");
  // a folder that is a link is never written through
  fs::create_directories(dir / "elsewhere");
  fs::create_directory_symlink(dir / "elsewhere", dir / "readings");
  EXPECT_THROW(WriteFileAtomically((dir / "readings" / "t_s.npy").string(), "x"), std::runtime_error);
  EXPECT_TRUE(fs::is_empty(dir / "elsewhere"));
  fs::remove_all(dir);
}

TEST(AtomicFileTest, FailedRenameLeavesNoTemporaryFile) {
  // the final name is a non-empty folder: the rename fails
  const auto dir = FreshDir("rename_fails");
  fs::create_directories(dir / "summary.json" / "inside");
  AtomicFile file((dir / "summary.json").string());
  file.Write("{}\n");
  EXPECT_THROW(file.Commit(), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "summary.json.tmp"));
  fs::remove_all(dir);
}

TEST(AtomicFileTest, UncommittedFileIsRemoved) {
  const auto dir = FreshDir("uncommitted");
  fs::create_directories(dir);
  {
    AtomicFile file((dir / "a.csv").string());
    file.Write("half a row,");
    EXPECT_TRUE(fs::exists(dir / "a.csv.tmp"));
  }
  EXPECT_FALSE(fs::exists(dir / "a.csv.tmp"));
  EXPECT_FALSE(fs::exists(dir / "a.csv"));
  fs::remove_all(dir);
}

// Same scenario, same seed: the same bytes whatever the thread count.
TEST(DeterminismTest, DefaultRunIsByteIdenticalWithOneTwoAndEightThreads) {
  const std::vector<std::string> files = {"readings.csv", "profile.ply", "poses.csv", "summary.json", "scene.json"};
  std::vector<std::vector<std::string>> contents;
  for (int threads : {1, 2, 8}) {
    const auto out = FreshDir("determinism_" + std::to_string(threads));
    const auto result = RunProxsim("run --no-report --threads " + std::to_string(threads) + " --out " + out.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    std::vector<std::string> run;
    for (const std::string& file : files) {
      ASSERT_TRUE(fs::exists(out / file)) << file;
      run.push_back(ReadFile(out / file));
    }
    // the timings (which differ) are apart, in timings.json
    EXPECT_EQ(nlohmann::json::parse(ReadFile(out / "timings.json"))["threads"].get<int>(), threads);
    contents.push_back(std::move(run));
  }
  for (std::size_t f = 0; f < files.size(); ++f) {
    EXPECT_GT(contents[0][f].size(), 100u) << files[f];
    EXPECT_TRUE(contents[0][f] == contents[1][f]) << files[f] << " differs between 1 and 2 threads";
    EXPECT_TRUE(contents[0][f] == contents[2][f]) << files[f] << " differs between 1 and 8 threads";
  }
}

// Enough rays per sample (592) that Cast and the sensor models run on several
// threads: still the same bytes.
TEST(DeterminismTest, ManyBeamsRunIsByteIdenticalWithOneTwoAndEightThreads) {
  const std::string scenario = std::string(PROXSIM_TEST_DATA_DIR) + "/scenarios/many_beams.yaml";
  std::vector<std::string> readings;
  for (int threads : {1, 2, 8}) {
    const auto out = FreshDir("determinism_beams_" + std::to_string(threads));
    const auto result =
        RunProxsim("run " + scenario + " --no-report --threads " + std::to_string(threads) + " --out " + out.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    readings.push_back(ReadFile(out / "readings.csv"));
  }
  // every kind of reading is there, so every draw path ran
  for (const char* status : {",ok,", ",dropout,", ",grazing,", ",self,"}) {
    EXPECT_NE(readings[0].find(status), std::string::npos) << status;
  }
  EXPECT_TRUE(readings[0] == readings[1]) << "readings.csv differs between 1 and 2 threads";
  EXPECT_TRUE(readings[0] == readings[2]) << "readings.csv differs between 1 and 8 threads";
}

}  // namespace
}  // namespace proxsim
