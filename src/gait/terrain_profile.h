// The ground along one foot's line, as the footstep planner sees it: a
// vertical cut of the scene's true surface (gait/terrain_query.h) along a
// horizontal line, across the width of the sole, made of level segments.
//
// The line is sampled every kProfileStep_m on three parallel lines (the
// sole's centre line and its two edges); the envelope at a sample is the
// highest of the three (what a sole passing over must clear), its support
// the lowest (what a sole standing there rests on). Consecutive samples whose
// envelopes stay within kLevelTolerance_m of a segment's first one make a
// level segment; between two segments the edge is located by bisection to
// within kEdgeResolution_m. A height the terrain does not know is taken as
// line.unknown_z_m. So a stair, a box or a hole in the floor is a few
// segments with exact edges; a slope is many short segments (no sole lies
// flat on it).
//
// Frames: W world; s is the distance along the line from its origin.
#pragma once

#include <cmath>
#include <vector>

#include "core/geometry.h"
#include "gait/terrain_query.h"

namespace proxsim {

/// Spacing of the profile's samples along the line, m.
constexpr double kProfileStep_m = 0.02;
/// Heights within this of a segment's first one belong to the same level, m.
constexpr double kLevelTolerance_m = 0.005;
/// Edges between segments are located to within this, m.
constexpr double kEdgeResolution_m = 0.0005;

/// One level stretch of ground along the line.
struct GroundSegment {
  double s_begin_m = 0;    ///< where it starts along the line (an edge, or the profile's start)
  double s_end_m = 0;      ///< where it ends
  double z_m = 0;          ///< its height: the highest envelope sample; kNoGround or kBlockedGround
  bool full_width = true;  ///< the whole sole width rests on it (every support sample within the tolerance)

  bool walkable() const { return std::isfinite(z_m) && full_width; }
};

/// Where the line, its width and its reach lie.
struct ProfileLine {
  Vec2 origin_W = Vec2::Zero();     ///< s = 0
  Vec2 direction_W = Vec2::UnitX(); ///< unit, horizontal
  double half_width_m = 0;          ///< half the sole's width: the two side lines' offset
  double s_begin_m = 0, s_end_m = 1;
  double z_top_m = 1;               ///< vertical lines start at this height (above any step the legs take)
  double depth_m = 3;               ///< and reach this far down
  /// Where the terrain does not know (kUnknownGround), the ground is taken to
  /// be level at this height: the stance foot's (a robot planning on its own
  /// map steps level into what it has not seen).
  double unknown_z_m = 0;
};

class TerrainProfile {
 public:
  /// Samples `terrain` along `line`.
  TerrainProfile(const TerrainQuery& terrain, const ProfileLine& line);

  const ProfileLine& line() const { return line_; }
  /// The segments in order along the line; they tile [s_begin_m, s_end_m].
  const std::vector<GroundSegment>& segments() const { return segments_; }
  /// The segment holding s (the first or last beyond the profile's ends).
  std::size_t SegmentAt(double s_m) const;
  /// Height of the envelope at s: its segment's height.
  double EnvelopeZ(double s_m) const { return segments_[SegmentAt(s_m)].z_m; }
  /// The world point of (s, z).
  Vec3 PointW(double s_m, double z_m) const;
  /// How many vertical lines were cast to make it (for the planning cost).
  int lines_cast() const { return lines_cast_; }

 private:
  // Envelope (highest) and support (lowest) across the sole's width at s.
  std::pair<double, double> Sample(const TerrainQuery& terrain, double s_m);

  ProfileLine line_;
  std::vector<GroundSegment> segments_;
  int lines_cast_ = 0;
};

}  // namespace proxsim
