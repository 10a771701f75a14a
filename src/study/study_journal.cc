#include "study/study_journal.h"

#include <algorithm>

#include <cmath>
#include <limits>

#include "core/input_error.h"

namespace proxsim {

namespace {

using nlohmann::json;

[[noreturn]] void BadJournalLine(const std::string& what) { throw InputError("journal line: " + what); }

// a number, or null for NaN (how nlohmann writes a non-finite double)
double JournalNumberOrNaN(const json& value, const std::string& where) {
  if (value.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!value.is_number()) BadJournalLine(where + ": expected a number, got " + value.dump());
  return value.get<double>();
}

std::int64_t Count(const json& value, const std::string& where) {
  if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<std::int64_t>() >= 0))
    BadJournalLine(where + ": expected a count >= 0, got " + value.dump());
  return value.get<std::int64_t>();
}

const json& JournalField(const json& object, const char* key, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) BadJournalLine(where + ": no '" + key + "'");
  return *it;
}

}  // namespace

json JournalMetricsJson(const std::vector<RunMetrics>& runs) {
  json out = json::array();
  for (const RunMetrics& m : runs) {
    json hazards = json::array();
    for (const HazardResult& h : m.hazards) hazards.push_back({h.applies, h.detected, h.first_t_s, h.lead_m});
    out.push_back({{"h", hazards},
                   {"n", m.samples},
                   {"fa", m.false_alarms},
                   {"self", m.self_share},
                   {"graze", m.grazing_share},
                   {"floor", m.floor_coverage},
                   {"out", OutcomeName(m.outcome)},
                   {"out_t", m.outcome_t_s}});
  }
  return out;
}

JournalEntry ParseJournalLine(const json& line, const JournalShape& shape) {
  if (!line.is_object()) BadJournalLine("expected an object {\"job\": ..., \"metrics\": [...]}");
  JournalEntry entry;
  const json& job = JournalField(line, "job", "the line");
  if (!job.is_number_unsigned() || job.get<std::uint64_t>() >= shape.jobs)
    BadJournalLine("job " + job.dump() + ": expected a job index below " + std::to_string(shape.jobs));
  entry.job = job.get<std::size_t>();
  const std::string at = "job " + std::to_string(entry.job);

  // one entry per candidate, each with one entry per hazard
  const json& metrics = JournalField(line, "metrics", at);
  if (!metrics.is_array() || metrics.size() != shape.candidates) {
    BadJournalLine(at + ": metrics of " + (metrics.is_array() ? std::to_string(metrics.size()) : std::string("no")) +
        " candidates, the study has " + std::to_string(shape.candidates) + " (a line of another study?)");
  }
  for (std::size_t c = 0; c < metrics.size(); ++c) {
    const json& r = metrics[c];
    const std::string where = at + ", candidate " + std::to_string(c);
    if (!r.is_object()) BadJournalLine(where + ": expected an object");
    RunMetrics m;
    const json& hazards = JournalField(r, "h", where);
    if (!hazards.is_array() || hazards.size() != shape.hazards) {
      BadJournalLine(where + ": " + (hazards.is_array() ? std::to_string(hazards.size()) : std::string("no")) +
          " hazard results, the study has " + std::to_string(shape.hazards));
    }
    for (const json& h : hazards) {
      if (!h.is_array() || h.size() != 4 || !h[0].is_boolean() || !h[1].is_boolean())
        BadJournalLine(where + ": a hazard result is not [applies, detected, first_t_s, lead_m]: " + h.dump());
      m.hazards.push_back({h[0].get<bool>(), h[1].get<bool>(), JournalNumberOrNaN(h[2], where), JournalNumberOrNaN(h[3], where)});
    }
    m.samples = Count(JournalField(r, "n", where), where + ": n");
    m.false_alarms = Count(JournalField(r, "fa", where), where + ": fa");
    m.self_share = JournalNumberOrNaN(JournalField(r, "self", where), where + ": self");
    m.grazing_share = JournalNumberOrNaN(JournalField(r, "graze", where), where + ": graze");
    m.floor_coverage = JournalNumberOrNaN(JournalField(r, "floor", where), where + ": floor");
    const json& outcome = JournalField(r, "out", where);
    const std::optional<OutcomeKind> kind = outcome.is_string() ? OutcomeFromName(outcome.get<std::string>()) : std::nullopt;
    if (!kind)
      BadJournalLine(where + ": out: expected an outcome name (reached_goal, stopped, collided, fell, refused, time_up), got " +
          outcome.dump());
    m.outcome = *kind;
    m.outcome_t_s = JournalNumberOrNaN(JournalField(r, "out_t", where), where + ": out_t");
    entry.metrics.push_back(std::move(m));
  }
  return entry;
}

}  // namespace proxsim
