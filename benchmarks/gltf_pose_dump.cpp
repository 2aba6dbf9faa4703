// Prints the world-space vertices of a glTF file posed at a frame, as rtpro renders it (the pose
// of `rtpro render F.gltf -D frame=N` at render.fps), for benchmarks/blender_posing_check.sh,
// which compares them with the vertices Blender's glTF importer poses.
//
//   rtpro_gltf_pose_dump FILE.gltf FRAME [FPS]
//
// One line per placed mesh, "mesh NAME VERTEX_COUNT", then one "x y z" line per vertex in the
// glTF's own frame (+y up, metres).
#include "gltf_asset.h"
#include "gltf_loader.h"
#include "gltf_pose.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: %s FILE.gltf FRAME [FPS]\n", argv[0]);
    return 2;
  }
  try {
    const rtpro::GltfAsset asset = rtpro::load_gltf_file(argv[1]);
    const double fps = argc == 4 ? std::stod(argv[3]) : 24.0;
    const rtpro::GltfPose pose = rtpro::pose_gltf(asset, std::stod(argv[2]) / fps);
    for (const rtpro::GltfPlacement& placement : pose.placements) {
      const rtpro::TriangleMesh& mesh =
          placement.deformed < 0 ? asset.meshes[placement.mesh] : pose.deformed[std::size_t(placement.deformed)];
      std::printf("mesh %u %zu\n", placement.mesh, mesh.vertices.size());
      for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const rtpro::Vec3 p = placement.transform.apply_point(mesh.vertices[i].position());
        std::printf("%.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
      }
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: %s\n", argv[1], error.what());
    return 2;
  }
  return 0;
}
