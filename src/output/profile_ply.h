// profile.ply: the world-frame points the sensors detected (paper §6.2), as an
// ASCII PLY point cloud with the sensor index, time and hit object of each
// point as vertex properties. Points are streamed to a side file while the run
// goes, and the header (which needs the final count) is written at Commit.
#pragma once

#include <cstdint>
#include <string>

#include "core/atomic_file.h"
#include "output/run_sink.h"

namespace proxsim {

class ProfilePlyWriter : public RunSink {
 public:
  explicit ProfilePlyWriter(const std::string& path);

  /// Adds every detection of the frame (status ok) at its measured distance
  /// along the ray: p = origin + d_m·dir, the point a real sensor would report;
  /// for a multizone sensor every valid target of every zone along its zone's
  /// axis (object -1: a zone's target stands for several rays).
  void Append(const SampleFrame& frame);
  void Add(const SampleFrame& frame) override { Append(frame); }
  void Commit() override;
  void AddToSummary(nlohmann::json& summary) const override { summary["outputs"].push_back("profile.ply"); }

  std::int64_t point_count() const { return point_count_; }

 private:
  void WriteWithHeader(const std::string& body_path);
  void AppendMeasurements(const SampleFrame& frame, std::size_t sensor);
  void AppendPoint(const Vec3& p_W, std::size_t sensor, double t_s, std::int32_t object_id);

  std::string path_;
  AtomicFile body_;  // the vertex lines, before the header exists
  std::int64_t point_count_ = 0;
  std::string line_;
};

}  // namespace proxsim
