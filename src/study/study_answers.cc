#include "study/study_answers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numeric>

#include "core/atomic_file.h"
#include "core/text_fields.h"
#include "study/outcome_stats.h"
#include "study/study_selection.h"

namespace proxsim {

namespace {

constexpr double kAnswerNaN = std::numeric_limits<double>::quiet_NaN();

// Student's t at 97.5 % (Boost.Math; the hand-kept table this replaced had
// 2.182 for 3 degrees of freedom, where it is 3.182, and 1.96 beyond 30)
double T975(std::size_t dof) { return StudentTQuantile(0.975, static_cast<double>(dof)); }

std::string Number(double value) {
  if (!std::isfinite(value)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

// per seed: the candidate's detection rate over the applicable (variant, hazard) items and its mean lead
struct SeedFigures {
  std::vector<double> rate, lead;
};

SeedFigures PerSeed(const StudyConfig& study, const StudyResults& results, std::size_t candidate) {
  SeedFigures f;
  for (std::size_t s = 0; s < study.seeds.size(); ++s) {
    double applicable = 0, detected = 0, lead_sum = 0;
    for (std::size_t v = 0; v < study.variants.size(); ++v) {
      for (const HazardResult& h : results[v][s][candidate].hazards) {
        if (!h.applies) continue;
        ++applicable;
        if (h.detected) {
          ++detected;
          lead_sum += h.lead_m;
        }
      }
    }
    if (applicable > 0) f.rate.push_back(detected / applicable);
    if (detected > 0) f.lead.push_back(lead_sum / detected);
  }
  return f;
}

}  // namespace

MeanCi MeanWithCi95(const std::vector<double>& values) {
  if (values.empty()) return {kAnswerNaN, kAnswerNaN};
  const double n = static_cast<double>(values.size());
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
  // one value, or all equal: no spread (not the rounding noise of a sum)
  if (std::all_of(values.begin(), values.end(), [&](double v) { return v == values.front(); })) return {mean, 0.0};
  double ss = 0;
  for (double v : values) ss += (v - mean) * (v - mean);
  return {mean, T975(values.size() - 1) * std::sqrt(ss / (n - 1)) / std::sqrt(n)};
}

nlohmann::json WriteStudyAnswers(const StudyConfig& study, const StudyResults& results, const std::string& out_dir) {
  namespace fs = std::filesystem;
  const fs::path out(out_dir);
  const std::size_t n = study.candidates.size();

  // results.csv: one row per run, every parameter and metric
  std::string csv = "candidate,type,part,link,along_m,forward_m,pitch_deg,yaw_deg,scene,seed,samples,false_alarms,"
                    "self_share,grazing_share,floor_coverage,outcome,outcome_t_s";
  // the "," + temporary string pieces appended one by one: GCC 12 takes
  // `"," + f()` for an overlapping memcpy (a false -Wrestrict at -O3)
  for (const std::string& h : study.hazards) {
    for (const char* column : {"_detected", "_first_t_s", "_lead_m"}) {
      csv += ',';
      csv += CsvField(h + column);
    }
  }
  csv += "\n";
  for (std::size_t c = 0; c < n; ++c) {
    const Candidate& cand = study.candidates[c];
    for (std::size_t v = 0; v < study.variants.size(); ++v) {
      for (std::size_t s = 0; s < study.seeds.size(); ++s) {
        const RunMetrics& m = results[v][s][c];
        csv += CsvField(cand.id) + "," + SensorTypeName(cand.sensor.spec.type) + "," + cand.sensor.spec.part + "," +
               CsvField(cand.sensor.link) + "," +
               Number(cand.along_m) + "," + Number(cand.forward_m) + "," + Number(cand.pitch_deg) + "," +
               Number(cand.yaw_deg) + "," + CsvField(study.variants[v].name) + "," + std::to_string(study.seeds[s]) + "," +
               std::to_string(m.samples) + "," + std::to_string(m.false_alarms) + "," + Number(m.self_share) + "," +
               Number(m.grazing_share) + "," + Number(m.floor_coverage) + "," + std::string(OutcomeName(m.outcome)) + "," +
               Number(m.outcome_t_s);
        for (const HazardResult& h : m.hazards) {
          csv += ',';
          if (h.applies) csv += h.detected ? "1" : "0";
          csv += ',';
          if (h.detected) csv += Number(h.first_t_s);
          csv += ',';
          if (h.detected) csv += Number(h.lead_m);
        }
        csv += "\n";
      }
    }
  }
  WriteFileAtomically((out / "results.csv").string(), csv);

  // ranking.csv: single mountings, by detection rate, then lead, then false alarms
  struct Row {
    std::size_t c;
    MeanCi rate, lead;
    double false_alarms, self_share, grazing_share, floor_coverage;
  };
  std::vector<Row> rows;
  const double runs = static_cast<double>(study.variants.size() * study.seeds.size());
  for (std::size_t c = 0; c < n; ++c) {
    const SeedFigures f = PerSeed(study, results, c);
    Row row{c, MeanWithCi95(f.rate), MeanWithCi95(f.lead), 0, 0, 0, 0};
    for (const auto& variant : results)
      for (const auto& seed : variant) {
        row.false_alarms += seed[c].false_alarms / runs;
        row.self_share += seed[c].self_share / runs;
        row.grazing_share += seed[c].grazing_share / runs;
        row.floor_coverage += seed[c].floor_coverage / runs;
      }
    rows.push_back(row);
  }
  const auto value = [](double x) { return std::isfinite(x) ? x : -std::numeric_limits<double>::infinity(); };
  std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) {
    if (value(a.rate.mean) != value(b.rate.mean)) return value(a.rate.mean) > value(b.rate.mean);
    if (value(a.lead.mean) != value(b.lead.mean)) return value(a.lead.mean) > value(b.lead.mean);
    return a.false_alarms < b.false_alarms;
  });
  std::vector<std::size_t> rank(n);
  std::string ranking = "rank,candidate,type,part,link,along_m,forward_m,pitch_deg,yaw_deg,detection_rate,detection_rate_ci95,"
                        "lead_mean_m,lead_ci95_m,false_alarms_mean,self_share,grazing_share,floor_coverage\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const Row& row = rows[r];
    const Candidate& cand = study.candidates[row.c];
    rank[row.c] = r;
    ranking += std::to_string(r + 1) + "," + CsvField(cand.id) + "," + SensorTypeName(cand.sensor.spec.type) + "," +
               cand.sensor.spec.part + "," + CsvField(cand.sensor.link) + "," + Number(cand.along_m) + "," + Number(cand.forward_m) + "," +
               Number(cand.pitch_deg) + "," + Number(cand.yaw_deg) + "," + Number(row.rate.mean) + "," +
               Number(row.rate.ci95) + "," + Number(row.lead.mean) + "," + Number(row.lead.ci95) + "," +
               Number(row.false_alarms) + "," + Number(row.self_share) + "," + Number(row.grazing_share) + "," +
               Number(row.floor_coverage) + "\n";
  }
  WriteFileAtomically((out / "ranking.csv").string(), ranking);

