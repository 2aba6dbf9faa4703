// The one file that includes OpenSubdiv: its headers are heavy and its types stay out of every
// other file.
#include "subdivision_refine.h"

#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"

#include <opensubdiv/far/error.h>
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace rtpro {

namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;
using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;

// OpenSubdiv reports topology it rejects through a global callback; the message is kept for the
// input error thrown when Create() returns null.
thread_local std::string opensubdiv_message;
void keep_opensubdiv_message(Far::ErrorType, const char* message) { opensubdiv_message = message; }

// A primvar as OpenSubdiv's refiner and patch evaluation interpolate it.
template <int N>
struct Primvar {
  float c[N] = {};
  void Clear(void* = nullptr) { std::fill(c, c + N, 0.0f); }
  void AddWithWeight(const Primvar& source, float weight) {
    for (int i = 0; i < N; ++i) c[i] += weight * source.c[i];
  }
};
using Point3 = Primvar<3>;
using Point2 = Primvar<2>;

Vec3 vec3(const Point3& p) { return {p.c[0], p.c[1], p.c[2]}; }
float squared_length(const Vec3& v) { return dot(v, v); }

Sdc::SchemeType scheme_type(SubdivisionScheme scheme) {
  switch (scheme) {
    case SubdivisionScheme::kCatmullClark: return Sdc::SCHEME_CATMARK;
    case SubdivisionScheme::kLoop: return Sdc::SCHEME_LOOP;
  }
  return Sdc::SCHEME_CATMARK;
}

// The cage's arrays in the layout OpenSubdiv's descriptor points into; lives while a refiner is made.
struct Topology {
  std::vector<int> sizes, corners, uv_corners, crease_pairs, corner_vertices;
  std::vector<float> crease_weights, corner_weights;
  Far::TopologyDescriptor::FVarChannel uv_channel{};
  Far::TopologyDescriptor descriptor{};

  explicit Topology(const CheckedCage& checked) {
    const PolygonCage& cage = checked.cage;
    sizes.assign(cage.face_sizes.begin(), cage.face_sizes.end());
    corners.assign(cage.face_vertices.begin(), cage.face_vertices.end());
    uv_corners.assign(cage.face_uvs.begin(), cage.face_uvs.end());
    for (const EdgeCrease& crease : checked.creases) {
      crease_pairs.insert(crease_pairs.end(), {int(crease.v0), int(crease.v1)});
      crease_weights.push_back(crease.sharpness);
    }
    for (const VertexCorner& corner : checked.corners) {
      corner_vertices.push_back(int(corner.vertex));
      corner_weights.push_back(corner.sharpness);
    }
    descriptor.numVertices = int(cage.positions.size());
    descriptor.numFaces = int(sizes.size());
    descriptor.numVertsPerFace = sizes.data();
    descriptor.vertIndicesPerFace = corners.data();
    descriptor.numCreases = int(crease_weights.size());
    descriptor.creaseVertexIndexPairs = crease_pairs.data();
    descriptor.creaseWeights = crease_weights.data();
    descriptor.numCorners = int(corner_weights.size());
    descriptor.cornerVertexIndices = corner_vertices.data();
    descriptor.cornerWeights = corner_weights.data();
    if (!uv_corners.empty()) {
      uv_channel.numValues = int(cage.uvs.size());
      uv_channel.valueIndices = uv_corners.data();
      descriptor.numFVarChannels = 1;
      descriptor.fvarChannels = &uv_channel;
    }
  }
};

std::unique_ptr<Far::TopologyRefiner> make_refiner(const CheckedCage& cage, SubdivisionScheme scheme,
                                                   const std::string& file) {
  const Topology topology(cage);
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  options.SetFVarLinearInterpolation(Sdc::Options::FVAR_LINEAR_CORNERS_ONLY);
  opensubdiv_message.clear();
  Far::SetErrorCallback(keep_opensubdiv_message);
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(topology.descriptor, Factory::Options(scheme_type(scheme), options)));
  Far::SetErrorCallback(nullptr);
  if (!refiner) throw InputError(SourceLocation{file}, "OpenSubdiv cannot refine this cage: " + opensubdiv_message);
  return refiner;
}

// Values of every level, level 0 first, the cage's values at the front.
template <typename Value, typename Count, typename Step>
std::vector<Value> refine_levels(const Far::TopologyRefiner& refiner, std::vector<Value> base, Count count_at,
                                 Step step) {
  const int levels = refiner.GetMaxLevel();
  std::size_t total = base.size();
  for (int l = 1; l <= levels; ++l) total += std::size_t(count_at(refiner.GetLevel(l)));
  base.resize(total);
  Value* source = base.data();
  for (int l = 1; l <= levels; ++l) {
    Value* destination = source + count_at(refiner.GetLevel(l - 1));
    step(l, source, destination);
    source = destination;
  }
  return base;
}

