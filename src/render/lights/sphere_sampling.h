#pragma once
// Sampling a spherical emitter from a point: by the cone it fills from points clearly outside it,
// by area from points on or inside it (where the cone degenerates to a hemisphere or everything),
// and the solid-angle pdf of either. The light set samples spheres with these; its quads and
// triangles convert area pdfs with area_to_solid_angle.
#include "rtpro/core/vec3.h"
#include "rtpro/render/sampler.h"

namespace rtpro {

bool clearly_outside(const Vec3& center, float radius, const Vec3& point);

// Solid-angle pdf of an area-sampled point `on_light` (normal `n`, area pdf `area_pdf`) from `from`.
float area_to_solid_angle(float area_pdf, const Vec3& from, const Vec3& on_light, const Vec3& n);

struct SphereSample {
  Vec3 point, normal;
  float pdf;  // solid angle
};

SphereSample sample_sphere(const Vec3& center, float radius, const Vec3& from, Sample2D u);
float sphere_pdf(const Vec3& center, float radius, const Vec3& from, const Vec3& on_light);

}  // namespace rtpro
