// The same seed gives the same world on every machine (docs/worlds.md): glibc
// picks its sin, cos, tan, atan2, exp and log among variants by the CPU (FMA
// and AVX2 ones where it has them), which differ in the last bits; the
// generators use none of them. Here `proxsim generate` runs with glibc's
// choice for this CPU and again with FMA and AVX2 masked
// (GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA: the baseline variants, as on a
// CPU without them), and the written worlds must be the same bytes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_helpers.h"

namespace proxsim {
namespace {

using testing::FreshDir;
using testing::ReadFile;
using testing::RunCommand;

constexpr const char* kMaskFmaAvx2 = "GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA";

// Whether this CPU has FMA: without it glibc has a single variant to pick, and there is nothing to compare.
bool CpuHasFma() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string word;
  while (cpuinfo >> word)
    if (word == "fma") return true;
  return false;
}

TEST(GeneratedWorldsAcrossCpus, TheWrittenWorldIsTheSameWithLibmsFmaVariantsMasked) {
  if (!CpuHasFma()) GTEST_SKIP() << "this CPU has no FMA: glibc picks the same libm variants either way";
  const auto dir = FreshDir("generate_cpu");
  std::filesystem::create_directories(dir);
  // each kind, with its turning parts on purpose: ramps (pitched slabs) and rooms full of people (walk directions)
  const char* kinds[] = {"{kind: course, difficulty: 1, length_m: 30}",
                         "{kind: course, difficulty: 0.7, elements: [ramp, step]}",
                         "{kind: room, difficulty: 1, size_m: [8, 8], people: [4, 12]}",
                         "{kind: room, difficulty: 0.5}"};
  for (const char* kind : kinds) {
    for (int seed = 1; seed <= 6; ++seed) {
      std::string generate = kind;
      generate.insert(generate.size() - 1, ", seed: " + std::to_string(seed));
      const auto scenario = dir / "scenario.yaml";
      std::ofstream(scenario) << "proxsim: 1\nscene:\n  generate: " << generate
                              << "\nrobot: {}\nsensors:\n  - {name: s, type: ideal, link: left_tibia}\n";
      std::string texts[2];
      for (int masked = 0; masked < 2; ++masked) {
        const auto out = dir / (masked ? "masked.yaml" : "native.yaml");
        const auto result = RunCommand(std::string(masked ? kMaskFmaAvx2 : "") + " " + PROXSIM_BINARY + " generate " +
                                       scenario.string() + " --out " + out.string());
        ASSERT_EQ(result.exit_code, 0) << generate << "\n" << result.output;
        texts[masked] = ReadFile(out);
      }
      EXPECT_FALSE(texts[0].empty());
      EXPECT_EQ(texts[0], texts[1]) << generate;
    }
  }
}

}  // namespace
}  // namespace proxsim