std::vector<Point3> base_positions(const PolygonCage& cage) {
  std::vector<Point3> points(cage.positions.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i] = Point3{{cage.positions[i].x, cage.positions[i].y, cage.positions[i].z}};
  return points;
}

// Finest-level positions, refined through every level.
std::vector<Point3> refined_positions(const Far::TopologyRefiner& refiner, const Far::PrimvarRefiner& primvar,
                                      const PolygonCage& cage) {
  return refine_levels(
      refiner, base_positions(cage), [](const Far::TopologyLevel& l) { return l.GetNumVertices(); },
      [&](int l, const Point3* s, Point3* d) { primvar.Interpolate(l, s, d); });
}

// Unit normal of the limit tangents, turned to the side the faces around it wind to; where the
// tangents are parallel (some boundary corners), the faces' own area-weighted normal.
Vec3 limit_normal(const Point3& du, const Point3& dv, const Vec3& faces) {
  const Vec3 n = cross(vec3(du), vec3(dv));
  const float len = length(n);
  if (!(len > 1e-20f) || !std::isfinite(len)) {
    const float faces_len = length(faces);
    return faces_len > 0.0f ? faces / faces_len : Vec3(0.0f, 0.0f, 1.0f);
  }
  return dot(n, faces) < 0.0f ? -n / len : n / len;
}

}  // namespace

std::uint64_t refined_face_count(const PolygonCage& cage, SubdivisionScheme scheme, int level) {
  if (level == 0) return cage.face_count();
  std::uint64_t first_level = 0;
  for (const std::uint32_t n : cage.face_sizes)
    first_level += scheme == SubdivisionScheme::kLoop ? 4 : (n == 4 ? 4 : n);
  std::uint64_t faces = first_level;
  for (int l = 1; l < level; ++l) faces = saturating_multiply(faces, 4);
  return faces;
}

int effective_subdivision_level(const CheckedCage& cage, SubdivisionScheme scheme, int level) {
  return scheme == SubdivisionScheme::kCatmullClark && !cage.all_quads ? std::max(level, 1) : level;
}

