#include "surface_batch.h"

#include "hit_prefetch.h"

#include "rtpro/core/lanes3.h"
#include "rtpro/core/avx2_clones.h"

#include <emmintrin.h>

#include <cstddef>
#include <initializer_list>
#include <limits>

namespace rtpro {

namespace {

using lanes::divide;
using lanes::dot;
using lanes::gather;
using lanes::Lanes3;
using lanes::Lanes4;
using lanes::select;
using lanes::transpose_rows;

// std::max(a, b) is (a < b) ? b : a, which maxps computes with its operands swapped (it returns its
// second operand when they are equal or either is NaN).
__m128 std_max(__m128 a, __m128 b) { return _mm_max_ps(b, a); }

// magnitude(v): std::max(|x|, std::max(|y|, |z|)).
__m128 magnitude(const Lanes3& v) {
  const __m128 sign_bit = _mm_set1_ps(-0.0f);
  return std_max(_mm_andnot_ps(sign_bit, v.x), std_max(_mm_andnot_ps(sign_bit, v.y), _mm_andnot_ps(sign_bit, v.z)));
}

// make_surface's steps after the local surface, for four hits: the geometric normal normalised
// (falling back to −normalize(ray.dir)) and turned to face the ray; the shading normal the
// geometric one where `flat` (all bits of a lane), else normalised (falling back to the geometric
// one) and turned into its hemisphere; the mirror direction reflect(normalize(dir), shading). A
// lane whose shading normal is zero (a flat mesh's) falls back to the geometric normal, which is
// what make_surface gives it. kAllFlat: every lane is flat (spheres, flat meshes), and `shading` is
// not read.
// Inlined into each caller's AVX2 and baseline builds.
template <bool kAllFlat>
[[gnu::always_inline]] inline void finish_surfaces4(const Hit* const hits[4], const Lanes3& dir, const Lanes3& position,
                                                    __m128 position_error, const Lanes3& geometric,
                                                    const Lanes3& shading, const std::uint32_t materials[4],
                                                    SurfacePoint* const out[4], Vec3* const mirrors[4]) {
  const __m128 zero = _mm_setzero_ps();
  const __m128 infinity = _mm_set1_ps(std::numeric_limits<float>::infinity());
  const __m128 sign_bit = _mm_set1_ps(-0.0f);
  const auto negate = [&](const Lanes3& v, __m128 mask) {
    return Lanes3{_mm_xor_ps(v.x, mask), _mm_xor_ps(v.y, mask), _mm_xor_ps(v.z, mask)};
  };

  const __m128 n_length = _mm_sqrt_ps(dot(geometric, geometric));
  const __m128 normalizable = _mm_and_ps(_mm_cmpgt_ps(n_length, zero), _mm_cmplt_ps(n_length, infinity));
  const Lanes3 back = divide(dir, _mm_sqrt_ps(dot(dir, dir)));
  Lanes3 ng = select(normalizable, divide(geometric, n_length), negate(back, sign_bit));
  const __m128 back_face = _mm_cmpgt_ps(dot(ng, dir), zero);
  ng = negate(ng, _mm_and_ps(back_face, sign_bit));

  Lanes3 ns = ng;
  if constexpr (!kAllFlat) {
    const __m128 s_length = _mm_sqrt_ps(dot(shading, shading));
    const __m128 s_normalizable = _mm_and_ps(_mm_cmpgt_ps(s_length, zero), _mm_cmplt_ps(s_length, infinity));
    ns = select(s_normalizable, divide(shading, s_length), ng);
    ns = negate(ns, _mm_and_ps(_mm_cmplt_ps(dot(ns, ng), zero), sign_bit));
  }

  // reflect(back, ns): back − ns · (2 · dot(back, ns)).
  const __m128 twice_cosine = _mm_mul_ps(_mm_set1_ps(2.0f), dot(back, ns));
  const Lanes3 mirror{_mm_sub_ps(back.x, _mm_mul_ps(ns.x, twice_cosine)),
                      _mm_sub_ps(back.y, _mm_mul_ps(ns.y, twice_cosine)),
                      _mm_sub_ps(back.z, _mm_mul_ps(ns.z, twice_cosine))};

  float px[4], py[4], pz[4], gx[4], gy[4], gz[4], sx[4], sy[4], sz[4], mx[4], my[4], mz[4], error[4];
  lanes::store(position, px, py, pz);
  lanes::store(ng, gx, gy, gz);
  lanes::store(ns, sx, sy, sz);
  lanes::store(mirror, mx, my, mz);
  _mm_storeu_ps(error, position_error);
  const int back_faces = _mm_movemask_ps(back_face);
  // Field by field from the lane arrays: reading a just-written field back (shading_normal from
  // geometric_normal) stalled on store forwarding.
  for (int i = 0; i < 4; ++i) {
    SurfacePoint& sp = *out[i];
    sp.position = Vec3(px[i], py[i], pz[i]);
    sp.geometric_normal = Vec3(gx[i], gy[i], gz[i]);
    sp.front_face = !(back_faces >> i & 1);
    sp.shading_normal = Vec3(sx[i], sy[i], sz[i]);
    sp.position_error = error[i];
    sp.material = materials[i];
    sp.object_id = hits[i]->geom_id;
    sp.tex_u = 0.0f;
    sp.tex_v = 0.0f;
    sp.tangent = Vec3(0.0f);
    sp.bitangent_sign = 1.0f;
    *mirrors[i] = Vec3(mx[i], my[i], mz[i]);
  }
}

// The helpers below are always inlined: a lambda or helper the compiler leaves out of line is
// compiled once for the baseline target and called from the AVX2 clones too.

// Corner `corner` of four triangles: a vertex is one 16-byte load (x, y, z and whatever follows:
// a vertex array has 16 readable bytes past its end, mesh.h), and four of them transpose into x, y
// and z lanes; the fourth lane is dropped.
[[gnu::always_inline]] inline Lanes3 corner_positions(const TriangleMesh* const meshes[4],
                                                      const TriangleIndices* const triangles[4],
                                                      std::uint32_t TriangleIndices::*corner) {
  __m128 a = _mm_loadu_ps(&meshes[0]->vertices[triangles[0]->*corner].x);
  __m128 b = _mm_loadu_ps(&meshes[1]->vertices[triangles[1]->*corner].x);
  __m128 c = _mm_loadu_ps(&meshes[2]->vertices[triangles[2]->*corner].x);
  __m128 d = _mm_loadu_ps(&meshes[3]->vertices[triangles[3]->*corner].x);
  _MM_TRANSPOSE4_PS(a, b, c, d);
  return Lanes3{a, b, c};
}

// The vertex normal at corner `corner` of four triangles; zero for a flat mesh's.
[[gnu::always_inline]] inline Lanes3 corner_normals(const TriangleMesh* const meshes[4],
                                                    const TriangleIndices* const triangles[4],
                                                    std::uint32_t TriangleIndices::*corner) {
  Vec3 n[4];
  for (int i = 0; i < 4; ++i) n[i] = meshes[i]->smooth() ? meshes[i]->normal(triangles[i]->*corner) : Vec3();
  return {_mm_setr_ps(n[0].x, n[1].x, n[2].x, n[3].x), _mm_setr_ps(n[0].y, n[1].y, n[2].y, n[3].y),
          _mm_setr_ps(n[0].z, n[1].z, n[2].z, n[3].z)};
}

// a·w + b·u + c·v, the barycentric interpolation triangle_surface does.
[[gnu::always_inline]] inline Lanes3 interpolate(const Lanes3& a, const Lanes3& b, const Lanes3& c, __m128 u, __m128 v,
                                                 __m128 w) {
  return Lanes3{_mm_add_ps(_mm_add_ps(_mm_mul_ps(a.x, w), _mm_mul_ps(b.x, u)), _mm_mul_ps(c.x, v)),
                _mm_add_ps(_mm_add_ps(_mm_mul_ps(a.y, w), _mm_mul_ps(b.y, u)), _mm_mul_ps(c.y, v)),
                _mm_add_ps(_mm_add_ps(_mm_mul_ps(a.z, w), _mm_mul_ps(b.z, u)), _mm_mul_ps(c.z, v))};
}

// make_sphere_surfaces4 for four spheres already looked up.
[[gnu::always_inline]] inline void sphere_surfaces4(const Sphere* const spheres[4], const Ray* const rays[4],
                                                    const Hit* const hits[4], SurfacePoint* const out[4],
                                                    Vec3* const mirrors[4]) {
  // Rows: a ray's origin and tnear, its direction and tfar; a sphere's centre and radius.
  static_assert(offsetof(Ray, tnear) == 12 && offsetof(Ray, dir) == 16 && offsetof(Sphere, radius) == 12);
  const Lanes3 org = transpose_rows(&rays[0]->org.x, &rays[1]->org.x, &rays[2]->org.x, &rays[3]->org.x).xyz;
  const Lanes3 dir = transpose_rows(&rays[0]->dir.x, &rays[1]->dir.x, &rays[2]->dir.x, &rays[3]->dir.x).xyz;
  const Lanes4 sphere =
      transpose_rows(&spheres[0]->center.x, &spheres[1]->center.x, &spheres[2]->center.x, &spheres[3]->center.x);
  const Lanes3& center = sphere.xyz;
  const __m128 radius = sphere.w;
  const __m128 t = _mm_setr_ps(hits[0]->t, hits[1]->t, hits[2]->t, hits[3]->t);
  const __m128 zero = _mm_setzero_ps();

  // sphere_surface: the hit point re-projected onto the sphere.
  const Lanes3 from_center{_mm_sub_ps(_mm_add_ps(org.x, _mm_mul_ps(dir.x, t)), center.x),
                           _mm_sub_ps(_mm_add_ps(org.y, _mm_mul_ps(dir.y, t)), center.y),
                           _mm_sub_ps(_mm_add_ps(org.z, _mm_mul_ps(dir.z, t)), center.z)};
  const __m128 len = _mm_sqrt_ps(dot(from_center, from_center));
  const __m128 has_direction = _mm_cmpgt_ps(len, zero);
  const Lanes3 up{zero, _mm_set1_ps(1.0f), zero};
  const Lanes3 n = select(has_direction, divide(from_center, len), up);
  const Lanes3 position{_mm_add_ps(center.x, _mm_mul_ps(n.x, radius)), _mm_add_ps(center.y, _mm_mul_ps(n.y, radius)),
                        _mm_add_ps(center.z, _mm_mul_ps(n.z, radius))};
  const __m128 local_magnitude = std_max(magnitude(position), _mm_add_ps(magnitude(center), radius));
  const __m128 position_error =
      _mm_mul_ps(_mm_set1_ps(kRelativePositionError), std_max(local_magnitude, magnitude(position)));

  const std::uint32_t materials[4] = {spheres[0]->material, spheres[1]->material, spheres[2]->material,
                                      spheres[3]->material};
  finish_surfaces4<true>(hits, dir, position, position_error, n, n, materials, out, mirrors);
}

// make_triangle_surfaces4 for four triangles whose meshes are already looked up and whose
// materials are read. kFlat: no mesh of the four has normals, so every lane shades with its
// geometric normal, which is what the smooth version gives a lane with zero normals (a flat
// mesh's among smooth ones), without gathering and normalising them.
template <bool kFlat>
[[gnu::always_inline]] inline void triangle_surfaces4(const TriangleMesh* const meshes[4],
                                                      const std::uint32_t materials[4], const Ray* const rays[4],
                                                      const Hit* const hits[4], SurfacePoint* const out[4],
                                                      Vec3* const mirrors[4]) {
  const TriangleIndices* triangles[4];
  for (int i = 0; i < 4; ++i) triangles[i] = &meshes[i]->triangles[hits[i]->prim_id];
  const Lanes3 p0 = corner_positions(meshes, triangles, &TriangleIndices::v0),
               p1 = corner_positions(meshes, triangles, &TriangleIndices::v1),
               p2 = corner_positions(meshes, triangles, &TriangleIndices::v2);
  const Lanes3 dir = gather([&](int i) { return rays[i]->dir; });
  const __m128 u = _mm_setr_ps(hits[0]->u, hits[1]->u, hits[2]->u, hits[3]->u);
  const __m128 v = _mm_setr_ps(hits[0]->v, hits[1]->v, hits[2]->v, hits[3]->v);
  const __m128 w = _mm_sub_ps(_mm_sub_ps(_mm_set1_ps(1.0f), u), v);

  // triangle_surface: barycentric position, the edges' cross product, interpolated normals.
  const Lanes3 position = interpolate(p0, p1, p2, u, v, w);
  const Lanes3 e1{_mm_sub_ps(p1.x, p0.x), _mm_sub_ps(p1.y, p0.y), _mm_sub_ps(p1.z, p0.z)};
  const Lanes3 e2{_mm_sub_ps(p2.x, p0.x), _mm_sub_ps(p2.y, p0.y), _mm_sub_ps(p2.z, p0.z)};
  const Lanes3 ng{_mm_sub_ps(_mm_mul_ps(e1.y, e2.z), _mm_mul_ps(e1.z, e2.y)),
                  _mm_sub_ps(_mm_mul_ps(e1.z, e2.x), _mm_mul_ps(e1.x, e2.z)),
                  _mm_sub_ps(_mm_mul_ps(e1.x, e2.y), _mm_mul_ps(e1.y, e2.x))};
  const __m128 local_magnitude = std_max(magnitude(p0), std_max(magnitude(p1), magnitude(p2)));
  const __m128 position_error =
      _mm_mul_ps(_mm_set1_ps(kRelativePositionError), std_max(local_magnitude, magnitude(position)));
  if constexpr (kFlat) {
    finish_surfaces4<true>(hits, dir, position, position_error, ng, ng, materials, out, mirrors);
  } else {
    // A flat mesh's lane interpolates zero normals; finish_surfaces4 then shades it with the
    // geometric normal, as make_surface does.
    const Lanes3 ns = interpolate(corner_normals(meshes, triangles, &TriangleIndices::v0),
                                  corner_normals(meshes, triangles, &TriangleIndices::v1),
                                  corner_normals(meshes, triangles, &TriangleIndices::v2), u, v, w);
    finish_surfaces4<false>(hits, dir, position, position_error, ng, ns, materials, out, mirrors);
  }
}

[[gnu::always_inline]] inline void triangle_surfaces4(const TriangleMesh* const meshes[4],
                                                      const std::uint32_t materials[4], const Ray* const rays[4],
                                                      const Hit* const hits[4], SurfacePoint* const out[4],
                                                      Vec3* const mirrors[4]) {
  if (!meshes[0]->smooth() && !meshes[1]->smooth() && !meshes[2]->smooth() && !meshes[3]->smooth())
    triangle_surfaces4<true>(meshes, materials, rays, hits, out, mirrors);
  else triangle_surfaces4<false>(meshes, materials, rays, hits, out, mirrors);
}

}  // namespace

RTPRO_AVX2_CLONES
void make_sphere_surfaces4(const RenderScene& scene, const Ray* const rays[4], const Hit* const hits[4],
                           SurfacePoint* const out[4], Vec3* const mirrors[4]) {
  const Sphere* spheres[4];
  for (int i = 0; i < 4; ++i)
    spheres[i] = &std::get<SphereSet>(scene.top.geometries[hits[i]->geom_id]).spheres[hits[i]->prim_id];
  sphere_surfaces4(spheres, rays, hits, out, mirrors);
}

RTPRO_AVX2_CLONES
void make_triangle_surfaces4(const RenderScene& scene, const Ray* const rays[4], const Hit* const hits[4],
                             SurfacePoint* const out[4], Vec3* const mirrors[4]) {
  const TriangleMesh* meshes[4];
  std::uint32_t materials[4];
  for (int i = 0; i < 4; ++i) {
    meshes[i] = &std::get<TriangleMesh>(scene.top.geometries[hits[i]->geom_id]);
    materials[i] = meshes[i]->material_of(hits[i]->prim_id);
  }
  triangle_surfaces4(meshes, materials, rays, hits, out, mirrors);
}

// Cloned itself, so that the four-at-a-time kernels inline into each version rather than being
// called through their dispatchers.
RTPRO_AVX2_CLONES
void make_surfaces(const RenderScene& scene, bool prefetch, std::span<const Ray> rays, std::span<const Hit> hits,
                   std::span<SurfacePoint> out) {
  // The hits waiting for three more of their kind, with what classifying them looked up.
  struct Waiting {
    const Ray* rays[4];
    const Hit* hits[4];
    SurfacePoint* points[4];
    unsigned count = 0;
    void add(const Ray& ray, const Hit& hit, SurfacePoint& point) {
      rays[count] = &ray;
      hits[count] = &hit;
      points[count] = &point;
      ++count;
    }
  };
  struct WaitingSpheres : Waiting {
    const Sphere* spheres[4];
  };
  struct WaitingTriangles : Waiting {
    const TriangleMesh* meshes[4];
    std::uint32_t materials[4];
  };
  // Flat and smooth meshes' triangles wait apart: four flat ones skip the normals.
  WaitingSpheres spheres;
  WaitingTriangles flat_triangles, smooth_triangles;
  Vec3 mirrors[4];  // the four-at-a-time kernels' mirror directions, not needed here
  Vec3* const four_mirrors[4] = {&mirrors[0], &mirrors[1], &mirrors[2], &mirrors[3]};
  const auto add_triangle = [&](WaitingTriangles& waiting, const TriangleMesh& mesh, std::uint32_t material,
                                std::size_t i) {
    waiting.meshes[waiting.count] = &mesh;
    waiting.materials[waiting.count] = material;
    waiting.add(rays[i], hits[i], out[i]);
  };
  const HitPrefetch prefetcher(scene, prefetch, hits);
  for (std::size_t i = 0; i < hits.size(); ++i) {
    prefetcher.before(i);
    const Hit& hit = hits[i];
    if (!hit.valid()) continue;
    // The tests of is_plain_sphere_hit and is_plain_triangle_hit, the geometry looked up once.
    if (hit.inst_id == kInvalidId) {
      const Geometry& geometry = scene.top.geometries[hit.geom_id];
      if (const auto* mesh = std::get_if<TriangleMesh>(&geometry)) {
        const std::uint32_t material = mesh->material_of(hit.prim_id);
        if (!has_image_texture(scene, material)) {
          if (!mesh->smooth()) {
            add_triangle(flat_triangles, *mesh, material, i);
            if (flat_triangles.count == 4) {
              triangle_surfaces4<true>(flat_triangles.meshes, flat_triangles.materials, flat_triangles.rays,
                                       flat_triangles.hits, flat_triangles.points, four_mirrors);
              flat_triangles.count = 0;
            }
          } else {
            add_triangle(smooth_triangles, *mesh, material, i);
            if (smooth_triangles.count == 4) {
              triangle_surfaces4<false>(smooth_triangles.meshes, smooth_triangles.materials, smooth_triangles.rays,
                                        smooth_triangles.hits, smooth_triangles.points, four_mirrors);
              smooth_triangles.count = 0;
            }
          }
          continue;
        }
      } else if (const auto* set = std::get_if<SphereSet>(&geometry)) {
        const Sphere& sphere = set->spheres[hit.prim_id];
        if (!has_image_texture(scene, sphere.material)) {
          spheres.spheres[spheres.count] = &sphere;
          spheres.add(rays[i], hit, out[i]);
          if (spheres.count == 4) {
            sphere_surfaces4(spheres.spheres, spheres.rays, spheres.hits, spheres.points, four_mirrors);
            spheres.count = 0;
          }
          continue;
        }
      }
    }
    make_surface(scene, rays[i], hit, out[i]);
  }
  for (const Waiting* waiting : std::initializer_list<const Waiting*>{&spheres, &flat_triangles, &smooth_triangles})
    for (unsigned k = 0; k < waiting->count; ++k)
      make_surface(scene, *waiting->rays[k], *waiting->hits[k], *waiting->points[k]);
}

void make_surfaces(const RenderScene& scene, bool prefetch, std::span<const Ray> rays, std::span<const float> times,
                   std::span<const Hit> hits, std::span<SurfacePoint> out) {
  if (times.empty()) return make_surfaces(scene, prefetch, rays, hits, out);
  const HitPrefetch prefetcher(scene, prefetch, hits, times);
  for (std::size_t i = 0; i < hits.size(); ++i) {
    prefetcher.before(i);
    if (hits[i].valid()) make_surface_at(scene, rays[i], times[i], hits[i], out[i]);
  }
}

}  // namespace rtpro
