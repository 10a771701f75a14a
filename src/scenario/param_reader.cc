#include "scenario/param_reader.h"

#include "core/nearest_key.h"

namespace proxsim {

std::optional<ParamValue> ReadParamValue(YamlReader& reader, const Field& field, const ParamDescription& param) {
  switch (param.type) {
    case ParamType::kNumber:
      if (param.whole) {
        if (const auto count = reader.Count(field)) return ParamValue(static_cast<double>(*count));
        return std::nullopt;
      }
      if (const auto number = reader.Number(field, AnyNumber())) return ParamValue(*number);
      return std::nullopt;
    case ParamType::kFlag:
      if (const auto flag = reader.Bool(field)) return ParamValue(*flag);
      return std::nullopt;
    case ParamType::kText:
      if (const auto text = reader.String(field)) return ParamValue(*text);
      return std::nullopt;
    case ParamType::kChoice: {
      const auto word = reader.String(field);
      if (!word) return std::nullopt;
      for (const std::string& choice : param.choices)
        if (*word == choice) return ParamValue(*word);
      std::string all;
      for (std::size_t i = 0; i < param.choices.size(); ++i) {
        const bool glossed = i < param.choice_glosses.size() && !param.choice_glosses[i].empty();
        all += (i == 0 ? "" : i + 1 == param.choices.size() ? " or " : ", ") + param.choices[i] +
               (glossed ? " (" + param.choice_glosses[i] + ")" : "");
      }
      const auto nearest = NearestKey(*word, param.choices);
      reader.Fail(field, "expected " + all + ", got '" + *word + "'" +
                             (nearest ? " (did you mean '" + *nearest + "'?)" : ""));
      return std::nullopt;
    }
    case ParamType::kNames: {
      const auto items = reader.List(field, "a list of names");
      if (!items) return std::nullopt;
      std::vector<std::string> names;
      bool good = true;
      for (const Field& item : *items) {
        if (const auto name = reader.String(item)) {
          names.push_back(*name);
        } else {
          good = false;
        }
      }
      if (!good) return std::nullopt;
      return ParamValue(names);
    }
  }
  return std::nullopt;
}

void ReportAtKeys(YamlReader& reader, const MapView& map, const std::vector<std::string>& problems) {
  for (const std::string& problem : problems) {
    const std::size_t colon = problem.find(": ");
    const std::string key = colon == std::string::npos ? "" : problem.substr(0, colon);
    if (!key.empty() && map.Has(key)) {
      reader.Fail(map[key], problem.substr(colon + 2));
    } else {
      reader.Fail(map.field(), problem);
    }
  }
}

}  // namespace proxsim
