// The room: four walls and a floor, furniture made of primitives (tables
// with legs, chairs with a back, shelves against the walls), clutter on the
// floor (boxes, cylinders, balls) and people walking across the robot's way,
// their numbers growing with the difficulty.
//
// What is in the way: the robot's path is the straight line from its start
// to the goal, and blockers (boxes, posts, chairs, low bars) are put across
// it first, so that a robot that ignores its sensors walks into them; each,
// like everything else, leaves a way around.
//
// The free corridor: every piece of furniture and clutter is placed only if
// a path still joins the robot's start to its goal on a 5 cm grid where the
// footprints are grown by half the corridor's width (robot_width_m +
// margin_m) and a cell: a breadth-first search on the layout as it would be, before the
// piece is accepted. The robot's path is that search's path, cut to
// waypoints wherever the straight line between two of them stays clear.
// That path is kept (GeneratedWorld::corridor_m) as the proof of a way around.
// Nothing is placed within 0.7 m of the start or the goal. A person's walk
// is a line across the robot's path that stays clear of the furniture (by
// 0.3 m), starting at least 1.5 m from the robot.
//
// Frames: W world; the room spans x from −1 to size_x − 1, y ±size_y/2.
#include <algorithm>
#include <cmath>

#include "scene/world_generator_internal.h"

namespace proxsim::gen {

namespace {

constexpr double kCell_m = 0.05;
constexpr double kKeepClear_m = 0.7;  // around the start and the goal
// along the walk from the start: the blind reference walk meets the first
// blocker about 0.4 m short of it, and a study counts a stop as one before
// the blocker within 1.2 m of there (study/outcome_runner.h) — from 2.2 m on,
// a robot that stops in its first stride has not stopped before them
constexpr double kFirstBlocker_m = 2.2;
constexpr double kWallThickness_m = 0.1;

/// An axis-aligned footprint in the plane.
struct Footprint {
  Vec2 min, max;
  bool Overlaps(const Footprint& other, double gap_m) const {
    return min.x() < other.max.x() + gap_m && other.min.x() < max.x() + gap_m && min.y() < other.max.y() + gap_m &&
           other.min.y() < max.y() + gap_m;
  }
  double DistanceTo(const Vec2& p) const { return (p.cwiseMax(min).cwiseMin(max) - p).norm(); }
};

/// Occupancy of the room's floor by grown footprints, and the search on it.
class FloorGrid {
 public:
  FloorGrid(const Vec2& min, const Vec2& max, double grow_m)
      : min_(min), nx_(static_cast<int>(std::ceil((max.x() - min.x()) / kCell_m))),
        ny_(static_cast<int>(std::ceil((max.y() - min.y()) / kCell_m))), grow_m_(grow_m), blocked_(nx_ * ny_, 0) {}

  Vec2 Centre(int cell) const { return min_ + kCell_m * Vec2(cell % nx_ + 0.5, cell / nx_ + 0.5); }
  int CellOf(const Vec2& p) const {
    const int ix = std::clamp(static_cast<int>((p.x() - min_.x()) / kCell_m), 0, nx_ - 1);
    const int iy = std::clamp(static_cast<int>((p.y() - min_.y()) / kCell_m), 0, ny_ - 1);
    return iy * nx_ + ix;
  }

  /// The cells a footprint blocks once grown; `count` +1 to block, −1 to unblock.
  void Mark(const Footprint& footprint, int count) {
    ForCells(footprint, [&](int cell) { blocked_[cell] += count; });
  }
  bool Touches(const Footprint& footprint, const std::vector<char>& on_path) const {
    bool touches = false;
    ForCells(footprint, [&](int cell) { touches = touches || on_path[cell]; });
    return touches;
  }

