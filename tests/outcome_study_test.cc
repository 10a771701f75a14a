// The outcome study's statistics against closed forms computed by hand, and
// its answers on a synthetic study whose outcomes are planted: the rates,
// intervals, paired tests and the cheapest set come out exactly as planted.
// Also the study file's validation: every problem listed at once.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"
#include "core/input_error.h"
#include "sensors/part_prices.h"
#include "study/outcome_answers.h"
#include "study/outcome_config.h"
#include "study/outcome_stats.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::ReadCsv;
using testing::ReadFile;

// Wilson 95 %: centre (p + z²/2n)/(1 + z²/n), half z/(1 + z²/n)·√(p(1−p)/n + z²/4n²),
// z = 1.959963984540054, evaluated by hand (the tables' 0/10 → [0, 0.2775], 5/10 → [0.2366, 0.7634])
TEST(OutcomeStats, WilsonIntervalMatchesTheClosedForm) {
  struct Case {
    int k, n;
    double low, high;
  };
  for (const Case& c : {Case{0, 10, 0.0, 0.2775327999}, Case{1, 10, 0.0178762131, 0.4041500268},
                        Case{5, 10, 0.2365930905, 0.7634069095}, Case{10, 10, 0.7224672001, 1.0},
                        Case{19, 20, 0.7638688066, 0.9911185512}, Case{81, 263, 0.2552885199, 0.3662095770}}) {
    const Interval ci = WilsonInterval95(c.k, c.n);
    EXPECT_NEAR(ci.low, c.low, 1e-9) << c.k << "/" << c.n;
    EXPECT_NEAR(ci.high, c.high, 1e-9) << c.k << "/" << c.n;
  }
  const Interval none = WilsonInterval95(0, 0);
  EXPECT_EQ(none.low, 0.0);
  EXPECT_EQ(none.high, 1.0);
}

