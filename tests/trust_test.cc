// Issue 23, "trust under attack", through the real binary: every input the
// adversarial review crashed, hung or bloated proxsim with is generated here
// (never committed: some are tens of megabytes), and each must now end with
// exit 2 and a message naming the limit — within a wall-clock bound, under
// `timeout`, so a regression shows as a failure, not as a hung suite.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"

extern char** environ;

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::FreshDir;
using testing::ReadFile;
using testing::RunCommand;
using testing::RunProxsimWithin;  // hang cases: exit 137 on overrun, never a hung suite

class TrustTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshDir("trust");
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A scenario of one world sensor, with `objects` (YAML list items) in its scene.
  fs::path Scenario(const std::string& name, const std::string& objects, const std::string& extra = "") {
    const fs::path path = dir_ / (name + ".yaml");
    std::ofstream(path) << "proxsim: 1\nduration_s: 0.1\nrate_hz: 10\n" << extra << "scene:\n  objects:\n"
                        << objects << "sensors:\n  - {name: s, type: ideal, pose: {xyz_m: [0, 0, 1]}}\n";
    return path;
  }
  fs::path MeshScenario(const std::string& name, const fs::path& mesh) {
    return Scenario(name, "    - name: thing\n      mesh: {file: " + mesh.string() + "}\n");
  }
  void Write(const fs::path& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

  // run and validate both refuse it: exit 2, every fragment in the message, no folder
  void ExpectRefused(const fs::path& scenario, const std::vector<std::string>& fragments) {
    const fs::path out = dir_ / "out";
    for (const std::string& command : {"run " + scenario.string() + " --no-report --out " + out.string(),
                                       "validate " + scenario.string()}) {
      SCOPED_TRACE(command);
      const auto result = RunProxsimWithin(command);
      EXPECT_EQ(result.exit_code, 2) << result.output;
      for (const std::string& fragment : fragments)
        EXPECT_NE(result.output.find(fragment), std::string::npos) << fragment << " not in:\n" << result.output;
      EXPECT_FALSE(fs::exists(out)) << "a refused run created its folder";
    }
  }

  fs::path dir_;
};

std::string Repeat(const std::string& text, std::size_t n) {
  std::string out;
  out.reserve(text.size() * n);
  for (std::size_t i = 0; i < n; ++i) out += text;
  return out;
}

// ----- (a) nesting deeper than the parsers' stacks

TEST_F(TrustTest, GltfOf20000NestedNodesIsRefusedBeforeAssimp) {
  std::string nodes;
  for (int i = 0; i < 20000; ++i) nodes += (i ? "," : "") + std::string("{\"children\":[") + std::to_string(i + 1) + "]}";
  nodes += ",{}";
  Write(dir_ / "deep.gltf", R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[)" + nodes + "]}");
  ExpectRefused(MeshScenario("deep_gltf", dir_ / "deep.gltf"), {"deep.gltf", "glTF node tree deeper than 256"});
}

TEST_F(TrustTest, GltfWith200000NestedBracketsInItsExtrasIsRefused) {
  Write(dir_ / "extras.gltf", R"({"asset":{"version":"2.0","extras":)" + Repeat("[", 200000) + Repeat("]", 200000) + "}}");
  ExpectRefused(MeshScenario("extras", dir_ / "extras.gltf"), {"extras.gltf", "JSON nested deeper than 256 levels"});
}

TEST_F(TrustTest, DeepJsonBehindMegabytesOfWhiteSpaceIsStillFound) {
  // the format is told by the first significant byte, however far in
  Write(dir_ / "spaced.gltf", std::string(2 << 20, ' ') + R"({"asset":{"version":"2.0","extras":)" +
                                  Repeat("[", 100000) + Repeat("]", 100000) + "}}");
  ExpectRefused(MeshScenario("spaced", dir_ / "spaced.gltf"), {"spaced.gltf", "JSON nested deeper than 256 levels"});
}

