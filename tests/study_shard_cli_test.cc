// `proxsim study --shard i/N` and `proxsim study merge` through the real CLI
// (docs/studies.md "Slices and Slurm job arrays"): a study cut into 3 slices,
// each run into a folder of its own, merged back gives every file of a
// single-process run byte for byte, in both study modes; a missing, a
// duplicated, a foreign or an unfinished slice and a study file changed
// since are refused by name (exit 2); `--shard slurm` reads a job array's
// variables and refuses clearly without them. The real Slurm job array:
// tests/slurm/test_slurm_job_array.py.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"
#include "core/input_error.h"
#include "study/study_shard.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::ReadFile;
using testing::RunProxsim;

const std::string kScenarios = std::string(PROXSIM_SOURCE_DIR) + "/data/scenarios/";

// Four mountings in two scenes with three seeds: 6 jobs, two per slice.
std::string PlacementStudy() {
  return "proxsim_study: 1\nbase: " + kScenarios + "paper_dining_room.yaml\n"
         "candidates:\n"
         "  axes: {type: [laser, ultrasonic], link: left_tibia, along_m: [-0.35, -0.25], forward_m: 0.06,\n"
         "         pitch_deg: 10}\n"
         "scenes:\n"
         "  - {name: obstacle_15cm, builtin: dining_room}\n"
         "  - {name: obstacle_30cm, builtin: dining_room, obstacle: {height_m: 0.30, x_m: 2.0}}\n"
         "seeds: [1, 2, 3]\n"
         "hazards: [obstacle]\n"
         "select: {sensors: 2}\n";
}

// A set that sees and one that looks at the ceiling, with the stop rule, in
// the circumvent example's room (no way through: a stop before the obstacle
// succeeds, a collision fails and gets a replay file) and in small generated
// rooms, with both baselines: 5 worlds, so the slices hold 2, 2 and 1.
std::string OutcomeStudy() {
  return "proxsim_study: 1\nmode: outcomes\nbase: " + kScenarios + "outcome_walker.yaml\n"
         "sets:\n"
         "  - {name: upward, sensors: [{name: up, type: laser, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.35], "
         "rpy_deg: [0, -80, 0]}}]}\n"
         "  - {name: ahead, sensors: [{name: ahead, type: laser, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.35], "
         "rpy_deg: [0, 8, 0]}}]}\n"
         "prices: {laser: {price_usd: 10}}\n"
         "strategies: [{name: stop}]\n"
         "worlds:\n"
         "  - {name: obstacle_room, scenario: " + kScenarios + "circumvent_obstacle.yaml, seeds: [1, 2]}\n"
         "  - {generate: {kind: room, difficulty: 0.3, size_m: [4, 4]}, seeds: [1, 2, 3]}\n";
}

// Every file under `root` by its relative path, but the journal (the single
// run's lines are in the order the jobs finished) and the lock.
std::map<std::string, std::string> FilesOf(const fs::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || name == "journal.jsonl" || name == ".proxsim.lock") continue;
    files[fs::relative(entry.path(), root).string()] = ReadFile(entry.path());
  }
  return files;
}

std::set<std::size_t> JournalJobs(const fs::path& journal) {
  std::set<std::size_t> jobs;
  std::ifstream in(journal);
  for (std::string line; std::getline(in, line);) {
    const auto entry = nlohmann::json::parse(line);
    if (entry.contains("job")) jobs.insert(entry["job"].get<std::size_t>());
  }
  return jobs;
}

// One study run whole and in 3 slices, once for every test of a mode.
struct Runs {
  fs::path dir, study, single;
  std::vector<fs::path> slices;  // slice 1, 2, 3
};

Runs RunWholeAndSliced(const std::string& name, const std::string& yaml) {
  Runs runs;
  runs.dir = FreshDir(name);
  fs::create_directories(runs.dir);
  runs.study = runs.dir / "study.yaml";
  std::ofstream(runs.study) << yaml;
  runs.single = runs.dir / "single";
  // from the study's folder, the study named relatively: the answers echo it
  // so (a failure's replay file), and the merge, run from elsewhere, must too
  const std::string in_dir = "cd " + runs.dir.string() + " && " + PROXSIM_BINARY + " study study.yaml ";
  const auto single = testing::RunCommand(in_dir + "--no-report --threads 2 --out single");
  EXPECT_EQ(single.exit_code, 0) << single.output;
  for (int i = 1; i <= 3; ++i) {
    runs.slices.push_back(runs.dir / ("slice" + std::to_string(i)));
    const auto slice = testing::RunCommand(in_dir + "--shard " + std::to_string(i) + "/3 --threads 1 --out slice" +
                                           std::to_string(i));
    EXPECT_EQ(slice.exit_code, 0) << slice.output;
    EXPECT_NE(slice.output.find("slice " + std::to_string(i) + "/3 done"), std::string::npos) << slice.output;
  }
  return runs;
}

