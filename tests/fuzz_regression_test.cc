// Replays the fuzzers' inputs in the ordinary suite, without clang: every seed
// in fuzz/corpus/<target>/ and every input that once crashed, leaked or hung in
// fuzz/regressions/<target>/ goes through the same entry point as the fuzz
// target (fuzz/fuzz_<target>.cc), and must load or throw InputError — never
// crash, never throw anything else. Under the asan preset this is the
// sanitizer check of those inputs too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>
#include <vector>

#include "core/input_error.h"
#include "gait/trajectory_player.h"
#include "scenario/scenario.h"
#include "robot/robot_model.h"
#include "scene/mesh_loader.h"
#include "study/study_journal.h"
#include "study/outcome_runner.h"
#include "sim/simulation.h"
#include "../fuzz/cosim_state_input.h"
#include "../fuzz/outcome_study_input.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;

const fs::path kFuzzDir = fs::path(PROXSIM_SOURCE_DIR) / "fuzz";

std::string ReadBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every file of corpus/<target> and regressions/<target>.
std::vector<fs::path> InputsOf(const std::string& target) {
  std::vector<fs::path> inputs;
  for (const char* folder : {"corpus", "regressions"}) {
    const fs::path dir = kFuzzDir / folder / target;
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file()) inputs.push_back(entry.path());
  }
  std::sort(inputs.begin(), inputs.end());
  return inputs;
}

// Runs `load` on every input of `target`; counts the ones it accepted.
template <typename Load>
void ReplayTarget(const std::string& target, Load load) {
  const auto inputs = InputsOf(target);
  ASSERT_FALSE(inputs.empty()) << "no seed corpus for " << target;
  int accepted = 0, refused = 0;
  for (const fs::path& input : inputs) {
    SCOPED_TRACE(input.string());
    const std::string bytes = ReadBytes(input);
    try {
      load(bytes);
      ++accepted;
    } catch (const InputError&) {
      ++refused;
    } catch (const std::exception& error) {
      ADD_FAILURE() << "not an InputError: " << error.what();
    }
  }
  EXPECT_EQ(accepted + refused, static_cast<int>(inputs.size()));
  // the seeds are mostly valid files: some must load, or the entry point is broken
  EXPECT_GT(accepted, 0) << target;
}

TEST(FuzzRegressionTest, Scenario) {
  ReplayTarget("scenario", [](const std::string& text) {
    LoadScenarioText(text, std::string(PROXSIM_SOURCE_DIR) + "/tests/data/scenarios/fuzz.yaml");
  });
}

TEST(FuzzRegressionTest, Urdf) {
  ReplayTarget("urdf", [](const std::string& text) {
    RobotModel::FromUrdfText(text, PROXSIM_SOURCE_DIR "/fuzz/corpus/urdf/fuzz.urdf");
  });
  // the corpus reaches the meshes: one of its URDFs reads a mesh file at three scales
  const RobotModel meshes = RobotModel::FromUrdfText(ReadBytes(kFuzzDir / "corpus/urdf/meshes_loaded.urdf"),
                                                     PROXSIM_SOURCE_DIR "/fuzz/corpus/urdf/fuzz.urdf");
  EXPECT_EQ(meshes.MeshFileCount(), 1u);
  EXPECT_EQ(meshes.MeshTriangleCount(), 12u);
}

TEST(FuzzRegressionTest, Trajectory) {
  const RobotModel biped = RobotModel::Builtin("biped");
  ReplayTarget("trajectory", [&](const std::string& text) {
    auto player = TrajectoryPlayer::FromCsvText(biped, text, "fuzz.csv");
    for (double t_s : {-1.0, 0.0, 0.01, 0.5, 1.0, 100.0}) player.Advance(t_s);
  });
}

TEST(FuzzRegressionTest, Journal) {
  // as fuzz/fuzz_journal.cc: every line against a study of 3 candidates, 2 hazards, 6 jobs
  const JournalShape shape{6, 3, 2};
  ReplayTarget("journal", [&](const std::string& text) {
    std::istringstream lines(text);
    bool refused = false;
    for (std::string line; std::getline(lines, line);) {
      const nlohmann::json json = nlohmann::json::parse(line, nullptr, false);
      if (json.is_discarded() || json.contains("study")) continue;
      try {
        const JournalEntry entry = ParseJournalLine(json, shape);
        EXPECT_LT(entry.job, shape.jobs);
        ASSERT_EQ(entry.metrics.size(), shape.candidates);
        for (const RunMetrics& m : entry.metrics) EXPECT_EQ(m.hazards.size(), shape.hazards);
      } catch (const InputError&) {
        refused = true;
      }
    }
    if (refused) throw InputError("a line was refused");
  });
}

