// The columns of a 2.5D grid that a 3D segment crosses, in order, with the
// part of the segment inside each: an exact 2D grid traversal (Amanatides &
// Woo, "A fast voxel traversal algorithm", 1987) of the segment's x-y
// projection. The grid is the lattice of cells of side `resolution_m`
// anchored at the world origin: cell (ix, iy) covers x in [ix·r, (ix+1)·r),
// y in [iy·r, (iy+1)·r) (half-open, so a point belongs to exactly one cell).
//
// Which cells are visited: the one holding the segment's start, then every
// cell whose open interior the segment enters over a length > 0. A segment
// through a cell corner goes diagonally: the two cells touching the corner
// only at that point are not visited. tests/terrain_test.cc checks this
// against a brute-force clip of the segment by every cell of its bounding box.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include "core/geometry.h"

namespace proxsim {

/// A cell of the world lattice.
struct CellIndex {
  std::int32_t ix = 0;
  std::int32_t iy = 0;
  bool operator==(const CellIndex&) const = default;
};

/// The cell holding world point (x, y).
inline CellIndex CellOf(double x_m, double y_m, double resolution_m) {
  return {static_cast<std::int32_t>(std::floor(x_m / resolution_m)),
          static_cast<std::int32_t>(std::floor(y_m / resolution_m))};
}

/// Calls visit(cell, t_in, t_out) for every cell the segment p0 → p1 crosses,
/// in order, until visit returns false; [t_in, t_out] ⊂ [0, 1] is the
/// segment's parameter inside the cell's column (the point p0 + t·(p1 − p0)).
/// A segment with no horizontal extent visits its one cell over [0, 1].
template <class Visit>
void TraverseColumns(const Vec3& p0, const Vec3& p1, double resolution_m, Visit&& visit) {
  // in cell units, so that cell boundaries are whole numbers
  const double ax = p0.x() / resolution_m, ay = p0.y() / resolution_m;
  const double dx = p1.x() / resolution_m - ax, dy = p1.y() / resolution_m - ay;
  CellIndex cell{static_cast<std::int32_t>(std::floor(ax)), static_cast<std::int32_t>(std::floor(ay))};
  const int step_x = dx > 0 ? 1 : (dx < 0 ? -1 : 0);
  const int step_y = dy > 0 ? 1 : (dy < 0 ? -1 : 0);
  constexpr double kNever = std::numeric_limits<double>::infinity();
  // parameter at which the segment leaves the current cell across x (or y):
  // computed from the cell index every time, never accumulated, so that
  // rounding does not drift along a long segment
  const auto exit_x = [&] { return step_x == 0 ? kNever : ((cell.ix + (step_x > 0 ? 1 : 0)) - ax) / dx; };
  const auto exit_y = [&] { return step_y == 0 ? kNever : ((cell.iy + (step_y > 0 ? 1 : 0)) - ay) / dy; };
  // the cells crossed are at most the end cell's Manhattan distance, plus one
  const auto end_x = static_cast<std::int64_t>(std::floor(ax + dx)), end_y = static_cast<std::int64_t>(std::floor(ay + dy));
  std::int64_t budget = std::llabs(end_x - cell.ix) + std::llabs(end_y - cell.iy) + 2;
  double t = 0.0;
  // each exit is a function of its own index: found again only when that index moved
  double tx = exit_x(), ty = exit_y();
  while (budget-- > 0) {
    const double t_next = std::min({tx, ty, 1.0});
    if (!visit(cell, t, t_next) || t_next >= 1.0) return;
    // leave across x, across y, or through the corner (both at once)
    const bool across_x = tx <= ty, across_y = ty <= tx;
    if (across_x) {
      cell.ix += step_x;
      tx = exit_x();
    }
    if (across_y) {
      cell.iy += step_y;
      ty = exit_y();
    }
    t = t_next;
  }
}

}  // namespace proxsim