  /// The cells of a 4-connected path from `from` to `to` through free cells, empty if none.
  std::vector<int> Search(const Vec2& from, const Vec2& to) const {
    const int start = CellOf(from), goal = CellOf(to);
    if (blocked_[start] || blocked_[goal]) return {};
    std::vector<int> parent(blocked_.size(), -1);
    // a cell is closed once blocked or reached: one test a neighbour
    std::vector<char> closed(blocked_.size());
    for (std::size_t cell = 0; cell < blocked_.size(); ++cell) closed[cell] = blocked_[cell] != 0;
    // breadth first, first in first out: every cell queued (once each) kept,
    // read from `head` on (a deque's order, without its bookkeeping)
    std::vector<int> queue;
    queue.reserve(blocked_.size());
    queue.push_back(start);
    parent[start] = start;
    closed[start] = 1;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int cell = queue[head];
      if (cell == goal) break;
      const int ix = cell % nx_, iy = cell / nx_;
      const int next[4] = {ix > 0 ? cell - 1 : -1, ix + 1 < nx_ ? cell + 1 : -1, iy > 0 ? cell - nx_ : -1,
                           iy + 1 < ny_ ? cell + nx_ : -1};
      for (const int n : next) {
        if (n < 0 || closed[n]) continue;
        closed[n] = 1;
        parent[n] = cell;
        queue.push_back(n);
      }
    }
    if (parent[goal] < 0) return {};
    std::vector<int> path{goal};
    while (path.back() != start) path.push_back(parent[path.back()]);
    std::reverse(path.begin(), path.end());
    return path;
  }

  /// Whether the straight segment a→b crosses only free cells (sampled every half cell).
  bool Clear(const Vec2& a, const Vec2& b) const {
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.5 * kCell_m))));
    for (int k = 0; k <= steps; ++k) {
      if (blocked_[CellOf(a + (b - a) * (static_cast<double>(k) / steps))]) return false;
    }
    return true;
  }

  std::size_t size() const { return blocked_.size(); }

 private:
  template <typename F>
  void ForCells(const Footprint& footprint, F f) const {
    const Vec2 lo = footprint.min - Vec2::Constant(grow_m_), hi = footprint.max + Vec2::Constant(grow_m_);
    const int ix0 = std::max(0, static_cast<int>(std::floor((lo.x() - min_.x()) / kCell_m)));
    const int iy0 = std::max(0, static_cast<int>(std::floor((lo.y() - min_.y()) / kCell_m)));
    const int ix1 = std::min(nx_ - 1, static_cast<int>(std::floor((hi.x() - min_.x()) / kCell_m)));
    const int iy1 = std::min(ny_ - 1, static_cast<int>(std::floor((hi.y() - min_.y()) / kCell_m)));
    for (int iy = iy0; iy <= iy1; ++iy) {
      for (int ix = ix0; ix <= ix1; ++ix) {
        // grown with round corners: the cell's centre within grow of the footprint
        const int cell = iy * nx_ + ix;
        if (footprint.DistanceTo(Centre(cell)) <= grow_m_) f(cell);
      }
    }
  }

  Vec2 min_;
  int nx_, ny_;
  double grow_m_;
  std::vector<int> blocked_;
};

/// A piece of furniture or clutter: its objects and its footprint.
struct Piece {
  std::vector<GenObject> objects;
  Footprint footprint;
};

GenObject Cylinder(std::string name, double radius, double length, const Vec3& centre, double albedo) {
  GenObject object;
  object.name = std::move(name);
  object.kind = GenObject::Kind::kCylinder;
  object.size_m = Vec3(Round_m(radius), Round_m(radius), Round_m(length));
  object.xyz_m = Vec3(Round_m(centre.x()), Round_m(centre.y()), Round_m(centre.z()));
  object.albedo = albedo;
  return object;
}

Footprint FootprintAt(const Vec2& centre, const Vec2& size) {
  return {Vec2(Round_m(centre.x() - 0.5 * size.x()), Round_m(centre.y() - 0.5 * size.y())),
          Vec2(Round_m(centre.x() + 0.5 * size.x()), Round_m(centre.y() + 0.5 * size.y()))};
}

// a table: a top on four legs at its corners
Piece Table(const std::string& name, const Vec2& centre, KeyedRandom& random, bool turned) {
  Vec2 size(Round_m(random.Uniform(0.8, 1.6)), Round_m(random.Uniform(0.6, 0.9)));
  if (turned) std::swap(size.x(), size.y());
  const double height = Round_m(random.Uniform(0.70, 0.78)), top = 0.04, leg_r = 0.03;
  Piece piece;
  piece.footprint = FootprintAt(centre, size);
  const Footprint& f = piece.footprint;
  piece.objects.push_back(Box(name + "_top", Vec3(f.min.x(), f.min.y(), height - top), Vec3(f.max.x(), f.max.y(), height),
                              false, 0.5));
  int leg = 1;
  for (const double x : {f.min.x() + 0.06, f.max.x() - 0.06}) {
    for (const double y : {f.min.y() + 0.06, f.max.y() - 0.06}) {
      piece.objects.push_back(Cylinder(name + "_leg_" + std::to_string(leg++), leg_r, height - top,
                                       Vec3(x, y, 0.5 * (height - top)), 0.5));
    }
  }
  return piece;
}

