#include "study/outcome_strategies.h"

#include <map>
#include <set>

#include "scenario/scenario_sections.h"

namespace proxsim {

namespace {

// One strategy of the study file, before tuning.
struct Given {
  std::string name;   // stop, circumvent, or none
  YAML::Node node;    // its map; null for none
  Field field;
};

// "k=v,k=v" of a strategy map's parameters (its name left out)
std::string ParametersText(const YAML::Node& node) {
  std::string text;
  for (const auto& entry : node) {
    const std::string key = entry.first.Scalar();
    if (key == "name") continue;
    const std::string value = entry.second.IsScalar() ? entry.second.Scalar() : FlowText(entry.second);
    text += (text.empty() ? "" : ",") + key + "=" + value;
  }
  return text;
}

// The tune: map as (strategy name, parameter, field of its values) in the file's order.
struct TuneKey {
  std::string strategy, parameter;
  Field values;
};

std::vector<TuneKey> ReadTune(YamlReader& reader, const Field& tune, const std::vector<Given>& given) {
  std::vector<TuneKey> keys;
  if (!tune) return keys;
  if (!tune.node.IsMap() || tune.node.size() == 0) {
    reader.Fail(tune, "expected a map of strategy.parameter: [candidate values], e.g. {stop.min_height_m: [0.03, 0.05]}");
    return keys;
  }
  for (const auto& entry : tune.node) {
    const std::string key = entry.first.Scalar();
    const Field values{entry.second, JoinPath(tune.path, key), true};
    const std::size_t dot = key.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == key.size() || key.find('.', dot + 1) != std::string::npos) {
      reader.Fail(values, "expected a key strategy.parameter (e.g. stop.min_height_m)");
      continue;
    }
    TuneKey one{key.substr(0, dot), key.substr(dot + 1), values};
    if (one.parameter == "name") {
      reader.Fail(values, "a strategy's name is not a parameter to tune: list each strategy in strategies");
      continue;
    }
    bool known = false;
    for (const Given& g : given) known |= g.name == one.strategy && g.node.IsMap();
    if (!known) {
      reader.Fail(values, "no strategy named '" + one.strategy + "' in strategies to tune");
      continue;
    }
    if (!values.node.IsSequence() || values.node.size() == 0) {
      reader.Fail(values, "expected a list of candidate values, got " + DescribeNode(values.node));
      continue;
    }
    std::set<std::string> seen;
    bool good = true;
    for (const auto& value : values.node) {
      if (!value.IsScalar()) {
        reader.Fail(values, "expected candidate values that are numbers or words, got " + DescribeNode(value));
        good = false;
      } else if (!seen.insert(value.Scalar()).second) {
        reader.Fail(values, "candidate value " + value.Scalar() + " appears twice");
        good = false;
      }
    }
    if (!good) continue;
    // each candidate value checked once, on each strategy it tunes: a bad
    // parameter or value is reported with the key that gave it
    for (const Given& g : given) {
      if (g.name != one.strategy || !g.node.IsMap()) continue;
      for (const auto& value : values.node) {
        YAML::Node variant = YAML::Clone(g.node);
        variant[one.parameter] = YAML::Clone(value);
        ReadStrategy(reader, Field{variant, JoinPath(tune.path, one.strategy), true});
      }
    }
    keys.push_back(one);
  }
  return keys;
}

}  // namespace

std::string FlowText(const YAML::Node& node) {
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  return out.c_str();
}

std::vector<StrategyChoice> ReadOutcomeStrategies(YamlReader& reader, const Field& strategies, const Field& tune) {
  // the strategies as the file gives them
  std::vector<Given> given;
  if (!strategies) {
    given.push_back({"stop", YAML::Load("{name: stop}"), strategies});
  } else if (const auto items = reader.List(strategies, "a list of strategies: {name: stop | circumvent, ...} or none")) {
    if (items->empty()) reader.Fail(strategies, "expected at least one strategy, got an empty list");
    for (const Field& item : *items) {
      if (item.node.IsScalar()) {
        const std::string name = item.node.Scalar();
        if (name.find(':') != std::string::npos) {
          reader.Fail(item, "'" + name + "': a Python strategy (module:Class) runs from Python (docs/strategies.md); "
                                         "a study runs the built-in ones: {name: stop}, {name: circumvent} or none");
        } else if (name != "none") {
          reader.Fail(item, "expected a strategy map {name: stop | circumvent, ...} or none, got '" + name + "'");
        } else {
          given.push_back({"none", YAML::Node(), item});
        }
      } else if (ReadStrategy(reader, item)) {
        given.push_back({item.node["name"].Scalar(), item.node, item});
      }
    }
  }

  // the groups' labels: the name, with the parameters where the name repeats
  std::map<std::string, int> uses;
  for (const Given& g : given) ++uses[g.name];
  std::set<std::string> labels;
  std::vector<std::string> group_labels;
  for (const Given& g : given) {
    std::string label = g.name;
    if (uses[g.name] > 1 && g.node.IsMap()) {
      const std::string parameters = ParametersText(g.node);
      if (!parameters.empty()) label += "[" + parameters + "]";
    }
    if (!labels.insert(label).second) reader.Fail(g.field, "strategy " + label + " appears twice");
    group_labels.push_back(label);
  }

  // each group's variants: the product of its tuned parameters' candidate values
  const std::vector<TuneKey> keys = ReadTune(reader, tune, given);
  std::vector<StrategyChoice> variants;
  for (std::size_t i = 0; i < given.size(); ++i) {
    const Given& g = given[i];
    std::vector<const TuneKey*> mine;
    for (const TuneKey& key : keys)
      if (key.strategy == g.name && g.node.IsMap()) mine.push_back(&key);
    std::size_t count = 1;
    for (const TuneKey* key : mine) count *= key->values.node.size();
    if (variants.size() + count > kMaxStrategyVariants) {
      reader.Fail(tune, std::to_string(variants.size() + count) + " strategy variants; expected at most " +
                            std::to_string(kMaxStrategyVariants));
      return variants;
    }
    for (std::size_t v = 0; v < count; ++v) {
      StrategyChoice choice;
      choice.group = group_labels[i];
      if (!g.node.IsMap()) {
        choice.label = choice.group;
        variants.push_back(choice);
        continue;
      }
      YAML::Node node = YAML::Clone(g.node);
      // the variant's index as digits, the last key's fastest
      std::size_t rest = v, stride = count;
      for (const TuneKey* key : mine) {
        stride /= key->values.node.size();
        const YAML::Node value = key->values.node[rest / stride];
        rest %= stride;
        node[key->parameter] = YAML::Clone(value);
        choice.tuned += (choice.tuned.empty() ? "" : ",") + key->parameter + "=" + value.Scalar();
      }
      choice.label = choice.tuned.empty() ? choice.group : choice.group + "[" + choice.tuned + "]";
      choice.yaml = FlowText(node);
      variants.push_back(choice);
    }
  }
  return variants;
}

}  // namespace proxsim
