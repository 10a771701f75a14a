#include "bench/bench_measures.h"

#include <unistd.h>

#include <fstream>

namespace proxsim::bench {

namespace {
bool g_progress = true;
}  // namespace

double Since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double RssBytes() {
  std::ifstream statm("/proc/self/statm");
  long pages_total = 0, pages_resident = 0;
  statm >> pages_total >> pages_resident;
  return static_cast<double>(pages_resident) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

double PeakRssBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) * 1024.0;
  }
  return 0;
}

// 5 in clear_refs resets the peak (VmHWM) to the current RSS
void ResetPeak() { std::ofstream("/proc/self/clear_refs") << "5"; }

double LoadAverage() {
  double one = 0;
  std::ifstream("/proc/loadavg") >> one;
  return one;
}

std::string CpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown";
}

void SetProgress(bool on) { g_progress = on; }
bool ProgressOn() { return g_progress; }

}  // namespace proxsim::bench
