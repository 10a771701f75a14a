#include "knowledge/map_route.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>

#include "knowledge/map_queries.h"

namespace proxsim {

namespace {

// at most this many planning cells: a longer walk plans on coarser cells
constexpr double kMaxRouteCells = 250000;
// leaving the grown obstacles from a start inside them costs this much more a metre
constexpr double kEscapeCost = 50.0;

// The planning grid: which cells hold a mapped obstacle, which lie within the
// clearance of one.
class RouteGrid {
 public:
  RouteGrid(const Vec2& min_W, const Vec2& max_W, double cell_m)
      : origin_(min_W), cell_m_(cell_m),
        nx_(std::max(1, static_cast<int>(std::ceil((max_W.x() - min_W.x()) / cell_m)))),
        ny_(std::max(1, static_cast<int>(std::ceil((max_W.y() - min_W.y()) / cell_m)))),
        core_(static_cast<std::size_t>(nx_) * ny_, 0), blocked_(core_.size(), 0) {}

  int size() const { return nx_ * ny_; }
  double cell_m() const { return cell_m_; }
  bool Contains(const Vec2& p_W) const {
    const Vec2 d = (p_W - origin_) / cell_m_;
    return d.x() >= 0 && d.y() >= 0 && d.x() < nx_ && d.y() < ny_;
  }
  int IndexOf(const Vec2& p_W) const {
    const int ix = std::clamp(static_cast<int>(std::floor((p_W.x() - origin_.x()) / cell_m_)), 0, nx_ - 1);
    const int iy = std::clamp(static_cast<int>(std::floor((p_W.y() - origin_.y()) / cell_m_)), 0, ny_ - 1);
    return iy * nx_ + ix;
  }
  Vec2 Centre(int index) const { return origin_ + cell_m_ * Vec2(index % nx_ + 0.5, index / nx_ + 0.5); }
  bool core(int index) const { return core_[index] != 0; }
  bool blocked(int index) const { return blocked_[index] != 0; }

  void MarkCore(const Vec2& p_W) {
    if (Contains(p_W)) core_[IndexOf(p_W)] = 1;
  }
  // every cell whose centre lies within clearance_m of a core cell's centre is blocked
  void Grow(double clearance_m) {
    const int reach = static_cast<int>(std::ceil(clearance_m / cell_m_));
    const double reach2 = (clearance_m / cell_m_) * (clearance_m / cell_m_);
    for (int index = 0; index < size(); ++index) {
      if (!core_[index]) continue;
      const int cx = index % nx_, cy = index / nx_;
      for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          const int x = cx + dx, y = cy + dy;
          if (x < 0 || y < 0 || x >= nx_ || y >= ny_ || dx * dx + dy * dy > reach2) continue;
          blocked_[y * nx_ + x] = 1;
        }
      }
    }
  }

  // the 8 neighbours of a cell and the step's length in cells
  template <typename Visit>
  void ForEachNeighbour(int index, Visit visit) const {
    const int cx = index % nx_, cy = index / nx_;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = cx + dx, y = cy + dy;
        if ((dx == 0 && dy == 0) || x < 0 || y < 0 || x >= nx_ || y >= ny_) continue;
        visit(y * nx_ + x, dx != 0 && dy != 0 ? std::sqrt(2.0) : 1.0);
      }
    }
  }

 private:
  Vec2 origin_;
  double cell_m_;
  int nx_, ny_;
  std::vector<std::uint8_t> core_, blocked_;
};