RefinedMesh refine_cage(const CheckedCage& checked, SubdivisionScheme scheme, int level, const std::string& file) {
  const PolygonCage& cage = checked.cage;
  level = effective_subdivision_level(checked, scheme, level);
  std::unique_ptr<Far::TopologyRefiner> refiner = make_refiner(checked, scheme, file);
  Far::TopologyRefiner::UniformOptions uniform(level);
  uniform.fullTopologyInLastLevel = true;  // the limit stencils need every relation of the last level
  refiner->RefineUniform(uniform);
  const Far::PrimvarRefiner primvar(*refiner);
  const Far::TopologyLevel& last = refiner->GetLevel(level);
  const int vertex_count = last.GetNumVertices();

  const std::vector<Point3> all_positions = refined_positions(*refiner, primvar, cage);
  const Point3* finest = all_positions.data() + (all_positions.size() - std::size_t(vertex_count));
  std::vector<Point3> position(vertex_count), du(vertex_count), dv(vertex_count);
  primvar.Limit(finest, position, du, dv);

  // With uvs each face-varying value is an output vertex (a vertex on a uv seam is several), else
  // each vertex is.
  const bool uvs = !cage.face_uvs.empty();
  RefinedMesh refined;
  TriangleMesh& mesh = refined.mesh;
  std::vector<int> vertex_of_output(std::size_t(uvs ? last.GetNumFVarValues(0) : vertex_count));
  if (uvs) {
    std::vector<Point2> base(cage.uvs.size());
    for (std::size_t i = 0; i < base.size(); ++i) base[i] = Point2{{cage.uvs[i].u, cage.uvs[i].v}};
    const std::vector<Point2> all_uvs = refine_levels(
        *refiner, std::move(base), [](const Far::TopologyLevel& l) { return l.GetNumFVarValues(0); },
        [&](int l, const Point2* s, Point2* d) { primvar.InterpolateFaceVarying(l, s, d, 0); });
    std::vector<Point2> limit_uvs(vertex_of_output.size());
    primvar.LimitFaceVarying(all_uvs.data() + (all_uvs.size() - limit_uvs.size()), limit_uvs, 0);
    for (const Point2& uv : limit_uvs) mesh.uvs.push_back({uv.c[0], uv.c[1]});
  }
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const Far::ConstIndexArray vertices = last.GetFaceVertices(f);
    const Far::ConstIndexArray outputs = uvs ? last.GetFaceFVarValues(f, 0) : vertices;
    for (int k = 0; k < vertices.size(); ++k) vertex_of_output[std::size_t(outputs[k])] = vertices[k];
  }
  mesh.vertices.reserve(vertex_of_output.size());
  for (const int v : vertex_of_output) {
    const Point3& p = position[std::size_t(v)];
    mesh.vertices.push_back({p.c[0], p.c[1], p.c[2]});
  }

  // Each refined face's cage face, for its material.
  std::vector<std::uint32_t> material(cage.face_materials.begin(), cage.face_materials.end());
  for (int l = 1; l <= level && !material.empty(); ++l) {
    std::vector<std::uint32_t> finer(std::size_t(refiner->GetLevel(l).GetNumFaces()));
    primvar.InterpolateFaceUniform(l, material, finer);
    material = std::move(finer);
  }

  std::vector<Vec3> face_normals(mesh.vertices.size(), Vec3(0.0f));
  const auto add_triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, int face) {
    mesh.triangles.push_back({a, b, c});
    if (!material.empty()) mesh.triangle_materials.push_back(material[std::size_t(face)]);
    const Vec3 n = cross(mesh.vertex(b) - mesh.vertex(a), mesh.vertex(c) - mesh.vertex(a));
    for (const std::uint32_t v : {a, b, c}) face_normals[v] += n;
  };
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const Far::ConstIndexArray o = uvs ? last.GetFaceFVarValues(f, 0) : last.GetFaceVertices(f);
    const auto at = [&](int k) { return std::uint32_t(o[k]); };
    if (o.size() == 3) {
      add_triangle(at(0), at(1), at(2), f);
      continue;
    }
    // The shorter diagonal keeps the triangles closer to the surface.
    const float d02 = squared_length(mesh.vertex(at(2)) - mesh.vertex(at(0)));
    const float d13 = squared_length(mesh.vertex(at(3)) - mesh.vertex(at(1)));
    if (d02 <= d13) {
      add_triangle(at(0), at(1), at(2), f);
      add_triangle(at(0), at(2), at(3), f);
    } else {
      add_triangle(at(0), at(1), at(3), f);
      add_triangle(at(1), at(2), at(3), f);
    }
  }
  mesh.normals.reserve(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const std::size_t v = std::size_t(vertex_of_output[i]);
    mesh.normals.push_back(limit_normal(du[v], dv[v], face_normals[i]));
  }
  refined.surface_vertex.assign(vertex_of_output.begin(), vertex_of_output.end());
  refined.surface_vertex_count = std::uint32_t(vertex_count);
  return refined;
}

std::vector<LimitPoint> evaluate_limit_surface(const CheckedCage& checked, SubdivisionScheme scheme,
                                               std::span<const LimitSample> samples) {
  std::unique_ptr<Far::TopologyRefiner> refiner = make_refiner(checked, scheme, "limit surface");
  Far::PatchTableFactory::Options options(10);
  options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
  options.useInfSharpPatch = true;
  refiner->RefineAdaptive(options.GetRefineAdaptiveOptions());
  const std::unique_ptr<Far::PatchTable> table(Far::PatchTableFactory::Create(*refiner, options));
  const Far::PrimvarRefiner primvar(*refiner);
  std::vector<Point3> points = refined_positions(*refiner, primvar, checked.cage);
  const std::size_t refined = points.size();
  points.resize(refined + std::size_t(table->GetNumLocalPoints()));
  if (table->GetNumLocalPoints() > 0) table->ComputeLocalPointValues(points.data(), points.data() + refined);

  const Far::PatchMap map(*table);
  std::vector<LimitPoint> result;
  for (const LimitSample& s : samples) {
    const Far::PatchTable::PatchHandle* handle = map.FindPatch(int(s.face), s.u, s.v);
    if (!handle) throw RuntimeError("no limit patch at face " + std::to_string(s.face));
    float wp[20], wu[20], wv[20];
    table->EvaluateBasis(*handle, s.u, s.v, wp, wu, wv);
    const Far::ConstIndexArray cvs = table->GetPatchVertices(*handle);
    Point3 p, du, dv;
    for (int i = 0; i < cvs.size(); ++i) {
      p.AddWithWeight(points[std::size_t(cvs[i])], wp[i]);
      du.AddWithWeight(points[std::size_t(cvs[i])], wu[i]);
      dv.AddWithWeight(points[std::size_t(cvs[i])], wv[i]);
    }
    result.push_back({vec3(p), normalize(cross(vec3(du), vec3(dv)))});
  }
  return result;
}

}  // namespace rtpro
