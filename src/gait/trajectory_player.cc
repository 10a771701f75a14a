#include "gait/trajectory_player.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "core/input_limits.h"
#include "core/text_fields.h"

namespace proxsim {

namespace {

const char* const kBaseColumns[] = {"t_s", "x_m", "y_m", "z_m", "roll_deg", "pitch_deg", "yaw_deg"};
constexpr int kBaseCount = 7;
constexpr std::size_t kMaxProblems = 20;

}  // namespace

TrajectoryPlayer::TrajectoryPlayer(RobotModel model, const std::string& csv_path) : model_(std::move(model)) {
  std::ifstream in(csv_path, std::ios::binary);
  if (!in) throw InputError(csv_path + ": cannot open the trajectory file (missing or unreadable)");
  std::stringstream text;
  text << in.rdbuf();
  Parse(text.str(), csv_path);
}

TrajectoryPlayer TrajectoryPlayer::FromCsvText(RobotModel model, const std::string& csv_text, const std::string& source) {
  TrajectoryPlayer player(Tag{}, std::move(model));
  player.Parse(csv_text, source);
  return player;
}

void TrajectoryPlayer::Parse(const std::string& text, const std::string& source) {
  std::vector<std::string> problems;
  std::stringstream in(text);
  std::string line;
  int line_no = 0;
  // header: the base columns in any order, then joint names
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    header = SplitCsvLine(line);
    break;
  }
  if (header.empty()) throw InputError(source + ": empty trajectory file; expected a header " + "t_s,x_m,y_m,z_m,roll_deg,pitch_deg,yaw_deg,<joint names...>");
  const int header_line = line_no;
  int base_col[kBaseCount];
  for (int b = 0; b < kBaseCount; ++b) {
    const auto it = std::find(header.begin(), header.end(), kBaseColumns[b]);
    base_col[b] = it == header.end() ? -1 : static_cast<int>(it - header.begin());
    if (base_col[b] < 0)
      problems.push_back(source + ":" + std::to_string(header_line) + ": missing column '" + kBaseColumns[b] + "'");
  }
  std::vector<std::pair<int, int>> joint_cols;  // (column, joint index)
  for (int c = 0; c < static_cast<int>(header.size()); ++c) {
    if (std::find(std::begin(kBaseColumns), std::end(kBaseColumns), header[c]) != std::end(kBaseColumns)) continue;
    const int j = model_.JointIndex(header[c]);
    if (j < 0)
      problems.push_back(source + ":" + std::to_string(header_line) + ": column '" + header[c] +
                         "' is not a joint of robot '" + model_.name() + "'");
    else
      joint_cols.emplace_back(c, j);
  }
  if (!problems.empty()) throw InputError(problems);

  // rows
  while (std::getline(in, line) && problems.size() < kMaxProblems) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::vector<std::string> cells = SplitCsvLine(line);
    const std::string where = source + ":" + std::to_string(line_no);
    if (cells.size() != header.size()) {
      problems.push_back(where + ": " + std::to_string(cells.size()) + " cells, expected " + std::to_string(header.size()));
      continue;
    }
    std::vector<double> v(cells.size(), 0.0);
    bool ok = true;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (!ParseFiniteNumber(cells[c], &v[c])) {
        problems.push_back(where + ": column '" + header[c] + "': '" + cells[c] + "' is not a finite number");
        ok = false;
      }
    }
    // the pelvis within the coordinate limit, as a scenario's positions (x = 1e308 once ran with NaN sensor positions)
    for (int b = 1; b <= 3; ++b) {
      if (ok && std::abs(v[base_col[b]]) > kMaxCoordinate_m) {
        problems.push_back(where + ": column '" + header[base_col[b]] + "': " + cells[base_col[b]] +
                           " m is beyond the coordinate limit of ±100000 m (rays are cast in single precision; "
                           "docs/trust.md)");
        ok = false;
      }
    }
    if (!ok) continue;
    const double t = v[base_col[0]];
    if (!t_s_.empty() && !(t > t_s_.back())) {
      problems.push_back(where + ": t_s " + cells[base_col[0]] + " is not after the previous row's; times must strictly increase");
      continue;
    }
    t_s_.push_back(t);
    X_WP_.push_back(PoseFromXyzRpy(Vec3(v[base_col[1]], v[base_col[2]], v[base_col[3]]),
                                   Vec3(DegToRad(v[base_col[4]]), DegToRad(v[base_col[5]]), DegToRad(v[base_col[6]]))));
    std::vector<double> q(model_.joint_count(), 0.0);
    for (const auto& [c, j] : joint_cols)
      q[j] = model_.joint(j).type == JointType::kPrismatic ? v[c] : DegToRad(v[c]);
    q_.push_back(std::move(q));
  }
  if (problems.empty() && t_s_.empty()) problems.push_back(source + ": no data rows after the header");
  if (!problems.empty()) throw InputError(problems);
}

RobotState TrajectoryPlayer::Sample(double t) const {
  RobotState s;
  const auto n = t_s_.size();
  std::size_t i = 0;
  double w = 0;
  if (t <= t_s_.front()) {
    i = 0;
  } else if (t >= t_s_.back()) {
    i = n - 1;
  } else {
    i = static_cast<std::size_t>(std::upper_bound(t_s_.begin(), t_s_.end(), t) - t_s_.begin()) - 1;
    w = (t - t_s_[i]) / (t_s_[i + 1] - t_s_[i]);
  }
  const std::size_t j = std::min(i + 1, n - 1);
  s.X_WP = Pose::Identity();
  s.X_WP.translation() = (1 - w) * X_WP_[i].translation() + w * X_WP_[j].translation();
  const Eigen::Quaterniond qa(X_WP_[i].linear()), qb(X_WP_[j].linear());
  s.X_WP.linear() = qa.slerp(w, qb).toRotationMatrix();
  s.q.resize(q_[i].size());
  for (std::size_t k = 0; k < s.q.size(); ++k) s.q[k] = (1 - w) * q_[i][k] + w * q_[j][k];
  return s;
}

RobotState TrajectoryPlayer::Advance(double t_s) {
  if (!started_) {
    started_ = true;
    last_t_s_ = t_s;
    play_t_s_ = t_s;
  }
  if (!stopped_) play_t_s_ += std::max(0.0, t_s - last_t_s_);
  last_t_s_ = std::max(last_t_s_, t_s);
  RobotState s = Sample(play_t_s_);
  s.t_s = t_s;
  s.support = SupportLeg::kDouble;
  s.stopped = stopped_;
  const Vec3 p = s.X_WP.translation();
  if (has_last_) distance_m_ += (p - last_p_WP_).head<2>().norm();
  has_last_ = true;
  last_p_WP_ = p;
  s.distance_walked_m = distance_m_;
  return s;
}

void TrajectoryPlayer::Reset() {
  started_ = false;
  stopped_ = false;
  last_t_s_ = 0;
  play_t_s_ = 0;
  has_last_ = false;
  last_p_WP_ = Vec3::Zero();
  distance_m_ = 0;
}

}  // namespace proxsim