std::string Folders(const std::vector<fs::path>& dirs) {
  std::string text;
  for (const fs::path& d : dirs) text += " " + d.string();
  return text;
}

// The slices hold disjoint jobs that cover the study, say so in their
// records, and carry no answers; merged (given in any order) they give every
// file of the single run, byte for byte.
void ExpectMergeEqualsSingleRun(const Runs& runs, std::size_t jobs, const std::vector<std::string>& required) {
  std::set<std::size_t> covered;
  std::set<std::string> digests;
  for (std::size_t i = 0; i < runs.slices.size(); ++i) {
    const auto record = nlohmann::json::parse(ReadFile(runs.slices[i] / "slice.json"));
    EXPECT_EQ(record["slice"], std::to_string(i + 1) + "/3");
    EXPECT_EQ(record["jobs"], jobs);
    EXPECT_EQ(record["study_file"], fs::canonical(runs.study).string());
    EXPECT_EQ(record["study_file_given"], "study.yaml");
    digests.insert(record["study_digest"].get<std::string>());
    for (const std::size_t job : JournalJobs(runs.slices[i] / "journal.jsonl")) {
      EXPECT_EQ(job % 3, i) << "job " << job << " in slice " << i + 1;
      EXPECT_TRUE(covered.insert(job).second) << "job " << job << " in two slices";
    }
    EXPECT_FALSE(fs::exists(runs.slices[i] / "ranking.csv")) << "a slice writes no answers of its own";
  }
  EXPECT_EQ(digests.size(), 1u) << "the slices of one study share its digest";
  EXPECT_EQ(covered.size(), jobs);

  const fs::path merged = runs.dir / "merged";
  const auto merge = RunProxsim("study merge " + runs.slices[2].string() + " " + runs.slices[0].string() + " " +
                                runs.slices[1].string() + " --no-report --out " + merged.string());
  ASSERT_EQ(merge.exit_code, 0) << merge.output;
  const auto single_files = FilesOf(runs.single), merged_files = FilesOf(merged);
  for (const std::string& file : required) EXPECT_TRUE(single_files.contains(file)) << file;
  EXPECT_EQ(merged_files.size(), single_files.size());
  for (const auto& [file, bytes] : single_files) {
    ASSERT_TRUE(merged_files.contains(file)) << file << " missing from the merged study";
    EXPECT_TRUE(merged_files.at(file) == bytes) << file << " differs from the single run's";
  }
  // the merged folder is a finished study: --resume finds every job done and writes the same files
  EXPECT_EQ(JournalJobs(merged / "journal.jsonl").size(), jobs);
  const auto resumed = testing::RunCommand("cd " + runs.dir.string() + " && " + PROXSIM_BINARY +
                                           " study study.yaml --no-report --resume --out merged");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find(std::to_string(jobs) + " jobs already done (resumed)"), std::string::npos)
      << resumed.output;
  EXPECT_EQ(FilesOf(merged), single_files);
}

// One study (a mode's) run whole and in 3 slices, once for all the tests of its suite.
template <typename Study>
class SlicedStudyTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { runs_ = new Runs(RunWholeAndSliced(Study::kName, Study::Yaml())); }
  static void TearDownTestSuite() {
    fs::remove_all(runs_->dir);
    delete runs_;
    runs_ = nullptr;
  }
  static inline Runs* runs_ = nullptr;
};

struct Placement {
  static constexpr const char* kName = "shard_placement";
  static std::string Yaml() { return PlacementStudy(); }
};
struct Outcomes {
  static constexpr const char* kName = "shard_outcomes";
  static std::string Yaml() { return OutcomeStudy(); }
};
using PlacementShardTest = SlicedStudyTest<Placement>;
using OutcomeShardTest = SlicedStudyTest<Outcomes>;