// a chair: a seat on four legs and a back on one side
Piece Chair(const std::string& name, const Vec2& centre, KeyedRandom& random) {
  const double seat = Round_m(random.Uniform(0.40, 0.48)), seat_z = Round_m(random.Uniform(0.43, 0.48));
  const int back_side = random.Integer(0, 3);  // −x, +x, −y, +y
  Piece piece;
  piece.footprint = FootprintAt(centre, Vec2(seat, seat));
  const Footprint& f = piece.footprint;
  piece.objects.push_back(Box(name + "_seat", Vec3(f.min.x(), f.min.y(), seat_z - 0.03), Vec3(f.max.x(), f.max.y(), seat_z),
                              false, 0.6));
  int leg = 1;
  for (const double x : {f.min.x() + 0.03, f.max.x() - 0.03}) {
    for (const double y : {f.min.y() + 0.03, f.max.y() - 0.03}) {
      piece.objects.push_back(Cylinder(name + "_leg_" + std::to_string(leg++), 0.015, seat_z - 0.03,
                                       Vec3(x, y, 0.5 * (seat_z - 0.03)), 0.6));
    }
  }
  Vec3 back_min(f.min.x(), f.min.y(), seat_z), back_max(f.max.x(), f.max.y(), seat_z + 0.45);
  if (back_side == 0) back_max.x() = f.min.x() + 0.03;
  if (back_side == 1) back_min.x() = f.max.x() - 0.03;
  if (back_side == 2) back_max.y() = f.min.y() + 0.03;
  if (back_side == 3) back_min.y() = f.max.y() - 0.03;
  piece.objects.push_back(Box(name + "_back", back_min, back_max, false, 0.6));
  return piece;
}

// a shelf: a tall box against a wall
Piece Shelf(const std::string& name, const RoomConfig& room, const Vec2& room_min, const Vec2& room_max,
            KeyedRandom& random) {
  const double width = Round_m(random.Uniform(0.8, 1.6)), depth = Round_m(random.Uniform(0.30, 0.45));
  const double height = Round_m(std::min(random.Uniform(1.2, 2.0), room.height_m - 0.1));
  const int wall = random.Integer(0, 3);
  Vec2 centre, size;
  if (wall < 2) {  // against the walls at y = min / max
    size = Vec2(width, depth);
    centre = Vec2(random.Uniform(room_min.x() + 0.5 * width, room_max.x() - 0.5 * width),
                  wall == 0 ? room_min.y() + 0.5 * depth : room_max.y() - 0.5 * depth);
  } else {  // against the walls at x = min / max
    size = Vec2(depth, width);
    centre = Vec2(wall == 2 ? room_min.x() + 0.5 * depth : room_max.x() - 0.5 * depth,
                  random.Uniform(room_min.y() + 0.5 * width, room_max.y() - 0.5 * width));
  }
  Piece piece;
  piece.footprint = FootprintAt(centre, size);
  piece.objects.push_back(Box(name, Vec3(piece.footprint.min.x(), piece.footprint.min.y(), 0),
                              Vec3(piece.footprint.max.x(), piece.footprint.max.y(), height), false, 0.55));
  return piece;
}

