#pragma once
// Walks a ray through a majorant grid cell by cell (a 3D DDA, pbrt-v4's DDAMajorantIterator),
// yielding for each stretch of the ray its majorant σ_maj = σ_t × the cell's maximum, σ_t being
// the largest channel's extinction per unit density (the path integrator's tracking uses one
// majorant for the three channels: render/media/medium_interface.h's MajorantSegment). Segments
// come in order; without skipping they tile the ray's overlap with the grid exactly (each starts
// where the last ended, the first at the entry, the last at the exit).
#include "rtpro/core/vec3.h"
#include "rtpro/volume/majorant_grid.h"

#include <array>
#include <optional>

namespace rtpro {

struct RayMajorantSegment {
  float t_min = 0.0f, t_max = 0.0f;
  float sigma_maj = 0.0f;
};

class DdaMajorantIterator {
 public:
  // Yields nothing.
  DdaMajorantIterator() = default;
  // The ray origin + t·dir for t in [t_min, t_max], in the grid's index space (t is the same in
  // any space an affine map relates to it). `skip_empty`: leave out cells whose maximum is 0.
  DdaMajorantIterator(const Vec3& origin, const Vec3& dir, float t_min, float t_max, const MajorantGrid& grid,
                      float sigma_t, bool skip_empty = false);

  std::optional<RayMajorantSegment> next() {
    RayMajorantSegment segment;
    return next(segment) ? std::optional<RayMajorantSegment>(segment) : std::nullopt;
  }
  // The same into `out` (left as it was at the end), for the tracking's loop: an optional
  // returned from out of line is put together on the stack field by field and loaded back whole,
  // which stalls on store forwarding.
  bool next(RayMajorantSegment& out);

 private:
  float crossing(int axis) const;

  const MajorantGrid* grid_ = nullptr;
  Vec3 origin_, dir_;
  float sigma_t_ = 0.0f;
  float t_min_ = 0.0f, t_max_ = 0.0f;  // t_min_ == t_max_: done
  std::array<int, 3> cell_{0, 0, 0}, step_{0, 0, 0};
  std::array<float, 3> next_t_{0.0f, 0.0f, 0.0f};
  bool skip_empty_ = false;
};

// Clips [t_min, t_max] to the ray's overlap with `box`; false when they do not meet. Robust to
// zero direction components and to rays in a face's plane.
bool clip_to_box(const Vec3& origin, const Vec3& dir, const BBox& box, float& t_min, float& t_max);

}  // namespace rtpro
