// Helpers for tests that drive the real `proxsim` binary (or a script on its
// output): run a command line, read a CSV back by column name.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace proxsim::testing {

/// Unitree's H1 description, read in place beside the project (../shared/robots).
inline const std::filesystem::path kH1Dir =
    std::filesystem::path(PROXSIM_SOURCE_DIR) / ".." / "shared" / "robots" / "h1_description";

struct CommandResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr together
};

/// Runs a command line through the shell, stderr with stdout.
inline CommandResult RunCommand(const std::string& command_line) {
  const std::string command = command_line + " 2>&1";
  CommandResult result;
  std::FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

/// Runs `proxsim ARGS` (the binary under test) through the shell.
inline CommandResult RunProxsim(const std::string& args) {
  return RunCommand(std::string(PROXSIM_BINARY) + " " + args);
}

/// `proxsim ARGS` under `timeout -s KILL LIMIT_S`: an overrun (a hang) ends
/// in exit 137 through the shell, a failure rather than a hung suite. The
/// default is far above the seconds any bounded case takes.
inline CommandResult RunProxsimWithin(const std::string& args, int limit_s = 60) {
  return RunCommand("timeout -s KILL " + std::to_string(limit_s) + " " + PROXSIM_BINARY + " " + args);
}

/// A fresh, empty folder under the system's temporary directory, private to
/// this process: CTest runs each test in a process of its own, in parallel.
inline std::filesystem::path FreshDir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("proxsim_test_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

// Writes `yaml` as a scenario in a fresh folder `name`, runs it without the
// report (expecting success) and returns its output folder.
inline std::filesystem::path RunScenarioYaml(const std::string& name, const std::string& yaml) {
  const std::filesystem::path dir = FreshDir(name);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "scenario.yaml") << yaml;
  const auto run = RunProxsim("run " + (dir / "scenario.yaml").string() + " --no-report --out " + (dir / "out").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return dir / "out";
}

// `proxsim validate` on `yaml` written as a scenario in a fresh folder `name`,
// expecting exit code 2 (bad input) and every one of `expected` in its output.
inline void ExpectRefused(const std::string& name, const std::string& yaml, const std::vector<std::string>& expected) {
  const std::filesystem::path dir = FreshDir(name);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "scenario.yaml") << yaml;
  const auto run = RunProxsim("validate " + (dir / "scenario.yaml").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  for (const std::string& text : expected) EXPECT_NE(run.output.find(text), std::string::npos) << text << "\n" << run.output;
}

inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The text of a docs page between two marker lines (`begin` includes its
/// newline); "<missing markers>" when either is absent. Tables that a command
/// prints are kept in the docs between such markers and compared by tests.
inline std::string DocsBetweenMarkers(const std::filesystem::path& page, const std::string& begin,
                                      const std::string& end) {
  const std::string docs = ReadFile(page);
  const auto from = docs.find(begin), to = docs.find(end);
  if (from == std::string::npos || to == std::string::npos || to < from) return "<missing markers>";
  return docs.substr(from + begin.size(), to - from - begin.size());
}

/// `proxsim ARGS` prints `table`, and docs page `page` holds it between the
/// markers `begin` (with its newline) and `end`.
inline void ExpectCliTableInDocs(const std::string& args, const std::string& table, const std::string& page,
                                 const std::string& begin, const std::string& end) {
  const auto printed = RunProxsim(args);
  ASSERT_EQ(printed.exit_code, 0) << printed.output;
  EXPECT_EQ(printed.output, table);
  EXPECT_EQ(DocsBetweenMarkers(std::filesystem::path(PROXSIM_SOURCE_DIR) / "docs" / page, begin, end), table)
      << "docs/" << page << ": replace the table between the markers with `proxsim " << args << "`'s output";
}

/// A CSV file as rows of named fields.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
};

/// One CSV record as its fields, RFC 4180: a field in double quotes may hold
/// commas and doubled quotes (proxsim quotes names that need it).
inline std::vector<std::string> SplitCsvLine(const std::string& text) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

inline Csv ReadCsv(const std::filesystem::path& path) {
  Csv csv;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return csv;
  csv.header = SplitCsvLine(line);
  while (std::getline(in, line)) {
    const auto fields = SplitCsvLine(line);
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < csv.header.size() && i < fields.size(); ++i) row[csv.header[i]] = fields[i];
    csv.rows.push_back(std::move(row));
  }
  return csv;
}

/// The rows of one sensor, in time order.
inline std::vector<std::map<std::string, std::string>> RowsOf(const Csv& csv, const std::string& sensor) {
  std::vector<std::map<std::string, std::string>> rows;
  for (const auto& row : csv.rows) {
    if (row.at("sensor") == sensor) rows.push_back(row);
  }
  return rows;
}

}  // namespace proxsim::testing
