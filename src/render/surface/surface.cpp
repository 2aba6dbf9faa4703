#include "surface.h"

#include "rtpro/core/error.h"
#include "rtpro/core/math_constants.h"
#include "rtpro/scene/curve_basis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

namespace rtpro {

namespace {

float magnitude(const Vec3& v) { return max_component(abs(v)); }

struct LocalSurface {
  Vec3 position;
  Vec3 geometric_normal;  // not necessarily unit
  Vec3 shading_normal;    // not necessarily unit
  float magnitude;        // largest coordinate magnitude that fed the computation
  std::uint32_t material;
  // The shading normal is the geometric one (spheres, meshes without normals): its unit, facing
  // version is then the geometric one's too, bit for bit, and is not worked out twice.
  bool shading_is_geometric;
};

// Inline into make_surface, all three: returned through memory, the record was written with 4-byte
// stores and read back with 8-byte loads, a store-forwarding stall that took about half of the
// surface reconstruction's time; inlined, it stays in registers.
[[gnu::always_inline]] inline LocalSurface sphere_surface(const Sphere& s, const Ray& ray, float t) {
  // Re-project onto the sphere: removes most of the error of org + t·dir.
  const Vec3 p = ray.at(t);
  const Vec3 from_center = p - s.center;
  const float len = length(from_center);
  // Coordinate by coordinate: a Vec3 picked by a conditional or built as a temporary was copied
  // through memory (two 4-byte stores read back by one 8-byte load), stalling store forwarding.
  const bool has_direction = len > 0.0f;
  const Vec3 n(has_direction ? from_center.x / len : 0.0f, has_direction ? from_center.y / len : 1.0f,
               has_direction ? from_center.z / len : 0.0f);
  LocalSurface out;
  out.position = Vec3(s.center.x + n.x * s.radius, s.center.y + n.y * s.radius, s.center.z + n.z * s.radius);
  out.geometric_normal = n;
  out.shading_normal = n;
  out.magnitude = std::max(magnitude(out.position), magnitude(s.center) + s.radius);
  out.material = s.material;
  out.shading_is_geometric = true;
  return out;
}

[[gnu::always_inline]] inline LocalSurface triangle_surface(const TriangleMesh& mesh, std::uint32_t prim, float u,
                                                            float v) {
  const TriangleIndices& tri = mesh.triangles[prim];
  const Vec3 p0 = mesh.vertex(tri.v0), p1 = mesh.vertex(tri.v1), p2 = mesh.vertex(tri.v2);
  const float w = 1.0f - u - v;
  const Vec3 p = p0 * w + p1 * u + p2 * v;
  const Vec3 ng = cross(p1 - p0, p2 - p0);
  const bool flat = !mesh.smooth();
  const Vec3 ns = flat ? ng : mesh.normal(tri.v0) * w + mesh.normal(tri.v1) * u + mesh.normal(tri.v2) * v;
  const float mag = std::max(magnitude(p0), std::max(magnitude(p1), magnitude(p2)));
  return {p, ng, ns, mag, mesh.material_of(prim), flat};
}

// A curve's unit direction at u (its chord where the derivative vanishes, as at a repeated end point).
Vec3 curve_direction(const BezierSegment& segment, float u) {
  for (const Vec3& d : {segment.derivative(u), segment.c[3].position - segment.c[0].position}) {
    const float len = length(d);
    if (len > 0.0f && std::isfinite(len)) return d / len;
  }
  return Vec3(1.0f, 0.0f, 0.0f);
}

// The hit on a fibre: its normal faces the ray (a round tube's points away from the axis; a flat
// ribbon's lies across the fibre, towards the ray), `tangent` is the fibre's unit direction and
// `fiber_offset` pbrt's h, the hit's signed offset from the axis along cross(tangent, ray) over the
// radius (the hair BSDF's sign: on a round tube, the h its frame gives the normal): worked out from the hit point on both shapes (on a ribbon pbrt's −1 + 2v, whatever v
// convention the backend has, so both backends give the same h). Secondary rays must clear the fibre, whose surface is known only to within the backends'
// tolerance and which a ribbon turns to face every ray: `fibre_error` is pbrt's two widths (its
// Curve's pError), a four-radius offset.
LocalSurface curve_surface(const CurveSet& curves, const Hit& hit, const Ray& ray, SurfacePoint& sp,
                           float& fibre_error) {
  const BezierSegment segment = bezier_segment(curves, hit.prim_id);
  const CurvePoint axis = segment.at(hit.u);
  const Vec3 tangent = curve_direction(segment, hit.u);
  const Vec3 p = ray.at(hit.t);
  const Vec3 facing = (ray.dir - tangent * dot(ray.dir, tangent)) * -1.0f;
  Vec3 across = cross(tangent, ray.dir);
  const float across_length = length(across);
  across = across_length > 0.0f ? across / across_length : Vec3(0.0f);
  const Vec3 offset = p - axis.position;
  const Vec3 radial = offset - tangent * dot(offset, tangent);
  const bool round = curves.shape == CurveShape::kRound;
  const float radius = std::max(axis.radius, 0.0f);
  const float h = radius > 0.0f ? dot(radial, across) / radius : 0.0f;
  sp.tangent = tangent;
  sp.fiber_offset = std::clamp(std::isfinite(h) ? h : 0.0f, -1.0f, 1.0f);
  fibre_error = 4.0f * radius;
  const Vec3 n = round && length(radial) > 0.0f ? radial : facing;
  return {p, n, n, std::max(magnitude(p), magnitude(axis.position) + radius), curves.material, true};
}

[[gnu::always_inline]] inline LocalSurface local_surface(const Group& group, const Hit& hit, const Ray& local_ray,
                                                         SurfacePoint& sp, float& fibre_error) {
  const Geometry& geometry = group.geometries[hit.geom_id];
  switch (kind_of(geometry)) {
    case GeometryKind::kSpheres:
      return sphere_surface(std::get<SphereSet>(geometry).spheres[hit.prim_id], local_ray, hit.t);
    case GeometryKind::kTriangles: return triangle_surface(std::get<TriangleMesh>(geometry), hit.prim_id, hit.u, hit.v);
    case GeometryKind::kCurves: return curve_surface(std::get<CurveSet>(geometry), hit, local_ray, sp, fibre_error);
    case GeometryKind::kInstance: break;
  }
  // Backends report the primitive inside the instance, never the instance itself.
  throw RuntimeError("hit record names an instance as its primitive");
}

// The surface of a hit at ray time `time`: a moving sphere or deforming triangle where it is then.
LocalSurface local_surface_at(const Group& group, const Hit& hit, const Ray& local_ray, float time, SurfacePoint& sp,
                              float& fibre_error) {
  const Geometry& geometry = group.geometries[hit.geom_id];
  if (const auto* set = std::get_if<SphereSet>(&geometry); set && set->moving()) {
    Sphere posed = set->spheres[hit.prim_id];
    posed.center = set->center_at(hit.prim_id, time);
    return sphere_surface(posed, local_ray, hit.t);
  }
  if (const auto* mesh = std::get_if<TriangleMesh>(&geometry); mesh && mesh->moving()) {
    const TriangleIndices& tri = mesh->triangles[hit.prim_id];
    const Vec3 p0 = mesh->vertex_at(tri.v0, time), p1 = mesh->vertex_at(tri.v1, time),
               p2 = mesh->vertex_at(tri.v2, time);
    const float w = 1.0f - hit.u - hit.v;
    const Vec3 ng = cross(p1 - p0, p2 - p0);
    const bool flat = !mesh->smooth();
    const Vec3 ns = flat ? ng
                         : mesh->normal_at(tri.v0, time) * w + mesh->normal_at(tri.v1, time) * hit.u +
                               mesh->normal_at(tri.v2, time) * hit.v;
    const float mag = std::max(magnitude(p0), std::max(magnitude(p1), magnitude(p2)));
    return {p0 * w + p1 * hit.u + p2 * hit.v, ng, ns, mag, mesh->material_of(hit.prim_id), flat};
  }
  return local_surface(group, hit, local_ray, sp, fibre_error);
}

// The surface's derivatives along its texture coordinates (object space, not unit).
struct TextureDerivatives {
  Vec3 dpdu, dpdv;
};

// Texture coordinates of the hit, from the object-space surface (before any instance transform).
// `object_normal` is the local surface's geometric normal, passed by value so that the local
// surface's address never escapes make_surface and its fields stay in registers.
TextureDerivatives texture_coordinates(const Group& group, const Hit& hit, const Vec3 object_normal, SurfacePoint& sp) {
  const Geometry& geometry = group.geometries[hit.geom_id];
  switch (kind_of(geometry)) {
    case GeometryKind::kSpheres: {
      const Vec3& n = object_normal;  // unit, object space
      const TexCoord uv = sphere_texture_coordinates(n);
      sp.tex_u = uv.u;
      sp.tex_v = uv.v;
      // Longitude grows towards +x from +z; latitude towards +y.
      return {Vec3(n.z, 0.0f, -n.x), Vec3(0.0f, 1.0f, 0.0f) - n * n.y};
    }
    case GeometryKind::kTriangles: {
      const TriangleMesh& mesh = std::get<TriangleMesh>(geometry);
      const TriangleIndices& tri = mesh.triangles[hit.prim_id];
      const Vec3 e1 = mesh.vertex(tri.v1) - mesh.vertex(tri.v0), e2 = mesh.vertex(tri.v2) - mesh.vertex(tri.v0);
      if (mesh.uvs.empty()) {
        sp.tex_u = hit.u;
        sp.tex_v = hit.v;
        return {e1, e2};
      }
      const float w = 1.0f - hit.u - hit.v;
      sp.tex_u = mesh.uvs[tri.v0].u * w + mesh.uvs[tri.v1].u * hit.u + mesh.uvs[tri.v2].u * hit.v;
      sp.tex_v = mesh.uvs[tri.v0].v * w + mesh.uvs[tri.v1].v * hit.u + mesh.uvs[tri.v2].v * hit.v;
      const float du1 = mesh.uvs[tri.v1].u - mesh.uvs[tri.v0].u, dv1 = mesh.uvs[tri.v1].v - mesh.uvs[tri.v0].v;
      const float du2 = mesh.uvs[tri.v2].u - mesh.uvs[tri.v0].u, dv2 = mesh.uvs[tri.v2].v - mesh.uvs[tri.v0].v;
      const float determinant = du1 * dv2 - du2 * dv1;
      // Texture coordinates that do not span the triangle give it no frame of their own.
      if (!(std::fabs(determinant) > 0.0f) || !std::isfinite(1.0f / determinant)) return {e1, e2};
      const float inverse = 1.0f / determinant;
      return {(e1 * dv2 - e2 * dv1) * inverse, (e2 * du1 - e1 * du2) * inverse};
    }
    case GeometryKind::kCurves: {
      // u along the segment, v across it (0.5 on the axis): the fibre's direction and the side.
      sp.tex_u = hit.u;
      sp.tex_v = 0.5f + 0.5f * sp.fiber_offset;
      return {sp.tangent, cross(object_normal, sp.tangent)};
    }
    case GeometryKind::kInstance: break;
  }
  throw RuntimeError("hit record names an instance as its primitive");
}

// `fallback()` is called only when `v` has no direction: callers pass work (a normalisation) that
// the common case must not pay for.
template <typename Fallback>
Vec3 safe_normalize(const Vec3& v, Fallback&& fallback) {
  const float len = length(v);
  return len > 0.0f && std::isfinite(len) ? v / len : fallback();
}

}  // namespace

TexCoord sphere_texture_coordinates(const Vec3& n) {
  return {0.5f + std::atan2(n.x, n.z) * (0.5f / kPi), 0.5f + std::asin(std::clamp(n.y, -1.0f, 1.0f)) * (1.0f / kPi)};
}

namespace {

// make_surface, and make_surface_at with kTimed: moving shapes and instances where they are at
// `time`. One body, so the static surface is the same code it was before motion existed.
template <bool kTimed>
[[gnu::always_inline]] inline void surface_of(const RenderScene& scene, const Ray& ray, const Hit& hit, float time,
                                              SurfacePoint& sp) {
  sp.tex_u = 0.0f;
  sp.tex_v = 0.0f;
  // `local` is initialised from the call's result, not assigned: an assignment copied the returned
  // record with 16-byte loads over the callee's 4-byte stores (a store-forwarding stall per hit).
  const bool instanced = hit.inst_id != kInvalidId;
  const Instance* instance = instanced ? &std::get<Instance>(scene.top.geometries[hit.inst_id]) : nullptr;
  const Group& group = instanced ? scene.prototypes[instance->prototype] : scene.top;
  InstancePlacement placement;
  if (instanced) placement = {instance->object_to_world, instance->world_to_object};
  if constexpr (kTimed) {
    // A backend reports no hit where the placement is singular, so it has an inverse here.
    if (instanced && instance->moving()) placement = placement_at(*instance, time).value_or(placement);
  }
  const Affine& to_world = placement.object_to_world;
  const Affine& to_object = placement.world_to_object;
  sp.tangent = Vec3(0.0f);
  sp.bitangent_sign = 1.0f;
  sp.fiber_offset = 0.0f;
  float fibre_error = 0.0f;  // a curve's (curve_surface), in the object's space
  const auto local_of = [&](const Ray& local_ray) {
    if constexpr (kTimed) return local_surface_at(group, hit, local_ray, time, sp, fibre_error);
    else return local_surface(group, hit, local_ray, sp, fibre_error);
  };
  LocalSurface local =
      instanced ? local_of(Ray{to_object.apply_point(ray.org), ray.tnear, to_object.apply_vector(ray.dir), ray.tfar})
                : local_of(ray);
  std::optional<TextureDerivatives> derivatives;
  if (has_image_texture(scene, local.material))
    derivatives = texture_coordinates(group, hit, local.geometric_normal, sp);
  if (instanced) {
    if (derivatives) {
      derivatives->dpdu = to_world.apply_vector(derivatives->dpdu);
      derivatives->dpdv = to_world.apply_vector(derivatives->dpdv);
    }
    local.position = to_world.apply_point(local.position);
    local.geometric_normal = to_object.apply_normal_of_inverse(local.geometric_normal);
    local.shading_normal = to_object.apply_normal_of_inverse(local.shading_normal);
    // The transform adds error proportional to the translation and the transformed magnitude.
    local.magnitude = std::max(local.magnitude, magnitude(local.position)) * 4.0f;
    if (fibre_error > 0.0f) {
      const Affine& m = to_world;
      fibre_error *=
          std::max({length(m.apply_vector(Vec3(1.0f, 0.0f, 0.0f))), length(m.apply_vector(Vec3(0.0f, 1.0f, 0.0f))),
                    length(m.apply_vector(Vec3(0.0f, 0.0f, 1.0f)))});
      sp.tangent = safe_normalize(m.apply_vector(sp.tangent), [] { return Vec3(1.0f, 0.0f, 0.0f); });
    }
    sp.object_id = hit.inst_id;
  } else {
    sp.object_id = hit.geom_id;
  }

  if (derivatives) {
    if (!(fibre_error > 0.0f)) sp.tangent = derivatives->dpdu;  // a fibre's stays its unit direction
    if (dot(cross(local.geometric_normal, derivatives->dpdu), derivatives->dpdv) < 0.0f) sp.bitangent_sign = -1.0f;
  }
  sp.position = local.position;
  sp.material = local.material;
  sp.position_error =
      std::max(kRelativePositionError * std::max(local.magnitude, magnitude(local.position)), fibre_error);

  Vec3 ng = safe_normalize(local.geometric_normal, [&] { return -normalize(ray.dir); });
  sp.front_face = !(dot(ng, ray.dir) > 0.0f);
  if (!sp.front_face) ng = -ng;
  sp.geometric_normal = ng;
  if (local.shading_is_geometric) {
    // safe_normalize of the same vector, flipped to ng's side, is ng itself.
    sp.shading_normal = ng;
    return;
  }
  Vec3 ns = safe_normalize(local.shading_normal, [&] { return ng; });
  if (dot(ns, ng) < 0.0f) ns = -ns;
  sp.shading_normal = ns;
}

}  // namespace

void make_surface(const RenderScene& scene, const Ray& ray, const Hit& hit, SurfacePoint& sp) {
  surface_of<false>(scene, ray, hit, 0.0f, sp);
}

void make_surface_at(const RenderScene& scene, const Ray& ray, float time, const Hit& hit, SurfacePoint& sp) {
  surface_of<true>(scene, ray, hit, time, sp);
}

}  // namespace rtpro
