// Names in output files, whatever the user called things (issue 23: a comma
// in a sensor's name shifted every column of readings.csv).
//
// The choice: names may hold any printable UTF-8 (commas and quotes
// included); the scenario parser refuses control characters and invalid
// UTF-8 (NamingProblem), so the JSON files, written by nlohmann::json, are
// always valid; and CSV fields are quoted per RFC 4180 where needed
// (AppendCsvField), which Python's csv module, NumPy and spreadsheets read.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace proxsim {

/// Appends `field` to a CSV line: as it is, or in double quotes with inner
/// quotes doubled when it holds a comma, a quote, CR or LF (RFC 4180).
void AppendCsvField(std::string& line, std::string_view field);

/// `field` as one CSV field (see AppendCsvField).
std::string CsvField(std::string_view field);

/// Why `name` cannot name a sensor, an object or a scene: empty when it can
/// (printable UTF-8 of at least one byte); else e.g. "a control character (byte 0x0a at 4)".
std::string NamingProblem(std::string_view name);

/// A sensor's folder under zones/ and echoes/: its name when that is a plain
/// file name (letters, digits, '_', '-', '.'; not "." or ".."), else
/// "sensor_INDEX". Two sensors whose folders would be the same (`sensor_1`
/// and a sensor 1 named `..`) are refused by the scenario parser.
std::string SensorFolderName(const std::string& name, std::size_t index);

/// `text` in double quotes, with backslash, quote and every control byte
/// escaped (\n, \r, \t, \xNN): a user's string safe inside a comment line
/// of a written YAML file (a newline in it could otherwise start a key).
std::string QuotedForComment(std::string_view text);

/// The fields of one CSV record as proxsim writes them (RFC 4180: a field in
/// double quotes may hold commas and doubled quotes; a Windows line end dropped).
std::vector<std::string> SplitQuotedCsvLine(const std::string& line);

/// The cells of one line of a plain CSV file (no quoting), each trimmed of
/// spaces, tabs and a Windows line end; a trailing comma gives an empty last cell.
std::vector<std::string> SplitCsvLine(const std::string& line);

/// Parses the whole of `text` as a finite number (std::from_chars: the same on every machine).
bool ParseFiniteNumber(const std::string& text, double* out);

}  // namespace proxsim
