// A study cut into slices (docs/studies.md "Slices and Slurm job arrays"):
// `proxsim study FILE --shard i/N` runs the i-th of N disjoint slices of the
// study's jobs into a folder of its own, with its own journal and a record of
// which study and which slice it holds (OUT/slice.json); `proxsim study merge`
// (study_merge.h) puts the slices back together.
//
// Slices are numbered from 1 (`--shard 1/3`, `2/3`, `3/3`). Slice i holds the
// jobs j with j mod N = i - 1: deterministic, disjoint, covering every job
// once, and balanced even where the jobs' cost grows with their index (an
// outcome study's worlds come family by family, easy ones first).
//
// `--shard slurm` takes the slice from a Slurm job array's environment: the
// task's position in the array, counted from 1 whatever range `--array`
// gives (`--array=0-2` and `--array=1-3` both make slices 1/3, 2/3, 3/3; a
// step, `--array=0-10:5`, is followed).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace proxsim {

/// One slice of a study's jobs: slice `index` of `count`, 1-based.
struct StudySlice {
  std::size_t index = 1;  ///< 1 .. count
  std::size_t count = 1;  ///< how many slices the study is cut into, >= 1
  /// Whether job `job` (0-based, the study's job order) belongs to this slice.
  bool Holds(std::size_t job) const { return job % count == index - 1; }
  /// How many of a study's `jobs` jobs this slice holds.
  std::size_t JobsOf(std::size_t jobs) const { return jobs / count + (jobs % count >= index ? 1 : 0); }
  /// "2/3", as `--shard` takes it.
  std::string Name() const { return std::to_string(index) + "/" + std::to_string(count); }
};

/// Reads an environment variable; nullptr when unset (std::getenv, or a test's map).
using EnvironmentLookup = std::function<const char*(const char* name)>;

/// Parses `--shard`: "i/N" with 1 <= i <= N, or "slurm" (the slice from
/// SLURM_ARRAY_TASK_ID, _MIN, _COUNT and, when set, _STEP and _MAX). Throws
/// InputError naming what was expected, or the Slurm variable that is missing
/// or does not fit.
StudySlice ParseStudySlice(const std::string& text, const EnvironmentLookup& environment);

/// What a slice's folder says about itself (OUT/slice.json).
struct SliceRecord {
  std::string dir = {};           ///< the folder it was read from (for messages; not stored)
  StudySlice slice = {};
  std::string study_digest = {};  ///< StudyDigest of the study the slice belongs to
  std::string study_file = {};    ///< the study file, absolute
  /// The study file as the slice's command line named it: what the answers
  /// echo (a failure's replay file), as a single run invoked that way does.
  std::string study_file_given = {};
  std::string mode = {};          ///< "detection" or "outcomes"
  std::size_t jobs = 0;      ///< the whole study's job count
};

/// The record's file name inside a slice's folder.
inline constexpr const char* kSliceRecordName = "slice.json";

/// Writes `record` as OUT/slice.json (atomically).
void WriteSliceRecord(const std::string& folder, const SliceRecord& record);

/// Reads DIR/slice.json; throws InputError naming the folder when it is not
/// a slice's (no record, or one that does not parse).
SliceRecord ReadSliceRecord(const std::string& dir);

/// What identifies a study's content for its slices: the mode's journal
/// fingerprint (its resolved jobs: candidates or sets, strategies, worlds,
/// seeds) and the bytes of the study file and of every scenario file it
/// reads, hashed (FNV-1a 64: the same in every build). Slices of one study
/// file run before and after an edit of it (or of its base) differ.
std::string StudyDigest(const std::string& fingerprint, const std::vector<std::string>& files);

}  // namespace proxsim
