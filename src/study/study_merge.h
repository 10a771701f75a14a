// `proxsim study merge DIR... --out DIR` (docs/studies.md "Slices and Slurm
// job arrays"): the slices of one study (study_shard.h), each run into its
// own folder, put back together. A single run writes its answers from its
// journal's lines, in job order; a merge checks the slices and joins their
// journals into the same lines, and the same code writes the answers from
// them — so the files are byte for byte those of a single run.
//
// Checked before anything is written, every problem listed at once: each
// folder is a slice (OUT/slice.json), all of one study (one digest, the study
// file and the scenario files it reads unchanged since), cut the same way,
// every slice given once (a missing or duplicated slice is named), each
// slice's journal complete and holding its own jobs only.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/study_jobs.h"
#include "study/study_shard.h"

namespace proxsim {

/// Reads the slice folders' records and checks that they are one study's
/// slices, each given once, none missing; throws InputError naming each
/// folder that is not a slice or not of the study, each duplicated slice with
/// its folders and each missing slice ("slice 2/3"). Returns them in slice order.
std::vector<SliceRecord> ReadStudySlices(const std::vector<std::string>& dirs);

/// Checks the slices against the study as it reads now (`set`: its digest,
/// its journal lines) and that each slice's journal holds every job of its
/// slice; then claims options.out_dir, writes there the union as the study's
/// journal (OUT/journal.jsonl, in job order: `proxsim study --resume` reads
/// it as a finished single run's) and returns every job's line. The slice
/// folders are locked while they are read (a slice still running is refused).
std::map<std::size_t, nlohmann::json> MergeStudySlices(const JobSet& set, const std::vector<SliceRecord>& slices,
                                                       const StudyOptions& options);

}  // namespace proxsim