TEST_F(TrustTest, GlbWhoseJsonChunkNestsTooDeepIsRefused) {
  const std::string json = R"({"asset":{"version":"2.0","extras":)" + Repeat("[", 100000) + Repeat("]", 100000) + "}}";
  std::string glb = "glTF";
  const auto u32 = [&](std::uint32_t v) {
    for (int k = 0; k < 4; ++k) glb += static_cast<char>((v >> (8 * k)) & 0xff);
  };
  u32(2);
  u32(static_cast<std::uint32_t>(20 + json.size()));
  u32(static_cast<std::uint32_t>(json.size()));
  glb += "JSON" + json;
  Write(dir_ / "deep.glb", glb);
  ExpectRefused(MeshScenario("glb", dir_ / "deep.glb"), {"deep.glb", "JSON nested deeper than 256 levels"});
}

TEST_F(TrustTest, ColladaOf50000NestedNodesIsRefused) {
  Write(dir_ / "deep.dae",
        "<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">"
        "<library_visual_scenes><visual_scene id=\"s\">" +
            Repeat("<node>", 50000) + Repeat("</node>", 50000) +
            "</visual_scene></library_visual_scenes><scene><instance_visual_scene url=\"#s\"/></scene></COLLADA>\n");
  ExpectRefused(MeshScenario("deep_dae", dir_ / "deep.dae"), {"deep.dae", "XML elements nested deeper than 256"});
}

TEST_F(TrustTest, UrdfOf200000NestedElementsIsRefusedBeforeTinyXml) {
  Write(dir_ / "deep.urdf", "<robot name=\"r\"><link name=\"a\">" + Repeat("<x>", 200000) + Repeat("</x>", 200000) +
                                "</link></robot>\n");
  const fs::path scenario = dir_ / "deep_urdf.yaml";
  std::ofstream(scenario) << "proxsim: 1\nduration_s: 0.1\nrate_hz: 10\nrobot:\n  model: deep.urdf\n"
                          << "sensors:\n  - {name: s, type: ideal, pose: {xyz_m: [0, 0, 1]}}\n";
  ExpectRefused(scenario, {"deep.urdf", "XML elements nested deeper than 256"});
}

// ----- (b) coordinates single precision cannot resolve

TEST_F(TrustTest, CoordinatesBeyondTheLimitAreInputErrorsNotEmbreeAborts) {
  ExpectRefused(Scenario("far_box", "    - name: far\n      box: {size_m: [1, 1, 1]}\n      pose: {xyz_m: [1e19, 0, 0]}\n"),
                {"far_box.yaml:", "xyz_m", "coordinate limit"});
  ExpectRefused(Scenario("huge_box", "    - name: huge\n      box: {size_m: [1e19, 1, 1]}\n"),
                {"huge_box.yaml:", "size_m", "coordinate limit"});
  Write(dir_ / "far.obj", "v 0 0 0\nv 1e19 0 0\nv 0 1 0\nf 1 2 3\n");
  ExpectRefused(MeshScenario("far_mesh", dir_ / "far.obj"), {"far.obj", "coordinate limit of ±100000 m"});
}

// ----- (j) declared sizes and files that never end

TEST_F(TrustTest, An45ByteOffClaiming2e9VerticesIsRefusedAtOnce) {
  Write(dir_ / "liar.off", "OFF\n2000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  ExpectRefused(MeshScenario("liar", dir_ / "liar.off"), {"liar.off", "OFF header declares 2000000000 1 0"});
}

TEST_F(TrustTest, GltfAccessorLargerThanItsBufferIsRefused) {
  Write(dir_ / "big_accessor.gltf",
        R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":12,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}],)"
        R"("bufferViews":[{"buffer":0,"byteLength":12}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":2000000000,"type":"VEC3"}]})");
  ExpectRefused(MeshScenario("big_accessor", dir_ / "big_accessor.gltf"), {"accessors[0]", "count 2000000000"});
}

