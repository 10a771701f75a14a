#include "sim/robot_in_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/surface_samples.h"

namespace proxsim {

namespace {

constexpr double kClearanceSpacing_m = 0.02;
// Point queries are capped this far above the running minimum: a capped
// distance still bounds its point from below, and the bound lasts until the
// point has moved this far, while a point farther than the cap costs only small
// empty queries. On the bench's heavy scenario 2 to 10 cm cost the same;
// without per-point bounds, 10 cm cost twice as much as 2 cm.
constexpr double kBoundMargin_m = 0.05;
// A world of closed forms only that moves (the moving objects' caster) is
// measured this far above the cap instead: a bound of 5 cm is spent in a few
// samples by objects walking at 1 m/s (their moves lower every bound:
// LowerClearanceBounds).
constexpr double kClosedFormBoundMargin_m = 0.25;
// A still one (a generated room's furniture, the ground) this far: its
// queries look only at the shapes within the cap of the link
// (RayCaster::Nearby), fewer the lower the cap, while its bounds are spent by
// the robot's own moves alone (the outcome study's 10 rooms under callgrind:
// 0.1 m cost 7 % fewer instructions in ClearanceTo than 0.25 m, 0.05 m 3 %
// more; once a chunk is tried by its centre first, 0.2 m cost the whole
// study 0.4 % fewer than 0.1 m, 0.3 m and 0.5 m a little more than 0.2 m).
constexpr double kStillClosedFormBoundMargin_m = 0.2;
// A query asked only for what lies very near (the contacts' 0.1 mm) still
// measures this far at least: a bound of a few centimetres would be spent by
// a swinging foot in a sample or two, and every sample of the robot measured
// again and again (closed-form shapes cost the same whatever the cap; only
// meshes' point queries grow with it).
constexpr double kMinBoundReach_m = 0.25;
// Rounding in the poses and distances is far below this: a skip never hinges
// on the last bits of a bound.
constexpr double kBoundSlack_m = 1e-9;
// Samples per chunk: a chunk whose bound, or whose centre's distance, keeps
// it out of reach is skipped without looking at its samples one by one (the
// 10 rooms under callgrind: 16 cost 1 % fewer instructions than 24 or 8).
constexpr std::size_t kChunkSamples = 16;

// The farthest any point within radius_m of center_L (link frame) moves when
// the link goes from X_WL_ref to X_WL: the centre's travel plus the rotation's
// sweep 2·sin(θ/2)·radius_m, where ‖R − R_ref‖_F = √8·sin(θ/2) for a turn by θ.
double MaxTravel_m(const Pose& X_WL_ref, const Pose& X_WL, const Vec3& center_L, double radius_m) {
  const double center_travel_m = (X_WL * center_L - X_WL_ref * center_L).norm();
  const double chord_per_m = (X_WL.linear() - X_WL_ref.linear()).norm() / std::sqrt(2.0);
  return center_travel_m + chord_per_m * radius_m;
}

}  // namespace

RobotInScene::RobotInScene(const RobotModel& model, RayCaster& caster, std::int32_t first_object_id)
    : model_(model), caster_(caster) {
  const RobotModel& robot = model_;
  link_body_.assign(robot.link_count(), -1);
  link_samples_.resize(robot.link_count());
  X_WL_.assign(robot.link_count(), Pose::Identity());
  for (int link = 0; link < robot.link_count(); ++link) {
    const auto& shapes = robot.link(link).shapes;
    if (shapes.empty()) continue;
    // one body per link, every shape reporting the link as the hit object
    std::vector<BodyShape> body;
    LinkSamples& samples = link_samples_[link];
    for (const LinkShape& shape : shapes) {
      body.push_back({shape.shape, shape.X_LO, first_object_id + link});
      for (const Vec3& p_O : SurfaceSamples_O(shape.shape, kClearanceSpacing_m)) {
        samples.points_L.push_back(shape.X_LO * p_O);
      }
    }
    link_body_[link] = caster.AddBody(std::move(body), BodyKind::kRobot);
    // a bounding sphere, to skip links that are far from everything
    if (!samples.points_L.empty()) {
      Vec3 lo = samples.points_L[0], hi = lo;
      for (const Vec3& p : samples.points_L) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
      samples.center_L = (lo + hi) / 2;
      for (const Vec3& p : samples.points_L) samples.radius_m = std::max(samples.radius_m, (p - samples.center_L).norm());
      for (std::size_t begin = 0; begin < samples.points_L.size(); begin += kChunkSamples) {
        Chunk chunk{.begin = begin, .end = std::min(begin + kChunkSamples, samples.points_L.size())};
        Vec3 chunk_lo = samples.points_L[begin], chunk_hi = chunk_lo;
        for (std::size_t i = chunk.begin; i < chunk.end; ++i) {
          chunk_lo = chunk_lo.cwiseMin(samples.points_L[i]);
          chunk_hi = chunk_hi.cwiseMax(samples.points_L[i]);
        }
        chunk.center_L = (chunk_lo + chunk_hi) / 2;
        for (std::size_t i = chunk.begin; i < chunk.end; ++i)
          chunk.radius_m = std::max(chunk.radius_m, (samples.points_L[i] - chunk.center_L).norm());
        samples.chunks.push_back(chunk);
      }
    }
  }
}

RobotInScene::~RobotInScene() = default;

void RobotInScene::Place(const RobotState& state) {
  model_.ForwardKinematics(state.X_WP, state.q, X_WL_);
  for (int link = 0; link < static_cast<int>(link_body_.size()); ++link) {
    if (link_body_[link] >= 0) caster_.SetBodyPose(link_body_[link], X_WL_[link]);
  }
}

RobotInScene::BoundsSlot& RobotInScene::SlotFor(std::span<const std::int32_t> exclude_object_ids,
                                                 const SampleMask* mask, const RayCaster* against) {
  constexpr std::size_t kSlots = 4;  // the clearance, the contacts with objects and with the ground
  constexpr double kNoBound = -std::numeric_limits<double>::infinity();
  for (BoundsSlot& slot : bounds_slots_)
    if (slot.mask == mask && slot.against == against && std::ranges::equal(exclude_object_ids, slot.exclude_ids))
      return slot;
  if (bounds_slots_.size() == kSlots) bounds_slots_.erase(bounds_slots_.begin());
  BoundsSlot& slot = bounds_slots_.emplace_back();
  slot.exclude_ids.assign(exclude_object_ids.begin(), exclude_object_ids.end());
  slot.mask = mask;
  slot.against = against;
  slot.links.assign(link_samples_.size(), ClearanceBounds{});
  for (std::size_t link = 0; link < link_samples_.size(); ++link) {
    slot.links[link].point_lower_m.assign(link_samples_[link].points_L.size(), kNoBound);
    slot.links[link].p_W_ref.assign(link_samples_[link].points_L.size(), Vec3::Zero());
    slot.links[link].chunk_lower_m.assign(link_samples_[link].chunks.size(), kNoBound);
    slot.links[link].chunk_X_WL_ref.assign(link_samples_[link].chunks.size(), Pose::Identity());
  }
  return slot;
}

void RobotInScene::LowerClearanceBounds(const RayCaster* against, double moved_m) {
  // an unbounded move (a moving plane) leaves nothing to remember
  if (!std::isfinite(moved_m)) {
    std::erase_if(bounds_slots_, [against](const BoundsSlot& slot) { return slot.against == against; });
    return;
  }
  for (BoundsSlot& slot : bounds_slots_)
    if (slot.against == against) slot.lowered_m += moved_m;
}

double RobotInScene::ClearanceTo(std::span<const std::int32_t> exclude_object_ids, double below_m,
                                 const SampleMask* mask, const RayCaster* against) {
  BoundsSlot& slot = SlotFor(exclude_object_ids, mask, against);
  const RayCaster& world = against != nullptr ? *against : caster_;
  double best_m = below_m;
  for (int link = 0; link < static_cast<int>(link_samples_.size()); ++link) {
    const LinkSamples& samples = link_samples_[link];
    if (samples.points_L.empty()) continue;
    const Pose& X_WL = X_WL_[link];
    ClearanceBounds& bounds = slot.links[link];

    // no sample has moved farther than the link's travel since its bound was taken: skip it when it cannot win
    const double travel_m = MaxTravel_m(bounds.X_WL_ref, X_WL, samples.center_L, samples.radius_m);
    if (bounds.link_lower_m - slot.lowered_m - travel_m - kBoundSlack_m >= best_m) continue;
    // the samples' queries below are capped here
    const double cap_m =
        std::max(best_m, kMinBoundReach_m) + (world.world_has_mesh() ? kBoundMargin_m
                                              : slot.lowered_m > 0      ? kClosedFormBoundMargin_m
                                                                        : kStillClosedFormBoundMargin_m);
    // the link's bounding sphere first, one capped query, before its samples:
    // nothing may be remembered (a first query), or the bounds may have
    // dropped because the world moved (an object turning on its path). In a
    // world of closed forms only (the moving objects' caster) it reaches the
    // samples' cap: closed forms cost the same whatever the reach, and that
    // bound lasts for samples, where a bound of best_m is spent by the next
    // sample's move. Meshes' point queries grow with the reach.
    const Vec3 center_W = X_WL * samples.center_L;
    {
      const double skip_m = samples.radius_m + best_m;
      const double reach_m = world.world_has_mesh() ? skip_m : samples.radius_m + cap_m;
      const double centre_m = world.DistanceToWorld(center_W, exclude_object_ids, reach_m);
      if (centre_m >= skip_m) {
        bounds.link_lower_m = centre_m - samples.radius_m + slot.lowered_m;
        bounds.X_WL_ref = X_WL;
        continue;
      }
    }

    // else each sample the same way with its own bound and travel, and the
    // ones that could win measured with capped queries: a distance below the
    // cap is exact, and only those can lower best_m (the cap is above it).
    // The queries walk only the shapes within the cap of the link's sphere.
    bool nearby_found = false;
    double link_lower_m = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < samples.chunks.size(); ++c) {
      const Chunk& chunk = samples.chunks[c];
      // a chunk out of reach as a whole, by its bound and its travel since, as the link above
      const double chunk_travel_m = MaxTravel_m(bounds.chunk_X_WL_ref[c], X_WL, chunk.center_L, chunk.radius_m);
      const double chunk_lower_m = bounds.chunk_lower_m[c] - slot.lowered_m - chunk_travel_m - kBoundSlack_m;
      if (chunk_lower_m >= best_m) {
        link_lower_m = std::min(link_lower_m, chunk_lower_m);
        continue;
      }
      if (!nearby_found) {
        world.FindNearby(center_W, samples.radius_m, cap_m, &nearby_);
        nearby_found = true;
      }
      // one capped query at the chunk's centre before its samples': a chunk
      // whose centre is clear of the world by more than its radius holds no
      // sample that can win (the distance at a sample is at least the
      // centre's less the radius), and that bound lasts as the samples' would
      {
        const double centre_m = world.DistanceToWorld(X_WL * chunk.center_L, exclude_object_ids, cap_m, &nearby_);
        const double centre_lower_m = centre_m - chunk.radius_m - kBoundSlack_m;
        if (centre_lower_m >= best_m) {
          bounds.chunk_lower_m[c] = centre_lower_m + slot.lowered_m;
          bounds.chunk_X_WL_ref[c] = X_WL;
          link_lower_m = std::min(link_lower_m, centre_lower_m);
          continue;
        }
      }
      double chunk_min_m = std::numeric_limits<double>::infinity();
      for (std::size_t i = chunk.begin; i < chunk.end; ++i) {
        if (mask != nullptr && !(*mask)[link][i]) continue;
        const Vec3 p_W = X_WL * samples.points_L[i];
        double lower_m = bounds.point_lower_m[i] - slot.lowered_m - (p_W - bounds.p_W_ref[i]).norm() - kBoundSlack_m;
        if (lower_m < best_m) {
          if (!nearby_found) {
            world.FindNearby(center_W, samples.radius_m, cap_m, &nearby_);
            nearby_found = true;
          }
          lower_m = world.DistanceToWorld(p_W, exclude_object_ids, cap_m, &nearby_);
          bounds.point_lower_m[i] = lower_m + slot.lowered_m;
          bounds.p_W_ref[i] = p_W;
          best_m = std::min(best_m, lower_m);
        }
        chunk_min_m = std::min(chunk_min_m, lower_m);
      }
      bounds.chunk_lower_m[c] = chunk_min_m + slot.lowered_m;
      bounds.chunk_X_WL_ref[c] = X_WL;
      link_lower_m = std::min(link_lower_m, chunk_min_m);
    }
    bounds.link_lower_m = link_lower_m + slot.lowered_m;
    bounds.X_WL_ref = X_WL;
  }
  return best_m;
}