  // selection.json: the greedy set of k and the Pareto front of count against rate and lead
  const Coverage coverage = CoverageOf(study, results);
  const std::size_t k_front = std::min<std::size_t>(n, std::max<std::size_t>(study.select_sensors, 6));
  std::vector<bool> eligible(n, true);
  if (!study.select_types.empty()) {
    for (std::size_t c = 0; c < n; ++c) {
      eligible[c] = std::find(study.select_types.begin(), study.select_types.end(), study.candidates[c].type) !=
                    study.select_types.end();
    }
  }
  const std::vector<std::size_t> order = GreedySelection(coverage, k_front, rank, eligible);
  nlohmann::json front = nlohmann::json::array(), chosen = nlohmann::json::array();
  std::vector<double> best_lead(coverage.items, -std::numeric_limits<double>::infinity());
  std::vector<bool> covered(coverage.items, false);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::size_t c = order[i];
    for (std::size_t j = 0; j < coverage.covers[c].size(); ++j) {
      const std::size_t item = coverage.covers[c][j];
      covered[item] = true;
      best_lead[item] = std::max(best_lead[item], coverage.lead_m[c][j]);
    }
    double count = 0, lead = 0;
    for (std::size_t item = 0; item < coverage.items; ++item) {
      if (!covered[item]) continue;
      ++count;
      lead += best_lead[item];
    }
    const double rate = coverage.items ? count / coverage.items : 0.0;
    const nlohmann::json point = {{"sensors", i + 1},
                                  {"added", study.candidates[c].id},
                                  {"detection_rate", rate},
                                  {"mean_lead_m", count > 0 ? nlohmann::json(lead / count) : nlohmann::json(nullptr)}};
    front.push_back(point);
    if (i < static_cast<std::size_t>(study.select_sensors)) chosen.push_back(point);
  }
  // a point is on the front when no smaller set does as well on both
  for (std::size_t i = 0; i < front.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < i; ++j) {
      const auto lead = [](const nlohmann::json& p) { return p["mean_lead_m"].is_null() ? -1e9 : p["mean_lead_m"].get<double>(); };
      dominated |= front[j]["detection_rate"].get<double>() >= front[i]["detection_rate"].get<double>() &&
                   lead(front[j]) >= lead(front[i]);
    }
    front[i]["pareto"] = !dominated;
  }
  const nlohmann::json selection = {
      {"k", study.select_sensors},
      {"objective", "the items covered, then the lead: an item is one hazard in one scene variant with one seed; a "
                    "set is worth the sum over items of its best weight 1 + max(lead_m, 0) / lead_scale_m among the "
                    "sensors that detected the item (0 if none did); the lead terms together weigh less than one item"},
      {"why_greedy", "the objective is a weighted coverage function with non-negative weights, monotone and "
                     "submodular, so the greedy set is within 1 - 1/e of the best set of its size (Nemhauser, "
                     "Wolsey and Fisher 1978)"},
      {"types", study.select_types.empty() ? nlohmann::json("every type") : nlohmann::json(study.select_types)},
      {"items", coverage.items},
      {"lead_scale_m", coverage.lead_scale_m},
      {"value", SelectionValue(coverage, std::vector<std::size_t>(
                                             order.begin(), order.begin() + std::min<std::size_t>(
                                                                                order.size(), study.select_sensors)))},
      {"chosen", chosen},
      {"pareto_front", front}};
  WriteFileAtomically((out / "selection.json").string(), selection.dump(2) + "\n");
  return selection;
}

}  // namespace proxsim