// exact two-sided: p = min(1, 2 Σ_{i ≤ min(b,c)} C(b+c, i) / 2^(b+c))
TEST(OutcomeStats, McNemarExactMatchesTheBinomialSums) {
  EXPECT_DOUBLE_EQ(McNemarExactP(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(McNemarExactP(5, 0), 2.0 / 32.0);                     // 0.0625: not significant
  EXPECT_DOUBLE_EQ(McNemarExactP(0, 6), 2.0 / 64.0);                     // 0.03125
  EXPECT_DOUBLE_EQ(McNemarExactP(9, 1), 2.0 * (1 + 10) / 1024.0);        // 0.021484375
  EXPECT_DOUBLE_EQ(McNemarExactP(10, 2), 2.0 * (1 + 12 + 66) / 4096.0);  // 0.0385742...
  EXPECT_DOUBLE_EQ(McNemarExactP(3, 3), 1.0);                            // 2·42/64 > 1, capped
  // beyond 1000 discordant pairs the terms are summed in logs: 600 against 500 is
  // 2 Σ_{i ≤ 500} C(1100, i) / 2^1100 = 0.00281954499143643 (in exact integers)
  EXPECT_NEAR(McNemarExactP(600, 500), McNemarExactP(500, 600), 1e-15);
  EXPECT_NEAR(McNemarExactP(600, 500), 0.00281954499143643, 1e-12);
}

// Boost.Math's quantiles against the published tables (Abramowitz & Stegun
// 26.2 and 26.7; NIST/SEMATECH e-Handbook 1.3.6.7.2): the normal's 97.5 %
// and Student's t at 97.5 % — 3 degrees of freedom is 3.182 (the hand-kept
// table this replaced had 2.182), 30 is 2.042, 120 is 1.980
TEST(OutcomeStats, QuantilesMatchThePublishedTables) {
  EXPECT_NEAR(NormalQuantile(0.975), 1.959964, 1e-6);
  EXPECT_DOUBLE_EQ(NormalQuantile(0.975), kZ95);
  EXPECT_NEAR(NormalQuantile(0.95), 1.644854, 1e-6);
  EXPECT_NEAR(StudentTQuantile(0.975, 1), 12.706, 1e-3);
  EXPECT_NEAR(StudentTQuantile(0.975, 2), 4.303, 1e-3);
  EXPECT_NEAR(StudentTQuantile(0.975, 3), 3.182, 1e-3);
  EXPECT_NEAR(StudentTQuantile(0.975, 10), 2.228, 1e-3);
  EXPECT_NEAR(StudentTQuantile(0.975, 30), 2.042, 1e-3);
  EXPECT_NEAR(StudentTQuantile(0.975, 120), 1.980, 1e-3);
  EXPECT_NEAR(StudentTQuantile(0.95, 5), 2.015, 1e-3);
}

// by hand: S = 11010, B = 00010, O = 11110 on 5 worlds; x = S − B = 11000,
// y = O − B = 11100, R = 2/3; z = x − R·y = (1/3, 1/3, −2/3, 0, 0), Σz² = 2/3;
// Var R = (2/3) / (5·4) / (3/5)² = 25/270; half = 1.959964·√(25/270) = 0.596398
TEST(OutcomeStats, PerceptionScoreMatchesAHandComputedCase) {
  const std::vector<char> set{1, 1, 0, 1, 0}, blind{0, 0, 0, 1, 0}, oracle{1, 1, 1, 1, 0};
  const PerceptionScore score = PerceptionScoreOf(set, blind, oracle);
  EXPECT_NEAR(score.score, 2.0 / 3.0, 1e-12);
  const double half = kZ95 * std::sqrt(25.0 / 270.0);
  EXPECT_NEAR(half, 0.596398, 1e-6);
  EXPECT_NEAR(score.low, 2.0 / 3.0 - half, 1e-12);
  EXPECT_NEAR(score.high, 2.0 / 3.0 + half, 1e-12);
  // the set as good as the oracle on every world: 1, no spread
  const PerceptionScore perfect = PerceptionScoreOf(oracle, blind, oracle);
  EXPECT_DOUBLE_EQ(perfect.score, 1.0);
  EXPECT_DOUBLE_EQ(perfect.low, 1.0);
  // an oracle no better than blind: undefined
  EXPECT_TRUE(std::isnan(PerceptionScoreOf(set, blind, blind).score));
}

TEST(OutcomeStats, Median) {
  EXPECT_TRUE(std::isnan(Median({})));
  EXPECT_EQ(Median({3, 1, 2}), 2.0);
  EXPECT_EQ(Median({4, 1, 3, 2}), 2.5);
}

TEST(OutcomeStats, EveryDatasheetPartHasAPriceAndAMass) {
  for (const char* part : {"hc_sr04", "sharp_gp2y0a21", "vl53l0x", "vl53l1x", "vl53l5cx", "vl53l7cx", "vl53l8cx"}) {
    const auto price = PartPriceOf(part);
    ASSERT_TRUE(price.has_value()) << part;
    EXPECT_GT(price->price_usd, 0) << part;
    EXPECT_GT(price->mass_g, 0) << part;
  }
  EXPECT_FALSE(PartPriceOf("laser").has_value()) << "the paper's models are not parts";
}

// Three sets, one strategy, 20 worlds; job 19's world has no way through.
//   A ($10): reached the goal in worlds 0-18, collided in 19         → 19/20
//   B ($5):  reached in 0-9, collided 10-14, fell 15-17, time up 18,
//            stopped in 19 (no way through: a success)               → 11/20
//   C (no price): reached everywhere                                  → 20/20
OutcomeStudyConfig PlantedStudy() {
  OutcomeStudyConfig study;
  study.source = "planted";
  study.sets = {{"A", "[]", {"a1"}, 10.0, 2.0, {}},
                {"B", "[]", {"b1"}, 5.0, 1.0, {}},
                {"C", "[]", {"c1"}, std::nan(""), std::nan(""), {"c1"}}};
  study.strategies = {{"stop", "{name: stop}"}};
  study.families = {{"room_d0.5", "room", 0.5, "", "", true}};
  for (std::uint64_t seed = 1; seed <= 20; ++seed) study.jobs.push_back({0, seed});
  study.target_success = 0.95;
  study.replay_files = 0;  // no world to write: the families are not real
  return study;
}

OutcomeResults PlantedResults() {
  OutcomeResults results(20);
  for (int j = 0; j < 20; ++j) {
    OutcomeJob& job = results[j];
    job.way_through = j != 19;
    if (j == 19) job.hazard_m = 3.0;  // B stopped after 2.0 m: within 2 m of it
    const double t = 8.0 + 0.1 * j;
    const OutcomeRun reached{"reached_goal", t, 4.4, 4.0, 0.2};
    job.runs.push_back(j < 19 ? reached : OutcomeRun{"collided", 3.0, 1.5, 4.0, 0.0});
    const char* b = j < 10 ? "reached_goal" : j < 15 ? "collided" : j < 18 ? "fell" : j == 18 ? "time_up" : "stopped";
    job.runs.push_back(j < 10 ? reached : OutcomeRun{b, 5.0, 2.0, 4.0, std::string(b) == "collided" ? 0.0 : 0.1});
    job.runs.push_back(reached);
  }
  return results;
}

TEST(OutcomeAnswers, APlantedStudyGivesExactlyThePlantedRates) {
  const fs::path dir = FreshDir("outcome_planted");
  fs::create_directories(dir);
  const nlohmann::json selection = WriteOutcomeAnswers(PlantedStudy(), PlantedResults(), dir.string());

  const auto ranking = ReadCsv(dir / "ranking.csv");
  ASSERT_EQ(ranking.rows.size(), 3u);
  // ranked by success rate: C, A, B
  EXPECT_EQ(ranking.rows[0].at("set"), "C");
  EXPECT_EQ(ranking.rows[1].at("set"), "A");
  EXPECT_EQ(ranking.rows[2].at("set"), "B");
  const auto& a = ranking.rows[1];
  EXPECT_EQ(a.at("successes"), "19");
  EXPECT_EQ(a.at("success_rate"), "0.95");
  EXPECT_NEAR(std::stod(a.at("success_ci95_low")), 0.7638688066, 1e-8);
  EXPECT_NEAR(std::stod(a.at("success_ci95_high")), 0.9911185512, 1e-8);
  EXPECT_EQ(a.at("collision_rate"), "0.05");
  EXPECT_EQ(a.at("median_time_to_goal_s"), "8.9");  // 8.0 + 0.1·j over worlds 0-18
  EXPECT_EQ(a.at("median_path_ratio"), "1.1");
  EXPECT_EQ(a.at("min_clearance_m"), "0");
  const auto& b = ranking.rows[2];
  EXPECT_EQ(b.at("successes"), "11");
  EXPECT_EQ(b.at("success_rate"), "0.55");
  EXPECT_EQ(b.at("reached_goal_rate"), "0.5");
  EXPECT_EQ(b.at("collision_rate"), "0.25");
  EXPECT_EQ(b.at("fall_rate"), "0.15");
  EXPECT_EQ(b.at("stopped_rate"), "0.05");
  EXPECT_EQ(b.at("time_up_rate"), "0.05");
  EXPECT_EQ(b.at("price_usd"), "5");
  EXPECT_EQ(ranking.rows[0].at("price_usd"), "") << "C has a sensor without a price";

  // A against B: A alone succeeded in worlds 10-18 (9), B alone in world 19 (1)
  const auto pairs = ReadCsv(dir / "pairs.csv");
  ASSERT_EQ(pairs.rows.size(), 3u);
  const auto& ab = pairs.rows[2];
  EXPECT_EQ(ab.at("set_a"), "A");
  EXPECT_EQ(ab.at("set_b"), "B");
  EXPECT_EQ(ab.at("a_only"), "9");
  EXPECT_EQ(ab.at("b_only"), "1");
  EXPECT_EQ(ab.at("both"), "10");
  EXPECT_EQ(ab.at("neither"), "0");
  EXPECT_EQ(ab.at("p_value"), "0.021484375");
  EXPECT_EQ(ab.at("verdict"), "a better");
  EXPECT_EQ(pairs.rows[0].at("verdict"), "no significant difference");  // C against A: 1 discordant world

  // the cheapest priced set reaching 0.95 is A; B is cheaper but does not; C has no price
  ASSERT_FALSE(selection["cheapest_reaching_target"].is_null());
  EXPECT_EQ(selection["cheapest_reaching_target"]["set"], "A");
  EXPECT_EQ(selection["cheapest_reaching_target"]["target_met_at_95_confidence"], false);
  ASSERT_EQ(selection["pareto_front"].size(), 2u);
  EXPECT_EQ(selection["pareto_front"][0]["set"], "B");
  EXPECT_EQ(selection["pareto_front"][1]["set"], "A");
  ASSERT_EQ(selection["unpriced_sets"].size(), 1u);
  EXPECT_EQ(selection["unpriced_sets"][0]["set"], "C");

  // every failed run listed once: A's world 19, B's worlds 10-18
  const auto failures = ReadCsv(dir / "failures.csv");
  EXPECT_EQ(failures.rows.size(), 10u);
  const auto results = ReadCsv(dir / "results.csv");
  EXPECT_EQ(results.rows.size(), 60u);
  fs::remove_all(dir);
}

// A set A with both baselines on 10 worlds, one strategy:
//   blind succeeds in worlds 0-2 (3/10: more than 20 %, a warning),
//   the oracle everywhere, A in worlds 0-7 and collides in 8 and 9.
// perception score = (8 − 3) / (10 − 3) = 5/7; A's expected cost per run =
// $10 / 1000 runs + 2/10 collisions · $50 = $10.01.
TEST(OutcomeAnswers, BaselinesGiveThePlantedPerceptionScoreCostAndWarning) {
  const fs::path dir = FreshDir("outcome_baselines");
  fs::create_directories(dir);
  OutcomeStudyConfig study;
  study.source = "planted";
  study.sets = {{"A", "[]", {"a1"}, 10.0, 2.0, {}}};
  SensorSet blind{"blind", "[]", {}, std::nan(""), std::nan(""), {}};
  blind.baseline = "blind";
  SensorSet oracle{"oracle", "[]", {}, std::nan(""), std::nan(""), {}};
  oracle.baseline = "oracle";
  study.sets.push_back(blind);
  study.sets.push_back(oracle);
  study.strategies = {{"stop", "{name: stop}"}};
  study.families = {{"room_d0.5", "room", 0.5, "", "", true}};
  for (std::uint64_t seed = 1; seed <= 10; ++seed) study.jobs.push_back({0, seed});
  study.replay_files = 0;
  OutcomeResults results(10);
  const OutcomeRun reached{"reached_goal", 8.0, 4.4, 4.0, 0.2}, collided{"collided", 3.0, 1.5, 4.0, 0.0};
  for (int j = 0; j < 10; ++j) {
    results[j].runs = {j < 8 ? reached : collided, j < 3 ? reached : collided, reached};
  }
  const nlohmann::json selection = WriteOutcomeAnswers(study, results, dir.string());
  const auto ranking = ReadCsv(dir / "ranking.csv");
  ASSERT_EQ(ranking.rows.size(), 3u);
  std::map<std::string, std::map<std::string, std::string>> by_set;
  for (const auto& row : ranking.rows) by_set[row.at("set")] = row;
  EXPECT_NEAR(std::stod(by_set["A"].at("perception_score")), 5.0 / 7.0, 1e-9);
  EXPECT_NEAR(std::stod(by_set["A"].at("expected_cost_per_run_usd")), 10.01, 1e-9);
  EXPECT_NEAR(std::stod(by_set["blind"].at("perception_score")), 0.0, 1e-12);
  EXPECT_NEAR(std::stod(by_set["oracle"].at("perception_score")), 1.0, 1e-12);
  EXPECT_EQ(by_set["oracle"].at("baseline"), "oracle");
  EXPECT_EQ(by_set["A"].at("baseline"), "");
  // the baselines are rows of the answer, never a set to buy
  ASSERT_FALSE(selection["lowest_expected_cost"].is_null());
  EXPECT_EQ(selection["lowest_expected_cost"]["set"], "A");
  EXPECT_TRUE(selection["unpriced_sets"].empty());
  ASSERT_EQ(selection["warnings"].size(), 1u);
  EXPECT_NE(selection["warnings"][0].get<std::string>().find("blind baseline (no sensors) succeeds in 30 %"),
            std::string::npos);
  // one episode per run in episodes.jsonl
  std::ifstream episodes(dir / "episodes.jsonl");
  std::string line;
  int lines = 0, blind_lines = 0;
  while (std::getline(episodes, line)) {
    const nlohmann::json e = nlohmann::json::parse(line);
    ++lines;
    blind_lines += e["baseline"] == "blind";
  }
  EXPECT_EQ(lines, 30);
  EXPECT_EQ(blind_lines, 10);
  fs::remove_all(dir);
}

// Without a way through, stopping counts only near the hazard (kStopBeforeHazard_m).
TEST(OutcomeAnswers, AStopIsASuccessOnlyBeforeAnImpassableHazard) {
  OutcomeJob blocked;
  blocked.way_through = false;
  blocked.hazard_m = 3.0;
  EXPECT_TRUE(IsSuccess({"stopped", 4.0, 2.5, 5.0, 0.3}, blocked));
  EXPECT_TRUE(IsSuccess({"refused", 4.0, 2.9, 5.0, 0.3}, blocked));
  EXPECT_FALSE(IsSuccess({"stopped", 1.0, 0.5, 5.0, 0.3}, blocked)) << "stopped at its start";
  EXPECT_FALSE(IsSuccess({"fell", 4.0, 3.0, 5.0, 0.3}, blocked));
  EXPECT_FALSE(IsSuccess({"time_up", 14.0, 2.5, 5.0, 0.3}, blocked));
  const OutcomeJob open;  // a way through: only the goal counts
  EXPECT_FALSE(IsSuccess({"stopped", 4.0, 2.5, 5.0, 0.3}, open));
  EXPECT_TRUE(IsSuccess({"reached_goal", 9.0, 5.2, 5.0, 0.3}, open));
}

// combine: every set of `size` among the `top` rows of a detection study's
// ranking.csv, or among this file's candidates; each mounting rebuilt as a
// scenario sensor on its link at its axes' values.
TEST(OutcomeConfig, CombineMakesEverySetOfSizeAmongTheTopMountings) {
  const fs::path dir = FreshDir("outcome_combine");
  fs::create_directories(dir);
  std::ofstream(dir / "ranking.csv")
      << "rank,candidate,type,part,link,along_m,forward_m,pitch_deg,yaw_deg,detection_rate,detection_rate_ci95,"
         "lead_mean_m,lead_ci95_m,false_alarms_mean,self_share,grazing_share,floor_coverage\n"
      << "1,laser@left_tibia:z-0.35:x0.06:p15:y0,laser,,left_tibia,-0.35,0.06,15,0,1,0,0.5,0,0,0,0,0.5\n"
      << "2,vl53l0x@right_tibia:z-0.25:x0.06:p0:y0,laser,vl53l0x,right_tibia,-0.25,0.06,0,0,1,0,0.4,0,0,0,0,0.5\n"
      << "3,hc_sr04@left_thigh:z-0.2:x0.06:p30:y0,ultrasonic,hc_sr04,left_thigh,-0.2,0.06,30,0,0.5,0,0.3,0,0,0,0,0\n"
      << "4,ideal@left_tibia:z-0.1:x0.06:p0:y0,ideal,,left_tibia,-0.1,0.06,0,0,0.2,0,0.1,0,0,0,0,0\n";
  const std::string head = "proxsim_study: 1\nmode: outcomes\nbase: " + std::string(PROXSIM_SOURCE_DIR) +
                           "/data/scenarios/outcome_walker.yaml\nworlds: {generate: {kind: room}}\n";
  std::ofstream(dir / "from_ranking.yaml") << head << "combine: {from: ranking.csv, size: 2, top: 3}\nbaselines: []\n";
  const OutcomeStudyConfig ranked = LoadOutcomeStudyFile((dir / "from_ranking.yaml").string());
  ASSERT_EQ(ranked.sets.size(), 3u);  // C(3, 2)
  EXPECT_EQ(ranked.sets[0].name, "laser@left_tibia:z-0.35:x0.06:p15:y0 + vl53l0x@right_tibia:z-0.25:x0.06:p0:y0");
  EXPECT_EQ(ranked.sets[2].sensor_names,
            (std::vector<std::string>{"vl53l0x@right_tibia:z-0.25:x0.06:p0:y0", "hc_sr04@left_thigh:z-0.2:x0.06:p30:y0"}));
  // the parts are priced from the catalogue; the paper's laser is not a part
  EXPECT_DOUBLE_EQ(ranked.sets[2].price_usd, PartPriceOf("vl53l0x")->price_usd + PartPriceOf("hc_sr04")->price_usd);
  EXPECT_TRUE(std::isnan(ranked.sets[0].price_usd));
  EXPECT_EQ(ranked.sets[0].unpriced, (std::vector<std::string>{"laser@left_tibia:z-0.35:x0.06:p15:y0"}));

  std::ofstream(dir / "from_candidates.yaml")
      << head << "combine: {from: candidates, size: 3}\n"
      << "candidates: {axes: {type: [vl53l0x, hc_sr04], link: [left_tibia, right_tibia], along_m: -0.3}}\n"
      << "prices: {hc_sr04: {price_usd: 2.5}}\nbaselines: []\n";
  const OutcomeStudyConfig listed = LoadOutcomeStudyFile((dir / "from_candidates.yaml").string());
  ASSERT_EQ(listed.sets.size(), 4u);  // C(4, 3)
  EXPECT_DOUBLE_EQ(listed.sets[0].price_usd, 2 * PartPriceOf("vl53l0x")->price_usd + 2.5);
  fs::remove_all(dir);
}

TEST(OutcomeConfig, EveryProblemOfABadStudyIsListedAtOnce) {
  const fs::path dir = FreshDir("outcome_bad");
  fs::create_directories(dir);
  std::ofstream(dir / "bad.yaml")
      << "proxsim_study: 1\nmode: outcomes\nbase: " << PROXSIM_SOURCE_DIR << "/data/scenarios/outcome_walker.yaml\n"
      << "sets:\n  - {name: s, sensors: [{name: a, type: no_such_part, link: left_tibia}]}\n"
      << "strategies: [{name: stop}, my_module:MyStrategy, {name: circumvnt}]\n"
      << "worlds: {generate: {kind: room, difficulty: [0.3, 1.5]}, seeds: {from: 3, to: 1}}\n"
      << "target_success: 2\nunknown_key: 1\n";
  try {
    LoadOutcomeStudyFile((dir / "bad.yaml").string());
    FAIL() << "a bad study loaded";
  } catch (const InputError& error) {
    std::string all;
    for (const std::string& p : error.problems()) all += p + "\n";
    for (const char* expected : {"unknown_key", "no_such_part", "module:Class", "circumvnt", "difficulty 1.5",
                                 "empty range", "target_success"}) {
      EXPECT_NE(all.find(expected), std::string::npos) << expected << " not in:\n" << all;
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace proxsim