TEST(FuzzRegressionTest, OutcomeJournal) {
  // as fuzz/fuzz_outcome_journal.cc: every line's metrics against 2 runs per job
  ReplayTarget("outcome_journal", [](const std::string& text) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      const nlohmann::json json = nlohmann::json::parse(line, nullptr, false);
      if (json.is_discarded() || !json.is_object() || !json.contains("metrics")) continue;
      const OutcomeJob job = ParseOutcomeJob(json["metrics"], 2, "job");
      ASSERT_EQ(job.runs.size(), 2u);
      EXPECT_TRUE(job.hazard_m >= 0 && job.hazard_m <= 1e9) << job.hazard_m;
      for (const OutcomeRun& run : job.runs) EXPECT_FALSE(run.outcome_t_s < 0 || run.walked_m < 0) << line;
    }
  });
}

TEST(FuzzRegressionTest, OutcomeStudy) {
  // as fuzz/fuzz_outcome_study.cc: each input a study file beside a base scenario and a ranking
  ReplayTarget("outcome_study", [](const std::string& bytes) { LoadFuzzedOutcomeStudy(bytes); });
  fs::remove_all(fs::temp_directory_path() / ("proxsim_fuzz_outcome_" + std::to_string(getpid())));
}

TEST(FuzzRegressionTest, CosimState) {
  // as fuzz/fuzz_cosim_state.cc: each input a state of the paper's robot driven from outside
  Scenario scenario = LoadBuiltinScenario("paper");
  scenario.robot->locomotion = LocomotionSource::kExternal;
  Simulation sim(std::move(scenario), 1);
  ReplayTarget("cosim_state", [&](const std::string& bytes) {
    sim.Reset(0);
    sim.Step(FuzzedExternalState(bytes));
  });
}

TEST(FuzzRegressionTest, Mesh) {
  // as fuzz/fuzz_mesh.cc: the first byte picks the extension, the rest is the file
  const char* const kExtensions[] = {"obj", "stl", "ply", "gltf", "dae", "off", "glb"};
  const fs::path dir = fs::temp_directory_path() / ("proxsim_test_fuzz_mesh_" + std::to_string(getpid()));
  fs::create_directories(dir);
  ReplayTarget("mesh", [&](const std::string& bytes) {
    if (bytes.empty()) return;
    const auto choice = static_cast<std::uint8_t>(bytes[0]) % (sizeof(kExtensions) / sizeof(kExtensions[0]));
    const fs::path path = dir / (std::string("input.") + kExtensions[choice]);
    {
      std::ofstream out(path, std::ios::binary | std::ios::trunc);
      out.write(bytes.data() + 1, static_cast<std::streamsize>(bytes.size() - 1));
    }
    LoadMeshFile(path.string(), Vec3(1, 1, 1));
  });
  fs::remove_all(dir);
}

TEST(FuzzRegressionTest, MalformedPlyHeadersNeverReachAssimp) {
  // the fuzzer's PLY findings: Assimp 5.2 corrupts its heap on these headers,
  // so the loader must refuse them itself, naming the header line
  const fs::path dir = fs::temp_directory_path() / ("proxsim_test_fuzz_ply_" + std::to_string(getpid()));
  fs::create_directories(dir);
  for (const char* name : {"ply_header_unknown_keyword_heap.bin", "ply_header_control_bytes_segv.bin"}) {
    SCOPED_TRACE(name);
    const std::string bytes = ReadBytes(kFuzzDir / "regressions" / "mesh" / name);
    ASSERT_GT(bytes.size(), 1u);
    const fs::path path = dir / "input.ply";
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data() + 1, bytes.size() - 1);
    try {
      LoadMeshFile(path.string(), Vec3(1, 1, 1));
      ADD_FAILURE() << "loaded";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("PLY header"), std::string::npos) << error.what();
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace proxsim