// clutter: a box, a standing cylinder or a ball on the floor
Piece Clutter(const std::string& name, const Vec2& centre, KeyedRandom& random) {
  Piece piece;
  const int kind = random.Integer(0, 2);
  if (kind == 0) {
    const Vec3 size(Round_m(random.Uniform(0.1, 0.5)), Round_m(random.Uniform(0.1, 0.5)), Round_m(random.Uniform(0.05, 0.5)));
    piece.footprint = FootprintAt(centre, size.head<2>());
    piece.objects.push_back(Box(name, Vec3(piece.footprint.min.x(), piece.footprint.min.y(), 0),
                                Vec3(piece.footprint.max.x(), piece.footprint.max.y(), size.z()), false, 0.7));
  } else if (kind == 1) {
    const double r = Round_m(random.Uniform(0.05, 0.2)), length = Round_m(random.Uniform(0.1, 0.6));
    piece.footprint = FootprintAt(centre, Vec2(2 * r, 2 * r));
    piece.objects.push_back(Cylinder(name, r, length, Vec3(centre.x(), centre.y(), 0.5 * length), 0.7));
  } else {
    const double r = Round_m(random.Uniform(0.05, 0.25));
    piece.footprint = FootprintAt(centre, Vec2(2 * r, 2 * r));
    GenObject ball;
    ball.name = name;
    ball.kind = GenObject::Kind::kSphere;
    ball.size_m = Vec3(r, r, r);
    ball.xyz_m = Vec3(Round_m(centre.x()), Round_m(centre.y()), r);
    ball.albedo = 0.7;
    piece.objects.push_back(ball);
  }
  return piece;
}

// a blocker across the walk at `centre`: a box, a post, a chair or a low
// bar, `width` across the walk (along `across`) and `height` tall
Piece Blocker(const std::string& name, const Vec2& centre, const Vec2& across, double width, double height,
              KeyedRandom& random) {
  const int kind = random.Integer(0, 3);
  const bool across_x = std::abs(across.x()) > std::abs(across.y());
  const auto oriented = [&](double w_across, double w_along) {
    return across_x ? Vec2(w_across, w_along) : Vec2(w_along, w_across);
  };
  Piece piece;
  if (kind == 1) {  // a post: a standing cylinder as wide as drawn, at least knee high
    const double r = Round_m(0.5 * width), length = Round_m(std::max(height, 0.5));
    piece.footprint = FootprintAt(centre, Vec2(2 * r, 2 * r));
    piece.objects.push_back(Cylinder(name, r, length, Vec3(centre.x(), centre.y(), 0.5 * length), 0.65));
    return piece;
  }
  if (kind == 2) return Chair(name, centre, random);  // furniture's own sizes
  // a box (as deep as wide) or a low bar (10 cm deep, twice as wide, at most 0.2 m high)
  const Vec2 size = kind == 0 ? oriented(width, width) : oriented(2 * width, 0.1);
  const double z = kind == 0 ? height : std::min(height, 0.2);
  piece.footprint = FootprintAt(centre, size);
  piece.objects.push_back(Box(name, Vec3(piece.footprint.min.x(), piece.footprint.min.y(), 0),
                              Vec3(piece.footprint.max.x(), piece.footprint.max.y(), Round_m(z)), false, 0.7));
  return piece;
}

// how many of a kind at this difficulty, for a room of this area (the ranges are for 10 × 10 m)
int CountOf(const GenRange& range, double difficulty, double area_m2, KeyedRandom& random) {
  return static_cast<int>(std::lround(Draw(range, difficulty, random) * area_m2 / 100.0));
}

}  // namespace

