#include "gait/gait_memo.h"

#include <cstring>
#include <map>
#include <mutex>
#include <type_traits>
#include <unordered_map>

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

std::map<std::string, double>& MaxStepMemo() {
  static std::map<std::string, double> memo;
  return memo;
}

// A step's checks: its duration, and its refusal at each duration asked
struct StepChecks {
  std::optional<double> duration_s;
  std::map<double, std::string> refusal_at_s;
};

std::unordered_map<std::string, StepChecks>& StepMemo() {
  static std::unordered_map<std::string, StepChecks> memo;
  return memo;
}

StepChecks& StepEntry(const std::string& key) {
  if (StepMemo().size() >= kMaxRememberedSteps && !StepMemo().contains(key)) StepMemo().clear();
  return StepMemo()[key];
}

template <typename T>
void Put(std::string& bytes, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  char raw[sizeof value];
  std::memcpy(raw, &value, sizeof value);
  bytes.append(raw, sizeof value);
}

template <typename Matrix>
void PutMatrix(std::string& bytes, const Matrix& m) {
  for (Eigen::Index i = 0; i < m.size(); ++i) Put(bytes, m.data()[i]);
}

}  // namespace

std::string StepPlanBytes(const StepPlan& plan) {
  // a field added to StepPlan or SwingArc must be added here too (their sizes on x86-64)
  static_assert(sizeof(SwingArc) == 96, "SwingArc changed: update StepPlanBytes");
  static_assert(sizeof(StepPlan) == 560, "StepPlan changed: update StepPlanBytes");
  std::string bytes;
  bytes.reserve(640);
  Put(bytes, plan.stance);
  Put(bytes, plan.swing);
  for (const double d : {plan.k_from, plan.k_to, plan.g_from, plan.g_to, plan.yaw_from, plan.yaw_to, plan.floor_z_m,
                         plan.stance_offset.hip, plan.stance_offset.knee, plan.stance_offset.pitch,
                         plan.swing_start_pitch, plan.clearance_bump_m, plan.landing_z_m, plan.pelvis_x0_offset_m,
                         plan.pelvis_z0_m, plan.pelvis_z1_m, plan.foothold_s_m, plan.highest_ground_z_m})
    Put(bytes, d);
  PutMatrix(bytes, plan.p_W_heel);
  PutMatrix(bytes, plan.X_WF.matrix());
  PutMatrix(bytes, plan.p_W_trailing_toe);
  PutMatrix(bytes, plan.swing_toe_off_delta);
  PutMatrix(bytes, plan.swing_toe_off_rate);
  PutMatrix(bytes, plan.swing_end_delta);
  PutMatrix(bytes, plan.p_W_H);
  for (const bool b : {plan.flat_latched, plan.natural_landing, plan.terrain, plan.dead_end, plan.swing_arc.hold_pitch}) Put(bytes, b);
  const SwingArc& arc = plan.swing_arc;
  PutMatrix(bytes, arc.start);
  PutMatrix(bytes, arc.start_rate);
  PutMatrix(bytes, arc.end);
  for (const double d : {arc.lift_m, arc.height_span, arc.carry_start, arc.start_pitch_rad}) Put(bytes, d);
  Put(bytes, plan.cannot_step.size());
  bytes += plan.cannot_step;
  return bytes;
}

std::optional<double> RememberedStepDuration(const std::string& key) {
  std::lock_guard<std::mutex> lock(MemoMutex());
  const auto found = StepMemo().find(key);
  if (found == StepMemo().end()) return std::nullopt;
  return found->second.duration_s;
}

void RememberStepDuration(const std::string& key, double duration_s) {
  std::lock_guard<std::mutex> lock(MemoMutex());
  StepEntry(key).duration_s = duration_s;
}

std::optional<std::string> RememberedStepRefusal(const std::string& key, double duration_s) {
  std::lock_guard<std::mutex> lock(MemoMutex());
  const auto found = StepMemo().find(key);
  if (found == StepMemo().end()) return std::nullopt;
  const auto refusal = found->second.refusal_at_s.find(duration_s);
  if (refusal == found->second.refusal_at_s.end()) return std::nullopt;
  return refusal->second;
}

void RememberStepRefusal(const std::string& key, double duration_s, const std::string& refusal) {
  std::lock_guard<std::mutex> lock(MemoMutex());
  StepEntry(key).refusal_at_s.emplace(duration_s, refusal);
}

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

std::optional<double> RememberedMaxStep(const std::string& key) {
  std::lock_guard<std::mutex> lock(MemoMutex());
  const auto found = MaxStepMemo().find(key);
  if (found == MaxStepMemo().end()) return std::nullopt;
  return found->second;
}

void RememberMaxStep(const std::string& key, double max_step_m) {
  std::lock_guard<std::mutex> lock(MemoMutex());
  if (MaxStepMemo().size() >= kMaxRememberedGaits) MaxStepMemo().clear();
  MaxStepMemo().emplace(key, max_step_m);
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
