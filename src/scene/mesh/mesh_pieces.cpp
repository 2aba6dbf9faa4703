#include "rtpro/scene/mesh_pieces.h"

#include "rtpro/core/bbox.h"
#include "rtpro/core/huge_page_buffer.h"

#include <algorithm>
#include <cstring>
#include <type_traits>
#include <vector>

namespace rtpro {

namespace {

// A triangle as the split sees it: three times its centroid (the same order, without a division)
// beside its number, so that every pass reads the items in order instead of the mesh at random.
struct Item {
  float centroid[3];
  std::uint32_t triangle;
};
// In huge pages where the kernel has them: first touches of 4 KiB pages were a third of the time.
using Items = std::vector<Item, HugePageAllocator<Item>>;

// Splits items[begin, end) until each part is at most `piece` long; a split falls on a multiple of
// `piece` from `begin`, itself one, so every part but the last is exactly `piece` long. Ties on
// the axis are broken by triangle number: the order depends on the mesh alone.
void split(Items& items, std::size_t begin, std::size_t end, std::uint32_t piece) {
  while (end - begin > piece) {
    BBox centroids;
    for (std::size_t i = begin; i < end; ++i)
      centroids.extend(Vec3(items[i].centroid[0], items[i].centroid[1], items[i].centroid[2]));
    const Vec3 extent = centroids.upper - centroids.lower;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const std::size_t pieces = (end - begin + piece - 1) / piece;
    const std::size_t middle = begin + pieces / 2 * piece;
    const auto at = [&](std::size_t i) { return items.begin() + static_cast<std::ptrdiff_t>(i); };
    std::nth_element(at(begin), at(middle), at(end), [axis](const Item& a, const Item& b) {
      return a.centroid[axis] < b.centroid[axis] || (a.centroid[axis] == b.centroid[axis] && a.triangle < b.triangle);
    });
    split(items, begin, middle, piece);
    begin = middle;
  }
}

// What an item's slot holds once its triangle is gathered into it.
struct Placed {
  TriangleIndices triangle;
  std::uint32_t material;
};
static_assert(sizeof(Placed) <= sizeof(Item) && std::is_trivially_copyable_v<Item> &&
              std::is_trivially_copyable_v<Placed>);

// Puts triangle items[i].triangle, with its material, at i. Each is first gathered into its item's
// own slot (read before it is written), then copied back in order: no second copy of the arrays to
// fault in, and reads that do not wait on each other (walking the permutation's cycles in place
// chains every read on the one before: twice the reorder's time on the dragon).
void permute(TriangleMesh& mesh, Items& items) {
  const bool materials = !mesh.triangle_materials.empty();
  for (Item& item : items) {
    const std::uint32_t t = item.triangle;
    const Placed placed{mesh.triangles[t], materials ? mesh.triangle_materials[t] : 0};
    std::memcpy(&item, &placed, sizeof placed);
  }
  for (std::size_t i = 0; i < items.size(); ++i) {
    Placed placed;
    std::memcpy(&placed, &items[i], sizeof placed);
    mesh.triangles[i] = placed.triangle;
    if (materials) mesh.triangle_materials[i] = placed.material;
  }
}

}  // namespace

void order_in_pieces(TriangleMesh& mesh, std::uint32_t piece_triangles) {
  piece_triangles = std::max(piece_triangles, kMinPieceTriangles);
  if (mesh.moving() || mesh.triangle_count() <= piece_triangles) return;
  Items items(mesh.triangle_count());
  for (std::uint32_t t = 0; t < items.size(); ++t) {
    const TriangleIndices& tri = mesh.triangles[t];
    const Vec3 sum = mesh.vertex(tri.v0) + mesh.vertex(tri.v1) + mesh.vertex(tri.v2);
    items[t] = {{sum.x, sum.y, sum.z}, t};
  }
  split(items, 0, items.size(), piece_triangles);
  permute(mesh, items);
  mesh.piece_triangles = piece_triangles;
}

}  // namespace rtpro
