// The readings' columns exist in one place (output/readings_columns.cc): the
// CSV's header, columns.json and the table in docs/outputs.md are made from
// it, and a real run's fields are what it says they are.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "cli_helpers.h"
#include "output/readings_columns.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::ReadCsv;
using testing::ReadFile;
using testing::RunProxsim;

TEST(ReadingsColumnsTest, DocsHoldTheTableTheCliPrints) {
  testing::ExpectCliTableInDocs("columns", ReadingsColumnsMarkdown(), "outputs.md",
                                 "<!-- readings columns: the output of `proxsim columns` -->\n",
                                 "<!-- end of readings columns -->");
}

TEST(ReadingsColumnsTest, EveryColumnHasANameATypeAndAMeaning) {
  std::set<std::string> names;
  for (const ReadingsColumn& column : ReadingsColumns()) {
    EXPECT_TRUE(names.insert(column.name).second) << "twice: " << column.name;
    EXPECT_NE(std::string(column.meaning), "") << column.name;
    const bool coded = column.type == ColumnType::kCode32 || column.type == ColumnType::kCode8;
    EXPECT_EQ(coded, column.codes != ColumnCodes::kNone) << column.name;
  }
}

// The paper's run: every field of readings.csv is of its column's type, every
// code's name is in columns.json's list for it.
TEST(ReadingsColumnsTest, ARunsFieldsAreWhatColumnsJsonSays) {
  const fs::path out = FreshDir("readings_columns");
  const auto run = RunProxsim("run --no-report --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const testing::Csv csv = ReadCsv(out / "readings.csv");
  const auto document = nlohmann::json::parse(ReadFile(out / "columns.json"));

  std::vector<std::string> header;
  for (const auto& column : document["columns"]) header.push_back(column["name"].get<std::string>());
  EXPECT_EQ(csv.header, header);
  EXPECT_EQ(ReadFile(out / "readings.csv").substr(0, ReadingsCsvHeader().size() + 1), ReadingsCsvHeader() + "\n");
  EXPECT_EQ(document["statuses"].front(), "ok");
  EXPECT_EQ(document["statuses"].size(), 8u);
  EXPECT_EQ(document["support_legs"], nlohmann::json({"left", "right", "double"}));
  EXPECT_EQ(document["types"], nlohmann::json({"ideal", "laser", "ultrasonic", "reflectance", "lookup", "multizone"}));

  ASSERT_GT(csv.rows.size(), 1000u);
  std::size_t empty_codes = 0, empty_floats = 0;
  for (const auto& column : document["columns"]) {
    const std::string name = column["name"], dtype = column["dtype"];
    for (const auto& row : csv.rows) {
      const std::string& field = row.at(name);
      if (column.contains("codes")) {
        const auto& names = document[column["codes"].get<std::string>()];
        if (field.empty()) ++empty_codes;
        else EXPECT_NE(std::find(names.begin(), names.end(), field), names.end()) << name << " = " << field;
      } else if (dtype == "<f8") {
        if (field.empty()) ++empty_floats;
        else EXPECT_NO_THROW((void)std::stod(field)) << name << " = " << field;
      } else if (dtype == "|b1") {
        EXPECT_TRUE(field == "0" || field == "1") << name << " = " << field;
      } else {
        ASSERT_EQ(dtype, "<i4") << name;
        EXPECT_EQ(std::to_string(std::stoi(field)), field) << name;
      }
    }
  }
  // the paper's run has misses (no object, no hit point) and no lookup sensor (no output)
  EXPECT_GT(empty_codes, 0u);
  EXPECT_GT(empty_floats, 0u);
  fs::remove_all(out);
}

}  // namespace
}  // namespace proxsim
