#include "rtpro/volume/majorant_iterator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rtpro {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The coordinate of the boundary between cells k - 1 and k along an axis, as cell_bounds has it.
float cell_boundary(const BBox& bounds, int axis, int k, int cells) {
  if (k >= cells) return bounds.upper[axis];
  const float width = (bounds.upper[axis] - bounds.lower[axis]) / static_cast<float>(cells);
  return bounds.lower[axis] + width * static_cast<float>(k);
}

}  // namespace

bool clip_to_box(const Vec3& origin, const Vec3& dir, const BBox& box, float& t_min, float& t_max) {
  if (box.empty()) return false;
  for (int a = 0; a < 3; ++a) {
    if (dir[a] == 0.0f) {
      // Parallel to the slab: inside it (faces included) or nowhere.
      if (origin[a] < box.lower[a] || origin[a] > box.upper[a]) return false;
      continue;
    }
    float near = (box.lower[a] - origin[a]) / dir[a], far = (box.upper[a] - origin[a]) / dir[a];
    if (near > far) std::swap(near, far);
    t_min = std::max(t_min, near);
    t_max = std::min(t_max, far);
    if (t_min > t_max) return false;
  }
  return true;
}

DdaMajorantIterator::DdaMajorantIterator(const Vec3& origin, const Vec3& dir, float t_min, float t_max,
                                         const MajorantGrid& grid, float sigma_t, bool skip_empty)
    : grid_(&grid), origin_(origin), dir_(dir), sigma_t_(sigma_t), skip_empty_(skip_empty) {
  if (!clip_to_box(origin, dir, grid.bounds(), t_min, t_max) || !(t_min < t_max)) return;
  t_min_ = t_min;
  t_max_ = t_max;
  const BBox& bounds = grid.bounds();
  const Vec3 entry = origin + dir * t_min;
  for (int a = 0; a < 3; ++a) {
    const int cells = grid.resolution()[a];
    const float width = (bounds.upper[a] - bounds.lower[a]) / static_cast<float>(cells);
    cell_[a] = std::clamp(static_cast<int>(std::floor((entry[a] - bounds.lower[a]) / width)), 0, cells - 1);
    step_[a] = dir[a] > 0.0f ? 1 : (dir[a] < 0.0f ? -1 : 0);
    next_t_[a] = crossing(a);
  }
}

// Where the ray leaves the current cell through its face on `axis`, computed from the origin
// rather than accumulated, so that long walks do not drift.
float DdaMajorantIterator::crossing(int axis) const {
  if (step_[axis] == 0) return kInfinity;
  const int face = step_[axis] > 0 ? cell_[axis] + 1 : cell_[axis];
  const float t = (cell_boundary(grid_->bounds(), axis, face, grid_->resolution()[axis]) - origin_[axis]) / dir_[axis];
  return std::max(t, t_min_);
}

bool DdaMajorantIterator::next(RayMajorantSegment& out) {
  while (t_min_ < t_max_) {
    int axis = 0;
    if (next_t_[1] < next_t_[axis]) axis = 1;
    if (next_t_[2] < next_t_[axis]) axis = 2;
    const float density_max = grid_->at(cell_[0], cell_[1], cell_[2]);
    RayMajorantSegment segment{t_min_, std::min(t_max_, next_t_[axis]), sigma_t_ * density_max};
    cell_[axis] += step_[axis];
    if (cell_[axis] < 0 || cell_[axis] >= grid_->resolution()[axis] || next_t_[axis] >= t_max_) {
      // The last cell: it reaches the exit, whatever rounding said about its far face.
      segment.t_max = t_max_;
      t_min_ = t_max_;
    } else {
      t_min_ = segment.t_max;
      next_t_[axis] = crossing(axis);
    }
    if (segment.t_max > segment.t_min && !(skip_empty_ && density_max == 0.0f)) {
      out = segment;
      return true;
    }
  }
  return false;
}

}  // namespace rtpro
