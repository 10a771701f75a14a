#include "study/outcome_config.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "core/regular_file.h"
#include "core/text_fields.h"
#include "scenario/scenario_generate.h"
#include "scenario/scenario_sections.h"
#include "scenario/yaml_reader.h"
#include "sensors/part_prices.h"
#include "study/outcome_baselines.h"
#include "study/outcome_strategies.h"
#include "study/study_config.h"

namespace proxsim {

namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// a detection study's ranking.csv: a row per candidate, 10 000 of them at most without --allow-large
constexpr unsigned long long kMaxRankingBytes = 256ull << 20;  // 256 MiB

std::string ReadText(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string ConfigNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

// a list of numbers, a range {from, to, step}, or one number
std::vector<double> NumbersOrRange(YamlReader& reader, const Field& field, std::vector<double> otherwise) {
  if (!field) return otherwise;
  std::vector<double> values;
  if (field.node.IsScalar()) {
    if (const auto v = reader.Number(field)) values.push_back(*v);
    return values;
  }
  if (field.node.IsMap()) {
    const auto range = reader.Map(field, {"from", "to", "step"}, "a range {from, to, step}");
    if (!range) return values;
    const auto from = reader.Number((*range)["from"]);
    const auto to = reader.Number((*range)["to"]);
    const double step = reader.Number((*range)["step"], PositiveNumber()).value_or(1.0);
    if (!from || !to) {
      reader.Fail(field, "expected both from and to");
      return values;
    }
    if (*from > *to) {
      reader.Fail(field, "empty range: from " + ConfigNumber(*from) + " is beyond to " + ConfigNumber(*to));
      return values;
    }
    const auto count = static_cast<std::size_t>(std::floor((*to - *from) / step + 1e-9)) + 1;
    if (count > 1'000'000) {
      reader.Fail(field, "a range of " + std::to_string(count) + " values: expected at most 1000000");
      return values;
    }
    for (std::size_t i = 0; i < count; ++i) values.push_back(*from + static_cast<double>(i) * step);
    return values;
  }
  const auto items = reader.List(field, "a number, a list of numbers or a range {from, to, step}");
  if (!items) return values;
  if (items->empty()) reader.Fail(field, "expected at least one value, got an empty list");
  for (const Field& item : *items)
    if (const auto v = reader.Number(item)) values.push_back(*v);
  return values;
}

std::vector<std::uint64_t> Seeds(YamlReader& reader, const Field& field, std::vector<std::uint64_t> otherwise) {
  if (!field) return otherwise;
  std::vector<std::uint64_t> seeds;
  for (double seed : NumbersOrRange(reader, field, {})) {
    if (seed < 0 || seed != std::floor(seed) || seed > 9.007199254740992e15) {
      reader.Fail(field, "expected whole numbers >= 0 as seeds");
      return {};
    }
    seeds.push_back(static_cast<std::uint64_t>(seed));
  }
  return seeds;
}

// A world's seeds: a list, a range, or {train: ..., test: ...} (tuning, docs/studies.md).
struct SeedSplit {
  std::vector<std::uint64_t> train, test;
};

SeedSplit ReadSeedSplit(YamlReader& reader, const Field& field, const SeedSplit& otherwise) {
  if (!field) return otherwise;
  const YAML::Node& node = field.node;  // (const: looking a key up must not add it)
  if (!node.IsMap() || !(node["train"] || node["test"])) return {{}, Seeds(reader, field, {})};
  SeedSplit split;
  const auto map = reader.Map(field, {"train", "test"}, "seeds {train: [...], test: [...]}");
  if (!map) return split;
  split.train = Seeds(reader, (*map)["train"], {});
  split.test = Seeds(reader, (*map)["test"], {});
  if (!(*map)["train"]) reader.Fail(field, "expected train: the seeds each set's strategy values are chosen on");
  if (!(*map)["test"]) reader.Fail(field, "expected test: the seeds the answer is measured on");
  // a seed in both would score a set on the worlds its values were chosen on
  const std::set<std::uint64_t> train(split.train.begin(), split.train.end());
  std::string shared;
  std::size_t n_shared = 0;
  for (std::uint64_t seed : split.test) {
    if (!train.contains(seed)) continue;
    if (++n_shared <= 5) shared += (shared.empty() ? "" : ", ") + std::to_string(seed);
  }
  if (n_shared > 0) {
    reader.Fail(field, std::to_string(n_shared) + " seed(s) both train and test (" + shared + (n_shared > 5 ? ", ..." : "") +
                           "): the test seeds must be worlds the tuning never saw");
  }
  return split;
}

// ----- sets

// the first `top` rows of a detection study's ranking.csv, as candidates
std::vector<Candidate> RankingCandidates(YamlReader& reader, const Field& field, const fs::path& path, std::size_t top) {
  std::vector<Candidate> candidates;
  // a FIFO would block for ever, /dev/zero fill memory: a regular file of a ranking's size only
  if (const std::string problem = RegularFileProblem(path.string(), kMaxRankingBytes); !problem.empty()) {
    reader.Fail(field, problem + " (expected a detection study's ranking.csv)");
    return candidates;
  }
  std::ifstream in(path);
  if (!in) {
    reader.Fail(field, "cannot read " + path.string() + " (a detection study's ranking.csv)");
    return candidates;
  }
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = SplitQuotedCsvLine(line);
  const auto column = [&](const char* name) -> int {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    return -1;
  };
  const int type = column("type"), part = column("part"), link = column("link"), along = column("along_m"),
            forward = column("forward_m"), pitch = column("pitch_deg"), yaw = column("yaw_deg");
  if (type < 0 || part < 0 || link < 0 || along < 0 || forward < 0 || pitch < 0 || yaw < 0) {
    reader.Fail(field, path.string() + " is not a detection study's ranking.csv (expected the columns type, part, "
                                       "link, along_m, forward_m, pitch_deg, yaw_deg)");
    return candidates;
  }
  for (int row = 2; candidates.size() < top && std::getline(in, line); ++row) {
    const std::vector<std::string> f = SplitQuotedCsvLine(line);
    const auto number = [&](int i, double* out) { return i < static_cast<int>(f.size()) && ParseFiniteNumber(f[i], out); };
    double a = 0, x = 0, p = 0, y = 0;
    if (static_cast<int>(f.size()) < static_cast<int>(header.size()) || !number(along, &a) || !number(forward, &x) ||
        !number(pitch, &p) || !number(yaw, &y)) {
      reader.Fail(field, path.string() + ":" + std::to_string(row) + ": expected a ranking row, got '" + line + "'");
      continue;
    }
    const std::string name = f[part].empty() ? f[type] : f[part];
    const auto candidate = MakeStudyCandidate(name, f[link], a, x, p, y);
    if (!candidate) {
      reader.Fail(field, path.string() + ":" + std::to_string(row) + ": unknown sensor type or part '" + name + "'");
      continue;
    }
    candidates.push_back(*candidate);
  }
  return candidates;
}

// a candidate as a scenario's sensor entry
YAML::Node SensorNode(const Candidate& c) {
  YAML::Node node;
  node["name"] = c.id;
  node["type"] = c.type;
  node["link"] = c.sensor.link;
  YAML::Node pose;
  for (int i = 0; i < 3; ++i) {
    pose["xyz_m"].push_back(ConfigNumber(c.xyz_m[i]));
    pose["rpy_deg"].push_back(ConfigNumber(c.rpy_deg[i]));
  }
  node["pose"] = pose;
  return node;
}

// every set of `size` among `candidates`, in lexicographic order of their indices
void CombineSets(YamlReader& reader, const Field& field, const std::vector<Candidate>& candidates, std::size_t size,
                 std::vector<std::pair<std::string, YAML::Node>>& sets) {
  const std::size_t n = candidates.size();
  if (size > n) {
    reader.Fail(field, "size " + std::to_string(size) + " exceeds the " + std::to_string(n) + " mountings to combine");
    return;
  }
  double count = 1;  // C(n, size), counted before any set is made
  for (std::size_t i = 0; i < size; ++i) count = count * static_cast<double>(n - i) / static_cast<double>(i + 1);
  if (count > static_cast<double>(kMaxOutcomeSets)) {
    reader.Fail(field, "C(" + std::to_string(n) + ", " + std::to_string(size) + ") = " + ConfigNumber(count) +
                           " sets; expected at most " + std::to_string(kMaxOutcomeSets) + " (lower top or size)");
    return;
  }
  std::vector<std::size_t> pick(size);
  for (std::size_t i = 0; i < size; ++i) pick[i] = i;
  while (true) {
    YAML::Node list;
    std::string name;
    for (std::size_t i : pick) {
      list.push_back(SensorNode(candidates[i]));
      name += (name.empty() ? "" : " + ") + candidates[i].id;
    }
    sets.emplace_back(name, list);
    // the next combination
    std::size_t i = size;
    while (i > 0 && pick[i - 1] == n - size + i - 1) --i;
    if (i == 0) break;
    ++pick[i - 1];
    for (std::size_t j = i; j < size; ++j) pick[j] = pick[j - 1] + 1;
  }
}

// `prices: {NAME: {price_usd, mass_g}}`, NAME a sensor's name, part or type
struct PriceOverride {
  std::optional<double> price_usd, mass_g;
};
std::map<std::string, PriceOverride> ReadPrices(YamlReader& reader, const Field& field) {
  std::map<std::string, PriceOverride> prices;
  if (!field) return prices;
  if (!field.node.IsMap()) {
    reader.Fail(field, "expected a map {sensor name, part or type: {price_usd, mass_g}}, got " + DescribeNode(field.node));
    return prices;
  }
  for (const auto& entry : field.node) {
    const std::string key = entry.first.as<std::string>();
    const auto one = reader.Map(Field{entry.second, JoinPath(field.path, key), true}, {"price_usd", "mass_g"});
    if (!one) continue;
    prices[key] = {reader.Number((*one)["price_usd"], NonNegativeNumber("USD")),
                   reader.Number((*one)["mass_g"], NonNegativeNumber("g"))};
  }
  return prices;
}

// a set's price and mass: each sensor's by its name, else its part (or type), else the catalogue's
void PriceSet(const std::vector<SensorConfig>& sensors, const std::map<std::string, PriceOverride>& prices,
              SensorSet& set) {
  set.price_usd = 0;
  set.mass_g = 0;
  for (const SensorConfig& sensor : sensors) {
    const std::string part = sensor.spec.part.empty() ? SensorTypeName(sensor.spec.type) : sensor.spec.part;
    std::optional<double> price, mass;
    if (const auto catalogue = PartPriceOf(sensor.spec.part)) {
      price = catalogue->price_usd;
      mass = catalogue->mass_g;
    }
    for (const std::string& key : {part, sensor.name}) {  // the sensor's own name last: it wins
      const auto it = prices.find(key);
      if (it == prices.end()) continue;
      if (it->second.price_usd) price = it->second.price_usd;
      if (it->second.mass_g) mass = it->second.mass_g;
    }
    set.price_usd += price.value_or(kNaN);
    set.mass_g += mass.value_or(kNaN);
    if (!price) set.unpriced.push_back(sensor.name);
  }
}

// ----- worlds

// the base scenario's document made a world of this family: its scene, path,
// strategy and sensors dropped (the map's sensor list with them)
YAML::Node Unfurnished(const YAML::Node& document, bool generated) {
  YAML::Node doc = YAML::Clone(document);
  doc.remove("sensors");
  if (doc["map"] && doc["map"].IsMap()) doc["map"].remove("sensors");
  if (doc["robot"] && doc["robot"].IsMap()) {
    doc["robot"].remove("strategy");
    doc["robot"].remove("stop_distance_m");
    if (generated) doc["robot"].remove("path");
  }
  return doc;
}

void ReadWorld(YamlReader& reader, const Field& item, const std::optional<YAML::Node>& base, const fs::path& base_path,
               const fs::path& dir, const SeedSplit& default_seeds, OutcomeStudyConfig& study,
               std::set<std::string>& names) {
  const auto map = reader.Map(item, {"name", "generate", "scenario", "seeds"});
  if (!map) return;
  const SeedSplit seeds = ReadSeedSplit(reader, (*map)["seeds"], default_seeds);
  const auto add = [&](WorldFamily family) {
    if (!names.insert(family.name).second) reader.Fail(item, "world family '" + family.name + "' appears twice");
    study.families.push_back(family);
    for (std::uint64_t seed : seeds.train) study.jobs.push_back({study.families.size() - 1, seed, true});
    for (std::uint64_t seed : seeds.test) study.jobs.push_back({study.families.size() - 1, seed, false});
  };
  if ((*map)["generate"] && (*map)["scenario"]) {
    reader.Fail(item, "expected generate or scenario, not both");
    return;
  }
  if (const Field generate = (*map)["generate"]) {
    if (!generate.node.IsMap()) {
      reader.Fail(generate, "expected a map {kind: room | course, difficulty: [...], ...}");
      return;
    }
    if (generate.node["seed"]) {
      reader.Fail(Field{generate.node["seed"], JoinPath(generate.path, "seed"), true},
                  "a study sets each world's seed from its seeds: give seeds beside generate");
    }
    const auto kind = reader.String(Field{generate.node["kind"], JoinPath(generate.path, "kind"),
                                          static_cast<bool>(generate.node["kind"])});
    if (!generate.node["kind"]) reader.Fail(generate, "expected kind: room or course");
    if (kind && *kind != "room" && *kind != "course") {
      reader.Fail(Field{generate.node["kind"], JoinPath(generate.path, "kind"), true},
                  "expected room or course, got '" + *kind + "'");
    }
    const std::vector<double> difficulties =
        NumbersOrRange(reader, Field{generate.node["difficulty"], JoinPath(generate.path, "difficulty"),
                                     static_cast<bool>(generate.node["difficulty"])},
                       {0.5});
    if (!base) {
      if (!(*map)["name"]) reader.Fail(item, "a generated world needs the study's base scenario (its robot and timing)");
      return;
    }
    if (!kind) return;
    const auto name = (*map)["name"] ? reader.String((*map)["name"]) : std::optional<std::string>(*kind);
    for (double d : difficulties) {
      if (!(d >= 0 && d <= 1)) {
        reader.Fail(generate, "difficulty " + ConfigNumber(d) + ": expected values in [0, 1]");
        continue;
      }
      YAML::Node doc = Unfurnished(*base, true);
      YAML::Node gen = YAML::Clone(generate.node);
      gen["difficulty"] = ConfigNumber(d);
      YAML::Node scene;
      scene["generate"] = gen;
      doc["scene"] = scene;
      add({name.value_or(*kind) + "_d" + ConfigNumber(d), *kind, d, YAML::Dump(doc), base_path.string(), true});
    }
    return;
  }
  if (const Field file = (*map)["scenario"]) {
    const auto text = reader.String(file);
    if (!text) return;
    const fs::path path = ResolveScenarioPath(dir, *text);
    std::error_code error;
    if (!fs::is_regular_file(path, error)) {
      reader.Fail(file, "cannot read the scenario " + path.string());
      return;
    }
    YAML::Node document;
    try {
      document = YAML::Load(ReadText(path.string()));
    } catch (const YAML::Exception& e) {
      reader.Fail(file, "the scenario does not parse: " + std::string(e.what()));
      return;
    }
    const auto name = (*map)["name"] ? reader.String((*map)["name"]) : std::optional<std::string>(path.stem().string());
    const bool generated = document["scene"] && document["scene"].IsMap() && document["scene"]["generate"];
    if (generated) {
      reader.Fail(file, "a scenario that generates its world: give its generate map under worlds instead");
      return;
    }
    add({name.value_or(path.stem().string()), "scenario", kNaN, YAML::Dump(Unfurnished(document, false)),
         path.string(), false});
    return;
  }
  reader.Fail(item, "expected generate: {kind, difficulty, ...} or scenario: FILE");
}

}  // namespace

bool IsOutcomeStudyFile(const std::string& path) {
  try {
    const YAML::Node document = YAML::Load(ReadText(path));
    return document.IsMap() && document["mode"] && document["mode"].IsScalar() &&
           document["mode"].Scalar() == "outcomes";
  } catch (const YAML::Exception&) {
    return false;  // the detection reader reports it, with its line
  }
}

OutcomeStudyConfig LoadOutcomeStudyFile(const std::string& path, bool allow_large) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) throw InputError(path + ": cannot read the study file: no such file");
  YamlReader reader(path);
  const YAML::Node document = reader.Parse(ReadText(path));
  OutcomeStudyConfig study;
  study.source = path;
  const auto top = reader.Map(reader.Root(document),
                              {"proxsim_study", "mode", "base", "sets", "combine", "candidates", "strategies", "worlds",
                               "seeds", "target_success", "prices", "replay_files", "baselines", "cost", "tune"},
                              "a study map starting with 'proxsim_study: 1'");
  if (!top) throw InputError(reader.Problems());
  if (const auto version = reader.Count((*top)["proxsim_study"]); !version || *version != 1) {
    if (!(*top)["proxsim_study"]) reader.Fail((*top)["proxsim_study"], "expected proxsim_study: 1");
    else if (version) reader.Fail((*top)["proxsim_study"], "expected 1, the only study schema");
  }
  const fs::path dir = fs::path(path).parent_path();

  // the base: its robot, gait and timing for the generated worlds (checked by loading it)
  std::optional<YAML::Node> base;
  fs::path base_path;
  if (const Field field = (*top)["base"]) {
    if (const auto text = reader.String(field)) {
      base_path = ResolveScenarioPath(dir, *text);
      try {
        const Scenario scenario = LoadScenarioFile(base_path.string());
        if (!scenario.robot) reader.Fail(field, "the base has no robot: nothing would walk");
        base = YAML::Load(ReadText(base_path.string()));
      } catch (const InputError& e) {
        for (const std::string& problem : e.problems()) reader.Fail(field, "the base does not load: " + problem);
      }
    }
  }

  // the sets: listed, and/or combined from the best mountings of a detection study
  std::vector<std::pair<std::string, YAML::Node>> set_nodes;
  std::vector<Field> set_fields;
  if (const Field field = (*top)["sets"]) {
    const auto items = reader.List(field, "a list of sensor sets {name, sensors: [...]}");
    for (const Field& item : items.value_or(std::vector<Field>{})) {
      const auto one = reader.Map(item, {"name", "sensors"});
      if (!one) continue;
      const auto name = reader.String((*one)["name"]);
      if (!(*one)["name"]) reader.Fail(item, "expected a name");
      if (!reader.Require((*one)["sensors"], "the set's sensors, as a scenario lists them") || !name) continue;
      set_nodes.emplace_back(*name, (*one)["sensors"].node);
      set_fields.push_back((*one)["sensors"]);
    }
  }
  if (const Field field = (*top)["combine"]) {
    const auto one = reader.Map(field, {"from", "size", "top"});
    if (one) {
      const auto from = reader.String((*one)["from"]);
      if (!(*one)["from"]) reader.Fail(field, "expected from: a detection study's ranking.csv, or candidates");
      const auto size = reader.Count((*one)["size"]);
      if (!(*one)["size"]) reader.Fail(field, "expected size: the number of sensors in a set");
      if (size && *size < 1) reader.Fail((*one)["size"], "expected a set of at least 1 sensor");
      const std::size_t top_n = reader.Count((*one)["top"]).value_or(std::numeric_limits<std::size_t>::max());
      std::vector<Candidate> candidates;
      if (from && *from == "candidates") {
        if (!(*top)["candidates"]) reader.Fail(field, "from: candidates, but the study has no candidates section");
        else candidates = ReadStudyCandidates(reader, (*top)["candidates"], allow_large);
        if (candidates.size() > top_n) candidates.resize(top_n);
      } else if (from) {
        candidates = RankingCandidates(reader, (*one)["from"], ResolveScenarioPath(dir, *from), top_n);
      }
      if (size && *size >= 1 && !reader.HasProblems()) {
        const std::size_t before = set_nodes.size();
        CombineSets(reader, field, candidates, *size, set_nodes);
        for (std::size_t i = before; i < set_nodes.size(); ++i) set_fields.push_back(field);
      }
    }
  } else if ((*top)["candidates"]) {
    reader.Fail((*top)["candidates"], "candidates are combined into sets by combine: {from: candidates, size, top}");
  }
  if (!(*top)["sets"] && !(*top)["combine"]) reader.Fail((*top)["sets"], "expected sets, combine, or both: no set to study");
  if (set_nodes.size() > kMaxOutcomeSets) {
    reader.Fail((*top)["sets"], std::to_string(set_nodes.size()) + " sets; expected at most " +
                                    std::to_string(kMaxOutcomeSets));
    set_nodes.clear();
  }

  // each set read as a scenario's sensors; priced
  const std::map<std::string, PriceOverride> prices = ReadPrices(reader, (*top)["prices"]);
  std::set<std::string> set_names;
  for (std::size_t i = 0; i < set_nodes.size(); ++i) {
    SensorSet set;
    set.name = set_nodes[i].first;
    if (!set_names.insert(set.name).second) reader.Fail(set_fields[i], "set '" + set.name + "' appears twice");
    if (IsBaselineName(set.name))
      reader.Fail(set_fields[i], "set '" + set.name + "': a baseline's name (blind, oracle); give the set another");
    const Field sensors_field{set_nodes[i].second, set_fields[i].path, true};
    const std::vector<SensorConfig> sensors = ReadSensors(reader, sensors_field, true);
    if (set_nodes[i].second.IsSequence() && set_nodes[i].second.size() == 0)
      reader.Fail(sensors_field, "a set with no sensor: give at least one (a walk without sensors needs no study)");
    for (const SensorConfig& s : sensors) set.sensor_names.push_back(s.name);
    PriceSet(sensors, prices, set);
    set.sensors_yaml = FlowText(set_nodes[i].second);
    study.sets.push_back(set);
  }
  for (const auto& [key, price] : prices) {
    bool used = PartPriceOf(key).has_value() || SensorTypeFromName(key).has_value();
    for (const SensorSet& set : study.sets)
      for (const std::string& name : set.sensor_names) used |= name == key;
    if (!used) reader.Fail((*top)["prices"], "'" + key + "' is neither a part, a type, nor a sensor of any set");
  }

  // the baselines, after the sets: blind and oracle unless the study says otherwise
  if (const Field field = (*top)["baselines"]) {
    study.baselines.clear();
    if (const auto items = reader.List(field, "a list of baselines: [blind, oracle], or [] for none")) {
      for (const Field& item : *items) {
        const auto name = reader.String(item);
        if (!name) continue;
        if (!IsBaselineName(*name)) reader.Fail(item, "unknown baseline '" + *name + "' (expected blind or oracle)");
        else if (std::find(study.baselines.begin(), study.baselines.end(), *name) != study.baselines.end())
          reader.Fail(item, "baseline '" + *name + "' appears twice");
        else study.baselines.push_back(*name);
      }
    }
  }
  for (const std::string& name : study.baselines) study.sets.push_back(BaselineSet(name));

  // what failures cost, for the expected cost per run
  if (const Field field = (*top)["cost"]) {
    if (const auto one = reader.Map(field, {"runs_per_unit", "collision_usd", "fall_usd"})) {
      RunCosts& c = study.costs;
      c.runs_per_unit = reader.Number((*one)["runs_per_unit"], PositiveNumber("runs")).value_or(c.runs_per_unit);
      c.collision_usd = reader.Number((*one)["collision_usd"], NonNegativeNumber("USD")).value_or(c.collision_usd);
      c.fall_usd = reader.Number((*one)["fall_usd"], NonNegativeNumber("USD")).value_or(c.fall_usd);
    }
  }

  study.strategies = ReadOutcomeStrategies(reader, (*top)["strategies"], (*top)["tune"]);

  // the worlds: one map or a list of them; each with its seeds, or the study's
  const SeedSplit default_seeds = ReadSeedSplit(reader, (*top)["seeds"], {{}, {1}});
  std::set<std::string> family_names;
  if (const Field worlds = (*top)["worlds"]) {
    if (worlds.node.IsMap()) {
      ReadWorld(reader, worlds, base, base_path, dir, default_seeds, study, family_names);
    } else if (const auto items = reader.List(worlds, "a world {generate | scenario, seeds} or a list of them")) {
      if (items->empty()) reader.Fail(worlds, "expected at least one world, got an empty list");
      for (const Field& item : *items) ReadWorld(reader, item, base, base_path, dir, default_seeds, study, family_names);
    }
  } else {
    reader.Fail(worlds, "expected worlds: {generate: {kind, difficulty}, seeds} and/or scenario variants");
  }

  // tuning needs worlds to tune on, and worlds to test on that it never saw
  bool tuned = false;
  for (const StrategyChoice& s : study.strategies) tuned |= !s.tuned.empty();
  std::vector<bool> has_train(study.families.size(), false), has_test(study.families.size(), false);
  for (const OutcomeStudyConfig::Job& job : study.jobs) (job.train ? has_train : has_test)[job.family] = true;
  for (std::size_t f = 0; f < study.families.size(); ++f) {
    if (tuned && !has_train[f])
      reader.Fail((*top)["worlds"], "world '" + study.families[f].name +
                                        "': tune: chooses values on training seeds; give seeds: {train: [...], test: [...]}");
    if (!tuned && has_train[f])
      reader.Fail((*top)["worlds"], "world '" + study.families[f].name +
                                        "': training seeds, but nothing to tune (give tune: {strategy.parameter: [values]})");
    if (!has_test[f]) reader.Fail((*top)["worlds"], "world '" + study.families[f].name + "': no test seeds");
  }

  if (const Field field = (*top)["target_success"]) {
    study.target_success = reader.Number(field, NumberIn(0, 1)).value_or(study.target_success);
  }
  if (const Field field = (*top)["replay_files"]) study.replay_files = reader.Count(field).value_or(study.replay_files);

  const double runs = static_cast<double>(study.runs_per_job()) * static_cast<double>(study.jobs.size());
  if (!allow_large && runs > static_cast<double>(kMaxOutcomeRuns)) {
    reader.Fail((*top)["worlds"], std::to_string(study.sets.size()) + " sets x " +
                                      std::to_string(study.strategies.size()) + " strategies x " +
                                      std::to_string(study.jobs.size()) + " worlds = " + ConfigNumber(runs) +
                                      " runs; expected at most " + std::to_string(kMaxOutcomeRuns) +
                                      " (pass --allow-large to run it anyway)");
  }
  if (reader.HasProblems()) throw InputError(reader.Problems());
  return study;
}