GeneratedWorld GenerateRoom(const GenerateConfig& config) {
  const RoomConfig& room = config.room;
  const double d = config.difficulty;
  GeneratedWorld world;
  world.corridor_cell_m = kCell_m;
  const Vec2 room_min(-1.0, -0.5 * room.size_m.y()), room_max(room.size_m.x() - 1.0, 0.5 * room.size_m.y());
  const Vec2 start(0, 0);

  // the floor and the walls
  GenObject floor;
  floor.name = "floor";
  floor.kind = GenObject::Kind::kPlane;
  floor.ground = true;
  floor.albedo = 0.45;
  world.objects.push_back(floor);
  const double t = kWallThickness_m, h = room.height_m;
  world.objects.push_back(Box("wall_west", Vec3(room_min.x() - t, room_min.y() - t, 0), Vec3(room_min.x(), room_max.y() + t, h), false, 0.85));
  world.objects.push_back(Box("wall_east", Vec3(room_max.x(), room_min.y() - t, 0), Vec3(room_max.x() + t, room_max.y() + t, h), false, 0.85));
  world.objects.push_back(Box("wall_south", Vec3(room_min.x(), room_min.y() - t, 0), Vec3(room_max.x(), room_min.y(), h), false, 0.85));
  world.objects.push_back(Box("wall_north", Vec3(room_min.x(), room_max.y(), 0), Vec3(room_max.x(), room_max.y() + t, h), false, 0.85));

  // the goal: near the far wall, anywhere across
  KeyedRandom layout(config.seed, 1);
  const Vec2 goal(Round_m(room_max.x() - 1.0), Round_m(layout.Uniform(room_min.y() + 1.0, room_max.y() - 1.0)));

  // the grid of the corridor: the walls block it, grown like everything else
  // grown by half the corridor and a cell more: the straight lines between
  // neighbouring cells' centres then keep the corridor's whole width
  const double grow_m = 0.5 * (room.robot_width_m + room.margin_m) + kCell_m;
  FloorGrid grid(room_min, room_max, grow_m);
  grid.Mark({room_min - Vec2::Constant(1), Vec2(room_min.x(), room_max.y() + 1)}, 1);
  grid.Mark({Vec2(room_max.x(), room_min.y() - 1), room_max + Vec2::Constant(1)}, 1);
  grid.Mark({room_min - Vec2::Constant(1), Vec2(room_max.x() + 1, room_min.y())}, 1);
  grid.Mark({Vec2(room_min.x() - 1, room_max.y()), room_max + Vec2::Constant(1)}, 1);
  std::vector<int> path = grid.Search(start, goal);
  std::vector<char> on_path(grid.size(), 0);
  for (const int cell : path) on_path[cell] = 1;

  // the furniture and clutter, piece after piece, each kept only if the corridor survives it
  const double area_m2 = room.size_m.x() * room.size_m.y();
  std::vector<Footprint> placed;
  const auto try_place = [&](Piece piece) {
    const Footprint& f = piece.footprint;
    if (f.DistanceTo(start) < kKeepClear_m || f.DistanceTo(goal) < kKeepClear_m) return false;
    if (f.min.x() < room_min.x() || f.min.y() < room_min.y() || f.max.x() > room_max.x() || f.max.y() > room_max.y())
      return false;
    for (const Footprint& other : placed) {
      if (f.Overlaps(other, 0.05)) return false;
    }
    grid.Mark(f, 1);
    // the path found so far still holds unless the piece sits on it
    if (!path.empty() && grid.Touches(f, on_path)) {
      std::vector<int> detour = grid.Search(start, goal);
      if (detour.empty()) {
        grid.Mark(f, -1);
        return false;
      }
      for (const int cell : path) on_path[cell] = 0;
      path = std::move(detour);
      for (const int cell : path) on_path[cell] = 1;
    }
    placed.push_back(f);
    for (GenObject& object : piece.objects) world.objects.push_back(std::move(object));
    return true;
  };
  constexpr int kTries = 20;
  // what is in the way first: blockers across the straight walk, one per
  // slot of it (clear of the start and the goal), each moved along its slot
  // and across the walk until it leaves a way around
  {
    const Vec2 along = (goal - start).normalized(), across(-along.y(), along.x());
    const double walk_m = (goal - start).norm();
    const double first_m = kFirstBlocker_m, last_m = walk_m - kKeepClear_m - 0.4;
    KeyedRandom count_random(config.seed, 50);
    const int count = std::max(1, static_cast<int>(std::lround(Draw(room.blockers, d, count_random) * walk_m / 5.0)));
    const double slot_m = (last_m - first_m) / count;
    int made = 0;
    for (int i = 0; i < count && slot_m > 0; ++i) {
      KeyedRandom random(config.seed, 51 + static_cast<std::uint64_t>(i) * 1000);
      const double width = Round_m(Draw(room.blocker_width_m, d, random));
      const double height = Round_m(Draw(room.blocker_height_m, d, random));
      for (int attempt = 0; attempt < kTries; ++attempt) {
        const double s_m = first_m + slot_m * (i + random.Uniform(0.2, 0.8));
        const double l_m = random.Uniform(-0.12, 0.12);  // within the feet's sweep
        const Vec2 centre = start + s_m * along + l_m * across;
        if (try_place(Blocker("blocker_" + std::to_string(made + 1), centre, across, width, height, random))) {
          ++made;
          break;
        }
      }
    }
  }

  const auto random_point = [&](KeyedRandom& random) {
    return Vec2(random.Uniform(room_min.x() + 0.3, room_max.x() - 0.3), random.Uniform(room_min.y() + 0.3, room_max.y() - 0.3));
  };
  struct Kind {
    const char* name;
    GenRange range;
    std::uint64_t stream;
  };
  const Kind kinds[] = {{"table", room.tables, 100}, {"shelf", room.shelves, 200}, {"chair", room.chairs, 300},
                        {"clutter", room.clutter, 400}};
  for (const Kind& kind : kinds) {
    KeyedRandom count_random(config.seed, kind.stream);
    const int count = CountOf(kind.range, d, area_m2, count_random);
    int made = 0;
    for (int i = 0; i < count; ++i) {
      KeyedRandom random(config.seed, kind.stream + 1 + static_cast<std::uint64_t>(i) * 1000);
      const std::string name = std::string(kind.name) + "_" + std::to_string(made + 1);
      for (int attempt = 0; attempt < kTries; ++attempt) {
        const std::string which = kind.name;
        Piece piece = which == "table"   ? Table(name, random_point(random), random, random.Uniform() < 0.5)
                      : which == "shelf" ? Shelf(name, room, room_min, room_max, random)
                      : which == "chair" ? Chair(name, random_point(random), random)
                                         : Clutter(name, random_point(random), random);
        if (try_place(std::move(piece))) {
          ++made;
          break;
        }
      }
    }
  }

  // the way around: the corridor's cells cut to waypoints where the line stays clear
  world.corridor_m.push_back(start);
  for (std::size_t i = 0; i < path.size();) {
    std::size_t far = i + 1;
    while (far + 1 < path.size() && grid.Clear(world.corridor_m.back(), grid.Centre(path[far + 1]))) ++far;
    if (far >= path.size() - 1) break;
    world.corridor_m.emplace_back(Round_m(grid.Centre(path[far]).x()), Round_m(grid.Centre(path[far]).y()));
    i = far;
  }
  world.corridor_m.push_back(goal);
  // the robot's path: straight to the goal, through whatever is in the way
  world.path_m = {start, goal};

  // people: walks across the robot's path, clear of the furniture by 0.3 m
  FloorGrid walk_grid(room_min, room_max, 0.3);
  for (const Footprint& f : placed) walk_grid.Mark(f, 1);
  KeyedRandom people_random(config.seed, 900);
  const int people = CountOf(room.people, d, area_m2, people_random);
  int made = 0;
  for (int i = 0; i < people; ++i) {
    KeyedRandom random(config.seed, 901 + static_cast<std::uint64_t>(i) * 1000);
    for (int attempt = 0; attempt < kTries; ++attempt) {
      // a point of the robot's path, a direction, a walk of 2 to 6 m through it
      const std::size_t segment = static_cast<std::size_t>(random.Integer(0, static_cast<int>(world.path_m.size()) - 2));
      const Vec2 on = world.path_m[segment] + random.Uniform(0.2, 1.0) * (world.path_m[segment + 1] - world.path_m[segment]);
      const Vec2 dir = UniformDirection(random);
      const double half = random.Uniform(1.0, 3.0);
      const Vec2 a(Round_m(on.x() - half * dir.x()), Round_m(on.y() - half * dir.y()));
      const Vec2 b(Round_m(on.x() + half * dir.x()), Round_m(on.y() + half * dir.y()));
      const bool inside = a.x() > room_min.x() + 0.4 && a.y() > room_min.y() + 0.4 && a.x() < room_max.x() - 0.4 &&
                          a.y() < room_max.y() - 0.4 && b.x() > room_min.x() + 0.4 && b.y() > room_min.y() + 0.4 &&
                          b.x() < room_max.x() - 0.4 && b.y() < room_max.y() - 0.4;
      if (!inside || (a - start).norm() < 1.5 || !walk_grid.Clear(a, b)) continue;
      GenObject person;
      person.name = "person_" + std::to_string(++made);
      person.kind = GenObject::Kind::kPerson;
      person.size_m = Vec3(0, 0, Round_m(Draw(room.person_height_m, d, random)));
      person.waypoints_m = {a, b};
      person.speed_m_s = std::round(100 * Draw(room.person_speed_m_s, d, random)) / 100;
      person.start_s = std::round(10 * random.Uniform(0, 2)) / 10;
      person.albedo = 0.5;
      world.objects.push_back(person);
      break;
    }
  }
  return world;
}

}  // namespace proxsim::gen
