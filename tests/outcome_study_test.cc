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
#include "sensors/sensor_spec.h"
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
  for (const std::string& part : SensorSpec::PartNames()) {
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
    const OutcomeRun reached{OutcomeKind::kReachedGoal, t, 4.4, 4.0, 0.2};
    job.runs.push_back(j < 19 ? reached : OutcomeRun{OutcomeKind::kCollided, 3.0, 1.5, 4.0, 0.0});
    const OutcomeKind b = j < 10   ? OutcomeKind::kReachedGoal
                          : j < 15 ? OutcomeKind::kCollided
                          : j < 18 ? OutcomeKind::kFell
                          : j == 18 ? OutcomeKind::kTimeUp
                                    : OutcomeKind::kStopped;
    job.runs.push_back(j < 10 ? reached : OutcomeRun{b, 5.0, 2.0, 4.0, b == OutcomeKind::kCollided ? 0.0 : 0.1});
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
  const OutcomeRun reached{OutcomeKind::kReachedGoal, 8.0, 4.4, 4.0, 0.2}, collided{OutcomeKind::kCollided, 3.0, 1.5, 4.0, 0.0};
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

// Tuning, planted: one strategy in two variants (min_height_m 0.03 and 0.06),
// 4 training worlds and 10 test worlds.
//   A: 0.06 succeeds in every training world, 0.03 in none → 0.06 chosen;
//      on the test worlds 0.06 succeeds in 8, 0.03 in all 10 (which the
//      choice must not see).
//   B: 0.03 succeeds in 3 of 4 training worlds, 0.06 in 1 → 0.03 chosen; on
//      test 0.03 in 6, 0.06 in none.
//   blind fails everywhere with both (a tie: the first variant), the oracle
//   succeeds everywhere.
TEST(OutcomeAnswers, TuningChoosesOnTrainingWorldsAndScoresOnTestWorlds) {
  const fs::path dir = FreshDir("outcome_tuning");
  fs::create_directories(dir);
  OutcomeStudyConfig study;
  study.source = "planted";
  study.sets = {{"A", "[]", {"a1"}, 10.0, 2.0, {}}, {"B", "[]", {"b1"}, 5.0, 1.0, {}}};
  for (const char* name : {"blind", "oracle"}) {
    SensorSet baseline{name, "[]", {}, std::nan(""), std::nan(""), {}};
    baseline.baseline = name;
    study.sets.push_back(baseline);
  }
  study.strategies = {{"stop[min_height_m=0.03]", "{name: stop, min_height_m: 0.03}", "stop", "min_height_m=0.03"},
                      {"stop[min_height_m=0.06]", "{name: stop, min_height_m: 0.06}", "stop", "min_height_m=0.06"}};
  study.families = {{"room_d0.5", "room", 0.5, "", "", true}};
  for (std::uint64_t seed = 1; seed <= 14; ++seed) study.jobs.push_back({0, seed, seed <= 4});
  study.replay_files = 0;
  const OutcomeRun ok{OutcomeKind::kReachedGoal, 8.0, 4.4, 4.0, 0.2}, hit{OutcomeKind::kCollided, 3.0, 1.5, 4.0, 0.0};
  OutcomeResults results(14);
  for (int j = 0; j < 14; ++j) {
    const bool train = j < 4;
    const int k = j - 4;  // the test world's index
    // runs[set · 2 + variant]: A, B, blind, oracle, each with 0.03 then 0.06
    results[j].runs = {train ? hit : ok,          train ? ok : (k < 8 ? ok : hit),
                       train ? (j < 3 ? ok : hit) : (k < 6 ? ok : hit), train ? (j < 1 ? ok : hit) : hit,
                       hit, hit, ok, ok};
  }
  const nlohmann::json selection = WriteOutcomeAnswers(study, results, dir.string());

  const auto ranking = ReadCsv(dir / "ranking.csv");
  ASSERT_EQ(ranking.rows.size(), 4u) << "one row per set and strategy, not per variant";
  std::map<std::string, std::map<std::string, std::string>> by_set;
  for (const auto& row : ranking.rows) by_set[row.at("set")] = row;
  EXPECT_EQ(by_set["A"].at("strategy"), "stop");
  EXPECT_EQ(by_set["A"].at("tuned"), "min_height_m=0.06");
  EXPECT_EQ(by_set["A"].at("runs"), "10");
  EXPECT_EQ(by_set["A"].at("success_rate"), "0.8") << "the test worlds only, the chosen variant only";
  EXPECT_EQ(by_set["A"].at("train_runs"), "4");
  EXPECT_EQ(by_set["A"].at("train_success_rate"), "1");
  EXPECT_EQ(by_set["B"].at("tuned"), "min_height_m=0.03");
  EXPECT_EQ(by_set["B"].at("success_rate"), "0.6");
  EXPECT_EQ(by_set["B"].at("train_success_rate"), "0.75");
  EXPECT_EQ(by_set["blind"].at("tuned"), "min_height_m=0.03") << "a tie goes to the first variant";
  EXPECT_NEAR(std::stod(by_set["A"].at("perception_score")), 0.8, 1e-12);
  EXPECT_NEAR(std::stod(by_set["B"].at("perception_score")), 0.6, 1e-12);
  EXPECT_EQ(selection["tuning"]["train_worlds"], 4);
  EXPECT_EQ(selection["tuning"]["test_worlds"], 10);

  // the paired test on the test worlds: A alone in 6-7, B alone in none
  const auto pairs = ReadCsv(dir / "pairs.csv");
  bool found = false;
  for (const auto& row : pairs.rows) {
    if (row.at("set_a") != "A" || row.at("set_b") != "B") continue;
    found = true;
    EXPECT_EQ(row.at("runs"), "10");
    EXPECT_EQ(row.at("a_only"), "2");
    EXPECT_EQ(row.at("b_only"), "0");
    EXPECT_EQ(row.at("both"), "6");
  }
  EXPECT_TRUE(found);
  // every run in results.csv, split and choice named; the failures are the answer's
  const auto rows = ReadCsv(dir / "results.csv");
  EXPECT_EQ(rows.rows.size(), 14u * 4u * 2u);
  int train_rows = 0, chosen_rows = 0;
  for (const auto& row : rows.rows) {
    train_rows += row.at("split") == "train";
    chosen_rows += row.at("chosen") == "1";
  }
  EXPECT_EQ(train_rows, 4 * 4 * 2);
  EXPECT_EQ(chosen_rows, 14 * 4);
  EXPECT_EQ(ReadCsv(dir / "failures.csv").rows.size(), 2u + 4u + 10u);  // A, B, blind on the test worlds
  fs::remove_all(dir);
}

// Without a way through, stopping counts only near the hazard (kStopBeforeHazard_m).
TEST(OutcomeAnswers, AStopIsASuccessOnlyBeforeAnImpassableHazard) {
  OutcomeJob blocked;
  blocked.way_through = false;
  blocked.hazard_m = 3.0;
  EXPECT_TRUE(IsSuccess({OutcomeKind::kStopped, 4.0, 2.5, 5.0, 0.3}, blocked));
  EXPECT_TRUE(IsSuccess({OutcomeKind::kRefused, 4.0, 2.9, 5.0, 0.3}, blocked));
  EXPECT_FALSE(IsSuccess({OutcomeKind::kStopped, 1.0, 0.5, 5.0, 0.3}, blocked)) << "stopped at its start";
  EXPECT_FALSE(IsSuccess({OutcomeKind::kFell, 4.0, 3.0, 5.0, 0.3}, blocked));
  EXPECT_FALSE(IsSuccess({OutcomeKind::kTimeUp, 14.0, 2.5, 5.0, 0.3}, blocked));
  const OutcomeJob open;  // a way through: only the goal counts
  EXPECT_FALSE(IsSuccess({OutcomeKind::kStopped, 4.0, 2.5, 5.0, 0.3}, open));
  EXPECT_TRUE(IsSuccess({OutcomeKind::kReachedGoal, 9.0, 5.2, 5.0, 0.3}, open));
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

// tune: makes every combination of the candidate values a variant named by
// them; a repeated strategy is told apart by its parameters; the seeds split
// into training and test worlds.
TEST(OutcomeConfig, TuneMakesVariantsNamedByTheirValues) {
  const fs::path dir = FreshDir("outcome_tune");
  fs::create_directories(dir);
  std::ofstream(dir / "tune.yaml")
      << "proxsim_study: 1\nmode: outcomes\nbase: " << PROXSIM_SOURCE_DIR << "/data/scenarios/outcome_walker.yaml\n"
      << "sets: [{name: s, sensors: [{name: a, type: vl53l0x, link: left_tibia}]}]\nbaselines: []\n"
      << "strategies: [{name: stop, perception: map}, {name: stop}, {name: circumvent}]\n"
      << "tune: {stop.min_height_m: [0.03, 0.05], stop.stop_distance_m: [0.4, 0.6]}\n"
      << "worlds: {generate: {kind: room}, seeds: {train: {from: 1, to: 3}, test: [7, 8]}}\n";
  const OutcomeStudyConfig study = LoadOutcomeStudyFile((dir / "tune.yaml").string());
  std::vector<std::string> labels;
  for (const StrategyChoice& s : study.strategies) labels.push_back(s.label);
  EXPECT_EQ(labels, (std::vector<std::string>{
                        "stop[perception=map][min_height_m=0.03,stop_distance_m=0.4]",
                        "stop[perception=map][min_height_m=0.03,stop_distance_m=0.6]",
                        "stop[perception=map][min_height_m=0.05,stop_distance_m=0.4]",
                        "stop[perception=map][min_height_m=0.05,stop_distance_m=0.6]",
                        "stop[min_height_m=0.03,stop_distance_m=0.4]", "stop[min_height_m=0.03,stop_distance_m=0.6]",
                        "stop[min_height_m=0.05,stop_distance_m=0.4]", "stop[min_height_m=0.05,stop_distance_m=0.6]",
                        "circumvent"}));
  EXPECT_EQ(study.strategies[5].yaml, "{name: stop, min_height_m: 0.03, stop_distance_m: 0.6}");
  const auto groups = study.strategy_groups();
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_EQ(groups[0].first, "stop[perception=map]");
  EXPECT_EQ(groups[1].second, (std::vector<std::size_t>{4, 5, 6, 7}));
  ASSERT_EQ(study.jobs.size(), 5u);
  EXPECT_TRUE(study.jobs[2].train);
  EXPECT_FALSE(study.jobs[3].train);
  EXPECT_EQ(study.jobs[3].seed, 7u);
  fs::remove_all(dir);
}

// The test worlds are worlds the tuning never saw; tuning needs both kinds.
TEST(OutcomeConfig, TrainingAndTestSeedsNeverOverlap) {
  const fs::path dir = FreshDir("outcome_tune_bad");
  fs::create_directories(dir);
  const std::string head = "proxsim_study: 1\nmode: outcomes\nbase: " + std::string(PROXSIM_SOURCE_DIR) +
                           "/data/scenarios/outcome_walker.yaml\n"
                           "sets: [{name: s, sensors: [{name: a, type: vl53l0x, link: left_tibia}]}]\n";
  const auto problems = [&](const std::string& body) {
    std::ofstream(dir / "study.yaml") << head << body;
    try {
      LoadOutcomeStudyFile((dir / "study.yaml").string());
    } catch (const InputError& error) {
      std::string all;
      for (const std::string& p : error.problems()) all += p + "\n";
      return all;
    }
    return std::string("(loaded)");
  };
  EXPECT_NE(problems("tune: {stop.min_height_m: [0.03, 0.05]}\n"
                     "worlds: {generate: {kind: room}, seeds: {train: {from: 1, to: 10}, test: {from: 8, to: 20}}}\n")
                .find("3 seed(s) both train and test (8, 9, 10)"),
            std::string::npos);
  EXPECT_NE(problems("tune: {stop.min_height_m: [0.03, 0.05]}\nworlds: {generate: {kind: room}, seeds: [1, 2]}\n")
                .find("tune: chooses values on training seeds"),
            std::string::npos);
  EXPECT_NE(problems("worlds: {generate: {kind: room}, seeds: {train: [1], test: [2]}}\n").find("nothing to tune"),
            std::string::npos);
  const std::string bad_keys = problems(
      "strategies: [{name: stop}]\ntune: {stop.min_hieght_m: [0.03], circumvent.margin_m: [0.1], stop: [1],"
      " stop.min_height_m: [-1, 0.05, 0.05]}\nworlds: {generate: {kind: room}, seeds: {train: [1], test: [2]}}\n");
  for (const char* expected : {"min_hieght_m", "no strategy named 'circumvent'", "strategy.parameter",
                               "0.05 appears twice"}) {
    EXPECT_NE(bad_keys.find(expected), std::string::npos) << expected << " not in:\n" << bad_keys;
  }
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
