#include "gait/gait_memo.h"

#include <cstring>
#include <map>
#include <mutex>

namespace proxsim {

namespace {

std::mutex& MemoMutex() {
  static std::mutex mutex;
  return mutex;
}

std::map<std::string, AmplitudeStride>& Memo() {
  static std::map<std::string, AmplitudeStride> memo;
  return memo;
}

}  // namespace

std::optional<AmplitudeStride> RememberedGait(const std::string& key) {
  std::lock_guard<std::mutex> lock(MemoMutex());
  const auto found = Memo().find(key);
  if (found == Memo().end()) return std::nullopt;
  return found->second;
}

void RememberGait(const std::string& key, const AmplitudeStride& walked) {
  std::lock_guard<std::mutex> lock(MemoMutex());
  if (Memo().size() >= kMaxRememberedGaits) Memo().clear();
  Memo().emplace(key, walked);
}

std::string GaitSearchKey(const std::string& legs_fingerprint, double stride_m, double period_s) {
  std::string key = legs_fingerprint;
  for (const double value : {stride_m, period_s}) {
    char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    key.append(bytes, sizeof value);
  }
  return key;
}

}  // namespace proxsim
