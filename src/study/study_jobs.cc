#include "study/study_jobs.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/regular_file.h"

namespace proxsim {

namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;

// ----- the journal: one line per finished job, flushed to disk at once

class Journal {
 public:
  Journal(const std::string& path, const json& header, bool resume, std::size_t jobs,
          const std::function<std::size_t(const json&)>& check, const std::optional<StudySlice>& slice)
      : path_(path), done_(jobs) {
    if (resume) {
      lines_ = ReadJournal(path_, header, check, slice);
      for (const auto& [job, line] : lines_) done_[job] = true;
    }
    // rewrite what was read (a line cut by a kill is dropped), then append;
    // neither step follows a link planted under the journal's name
    std::string text = header.dump() + "\n";
    for (const auto& [job, line] : lines_) text += line + "\n";
    WriteFileAtomically(path_, text);
    fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_NOFOLLOW | O_CLOEXEC);
    if (fd_ < 0) throw std::runtime_error("cannot write the study's journal " + path_);
  }
  ~Journal() {
    if (fd_ >= 0) ::close(fd_);
  }

  bool done(std::size_t job) const { return done_[job]; }
  std::size_t done_count() const { return lines_.size(); }
  const std::map<std::size_t, std::string>& lines() const { return lines_; }

  void Append(std::size_t job, const json& metrics) {
    const std::string line = json{{"job", job}, {"metrics", metrics}}.dump();
    std::lock_guard lock(mutex_);
    const std::string with_newline = line + "\n";
    if (::write(fd_, with_newline.data(), with_newline.size()) != static_cast<ssize_t>(with_newline.size()) ||
        ::fsync(fd_) != 0) {
      throw std::runtime_error("cannot write the study's journal " + path_);
    }
    lines_[job] = line;
    done_[job] = true;
  }

 private:
  std::string path_;
  std::vector<bool> done_;
  std::map<std::size_t, std::string> lines_;
  std::mutex mutex_;
  int fd_ = -1;
};

// ----- the progress line: rewritten in place on a terminal; under mpirun,
// Slurm or a pipe, one line every 10 s and at the end (a log stays readable)

class Progress {
 public:
  Progress(bool enabled, std::size_t total, std::size_t already, std::size_t candidates)
      : enabled_(enabled), tty_(isatty(STDERR_FILENO) != 0), total_(total), start_done_(already),
        candidates_(candidates), start_(Clock::now()), last_line_(start_) {}
  void Update(std::size_t done) {
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    const Clock::time_point now = Clock::now();
    const bool last = done == total_;
    if (!tty_ && !last && now - last_line_ < std::chrono::seconds(10)) return;
    last_line_ = now;
    const double elapsed_s = std::chrono::duration<double>(now - start_).count();
    const double rate = elapsed_s > 0 ? (done - start_done_) / elapsed_s : 0;
    const double eta_s = rate > 0 ? (total_ - done) / rate : 0;
    std::fprintf(stderr, "%sproxsim study: %zu/%zu runs (%zu/%zu jobs), %.1f runs/s, ETA %.0f s%s",
                 tty_ ? "\r" : "", done * candidates_, total_ * candidates_, done, total_, rate * candidates_, eta_s,
                 tty_ && !last ? "   " : "\n");
  }

 private:
  bool enabled_, tty_;
  std::size_t total_, start_done_, candidates_;
  Clock::time_point start_, last_line_;
  std::mutex mutex_;
};

}  // namespace

int WorkerThreads(int requested, const StudyMpi& mpi) {
  return requested > 0 ? requested
         : mpi.size() > 1 ? 1
                          : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

json JournalHeader(const std::string& fingerprint, const std::optional<StudySlice>& slice) {
  json header = {{"study", fingerprint}};
  if (slice) header["slice"] = slice->Name();
  return header;
}

std::map<std::size_t, std::string> ReadJournal(const std::string& path, const json& header,
                                               const std::function<std::size_t(const json&)>& check,
                                               const std::optional<StudySlice>& slice) {
  std::map<std::size_t, std::string> lines;
  // a FIFO blocks its reader for ever, /dev/zero is read until memory runs out: stat() first, never open()
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return lines;  // nothing to resume: start afresh
  if (const std::string problem = RegularFileProblem(path, std::numeric_limits<unsigned long long>::max());
      !problem.empty()) {
    throw InputError(problem + "; the study journal must be the regular file a study wrote");
  }
  std::ifstream in(path);
  if (!in) return lines;
  std::string line;
  bool first = true;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    const json entry = json::parse(line, nullptr, false);
    if (entry.is_discarded()) continue;  // the line a kill cut short
    if (first) {
      first = false;
      if (entry != header) {
        throw InputError(path + ": this journal belongs to another study or slice (its candidates, sets, scenes, "
                                "worlds, seeds or hazards differ, or its --shard): expected the header " +
                         header.dump() + ", found " + entry.dump() + "; remove it or give another --out");
      }
      continue;
    }
    // every line checked against this study's shape before it is used
    try {
      const std::size_t job = check(entry);
      if (slice && !slice->Holds(job))
        throw InputError("job " + std::to_string(job) + " is not one of slice " + slice->Name() + "'s jobs");
      lines[job] = line;
    } catch (const InputError& error) {
      throw InputError(path + ":" + std::to_string(line_no) + ": " + error.problems().front() +
                       "; remove the journal or give another --out");
    }
  }
  return lines;
}