TEST_F(PlacementShardTest, ThreeSlicesMergeToTheSingleRunsBytes) {
  ExpectMergeEqualsSingleRun(*runs_, 6, {"results.csv", "ranking.csv", "selection.json"});
}

TEST_F(PlacementShardTest, AMissingSliceIsRefusedByName) {
  const auto merge = RunProxsim("study merge" + Folders({runs_->slices[0], runs_->slices[2]}) + " --no-report --out " +
                                (runs_->dir / "missing").string());
  EXPECT_EQ(merge.exit_code, 2) << merge.output;
  EXPECT_NE(merge.output.find("slice 2/3 is missing"), std::string::npos) << merge.output;
  EXPECT_FALSE(fs::exists(runs_->dir / "missing")) << "nothing written for a refused merge";
}

TEST_F(PlacementShardTest, ADuplicatedSliceIsRefusedByNameWithItsFolders) {
  // a copy of slice 3 under another name, given beside slice 3 itself
  const fs::path copy = runs_->dir / "slice3_again";
  fs::copy(runs_->slices[2], copy, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  const auto merge = RunProxsim("study merge" + Folders({runs_->slices[0], runs_->slices[1], runs_->slices[2], copy}) +
                                " --no-report --out " + (runs_->dir / "dup").string());
  EXPECT_EQ(merge.exit_code, 2) << merge.output;
  EXPECT_NE(merge.output.find("slice 3/3 is duplicated"), std::string::npos) << merge.output;
  EXPECT_NE(merge.output.find(copy.string()), std::string::npos) << merge.output;
  EXPECT_FALSE(fs::exists(runs_->dir / "dup"));
}

TEST_F(PlacementShardTest, AFolderThatIsNoSliceAndAnUnfinishedSliceAreRefused) {
  const auto not_slice = RunProxsim("study merge" + Folders({runs_->slices[0], runs_->slices[1], runs_->single}) +
                                    " --no-report --out " + (runs_->dir / "no_slice").string());
  EXPECT_EQ(not_slice.exit_code, 2) << not_slice.output;
  EXPECT_NE(not_slice.output.find(runs_->single.string() + ": not a study slice"), std::string::npos)
      << not_slice.output;

  // slice 2 cut after its first job's line, as a kill leaves it
  const fs::path cut = runs_->dir / "slice2_cut";
  fs::copy(runs_->slices[1], cut, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  {
    std::ifstream whole(runs_->slices[1] / "journal.jsonl");
    std::string header, first;
    std::getline(whole, header);
    std::getline(whole, first);
    std::ofstream(cut / "journal.jsonl") << header << "\n" << first << "\n";
  }
  const auto unfinished = RunProxsim("study merge" + Folders({runs_->slices[0], cut, runs_->slices[2]}) +
                                     " --no-report --out " + (runs_->dir / "unfinished").string());
  EXPECT_EQ(unfinished.exit_code, 2) << unfinished.output;
  EXPECT_NE(unfinished.output.find("slice 2/3 is unfinished: 1 of its 2 jobs not done"), std::string::npos)
      << unfinished.output;
  EXPECT_NE(unfinished.output.find("--shard 2/3 --out " + cut.string() + " --resume"), std::string::npos)
      << unfinished.output;

  // the command it names finishes the slice (its one missing job), and the merge then goes through
  const auto finished = testing::RunCommand("cd " + runs_->dir.string() + " && " + PROXSIM_BINARY +
                                            " study study.yaml --shard 2/3 --resume --out " + cut.string());
  ASSERT_EQ(finished.exit_code, 0) << finished.output;
  EXPECT_NE(finished.output.find("1 jobs already done (resumed)"), std::string::npos) << finished.output;
  const fs::path merged = runs_->dir / "after_resume";
  const auto merge = RunProxsim("study merge" + Folders({runs_->slices[0], cut, runs_->slices[2]}) +
                                " --no-report --out " + merged.string());
  ASSERT_EQ(merge.exit_code, 0) << merge.output;
  EXPECT_EQ(FilesOf(merged), FilesOf(runs_->single));
}

TEST_F(PlacementShardTest, SlicesOfAnotherStudyAndAStudyChangedSinceAreRefused) {
  // slice 2 of the same study with another seed list: another study's slice
  const fs::path other_study = runs_->dir / "other.yaml";
  std::string yaml = PlacementStudy();
  yaml.replace(yaml.find("seeds: [1, 2, 3]"), 16, "seeds: [4, 5, 6]");
  std::ofstream(other_study) << yaml;
  const fs::path other = runs_->dir / "other_slice2";
  ASSERT_EQ(RunProxsim("study " + other_study.string() + " --shard 2/3 --out " + other.string()).exit_code, 0);
  const auto foreign = RunProxsim("study merge" + Folders({runs_->slices[0], other, runs_->slices[2]}) +
                                  " --no-report --out " + (runs_->dir / "foreign").string());
  EXPECT_EQ(foreign.exit_code, 2) << foreign.output;
  EXPECT_NE(foreign.output.find(other.string() + ": slice 2/3 of another study"), std::string::npos) << foreign.output;

  // the study file edited after its slices ran (a comment is enough: its bytes are in the digest)
  const fs::path copy_dir = runs_->dir / "edited";
  fs::create_directories(copy_dir);
  const fs::path edited_study = copy_dir / "study.yaml";
  std::ofstream(edited_study) << PlacementStudy();
  std::vector<fs::path> slices;
  for (int i = 1; i <= 3; ++i) {
    slices.push_back(copy_dir / ("s" + std::to_string(i)));
    ASSERT_EQ(RunProxsim("study " + edited_study.string() + " --shard " + std::to_string(i) + "/3 --out " +
                         slices.back().string())
                  .exit_code,
              0);
  }
  std::ofstream(edited_study, std::ios::app) << "# edited\n";
  const auto changed = RunProxsim("study merge" + Folders(slices) + " --no-report --out " + (copy_dir / "m").string());
  EXPECT_EQ(changed.exit_code, 2) << changed.output;
  EXPECT_NE(changed.output.find("changed since its slices ran"), std::string::npos) << changed.output;
}

TEST_F(OutcomeShardTest, ThreeSlicesMergeToTheSingleRunsBytes) {
  ExpectMergeEqualsSingleRun(*runs_, 5,
                             {"results.csv", "ranking.csv", "pairs.csv", "selection.json", "failures.csv",
                              "episodes.jsonl"});
  // the failures' replay files are among the files compared
  bool replay = false;
  for (const auto& [file, bytes] : FilesOf(runs_->single)) replay = replay || file.starts_with("failures/");
  EXPECT_TRUE(replay) << "the study was meant to have failed runs with replay files";
}

// ----- the slice from the command line and from a Slurm job array's variables

class ShardArgumentTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshDir("shard_argument");
    fs::create_directories(dir_);
    study_ = (dir_ / "study.yaml").string();
    std::ofstream(study_) << PlacementStudy();
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  std::string study_;
};

TEST_F(ShardArgumentTest, SlurmWithoutItsVariablesIsRefusedNamingTheVariable) {
  const std::string unset = "env -u SLURM_ARRAY_TASK_ID -u SLURM_ARRAY_TASK_MIN -u SLURM_ARRAY_TASK_COUNT "
                            "-u SLURM_ARRAY_TASK_STEP -u SLURM_ARRAY_TASK_MAX ";
  const auto none = testing::RunCommand(unset + PROXSIM_BINARY + " study " + study_ + " --shard slurm --out " +
                                        (dir_ / "none").string());
  EXPECT_EQ(none.exit_code, 2) << none.output;
  EXPECT_NE(none.output.find("SLURM_ARRAY_TASK_ID is not set"), std::string::npos) << none.output;
  EXPECT_FALSE(fs::exists(dir_ / "none")) << "nothing written before the slice is known";

  const auto no_count = testing::RunCommand(unset + "SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=1 " + PROXSIM_BINARY +
                                            " study " + study_ + " --shard slurm --out " + (dir_ / "c").string());
  EXPECT_EQ(no_count.exit_code, 2) << no_count.output;
  EXPECT_NE(no_count.output.find("SLURM_ARRAY_TASK_COUNT is not set"), std::string::npos) << no_count.output;
}

TEST_F(ShardArgumentTest, SlurmTaskFiveOfAnArrayFromFourIsSliceTwo) {
  // sbatch --array=4-6: task 5 is the array's second
  const auto run = testing::RunCommand(
      "SLURM_ARRAY_TASK_ID=5 SLURM_ARRAY_TASK_MIN=4 SLURM_ARRAY_TASK_MAX=6 SLURM_ARRAY_TASK_COUNT=3 "
      "SLURM_ARRAY_TASK_STEP=1 " + std::string(PROXSIM_BINARY) + " study " + study_ + " --shard slurm --out " +
      (dir_ / "task5").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(nlohmann::json::parse(ReadFile(dir_ / "task5" / "slice.json"))["slice"], "2/3");
  EXPECT_EQ(JournalJobs(dir_ / "task5" / "journal.jsonl"), (std::set<std::size_t>{1, 4}));
}

TEST_F(ShardArgumentTest, ABadShardIsRefusedSayingWhatIsExpected) {
  for (const char* shard : {"0/3", "4/3", "1/0", "a/3", "2", "1/3/3", "-1/3"}) {
    const auto run = RunProxsim("study " + study_ + " --shard " + shard + " --out " + (dir_ / "bad").string());
    EXPECT_EQ(run.exit_code, 2) << shard << "\n" << run.output;
    EXPECT_NE(run.output.find("expected i/N"), std::string::npos) << shard << "\n" << run.output;
  }
  EXPECT_FALSE(fs::exists(dir_ / "bad"));
}

// ParseStudySlice on its own, with the environment given as a map

const char* Lookup(const std::map<std::string, std::string>& environment, const char* name) {
  const auto it = environment.find(name);
  return it == environment.end() ? nullptr : it->second.c_str();
}

StudySlice FromSlurm(const std::map<std::string, std::string>& environment) {
  return ParseStudySlice("slurm", [&](const char* name) { return Lookup(environment, name); });
}

TEST(StudySlice, SlicesAreDisjointAndCoverEveryJobOnce) {
  for (std::size_t count = 1; count <= 5; ++count) {
    for (std::size_t jobs = 0; jobs <= 12; ++jobs) {
      std::vector<int> held(jobs, 0);
      std::size_t sum = 0;
      for (std::size_t index = 1; index <= count; ++index) {
        const StudySlice slice{index, count};
        std::size_t mine = 0;
        for (std::size_t job = 0; job < jobs; ++job)
          if (slice.Holds(job)) ++held[job], ++mine;
        EXPECT_EQ(slice.JobsOf(jobs), mine) << slice.Name() << " of " << jobs;
        sum += mine;
      }
      EXPECT_EQ(sum, jobs);
      EXPECT_TRUE(std::ranges::all_of(held, [](int n) { return n == 1; })) << count << " slices of " << jobs;
    }
  }
}

TEST(StudySlice, TheSlurmTaskIsItsPositionInTheArrayCountedFromOne) {
  // --array=0-2 and --array=1-3: slices 1/3 .. 3/3 either way
  for (const std::size_t min : {0u, 1u}) {
    for (std::size_t k = 0; k < 3; ++k) {
      const StudySlice slice = FromSlurm({{"SLURM_ARRAY_TASK_ID", std::to_string(min + k)},
                                          {"SLURM_ARRAY_TASK_MIN", std::to_string(min)},
                                          {"SLURM_ARRAY_TASK_MAX", std::to_string(min + 2)},
                                          {"SLURM_ARRAY_TASK_COUNT", "3"},
                                          {"SLURM_ARRAY_TASK_STEP", "1"}});
      EXPECT_EQ(slice.index, k + 1);
      EXPECT_EQ(slice.count, 3u);
    }
  }
  // --array=0-10:5: tasks 0, 5, 10
  EXPECT_EQ(FromSlurm({{"SLURM_ARRAY_TASK_ID", "10"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_MAX", "10"},
                       {"SLURM_ARRAY_TASK_COUNT", "3"}, {"SLURM_ARRAY_TASK_STEP", "5"}})
                .Name(),
            "3/3");
  // --array=1,4,9: Slurm says step 1, and the ids are no range
  EXPECT_THROW(FromSlurm({{"SLURM_ARRAY_TASK_ID", "4"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_MAX", "9"},
                          {"SLURM_ARRAY_TASK_COUNT", "3"}, {"SLURM_ARRAY_TASK_STEP", "1"}}),
               InputError);
  EXPECT_THROW(
      FromSlurm({{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_COUNT", "3"}}),
      InputError);
  EXPECT_EQ(ParseStudySlice("2/3", [](const char*) { return nullptr; }).Name(), "2/3");
}

}  // namespace
}  // namespace proxsim