std::vector<std::pair<std::string, std::vector<std::size_t>>> OutcomeStudyConfig::strategy_groups() const {
  std::vector<std::pair<std::string, std::vector<std::size_t>>> groups;
  for (std::size_t i = 0; i < strategies.size(); ++i) {
    const std::string& group = strategies[i].group.empty() ? strategies[i].label : strategies[i].group;
    if (groups.empty() || groups.back().first != group) groups.push_back({group, {}});
    groups.back().second.push_back(i);
  }
  return groups;
}

YAML::Node WorldNode(const OutcomeStudyConfig& study, std::size_t job) {
  const WorldFamily& family = study.families[study.jobs[job].family];
  const std::uint64_t seed = study.jobs[job].seed;
  YAML::Node doc = YAML::Load(family.document_yaml);
  doc["seed"] = seed;
  if (!family.generated) return doc;
  doc["scene"]["generate"]["seed"] = seed;
  return GeneratedScenarioNode(doc, family.source);
}

std::string WorldText(const OutcomeStudyConfig& study, std::size_t job) {
  const WorldFamily& family = study.families[study.jobs[job].family];
  const YAML::Node doc = WorldNode(study, job);
  if (!family.generated) return YAML::Dump(doc);
  return "# generated by proxsim from " + QuotedForComment(family.source) + "\n" + YAML::Dump(doc) + "\n";
}