std::string StudyFingerprint(const std::string& shape, const std::string& identity) {
  std::uint64_t hash = 1469598103934665603ull;
  for (const char c : identity) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return shape + "-" + hex;
}

std::map<std::size_t, json> RunJobs(const JobSet& set, const StudyOptions& options, StudyMpi& mpi, bool* is_writer) {
  *is_writer = mpi.rank() == 0;
  if (!*is_writer) {
    // a worker rank: ask rank 0 for jobs until there are none
    std::string result;
    for (;;) {
      const long job = mpi.ExchangeWithWriter(result);
      if (job < 0) break;
      result = json{{"job", job}, {"metrics", set.workers.front()(static_cast<std::size_t>(job))}}.dump();
    }
    return {};
  }

  // the folder, claimed and locked: a second study (or run) into it fails at once
  auto folder = std::make_shared<OutputFolder>(
      options.out_dir, ClaimOptions{.command = "study", .force = options.force, .ours = "journal.jsonl"});
  if (options.folder != nullptr) *options.folder = folder;
  const std::optional<StudySlice>& slice = options.slice;
  Journal journal((std::filesystem::path(folder->path()) / "journal.jsonl").string(),
                  JournalHeader(set.fingerprint, slice), options.resume, set.jobs, set.check, slice);
  if (!slice) {
    // a whole study where a slice ran before: its record would call this folder a slice
    std::error_code ignored;
    std::filesystem::remove(std::filesystem::path(folder->path()) / kSliceRecordName, ignored);
  } else {
    // the slice says which study and which slice it is, once its journal is this slice's: merge reads it
    const std::string study_file = std::filesystem::absolute(set.study_file).lexically_normal().string();
    WriteSliceRecord(folder->path(), {.slice = *slice,
                                      .study_digest = set.digest,
                                      .study_file = study_file,
                                      .study_file_given = set.study_file,
                                      .mode = set.mode,
                                      .jobs = set.jobs});
  }
  const std::size_t my_jobs = slice ? slice->JobsOf(set.jobs) : set.jobs;
  Progress progress(options.progress, my_jobs, journal.done_count(), set.runs_per_job);
  if (options.progress) {
    const std::string of_slice =
        slice ? ", slice " + slice->Name() + " (" + std::to_string(my_jobs) + " of the jobs)" : std::string();
    std::fprintf(stderr, "proxsim study: %s%s, %zu thread%s x %d rank%s%s\n", set.header.c_str(), of_slice.c_str(),
                 set.workers.size(),
                 set.workers.size() == 1 ? "" : "s", mpi.size(), mpi.size() == 1 ? "" : "s",
                 journal.done_count() > 0
                     ? (", " + std::to_string(journal.done_count()) + " jobs already done (resumed)").c_str()
                     : "");
  }

  // the jobs still to do, handed out one at a time
  std::vector<std::size_t> todo;
  for (std::size_t job = 0; job < set.jobs; ++job)
    if (!journal.done(job) && (!slice || slice->Holds(job))) todo.push_back(job);
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> finished{journal.done_count()};
  // after a failure no job is handed out: every thread and rank stops at its next request
  std::exception_ptr failure;
  std::mutex failure_mutex;
  std::atomic<bool> failed{false};
  const auto fail = [&](std::exception_ptr error) {
    std::lock_guard lock(failure_mutex);
    if (!failure) failure = std::move(error);
    failed = true;
  };
  const auto take = [&]() -> long {
    if (failed) return -1;
    const std::size_t i = next.fetch_add(1);
    return i < todo.size() ? static_cast<long>(todo[i]) : -1;
  };
  const auto record = [&](std::size_t job, const json& metrics) {
    journal.Append(job, metrics);
    progress.Update(finished.fetch_add(1) + 1);
  };

  // the other ranks, served by one thread of rank 0; this rank's threads work too
  std::thread dispatcher;
  if (mpi.size() > 1) {
    dispatcher = std::thread([&] {
      // a failure here (a worker's bad message, a full disk) ends the study with its message, never
      // std::terminate: the worker ranks wait in MPI_Recv until the CLI's MPI_Abort ends them
      try {
        mpi.ServeWorkers(take, [&](const std::string& message) {
          // a worker's message has a journal line's form: checked the same way
          const json line = json::parse(message);
          record(set.check(line), line.at("metrics"));
        });
      } catch (...) {
        fail(std::current_exception());
      }
    });
  }
  std::vector<std::thread> pool;
  for (const auto& worker : set.workers) {
    pool.emplace_back([&, w = &worker] {
      try {
        for (long job = take(); job >= 0; job = take()) record(job, (*w)(static_cast<std::size_t>(job)));
      } catch (...) {
        fail(std::current_exception());
      }
    });
  }
  for (std::thread& t : pool) t.join();
  if (dispatcher.joinable()) dispatcher.join();
  if (failure) std::rethrow_exception(failure);

  // every job's line, from the journal: the same whatever ran them
  std::map<std::size_t, json> lines;
  for (const auto& [job, line] : journal.lines()) lines[job] = json::parse(line);
  return lines;
}

}  // namespace proxsim
