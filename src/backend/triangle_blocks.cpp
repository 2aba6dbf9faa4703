#include "triangle_blocks.h"

#include "rtpro/backend/hit.h"

#include <algorithm>
#include <variant>

namespace rtpro {

namespace {

bool all_triangles(const Group& group, const Bvh& bvh, const BvhNode& leaf) {
  for (std::uint32_t i = 0; i < leaf.count; ++i)
    if (kind_of(group.geometries[bvh.refs[leaf.index + i].geom]) != GeometryKind::kTriangles) return false;
  return true;
}

TriangleBlock block_of(const Group& group, const PrimitiveRef* refs, std::uint32_t count) {
  TriangleBlock block{};
  std::fill(std::begin(block.geom), std::end(block.geom), kInvalidId);
  std::fill(std::begin(block.prim), std::end(block.prim), kInvalidId);
  for (std::uint32_t slot = 0; slot < count; ++slot) {
    const TriangleMesh& mesh = *std::get_if<TriangleMesh>(&group.geometries[refs[slot].geom]);
    const TriangleIndices& tri = mesh.triangles[refs[slot].prim];
    const Vec3 p[3] = {mesh.vertex(tri.v0), mesh.vertex(tri.v1), mesh.vertex(tri.v2)};
    for (int c = 0; c < 3; ++c) {
      block.v0[c][slot] = p[0][c];
      block.v1[c][slot] = p[1][c];
      block.v2[c][slot] = p[2][c];
    }
    block.geom[slot] = refs[slot].geom;
    block.prim[slot] = refs[slot].prim;
  }
  return block;
}

}  // namespace

TriangleLeaves build_triangle_leaves(const Group& group, const Bvh& bvh) {
  TriangleLeaves leaves;
  leaves.first_block.assign(bvh.nodes.size(), TriangleLeaves::kNoBlocks);
  std::size_t block_count = 0;
  for (const BvhNode& node : bvh.nodes)
    if (node.is_leaf() && all_triangles(group, bvh, node)) block_count += (node.count + kBlockWidth - 1) / kBlockWidth;
  leaves.blocks.reserve(block_count);
  for (std::size_t n = 0; n < bvh.nodes.size(); ++n) {
    const BvhNode& node = bvh.nodes[n];
    if (!node.is_leaf() || !all_triangles(group, bvh, node)) continue;
    leaves.first_block[n] = static_cast<std::uint32_t>(leaves.blocks.size());
    for (std::uint32_t i = 0; i < node.count; i += kBlockWidth)
      leaves.blocks.push_back(block_of(group, &bvh.refs[node.index + i], std::min(kBlockWidth, node.count - i)));
  }
  return leaves;
}

}  // namespace rtpro
