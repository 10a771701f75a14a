#include "study/study_merge.h"

#include <algorithm>
#include <filesystem>
#include <memory>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/output_folder.h"

namespace proxsim {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// the first few job indices of a list, for a message
std::string JobList(const std::vector<std::size_t>& jobs) {
  std::string text;
  for (std::size_t i = 0; i < jobs.size() && i < 5; ++i) text += (i > 0 ? ", " : "") + std::to_string(jobs[i]);
  return jobs.size() > 5 ? text + ", … (" + std::to_string(jobs.size()) + " in all)" : text;
}

// the folder as one path, whatever way it was named (a link, "a/../b")
fs::path Resolved(const std::string& dir) {
  std::error_code error;
  return fs::weakly_canonical(fs::absolute(dir), error);
}

}  // namespace

std::vector<SliceRecord> ReadStudySlices(const std::vector<std::string>& dirs) {
  if (dirs.empty()) throw InputError("study merge: no slice folder given; expected DIR... of `proxsim study --shard`");
  std::vector<std::string> problems;
  std::vector<SliceRecord> records;
  for (const std::string& dir : dirs) {
    try {
      records.push_back(ReadSliceRecord(dir));
    } catch (const InputError& error) {
      problems.insert(problems.end(), error.problems().begin(), error.problems().end());
    }
  }
  if (!problems.empty()) throw InputError(problems);

  // one study, cut one way: the first folder sets both
  const SliceRecord& first = records.front();
  for (const SliceRecord& r : records) {
    if (r.study_digest != first.study_digest) {
      problems.push_back(r.dir + ": slice " + r.slice.Name() + " of another study (" + r.study_file + ", digest " +
                         r.study_digest + "; " + first.dir + " is of " + first.study_file + ", digest " +
                         first.study_digest + ")");
    } else if (r.slice.count != first.slice.count) {
      problems.push_back(r.dir + ": slice " + r.slice.Name() + ", but " + first.dir + " is slice " +
                         first.slice.Name() + ": the study was cut into " + std::to_string(first.slice.count) +
                         " slices there; give the slices of one cut");
    }
  }
  if (!problems.empty()) throw InputError(problems);

  // every slice once
  std::vector<std::vector<std::string>> by_slice(first.slice.count);
  std::vector<fs::path> seen;
  for (const SliceRecord& r : records) {
    by_slice[r.slice.index - 1].push_back(r.dir);
    const fs::path path = Resolved(r.dir);
    for (const fs::path& other : seen)
      if (other == path) problems.push_back(r.dir + ": the same folder given twice");
    seen.push_back(path);
  }
  for (std::size_t i = 0; i < by_slice.size(); ++i) {
    const StudySlice slice{i + 1, first.slice.count};
    if (by_slice[i].empty()) {
      problems.push_back("slice " + slice.Name() + " is missing (" + std::to_string(slice.JobsOf(first.jobs)) +
                         " of the study's " + std::to_string(first.jobs) + " jobs): give its folder, or run it with " +
                         "`proxsim study " + first.study_file + " --shard " + slice.Name() + " --out DIR`");
    } else if (by_slice[i].size() > 1) {
      std::string folders;
      for (const std::string& dir : by_slice[i]) folders += (folders.empty() ? "" : ", ") + dir;
      problems.push_back("slice " + slice.Name() + " is duplicated: given " + std::to_string(by_slice[i].size()) +
                         " times (" + folders + "); give each slice once");
    }
  }
  if (!problems.empty()) throw InputError(problems);
  std::ranges::sort(records, {}, [](const SliceRecord& r) { return r.slice.index; });
  return records;
}

std::map<std::size_t, json> MergeStudySlices(const JobSet& set, const std::vector<SliceRecord>& slices,
                                             const StudyOptions& options) {
  const SliceRecord& first = slices.front();
  if (set.digest != first.study_digest) {
    throw InputError(first.study_file + ": the study (or a scenario file it reads) changed since its slices ran: " +
                     "its digest is now " + set.digest + ", the slices' " + first.study_digest +
                     "; run the slices again, or restore the file");
  }

  // each slice's journal, held against a slice still writing into it, complete
  const fs::path out = Resolved(options.out_dir);
  std::vector<std::unique_ptr<OutputFolder>> held;
  std::vector<std::string> problems;
  std::map<std::size_t, json> lines;
  for (const SliceRecord& r : slices) {
    if (Resolved(r.dir) == out) {
      problems.push_back("--out " + options.out_dir + ": it is slice " + r.slice.Name() +
                         "'s folder; give the merged study a folder of its own");
      continue;
    }
    held.push_back(std::make_unique<OutputFolder>(
        r.dir, ClaimOptions{.command = "study merge", .create = false, .check_contents = false}));
    const fs::path journal = fs::path(r.dir) / "journal.jsonl";
    std::error_code error;
    if (!fs::is_regular_file(journal, error)) {
      problems.push_back(r.dir + ": slice " + r.slice.Name() + " has no journal.jsonl (it did not start?)");
      continue;
    }
    try {
      const std::map<std::size_t, std::string> mine =
          ReadJournal(journal.string(), JournalHeader(set.fingerprint, r.slice), set.check, r.slice);
      std::vector<std::size_t> missing;
      for (std::size_t job = r.slice.index - 1; job < set.jobs; job += r.slice.count)
        if (!mine.contains(job)) missing.push_back(job);
      if (!missing.empty()) {
        problems.push_back(r.dir + ": slice " + r.slice.Name() + " is unfinished: " +
                           std::to_string(missing.size()) + " of its " + std::to_string(r.slice.JobsOf(set.jobs)) +
                           " jobs not done (jobs " + JobList(missing) + "); finish it with `proxsim study " +
                           r.study_file + " --shard " + r.slice.Name() + " --out " + r.dir + " --resume`");
      }
      for (const auto& [job, line] : mine) lines[job] = json::parse(line);
    } catch (const InputError& error) {
      problems.insert(problems.end(), error.problems().begin(), error.problems().end());
    }
  }
  if (!problems.empty()) throw InputError(problems);
  // the slices hold disjoint jobs (each line checked to be its slice's) and
  // none is missing: every job once
  if (lines.size() != set.jobs) throw std::logic_error("study merge: the slices' jobs do not add up to the study's");

  // the merged folder: the study's journal as a finished single run leaves it
  auto folder = std::make_shared<OutputFolder>(
      options.out_dir, ClaimOptions{.command = "study", .force = options.force, .ours = "journal.jsonl"});
  if (options.folder != nullptr) *options.folder = folder;
  std::string text = JournalHeader(set.fingerprint, std::nullopt).dump() + "\n";
  for (const auto& [job, line] : lines) text += line.dump() + "\n";
  WriteFileAtomically((fs::path(folder->path()) / "journal.jsonl").string(), text);
  return lines;
}

}  // namespace proxsim