TEST_F(TrustTest, AMeshThatIsDevZeroOrAFifoIsRefusedNotRead) {
  ExpectRefused(MeshScenario("zero", "/dev/zero"), {"/dev/zero", "not a regular file"});
  const fs::path fifo = dir_ / "pipe.obj";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  ExpectRefused(MeshScenario("fifo", fifo), {"pipe.obj", "not a regular file"});
  // and a file Assimp would open on its own: an OBJ's material library
  Write(dir_ / "with_mtl.obj", "mtllib pipe.obj\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto result = RunProxsimWithin("validate " + MeshScenario("mtl", dir_ / "with_mtl.obj").string());
  EXPECT_NE(result.exit_code, 137) << "hung on the FIFO: " << result.output;
}

TEST_F(TrustTest, BenchFromAFifoIsRefusedNotRead) {
  const fs::path fifo = dir_ / "bench.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  const auto result = RunProxsimWithin("bench --from " + fifo.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("not a regular file"), std::string::npos) << result.output;
}

// ----- (l) degenerate gaits

TEST_F(TrustTest, AGaitPeriodOf1e9SecondsIsAnInputError) {
  const fs::path scenario = dir_ / "gait.yaml";
  std::ofstream(scenario) << "proxsim: 1\nduration_s: 2\nrate_hz: 50\nscene:\n  objects:\n    - {name: floor, plane: {}}\n"
                          << "robot:\n  model: builtin:biped\n  start: {yaw_deg: 90}\n  gait: {period_s: 1e-9}\n"
                          << "sensors:\n  - {name: s, type: ideal, link: left_tibia}\n";
  ExpectRefused(scenario, {"gait.yaml:", "period_s", "a gait cycle a walking robot can take"});
}

// ----- (k) a long load can be interrupted

TEST_F(TrustTest, SigintWhileLoadingEndsTheRunWithinASecondWritingNothing) {
  // a 2.25-million-triangle OBJ: seconds of loading
  {
    std::ofstream obj(dir_ / "big.obj");
    constexpr int n = 1500;
    std::string chunk;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) obj << "v " << i << ' ' << j << " 0\n";
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) obj << "f " << i * (n + 1) + j + 1 << ' ' << (i + 1) * (n + 1) + j + 1 << ' ' << i * (n + 1) + j + 2 << '\n';
  }
  const std::string scenario = MeshScenario("big", dir_ / "big.obj").string();
  const fs::path out = dir_ / "out";
  for (const int signal_number : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(signal_number);
    std::vector<std::string> args = {PROXSIM_BINARY, "run", scenario, "--out", out.string(), "--no-report"};
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, PROXSIM_BINARY, nullptr, nullptr, argv.data(), environ), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(700));  // well inside the load
    const auto signalled = std::chrono::steady_clock::now();
    kill(pid, signal_number);
    int status = 0;
    while (waitpid(pid, &status, WNOHANG) == 0 && std::chrono::steady_clock::now() - signalled < std::chrono::seconds(10))
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const double waited_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count();
    if (waited_s >= 10) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
    }
    EXPECT_LT(waited_s, 1.0) << "the load went on after the signal";
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal_number);
    EXPECT_FALSE(fs::exists(out)) << "an interrupted load wrote its folder";
  }
}

// ----- (e, f, g) a run touches only what it owns

const std::string kWorld = std::string(PROXSIM_TEST_DATA_DIR) + "/cli/world_closed_form.yaml";

TEST_F(TrustTest, APlantedSummaryTmpLinkIsNeverWrittenThrough) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(RunProxsimWithin("run " + kWorld + " --no-report --out " + out.string()).exit_code, 0);
  Write(dir_ / "victim.txt", "precious\n");
  fs::create_symlink(dir_ / "victim.txt", out / "summary.json.tmp");
  const auto result = RunProxsimWithin("run " + kWorld + " --no-report --out " + out.string());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("never writes through"), std::string::npos) << result.output;
  EXPECT_EQ(ReadFile(dir_ / "victim.txt"), "precious\n");
}

TEST_F(TrustTest, ACraftedManifestEntryUnderALinkedFolderRemovesNothingOutside) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(RunProxsimWithin("run " + kWorld + " --no-report --out " + out.string()).exit_code, 0);
  fs::create_directories(dir_ / "elsewhere");
  Write(dir_ / "elsewhere" / "victim.txt", "precious\n");
  fs::create_directory_symlink(dir_ / "elsewhere", out / "report");
  // the entry names the victim through the link, with its true size (a digest matching it too would change nothing)
  std::string manifest = ReadFile(out / "manifest.json");
  manifest.replace(manifest.find("\"files\": ["), 10,
                   "\"files\": [{\"path\": \"report/victim.txt\", \"bytes\": 9, \"fnv1a64\": \"0\"}, "
                   "{\"path\": \"../elsewhere/victim.txt\", \"bytes\": 9},");
  Write(out / "manifest.json", manifest);
  EXPECT_EQ(RunProxsimWithin("run " + kWorld + " --no-report --out " + out.string()).exit_code, 0);
  EXPECT_EQ(ReadFile(dir_ / "elsewhere" / "victim.txt"), "precious\n");
}

