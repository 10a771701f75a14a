#include "study/outcome_answers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>

#include <yaml-cpp/yaml.h>

#include "core/atomic_file.h"
#include "core/text_fields.h"
#include "scenario/scenario_paths.h"
#include "study/outcome_baselines.h"
#include "study/outcome_stats.h"

namespace proxsim {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string Format(double value) {
  if (!std::isfinite(value)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

json JsonNumber(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

// a name made safe for a file name
std::string FileSafe(const std::string& text) {
  std::string out;
  for (const char c : text) out += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ? c : '_';
  return out;
}

// the tally of one set with one strategy group (its chosen variant) over the test worlds
struct Tally {
  std::size_t set = 0, group = 0, strategy = 0;  // strategy: the chosen variant
  std::int64_t runs = 0, successes = 0, reached = 0, collided = 0, fell = 0, stopped = 0, time_up = 0;
  std::int64_t train_runs = 0, train_successes = 0;
  std::vector<double> time_to_goal_s, path_ratio, clearance_m;
  double min_clearance_m = std::numeric_limits<double>::infinity();
  double rate() const { return runs > 0 ? static_cast<double>(successes) / static_cast<double>(runs) : 0.0; }
};

}  // namespace

json WriteOutcomeAnswers(const OutcomeStudyConfig& study, const OutcomeResults& results, const std::string& out_dir) {
  const fs::path out(out_dir);
  const std::size_t n_sets = study.sets.size(), n_strategies = study.strategies.size();
  const auto run_of = [&](std::size_t job, std::size_t set, std::size_t strategy) -> const OutcomeRun& {
    return results[job].runs[set * n_strategies + strategy];
  };
  const auto groups = study.strategy_groups();
  const std::size_t n_groups = groups.size();
  std::vector<std::size_t> group_of(n_strategies);
  for (std::size_t g = 0; g < n_groups; ++g)
    for (std::size_t v : groups[g].second) group_of[v] = g;
  std::vector<std::size_t> train_jobs, test_jobs;
  for (std::size_t job = 0; job < results.size(); ++job) (study.jobs[job].train ? train_jobs : test_jobs).push_back(job);

  // each set's variant of each group, chosen on the training worlds: the most
  // successes, then the fewest failure dollars, then the order given (the
  // only variant when nothing is tuned)
  const auto failure_usd = [&](const OutcomeRun& run) {
    return run.outcome == OutcomeKind::kCollided ? study.costs.collision_usd
           : run.outcome == OutcomeKind::kFell   ? study.costs.fall_usd
                                                 : 0.0;
  };
  std::vector<Tally> tallies;
  for (std::size_t s = 0; s < n_sets; ++s) {
    for (std::size_t g = 0; g < n_groups; ++g) {
      Tally best;
      double best_usd = 0;
      for (std::size_t v : groups[g].second) {
        Tally t;
        t.set = s;
        t.group = g;
        t.strategy = v;
        double usd = 0;
        for (std::size_t job : train_jobs) {
          ++t.train_runs;
          t.train_successes += IsSuccess(run_of(job, s, v), results[job]);
          usd += failure_usd(run_of(job, s, v));
        }
        if (v == groups[g].second.front() || t.train_successes > best.train_successes ||
            (t.train_successes == best.train_successes && usd < best_usd)) {
          best = t;
          best_usd = usd;
        }
      }
      tallies.push_back(best);
    }
  }
  const auto chosen = [&](std::size_t set, std::size_t strategy) {
    return tallies[set * n_groups + group_of[strategy]].strategy == strategy;
  };

  // results.csv: one row per run, in job order (training runs too, and every variant)
  std::string csv = "set,strategy,world,kind,difficulty,seed,way_through,outcome,outcome_t_s,success,time_to_goal_s,"
                    "walked_m,straight_m,path_ratio,min_clearance_m,price_usd,split,chosen,tuned\n";
  for (std::size_t job = 0; job < results.size(); ++job) {
    const WorldFamily& family = study.families[study.jobs[job].family];
    for (std::size_t s = 0; s < n_sets; ++s) {
      for (std::size_t g = 0; g < n_strategies; ++g) {
        const OutcomeRun& run = run_of(job, s, g);
        const bool success = IsSuccess(run, results[job]);
        const bool reached = run.outcome == OutcomeKind::kReachedGoal;
        const double ratio = reached && run.straight_m > 0 ? run.walked_m / run.straight_m : NAN;
        csv += CsvField(study.sets[s].name) + "," + CsvField(groups[group_of[g]].first) + "," + CsvField(family.name) +
               "," + family.kind + "," + Format(family.difficulty) + "," + std::to_string(study.jobs[job].seed) + "," +
               (results[job].way_through ? "1" : "0") + "," + std::string(OutcomeName(run.outcome)) + "," + Format(run.outcome_t_s) + "," +
               (success ? "1" : "0") + "," + (reached ? Format(run.outcome_t_s) : "") + "," + Format(run.walked_m) +
               "," + Format(run.straight_m) + "," + Format(ratio) + "," + Format(run.min_clearance_m) + "," +
               Format(study.sets[s].price_usd) + "," + (study.jobs[job].train ? "train" : "test") + "," +
               (chosen(s, g) ? "1" : "0") + "," + CsvField(study.strategies[g].tuned) + "\n";
        if (study.jobs[job].train || !chosen(s, g)) continue;
        Tally& t = tallies[s * n_groups + group_of[g]];
        ++t.runs;
        t.successes += success;
        t.reached += reached;
        t.collided += run.outcome == OutcomeKind::kCollided;
        t.fell += run.outcome == OutcomeKind::kFell;
        t.stopped += run.outcome == OutcomeKind::kStopped || run.outcome == OutcomeKind::kRefused;
        t.time_up += run.outcome == OutcomeKind::kTimeUp;
        if (reached) t.time_to_goal_s.push_back(run.outcome_t_s);
        if (std::isfinite(ratio)) t.path_ratio.push_back(ratio);
        if (std::isfinite(run.min_clearance_m)) {
          t.clearance_m.push_back(run.min_clearance_m);
          t.min_clearance_m = std::min(t.min_clearance_m, run.min_clearance_m);
        }
      }
    }
  }
  WriteFileAtomically((out / "results.csv").string(), csv);

  // each set's success with each group's chosen variant, test world by test
  // world, for the paired statistics: succeeded[set · groups + group][i] on test_jobs[i]
  std::vector<std::vector<char>> succeeded(n_sets * n_groups, std::vector<char>(test_jobs.size(), 0));
  for (std::size_t i = 0; i < test_jobs.size(); ++i)
    for (const Tally& t : tallies)
      succeeded[t.set * n_groups + t.group][i] = IsSuccess(run_of(test_jobs[i], t.set, t.strategy), results[test_jobs[i]]);
  const auto baseline_index = [&](const char* name) -> std::optional<std::size_t> {
    for (std::size_t s = 0; s < n_sets; ++s)
      if (study.sets[s].baseline == name) return s;
    return std::nullopt;
  };
  const std::optional<std::size_t> blind = baseline_index("blind"), oracle = baseline_index("oracle");
  const auto perception = [&](const Tally& t) -> PerceptionScore {
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    if (!blind || !oracle) return {kNone, kNone, kNone};
    return PerceptionScoreOf(succeeded[t.set * n_groups + t.group], succeeded[*blind * n_groups + t.group],
                             succeeded[*oracle * n_groups + t.group]);
  };
  // dollars per run: failures (collisions, falls), and the hardware amortised over its runs
  const auto failure_cost = [&](const Tally& t) {
    if (t.runs == 0) return 0.0;
    return (static_cast<double>(t.collided) * study.costs.collision_usd + static_cast<double>(t.fell) * study.costs.fall_usd) /
           static_cast<double>(t.runs);
  };
  const auto expected_cost = [&](const Tally& t) {
    const SensorSet& set = study.sets[t.set];
    const double hardware = set.baseline == "blind" ? 0.0 : set.price_usd / study.costs.runs_per_unit;
    return hardware + failure_cost(t);
  };

  // ranking.csv, in the order given, then sorted
  std::vector<std::size_t> order(tallies.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto price_key = [&](const Tally& t) {
    const double p = study.sets[t.set].price_usd;
    return std::isfinite(p) ? p : std::numeric_limits<double>::infinity();
  };
  // by perception score where both baselines ran (how much of what perfect
  // sensing buys the set delivers; undefined last), then success rate, then price
  std::vector<double> score_key(tallies.size());
  for (std::size_t i = 0; i < tallies.size(); ++i) {
    const double score = perception(tallies[i]).score;
    score_key[i] = std::isfinite(score) ? score : -std::numeric_limits<double>::infinity();
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (score_key[a] != score_key[b]) return score_key[a] > score_key[b];
    if (tallies[a].rate() != tallies[b].rate()) return tallies[a].rate() > tallies[b].rate();
    return price_key(tallies[a]) < price_key(tallies[b]);
  });
  std::string ranking = "rank,set,strategy,sensors,price_usd,mass_g,runs,successes,success_rate,success_ci95_low,"
                        "success_ci95_high,reached_goal_rate,collision_rate,fall_rate,stopped_rate,time_up_rate,"
                        "median_time_to_goal_s,median_path_ratio,median_min_clearance_m,min_clearance_m,baseline,"
                        "perception_score,perception_ci95_low,perception_ci95_high,failure_cost_per_run_usd,"
                        "expected_cost_per_run_usd,tuned,train_runs,train_success_rate\n";
  json rows = json::array();
  for (std::size_t r = 0; r < order.size(); ++r) {
    const Tally& t = tallies[order[r]];
    const SensorSet& set = study.sets[t.set];
    const Interval ci = WilsonInterval95(t.successes, t.runs);
    const PerceptionScore score = perception(t);
    const auto share = [&](std::int64_t k) { return t.runs > 0 ? static_cast<double>(k) / static_cast<double>(t.runs) : 0.0; };
    std::string sensors;
    for (const std::string& name : SensorsOfRuns(set, study.strategies[t.strategy]))
      sensors += (sensors.empty() ? "" : " ") + name;
    const double train_rate =
        t.train_runs > 0 ? static_cast<double>(t.train_successes) / static_cast<double>(t.train_runs) : NAN;
    ranking += std::to_string(r + 1) + "," + CsvField(set.name) + "," + CsvField(groups[t.group].first) +
               "," + CsvField(sensors) + "," + Format(set.price_usd) + "," + Format(set.mass_g) + "," +
               std::to_string(t.runs) + "," + std::to_string(t.successes) + "," + Format(t.rate()) + "," +
               Format(ci.low) + "," + Format(ci.high) + "," + Format(share(t.reached)) + "," +
               Format(share(t.collided)) + "," + Format(share(t.fell)) + "," + Format(share(t.stopped)) + "," +
               Format(share(t.time_up)) + "," + Format(Median(t.time_to_goal_s)) + "," + Format(Median(t.path_ratio)) +
               "," + Format(Median(t.clearance_m)) + "," + Format(t.min_clearance_m) + "," + set.baseline + "," +
               Format(score.score) + "," + Format(score.low) + "," + Format(score.high) + "," +
               Format(failure_cost(t)) + "," + Format(expected_cost(t)) + "," +
               CsvField(study.strategies[t.strategy].tuned) + "," + std::to_string(t.train_runs) + "," +
               Format(train_rate) + "\n";
    rows.push_back({{"set", set.name},
                    {"baseline", set.baseline.empty() ? json(nullptr) : json(set.baseline)},
                    {"perception_score", JsonNumber(score.score)},
                    {"perception_ci95", {JsonNumber(score.low), JsonNumber(score.high)}},
                    {"expected_cost_per_run_usd", JsonNumber(expected_cost(t))},
                    {"strategy", groups[t.group].first},
                    {"tuned", study.strategies[t.strategy].tuned},
                    {"train_success_rate", JsonNumber(train_rate)},
                    {"price_usd", JsonNumber(set.price_usd)},
                    {"mass_g", JsonNumber(set.mass_g)},
                    {"runs", t.runs},
                    {"success_rate", t.rate()},
                    {"success_ci95", {ci.low, ci.high}}});
  }
  WriteFileAtomically((out / "ranking.csv").string(), ranking);

  // pairs.csv: every two sets with the same strategy, on the same worlds and seeds
  std::string pairs = "strategy,set_a,set_b,runs,a_only,b_only,both,neither,success_rate_a,success_rate_b,p_value,"
                      "verdict\n";
  for (std::size_t g = 0; g < n_groups; ++g) {
    std::vector<std::size_t> sets;  // the strategy's sets in ranking order, the best kMaxPairedSets
    for (std::size_t i : order)
      if (tallies[i].group == g && sets.size() < kMaxPairedSets) sets.push_back(tallies[i].set);
    for (std::size_t i = 0; i < sets.size(); ++i) {
      for (std::size_t j = i + 1; j < sets.size(); ++j) {
        std::int64_t a_only = 0, b_only = 0, both = 0, neither = 0;
        for (std::size_t k = 0; k < test_jobs.size(); ++k) {
          const bool a = succeeded[sets[i] * n_groups + g][k];
          const bool b = succeeded[sets[j] * n_groups + g][k];
          a_only += a && !b;
          b_only += b && !a;
          both += a && b;
          neither += !a && !b;
        }
        const double p = McNemarExactP(a_only, b_only);
        const double runs = static_cast<double>(test_jobs.size());
        const std::string verdict = p >= 0.05         ? "no significant difference"
                                    : a_only > b_only ? "a better"
                                                      : "b better";
        pairs += CsvField(groups[g].first) + "," + CsvField(study.sets[sets[i]].name) + "," +
                 CsvField(study.sets[sets[j]].name) + "," + std::to_string(test_jobs.size()) + "," +
                 std::to_string(a_only) + "," + std::to_string(b_only) + "," + std::to_string(both) + "," +
                 std::to_string(neither) + "," + Format(static_cast<double>(a_only + both) / runs) + "," +
                 Format(static_cast<double>(b_only + both) / runs) + "," + Format(p) + "," + verdict + "\n";
      }
    }
  }
  WriteFileAtomically((out / "pairs.csv").string(), pairs);

  // selection.json: the cheapest set reaching the target, and the Pareto front of price against success
  std::vector<std::size_t> priced;
  json unpriced = json::array();
  for (std::size_t i : order) {
    const SensorSet& set = study.sets[tallies[i].set];
    if (set.baseline.empty() && std::isfinite(set.price_usd)) priced.push_back(i);
  }
  for (const SensorSet& set : study.sets)
    if (set.baseline.empty() && !std::isfinite(set.price_usd))
      unpriced.push_back({{"set", set.name}, {"sensors_without_price", set.unpriced}});
  std::stable_sort(priced.begin(), priced.end(), [&](std::size_t a, std::size_t b) {
    if (price_key(tallies[a]) != price_key(tallies[b])) return price_key(tallies[a]) < price_key(tallies[b]);
    return tallies[a].rate() > tallies[b].rate();
  });
  const auto point = [&](std::size_t i) {
    const Tally& t = tallies[i];
    const Interval ci = WilsonInterval95(t.successes, t.runs);
    return json{{"set", study.sets[t.set].name},
                {"strategy", groups[t.group].first},
                {"tuned", study.strategies[t.strategy].tuned},
                {"price_usd", study.sets[t.set].price_usd},
                {"mass_g", JsonNumber(study.sets[t.set].mass_g)},
                {"sensors", SensorsOfRuns(study.sets[t.set], study.strategies[t.strategy])},
                {"success_rate", t.rate()},
                {"success_ci95", {ci.low, ci.high}},
                {"target_met_at_95_confidence", ci.low >= study.target_success},
                {"perception_score", JsonNumber(perception(t).score)},
                {"expected_cost_per_run_usd", JsonNumber(expected_cost(t))}};
  };
  json lowest_cost = nullptr;
  {
    std::optional<std::size_t> best;
    for (std::size_t i : priced)
      if (!best || expected_cost(tallies[i]) < expected_cost(tallies[*best])) best = i;
    if (best) lowest_cost = point(*best);
  }

  // warnings: where the worlds or the strategy, not the sensors, limit the answer
  json warnings = json::array();
  for (std::size_t f = 0; f < study.families.size() && blind && oracle; ++f) {
    for (std::size_t g = 0; g < n_groups; ++g) {
      std::int64_t n = 0, blind_ok = 0, oracle_ok = 0;
      for (std::size_t k = 0; k < test_jobs.size(); ++k) {
        if (study.jobs[test_jobs[k]].family != f) continue;
        ++n;
        blind_ok += succeeded[*blind * n_groups + g][k];
        oracle_ok += succeeded[*oracle * n_groups + g][k];
      }
      if (n == 0) continue;
      const double blind_rate = static_cast<double>(blind_ok) / static_cast<double>(n);
      const double oracle_rate = static_cast<double>(oracle_ok) / static_cast<double>(n);
      const auto warn = [&](const char* baseline, double rate, const char* bound, const char* meaning) {
        char text[400];
        std::snprintf(text, sizeof text, "world %s, strategy %s: %s succeeds in %.0f %% of %lld worlds (%s): %s",
                      study.families[f].name.c_str(), groups[g].first.c_str(), baseline, 100 * rate,
                      static_cast<long long>(n), bound, meaning);
        warnings.push_back(text);
      };
      if (oracle_rate < 0.95)
        warn("the oracle (perfect perception)", oracle_rate, "< 95 %",
             "the strategy or the legs, not the sensors, limit the answer there");
      if (blind_rate > 0.20)
        warn("the blind baseline (no sensors)", blind_rate, "> 20 %", "these worlds do not test the sensors");
    }
  }
  json cheapest = nullptr;
  for (std::size_t i : priced) {
    if (tallies[i].rate() >= study.target_success) {
      cheapest = point(i);
      break;
    }
  }
  json front = json::array();
  double best_rate = -1;
  for (std::size_t i : priced) {  // by price: a point is on the front when no cheaper one succeeds as often
    if (tallies[i].rate() > best_rate) {
      front.push_back(point(i));
      best_rate = tallies[i].rate();
    }
  }
  const json selection = {
      {"mode", "outcomes"},
      {"target_success", study.target_success},
      {"success",
       "a run succeeds when the robot reached its goal, or, where the path given has no way through (the "
       "reference walk, blind and without a strategy, refused a step or collided), stopped (its strategy, or its "
       "legs refusing a step) past half the way to where the reference met the hazard and within 2 m of it (a "
       "refusal) or 1.2 m (a collision)"},
      {"interval", "95 % Wilson score interval"},
      {"tuning",
       {{"train_worlds", train_jobs.size()},
        {"test_worlds", test_jobs.size()},
        {"rule", "each set's values of each strategy's tuned parameters (tune:) chosen on the training worlds: the "
                 "most successes, then the fewest failure dollars, then the order given; every rate, score and test "
                 "measured on the test worlds only"}}},
      {"pairs", "McNemar's exact two-sided test on the discordant worlds (pairs.csv)"},
      {"perception_score",
       "(success - blind) / (oracle - blind) on the same worlds, seeds and strategy: the share of what perfect "
       "perception would achieve over no sensors that the set delivers; 95 % interval by the delta method on the paired "
       "worlds"},
      {"baselines",
       {{"blind", "no sensors: the strategy never sees anything"},
        {"oracle", "perfect perception: a fan of exact rays from the robot's root link over the ground 0.3 to 3 m ahead, "
                   "120 degrees wide, 10 Hz"}}},
      {"costs",
       {{"runs_per_unit", study.costs.runs_per_unit},
        {"collision_usd", study.costs.collision_usd},
        {"fall_usd", study.costs.fall_usd},
        {"expected_cost_per_run_usd", "price_usd / runs_per_unit + collision_rate * collision_usd + fall_rate * fall_usd"}}},
      {"warnings", warnings},
      {"cheapest_reaching_target", cheapest},
      {"lowest_expected_cost", lowest_cost},
      {"pareto_front", front},
      {"unpriced_sets", unpriced},
      {"ranking", rows}};
  WriteFileAtomically((out / "selection.json").string(), selection.dump(2) + "\n");

  // failures.csv and the world files their replay commands run: the
  // answer's failures (test worlds, each set's chosen variants)
  std::string failures = "set,strategy,world,seed,outcome,outcome_t_s,world_file,command,viewer,tuned\n";
  std::size_t written = 0;
  std::set<std::string> stems;  // one file per failure: `x y` and `x_y` once shared one
  for (std::size_t job : test_jobs) {
    const WorldFamily& family = study.families[study.jobs[job].family];
    for (std::size_t s = 0; s < n_sets; ++s) {
      for (std::size_t g = 0; g < n_strategies; ++g) {
        const OutcomeRun& run = run_of(job, s, g);
        if (!chosen(s, g) || IsSuccess(run, results[job])) continue;
        const std::string safe_stem = FileSafe(family.name) + "_seed" + std::to_string(study.jobs[job].seed) +
                                      "_set" + std::to_string(s + 1) + "_" + FileSafe(study.strategies[g].label);
        // names that FileSafe maps alike get _2, _3, ...: the mapping stays one to one
        std::string stem = safe_stem;
        for (int copy = 2; !stems.insert(stem).second; ++copy) stem = safe_stem + "_" + std::to_string(copy);
        std::string file, command, viewer;
        // the blind baseline is meant to fail: its failures are listed, not replayed
        if (written < study.replay_files && study.sets[s].baseline != "blind") {
          ++written;
          fs::create_directories(out / "failures");
          // the replay's relative paths (a user's robot, meshes) rebased to its folder, as `proxsim generate` does
          YAML::Node replay = YAML::Load(RunScenarioText(study, job, s, g));
          RebaseScenarioPaths(replay, fs::path(family.source).parent_path(), out / "failures");
          YAML::Emitter emitted;
          emitted << replay;
          // the user's names quoted and escaped (JSON strings): a newline in one cannot start a key of the file
          const std::string text =
              "# " + std::string(OutcomeName(run.outcome)) + " at t = " + Format(run.outcome_t_s) + " s: set " + QuotedForComment(study.sets[s].name) +
              ", strategy " + QuotedForComment(study.strategies[g].label) + ", world " + QuotedForComment(family.name) +
              " seed " + std::to_string(study.jobs[job].seed) + " (written by proxsim study " +
              QuotedForComment(study.source) + ")\n" + emitted.c_str() + "\n";
          WriteFileAtomically((out / "failures" / (stem + ".yaml")).string(), text);
          // relative to the study's folder: the files are the same wherever the study was written
          file = "failures/" + stem + ".yaml";
          command = "proxsim run " + file + " --out replays/" + stem;
          viewer = "replays/" + stem + "/report/index.html";
        }
        failures += CsvField(study.sets[s].name) + "," + CsvField(groups[group_of[g]].first) + "," +
                    CsvField(family.name) + "," + std::to_string(study.jobs[job].seed) + "," + std::string(OutcomeName(run.outcome)) + "," +
                    Format(run.outcome_t_s) + "," + CsvField(file) + "," + CsvField(command) + "," +
                    CsvField(viewer) + "," + CsvField(study.strategies[g].tuned) + "\n";
      }
    }
  }
  WriteFileAtomically((out / "failures.csv").string(), failures);

  // episodes.jsonl: one object per run, for a user's own analysis of the factors
  std::string episodes;
  for (std::size_t job = 0; job < results.size(); ++job) {
    const WorldFamily& family = study.families[study.jobs[job].family];
    for (std::size_t s = 0; s < n_sets; ++s) {
      for (std::size_t g = 0; g < n_strategies; ++g) {
        const OutcomeRun& run = run_of(job, s, g);
        const json strategy = study.strategies[g].yaml.empty() ? json(nullptr) : json(study.strategies[g].yaml);
        episodes += json{{"set", study.sets[s].name},
                         {"baseline", study.sets[s].baseline.empty() ? json(nullptr) : json(study.sets[s].baseline)},
                         {"strategy", groups[group_of[g]].first},
                         {"variant", study.strategies[g].label},
                         {"tuned", study.strategies[g].tuned},
                         {"chosen", chosen(s, g)},
                         {"split", study.jobs[job].train ? "train" : "test"},
                         {"strategy_parameters", strategy},
                         {"world", family.name},
                         {"kind", family.kind},
                         {"difficulty", JsonNumber(family.difficulty)},
                         {"seed", study.jobs[job].seed},
                         {"way_through", results[job].way_through},
                         {"outcome", OutcomeName(run.outcome)},
                         {"outcome_t_s", JsonNumber(run.outcome_t_s)},
                         {"success", IsSuccess(run, results[job])},
                         {"walked_m", JsonNumber(run.walked_m)},
                         {"straight_m", JsonNumber(run.straight_m)},
                         {"min_clearance_m", JsonNumber(run.min_clearance_m)},
                         {"price_usd", JsonNumber(study.sets[s].price_usd)}}
                        .dump() +
                    "\n";
      }
    }
  }
  WriteFileAtomically((out / "episodes.jsonl").string(), episodes);
  return selection;
}

}  // namespace proxsim
