#include "output/profile_ply.h"

#include <cstdio>
#include <stdexcept>
#include <vector>

#include "core/number_format.h"
#include "sensors/measured_point.h"

namespace proxsim {

ProfilePlyWriter::ProfilePlyWriter(const std::string& path) : path_(path), body_(path + ".body") {}

void ProfilePlyWriter::Append(const SampleFrame& frame) {
  for (std::size_t i = 0; i < frame.sensors.size(); ++i) {
    const SensorSample& s = frame.sensors[i];
    if (!s.reading.detected()) continue;
    // the profile is built from what the sensor measured, not from the truth
    if (!s.measurements.empty()) {
      AppendMeasurements(frame, i);
      continue;
    }
    AppendPoint(MeasuredPoint_W(s.p_WS, s.dir_W, s.reading.d_m), i, frame.t_s, s.object_id);
  }
}

void ProfilePlyWriter::AppendMeasurements(const SampleFrame& frame, std::size_t i) {
  // every detection the part reports beside its reading (a multi-zone part's
  // targets, a beam's echoes), each along its own direction (no object: the truth is per ray)
  for (const Measurement& measurement : frame.sensors[i].measurements) {
    if (measurement.detected()) AppendPoint(measurement.p_W(), i, frame.t_s, -1);
  }
}

void ProfilePlyWriter::AppendPoint(const Vec3& p_W, std::size_t i, double t_s, std::int32_t object_id) {
  line_.clear();
  for (int k = 0; k < 3; ++k) {
    AppendNumber(line_, static_cast<float>(p_W[k]));
    line_ += ' ';
  }
  AppendInteger(line_, static_cast<long long>(i));
  line_ += ' ';
  AppendNumber(line_, t_s);
  line_ += ' ';
  AppendInteger(line_, object_id);
  line_ += '\n';
  body_.Write(line_);
  ++point_count_;
}

void ProfilePlyWriter::Commit() {
  body_.Commit();  // now complete under path_ + ".body"
  const std::string body_path = path_ + ".body";
  try {
    WriteWithHeader(body_path);
  } catch (...) {
    std::remove(body_path.c_str());  // a failed run leaves no part behind
    throw;
  }
}

void ProfilePlyWriter::WriteWithHeader(const std::string& body_path) {
  AtomicFile ply(path_);
  ply.Write("ply\nformat ascii 1.0\ncomment proxsim profile: world-frame detections\n");
  std::string element = "element vertex ";
  AppendInteger(element, point_count_);
  ply.Write(element);
  ply.Write(
      "\nproperty float x\nproperty float y\nproperty float z\n"
      "property int sensor\nproperty double t_s\nproperty int object\nend_header\n");
  // copy the streamed vertices after the header
  std::FILE* body = std::fopen(body_path.c_str(), "rb");
  if (body == nullptr) throw std::runtime_error("cannot reopen " + body_path);
  std::vector<char> chunk(1 << 20);
  std::size_t n;
  try {
    while ((n = std::fread(chunk.data(), 1, chunk.size(), body)) > 0) ply.Write({chunk.data(), n});
  } catch (...) {
    std::fclose(body);
    throw;
  }
  std::fclose(body);
  std::remove(body_path.c_str());
  ply.Commit();
}

}  // namespace proxsim