TEST_F(TrustTest, TheUsersFilesInReadingsAndTerrainSurviveTheFirstAndEveryRun) {
  const fs::path out = dir_ / "out";
  fs::create_directories(out / "readings");
  fs::create_directories(out / "terrain");
  Write(out / "readings" / "my_notes.txt", "mine\n");
  Write(out / "terrain" / "my_map.npy", "mine too\n");
  // a folder of the user's own: refused, then written among them with --force
  const auto refused = RunProxsimWithin("run --format npy --no-report --out " + out.string());
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("--force"), std::string::npos) << refused.output;
  for (int run = 0; run < 2; ++run) {
    const auto result = RunProxsimWithin("run --format npy --no-report --force --out " + out.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(fs::exists(out / "readings" / "t_s.npy"));
    EXPECT_TRUE(fs::exists(out / "terrain" / "elevation.npy"));
    EXPECT_EQ(ReadFile(out / "readings" / "my_notes.txt"), "mine\n");
    EXPECT_EQ(ReadFile(out / "terrain" / "my_map.npy"), "mine too\n");
    EXPECT_EQ(ReadFile(out / "manifest.json").find("my_notes"), std::string::npos) << "a user's file in the manifest";
  }
  // a run's file the user changed is no longer the run's: it stays
  Write(out / "readings" / "t_s.npy", "edited by the user\n");
  ASSERT_EQ(RunProxsimWithin("run --no-report --out " + out.string()).exit_code, 0);  // csv: readings/ not rewritten
  EXPECT_EQ(ReadFile(out / "readings" / "t_s.npy"), "edited by the user\n");
  EXPECT_FALSE(fs::exists(out / "readings" / "d_m.npy")) << "the previous run's unchanged columns go";
}

TEST_F(TrustTest, RootHomeAndEmptyOutAreRefused) {
  for (const std::string& out : {std::string("/"), std::string("''"), std::string("~")}) {
    const auto result = RunProxsimWithin("run " + kWorld + " --no-report --out " + out);
    EXPECT_EQ(result.exit_code, 2) << out << ": " << result.output;
  }
  const auto home = RunCommand("HOME=" + dir_.string() + " " + PROXSIM_BINARY + " run " + kWorld +
                               " --no-report --force --out " + dir_.string());
  EXPECT_EQ(home.exit_code, 2) << home.output;
  EXPECT_NE(home.output.find("the home folder"), std::string::npos) << home.output;
}

// ----- (h) one run at a time in a folder

TEST_F(TrustTest, ASecondRunOrStudyIntoAFolderInUseFailsAtOnceNamingTheHolder) {
  const fs::path out = dir_ / "out";
  const std::string long_walk = std::string(PROXSIM_TEST_DATA_DIR) + "/cli/long_walk.yaml";
  std::vector<std::string> args = {PROXSIM_BINARY, "run", long_walk, "--out", out.string(), "--no-report"};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, PROXSIM_BINARY, &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(out / "readings.csv.tmp") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));

  const auto second = RunProxsimWithin("run " + kWorld + " --no-report --out " + out.string(), 10);
  EXPECT_EQ(second.exit_code, 2) << second.output;
  EXPECT_NE(second.output.find("in use by pid " + std::to_string(pid) + ": proxsim run"), std::string::npos)
      << second.output;
  const auto study = RunProxsimWithin("study " + std::string(PROXSIM_SOURCE_DIR) +
                                       "/data/studies/tibia_placement.yaml --no-report --force --out " + out.string(),
                                   10);
  EXPECT_EQ(study.exit_code, 2) << study.output;
  EXPECT_NE(study.output.find("in use by pid"), std::string::npos) << study.output;

  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_FALSE(fs::exists(out / ".proxsim.lock")) << "the lock file outlived its run";
  // the folder is free again
  EXPECT_EQ(RunProxsimWithin("run " + kWorld + " --no-report --out " + out.string()).exit_code, 0);
}

