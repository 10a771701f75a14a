#include "study/study_shard.h"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "study/study_jobs.h"

namespace proxsim {

namespace {

using nlohmann::json;

// a whole number >= 0 written in decimal digits only ("+1", "1.0", " 1" are not)
std::optional<std::size_t> WholeNumber(const std::string& text) {
  std::size_t value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

// one of the array's variables, read as a whole number
std::optional<std::size_t> SlurmNumber(const EnvironmentLookup& environment, const char* name, bool required) {
  const char* value = environment(name);
  if (value == nullptr) {
    if (!required) return std::nullopt;
    throw InputError(std::string("--shard slurm: ") + name +
                     " is not set: expected to run as a task of a Slurm job array (sbatch --array=1-N); "
                     "outside one, give --shard i/N");
  }
  const std::optional<std::size_t> number = WholeNumber(value);
  if (!number)
    throw InputError(std::string("--shard slurm: ") + name + "='" + value + "': expected a whole number >= 0");
  return number;
}

StudySlice SliceFromSlurm(const EnvironmentLookup& environment) {
  const std::size_t id = *SlurmNumber(environment, "SLURM_ARRAY_TASK_ID", true);
  const std::size_t min = *SlurmNumber(environment, "SLURM_ARRAY_TASK_MIN", true);
  const std::size_t count = *SlurmNumber(environment, "SLURM_ARRAY_TASK_COUNT", true);
  // Slurm sets the step to 1 for a list (--array=1,4,9); then MAX tells it from a range
  const std::size_t step = SlurmNumber(environment, "SLURM_ARRAY_TASK_STEP", false).value_or(1);
  const std::optional<std::size_t> max = SlurmNumber(environment, "SLURM_ARRAY_TASK_MAX", false);
  const std::string values = "SLURM_ARRAY_TASK_ID=" + std::to_string(id) + ", _MIN=" + std::to_string(min) +
                             ", _COUNT=" + std::to_string(count) + ", _STEP=" + std::to_string(step) +
                             (max ? ", _MAX=" + std::to_string(*max) : std::string());
  if (count == 0 || step == 0) throw InputError("--shard slurm: " + values + ": expected a count and a step >= 1");
  const bool one_range = id >= min && (id - min) % step == 0 && (id - min) / step < count &&
                         (!max || *max == min + (count - 1) * step);
  if (!one_range) {
    throw InputError("--shard slurm: " + values +
                     ": the array's task ids are not one range A-B or A-B:S (a list such as --array=1,4,9?); "
                     "give the array as a range, or --shard i/N");
  }
  return {(id - min) / step + 1, count};
}

std::string FileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace

StudySlice ParseStudySlice(const std::string& text, const EnvironmentLookup& environment) {
  if (text == "slurm") return SliceFromSlurm(environment);
  const std::size_t slash = text.find('/');
  const bool split = slash != std::string::npos;
  const std::optional<std::size_t> index = split ? WholeNumber(text.substr(0, slash)) : std::nullopt;
  const std::optional<std::size_t> count = split ? WholeNumber(text.substr(slash + 1)) : std::nullopt;
  if (!index || !count || *count == 0 || *index == 0 || *index > *count) {
    throw InputError("--shard '" + text +
                     "': expected i/N, slice i of N counted from 1 (1/3, 2/3, 3/3), or slurm (a job array's task)");
  }
  return {*index, *count};
}

void WriteSliceRecord(const std::string& folder, const SliceRecord& record) {
  const json out = {{"proxsim_study_slice", 1},
                    {"slice", record.slice.Name()},
                    {"index", record.slice.index},
                    {"count", record.slice.count},
                    {"study_digest", record.study_digest},
                    {"study_file", record.study_file},
                    {"study_file_given", record.study_file_given},
                    {"mode", record.mode},
                    {"jobs", record.jobs},
                    {"slice_jobs", record.slice.JobsOf(record.jobs)}};
  WriteFileAtomically((std::filesystem::path(folder) / kSliceRecordName).string(), out.dump(2) + "\n");
}

SliceRecord ReadSliceRecord(const std::string& dir) {
  const std::filesystem::path path = std::filesystem::path(dir) / kSliceRecordName;
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(dir + ": not a study slice (no " + kSliceRecordName +
                     "); expected a folder written by `proxsim study FILE --shard i/N --out DIR`");
  }
  const json in = json::parse(FileBytes(path.string()), nullptr, false);
  const auto text = [&](const char* key) {
    return in.is_object() && in.contains(key) && in[key].is_string() ? in[key].get<std::string>() : std::string();
  };
  const auto count = [&](const char* key) -> std::size_t {
    return in.is_object() && in.contains(key) && in[key].is_number_unsigned() ? in[key].get<std::size_t>() : 0;
  };
  SliceRecord record{.dir = dir,
                     .slice = {count("index"), count("count")},
                     .study_digest = text("study_digest"),
                     .study_file = text("study_file"),
                     .study_file_given = text("study_file_given"),
                     .mode = text("mode"),
                     .jobs = count("jobs")};
  if (record.slice.count == 0 || record.slice.index == 0 || record.slice.index > record.slice.count ||
      record.study_digest.empty() || record.study_file.empty() || record.study_file_given.empty() ||
      record.mode.empty()) {
    throw InputError(path.string() +
                     ": expected a slice record (index, count, study_digest, study_file, study_file_given, mode, "
                     "jobs), as "
                     "`proxsim study --shard` writes it");
  }
  return record;
}

std::string StudyDigest(const std::string& fingerprint, const std::vector<std::string>& files) {
  // each file's length before its bytes: no two lists of files hash alike by
  // concatenation. Bytes, not paths: slices started from other folders (a
  // relative path given from elsewhere) are one study. A source that is no
  // file (builtin:NAME) counts by its name.
  std::string identity = fingerprint + "\n";
  for (const std::string& file : files) {
    std::error_code error;
    const std::string bytes = std::filesystem::is_regular_file(file, error) ? FileBytes(file) : "=" + file;
    identity += std::to_string(bytes.size()) + ":" + bytes;
  }
  return StudyFingerprint("study", identity);
}

}  // namespace proxsim