// A* from `start` to `goal`: blocked cells are passable only while leaving
// the start's own (a robot standing beside an obstacle), at kEscapeCost
std::vector<int> SearchRoute(const RouteGrid& grid, int start, int goal) {
  const auto heuristic = [&](int index) { return (grid.Centre(index) - grid.Centre(goal)).norm() / grid.cell_m(); };
  std::vector<double> cost(grid.size(), std::numeric_limits<double>::infinity());
  std::vector<int> parent(grid.size(), -1);
  std::vector<std::uint8_t> escaping(grid.size(), 0);  // reached through blocked cells from the start only
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  cost[start] = 0;
  escaping[start] = grid.blocked(start);
  open.emplace(heuristic(start), start);
  while (!open.empty()) {
    const auto [f, index] = open.top();
    open.pop();
    if (index == goal) break;
    if (f > cost[index] + heuristic(index) + 1e-9) continue;  // a stale entry
    grid.ForEachNeighbour(index, [&](int next, double step) {
      if (grid.core(next)) return;
      const bool next_blocked = grid.blocked(next);
      if (next_blocked && !escaping[index]) return;
      const double next_cost = cost[index] + step * (next_blocked ? kEscapeCost : 1.0);
      if (next_cost >= cost[next]) return;
      cost[next] = next_cost;
      parent[next] = index;
      escaping[next] = next_blocked;
      open.emplace(next_cost + heuristic(next), next);
    });
  }
  std::vector<int> cells;
  if (!std::isfinite(cost[goal])) return cells;
  for (int index = goal; index >= 0; index = parent[index]) cells.push_back(index);
  std::reverse(cells.begin(), cells.end());
  return cells;
}

// whether the straight line from a to b crosses only cells the route may take
bool LineClear(const RouteGrid& grid, const Vec2& a, const Vec2& b, const std::vector<std::uint8_t>& allowed) {
  const double length_m = (b - a).norm();
  const int samples = std::max(1, static_cast<int>(std::ceil(length_m / (0.5 * grid.cell_m()))));
  for (int i = 0; i <= samples; ++i) {
    const int index = grid.IndexOf(a + (b - a) * (static_cast<double>(i) / samples));
    if (grid.blocked(index) && !allowed[index]) return false;
  }
  return true;
}

}  // namespace

std::optional<std::vector<Vec2>> RouteAroundObstacles(const TerrainMap& map, const Vec2& p_W_from,
                                                      const Vec2& p_W_goal, double clearance_m, double reach_m) {
  // the grid: the box of the start and the goal, grown by kRouteReach_m
  const Vec2 min_W = p_W_from.cwiseMin(p_W_goal) - Vec2::Constant(kRouteReach_m);
  const Vec2 max_W = p_W_from.cwiseMax(p_W_goal) + Vec2::Constant(kRouteReach_m);
  const Vec2 size = max_W - min_W;
  const double cell_m = std::max(kRouteCell_m, std::sqrt(size.x() * size.y() / kMaxRouteCells));
  RouteGrid grid(min_W, max_W, cell_m);

  // the map's obstacle cells, raised above the ground they were classified against
  const std::vector<bool> avoid = ObstaclesToWalkAround(map);
  for (std::size_t i = 0; i < map.hazards().size(); ++i) {
    if (!avoid[i]) continue;
    ForEachRaisedCellOf(map, map.hazards()[i], [&](const Vec2& centre_W, CellIndex) {
      if ((centre_W - p_W_from).norm() <= reach_m) grid.MarkCore(centre_W);
    });
  }
  grid.Grow(clearance_m);

  const int start = grid.IndexOf(p_W_from), goal = grid.IndexOf(p_W_goal);
  if (grid.blocked(goal)) return std::nullopt;
  const std::vector<int> route = SearchRoute(grid, start, goal);
  if (route.empty()) return std::nullopt;

  // the cells the route took through the grown obstacles (leaving the start's) it may cross again
  std::vector<std::uint8_t> allowed(grid.size(), 0);
  for (const int index : route) allowed[index] = grid.blocked(index);
  std::vector<Vec2> points;
  points.reserve(route.size());
  for (const int index : route) points.push_back(grid.Centre(index));
  points.front() = p_W_from;
  points.back() = p_W_goal;

  // cut to the farthest point each straight leg reaches clear
  std::vector<Vec2> waypoints;
  for (std::size_t from = 0; from + 1 < points.size();) {
    std::size_t to = from + 1;
    while (to + 1 < points.size() && LineClear(grid, points[from], points[to + 1], allowed)) ++to;
    waypoints.push_back(points[to]);
    from = to;
  }
  return waypoints;
}

}  // namespace proxsim