std::vector<RobotInScene::NearSample> RobotInScene::SamplesNear(std::span<const std::int32_t> exclude_object_ids,
                                                                double within_m, const SampleMask* mask,
                                                                const RayCaster* against) const {
  const RayCaster& world = against != nullptr ? *against : caster_;
  std::vector<NearSample> near;
  for (int link = 0; link < static_cast<int>(link_samples_.size()); ++link) {
    const LinkSamples& samples = link_samples_[link];
    if (samples.points_L.empty()) continue;
    const Pose& X_WL = X_WL_[link];
    // a link whose bounding sphere is clear of the world by more than within_m has no such sample
    if (world.DistanceToWorld(X_WL * samples.center_L, exclude_object_ids, samples.radius_m + within_m) >=
        samples.radius_m + within_m) {
      continue;
    }
    for (std::size_t i = 0; i < samples.points_L.size(); ++i) {
      if (mask != nullptr && !(*mask)[link][i]) continue;
      const Vec3 p_W = X_WL * samples.points_L[i];
      const RayCaster::NearestSurface nearest = world.NearestToWorld(p_W, exclude_object_ids, within_m);
      if (nearest.object_id >= 0 && nearest.distance_m <= within_m) near.push_back({link, p_W, nearest});
    }
  }
  return near;
}

std::vector<LinkShapes> RobotInScene::LinkGeometry() const {
  std::vector<LinkShapes> links;
  for (int link = 0; link < model().link_count(); ++link) {
    LinkShapes json{model().link_name(link), {}};
    for (const LinkShape& shape : model().link(link).shapes) json.shapes.push_back({shape.shape, shape.X_LO, link});
    links.push_back(std::move(json));
  }
  return links;
}

}  // namespace proxsim
