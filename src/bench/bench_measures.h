// The bench's instruments: the wall clock and rays per second, the process's
// memory (/proc), the machine's load and CPU, and the progress lines on stderr.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace proxsim::bench {

using Clock = std::chrono::steady_clock;

/// Seconds of wall time since `start`.
double Since(Clock::time_point start);

/// The rays/s of `cast()` over `rays` rays, the best of `repeats` runs.
template <typename F>
double RaysPerSecond(std::size_t rays, int repeats, F&& cast) {
  double best = 0;
  for (int r = 0; r < repeats; ++r) {
    const auto start = Clock::now();
    cast();
    best = std::max(best, static_cast<double>(rays) / Since(start));
  }
  return best;
}

/// Resident set size now, in bytes (/proc/self/statm).
double RssBytes();

/// Peak RSS (VmHWM) in bytes; ResetPeak() starts a new peak from the current RSS.
double PeakRssBytes();
void ResetPeak();

/// The load average over the last minute (/proc/loadavg).
double LoadAverage();

/// The CPU's model name (/proc/cpuinfo), "unknown" when there is none.
std::string CpuModel();

/// Whether Progress prints; RunBench sets it from its options.
void SetProgress(bool on);
bool ProgressOn();

/// One progress line on stderr: "bench: " and printf's `format`.
template <typename... Args>
void Progress(const char* format, Args... args) {
  if (!ProgressOn()) return;
  std::fprintf(stderr, "bench: ");
  std::fprintf(stderr, format, args...);
  std::fputc('\n', stderr);
}

}  // namespace proxsim::bench