YAML::Node RunNodeFromWorld(YAML::Node&& world, const SensorSet* set, const StrategyChoice* strategy, bool reference) {
  YAML::Node doc = std::move(world);
  if (set != nullptr) doc["sensors"] = YAML::Load(set->sensors_yaml);
  if (strategy != nullptr && !strategy->yaml.empty()) doc["robot"]["strategy"] = YAML::Load(strategy->yaml);
  if (set != nullptr && set->baseline == kOracleBaseline) GiveOraclePerception(doc);
  if (reference) {
    doc["sensors"] = YAML::Load("[]");  // blind
    doc["robot"]["gait"]["unsafe_steps"] = "refuse";
    doc["robot"]["gait"]["footholds"] = "truth";  // legs that feel the true ground, whatever the runs plan on
    doc["robot"]["on_collision"] = "stop";
  }
  return doc;
}

YAML::Node RunNodeFromWorld(const YAML::Node& world, const SensorSet* set, const StrategyChoice* strategy,
                            bool reference) {
  return RunNodeFromWorld(YAML::Clone(world), set, strategy, reference);
}

std::string RunTextFromWorld(const std::string& world_text, const SensorSet* set, const StrategyChoice* strategy,
                             bool reference) {
  return YAML::Dump(RunNodeFromWorld(YAML::Load(world_text), set, strategy, reference)) + "\n";
}

std::string RunScenarioText(const OutcomeStudyConfig& study, std::size_t job, std::size_t set, std::size_t strategy) {
  return RunTextFromWorld(WorldText(study, job), &study.sets[set], &study.strategies[strategy], false);
}


}  // namespace proxsim