// ----- (i) names with commas and quotes

TEST_F(TrustTest, NamesWithCommasAndQuotesAreQuotedInCsvAndTheReportReadsThem) {
  const fs::path scenario = dir_ / "names.yaml";
  std::ofstream(scenario) << "proxsim: 1\nduration_s: 0.2\nrate_hz: 20\nscene:\n  objects:\n"
                          << "    - {name: 'wall, north \"A\"', box: {size_m: [0.2, 4, 2]}, pose: {xyz_m: [1.6, 0, 1]}}\n"
                          << "sensors:\n  - {name: 'front, \"left\"', type: ideal, pose: {xyz_m: [0, 0, 1]}}\n"
                          << "  - {name: plain, type: ideal, pose: {xyz_m: [0, 0.5, 1]}}\n";
  const fs::path out = dir_ / "out";
  const auto result = RunProxsimWithin("run " + scenario.string() + " --out " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto csv = testing::ReadCsv(out / "readings.csv");
  ASSERT_FALSE(csv.rows.empty());
  std::ifstream lines(out / "readings.csv");
  std::string line;
  while (std::getline(lines, line)) EXPECT_EQ(testing::SplitCsvLine(line).size(), csv.header.size()) << line;
  const auto rows = testing::RowsOf(csv, "front, \"left\"");
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.front().at("object"), "wall, north \"A\"");
  EXPECT_EQ(rows.front().at("d_m"), "1.5");
  // the JSON files parse, and plot (Python's csv module) draws them again
  EXPECT_TRUE(nlohmann::json::accept(ReadFile(out / "summary.json")));
  EXPECT_TRUE(nlohmann::json::accept(ReadFile(out / "scene.json")));
  const auto plot = RunProxsimWithin("plot " + out.string(), 300);
  EXPECT_EQ(plot.exit_code, 0) << plot.output;
}

TEST_F(TrustTest, NamesWithControlCharactersOrInvalidUtf8AreInputErrors) {
  ExpectRefused(Scenario("newline", "    - {name: \"two\\nlines\", box: {size_m: [1, 1, 1]}}\n"),
                {"newline.yaml:", "name", "a control character"});
  ExpectRefused(Scenario("latin1", "    - {name: \"caf\xe9\", box: {size_m: [1, 1, 1]}}\n"),
                {"latin1.yaml:", "name"});
}

// ----- smaller ones

TEST_F(TrustTest, LegMapProblemsComeWithTheScenarioLevelOnes) {
  // they once appeared only after the scenario-level problems were fixed
  const fs::path scenario = dir_ / "legs.yaml";
  std::ofstream(scenario) << "proxsim: 1\nduration_s: -1\nrobot:\n  model: builtin:biped\n  legs:\n"
                          << "    left:  {hip: left_hip_pich, knee: left_knee_pitch, ankle: left_ankle_pitch, foot: left_foot}\n"
                          << "    right: {hip: right_hip_pitch, knee: right_knee_pitch, ankle: right_ankle_pitch, foot: right_foot}\n"
                          << "sensors:\n  - {name: s, type: ideal, link: left_tibia}\n";
  ExpectRefused(scenario, {"legs.yaml:2: duration_s", "robot.legs.left.hip: no joint 'left_hip_pich'"});
}

TEST_F(TrustTest, SeedsOutsideSixtyFourBitsAreRefusedNotWrapped) {
  for (const char* seed : {"-1", "18446744073709551616", "1e3", "0x10"}) {
    const auto result = RunProxsimWithin("run " + kWorld + " --no-report --seed " + seed + " --out " + (dir_ / "o").string());
    EXPECT_EQ(result.exit_code, 2) << seed << ": " << result.output;
    EXPECT_NE(result.output.find("--seed: expected a whole number in [0, 18446744073709551615]"), std::string::npos)
        << result.output;
  }
  EXPECT_EQ(RunProxsimWithin("run " + kWorld + " --no-report --seed 18446744073709551615 --out " + (dir_ / "o").string())
                .exit_code,
            0);
}

}  // namespace
}  // namespace proxsim
