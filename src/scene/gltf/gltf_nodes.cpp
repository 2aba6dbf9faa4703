#include "gltf_nodes.h"

#include "ascii_scan.h"
#include "gltf_morph.h"
#include "gltf_pose.h"
#include "mesh_limits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace rtpro::gltf {

namespace {

constexpr float kRadiansToDegrees = 57.29577951308232f;
constexpr double kHalfPi = std::numbers::pi / 2.0;
constexpr double kMinCameraAspect = 1.0 / 16.0;  // a glTF camera's aspectRatio, clamped into this range
constexpr double kMaxCameraAspect = 16.0;
// How far past its limits a spot light's angle may lie and be read as the limit: rounding in
// exporters (Blender's π/2 as a float is 4e-8 above it).
constexpr double kConeAngleSlack = 1e-6;
// A punctual light's intensity (cd, or lx for a directional light), as FORMAT.md gives it: the scene
// format's limit on numbers, far above the sun's 1e5 lx.
constexpr double kMaxLightIntensity = 1e9;

std::string node_path(int node) { return gltf_node_path(std::uint32_t(node)); }

std::string shown(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The scene format's bounds (yaml_reader.h): translations reach as far as mesh vertices, every
// other transform entry (scale, rotation, the matrix's linear part) stays within 1e9.
constexpr double kMaxTransformFactor = 1e9;
constexpr double kMaxTranslation = kMaxAbsCoordinate;

bool within(double value, double bound) { return std::isfinite(value) && std::fabs(value) <= bound; }

bool all_finite(const std::vector<double>& values, double bound = kMaxTransformFactor) {
  return std::all_of(values.begin(), values.end(), [bound](double v) { return within(v, bound); });
}

// A column-major 4x4 matrix: elements 12-14 are the translation.
bool matrix_within_bounds(const std::vector<double>& c) {
  for (std::size_t i = 0; i < c.size(); ++i)
    if (!within(c[i], i >= 12 && i < 15 ? kMaxTranslation : kMaxTransformFactor)) return false;
  return true;
}

// The node's placement before animation, its references checked.
GltfNode read_node(const tinygltf::Model& model, const tinygltf::Node& node, int index, const AccessorReader& reader) {
  const std::string path = node_path(index);
  GltfNode out;
  if (node.mesh >= 0 && std::size_t(node.mesh) >= model.meshes.size())
    reader.fail(path + ".mesh", "mesh " + std::to_string(node.mesh) + " does not exist");
  if (node.skin >= 0 && std::size_t(node.skin) >= model.skins.size())
    reader.fail(path + ".skin", "skin " + std::to_string(node.skin) + " does not exist");
  out.mesh = node.mesh;
  out.skin = node.skin;
  if (!node.weights.empty()) {
    if (node.mesh < 0 || node.weights.size() != morph_target_count(model, node.mesh, reader))
      reader.fail(path + ".weights", "needs one weight per morph target of the node's mesh");
    if (!all_finite(node.weights)) reader.fail(path + ".weights", "needs finite numbers (magnitude <= 1e9)");
    out.weights = node.weights;
  }
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16 || !matrix_within_bounds(node.matrix))
      reader.fail(path + ".matrix", "needs 16 finite numbers (magnitude <= 1e9; <= 1e16 for the translation)");
    const auto& c = node.matrix;  // column-major: element (row r, column k) is c[4k + r]
    if (c[3] != 0.0 || c[7] != 0.0 || c[11] != 0.0 || c[15] != 1.0)
      reader.fail(path + ".matrix", "is not affine: its last row must be 0 0 0 1");
    Affine a;
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 4; ++k) a.m[std::size_t(r)][std::size_t(k)] = float(c[std::size_t(4 * k + r)]);
    out.matrix = a;
    return out;
  }
  if (!node.scale.empty()) {
    if (node.scale.size() != 3 || !all_finite(node.scale))
      reader.fail(path + ".scale", "needs 3 finite numbers (magnitude <= 1e9)");
    out.scale = Vec3(float(node.scale[0]), float(node.scale[1]), float(node.scale[2]));
  }
  if (!node.rotation.empty()) {
    if (node.rotation.size() != 4 || !all_finite(node.rotation))
      reader.fail(path + ".rotation", "needs 4 finite numbers (x, y, z, w)");
    const Quaternion q{node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]};
    if (!(dot(q, q) > 0.0)) reader.fail(path + ".rotation", "is a zero quaternion");
    out.rotation = normalized(q);
  }
  if (!node.translation.empty()) {
    if (node.translation.size() != 3 || !all_finite(node.translation, kMaxTranslation))
      reader.fail(path + ".translation", "needs 3 finite numbers (magnitude <= 1e16)");
    out.translation = Vec3(float(node.translation[0]), float(node.translation[1]), float(node.translation[2]));
  }
  return out;
}

int light_of(const tinygltf::Node& node) {
  const auto ext = node.extensions.find("KHR_lights_punctual");
  if (ext == node.extensions.end() || !ext->second.IsObject() || !ext->second.Has("light")) return -1;
  const tinygltf::Value& light = ext->second.Get("light");
  return light.IsNumber() || light.IsInt() ? light.GetNumberAsInt() : -2;
}

class NodeWalker {
 public:
  NodeWalker(const tinygltf::Model& model, const AccessorReader& reader, GltfAsset& asset)
      : model_(model), reader_(reader), asset_(asset), parent_(model.nodes.size(), kNone) {}

  void run() {
    link_children();
    for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
      asset_.nodes.push_back(read_node(model_, model_.nodes[n], int(n), reader_));
      if (parent_[n] != kNone) asset_.nodes.back().parent = std::uint32_t(parent_[n]);
    }
    order_nodes();
    std::vector<int> roots = scene_roots();
    for (int root : roots) walk(root);
    asset_.world = node_worlds(asset_, node_locals(asset_.nodes));
    for (const std::uint32_t n : asset_.scene_nodes) visit(int(n), asset_.world[n]);
    check_skins();
    if (const std::size_t singular = place_meshes(asset_, rest_weights(asset_), asset_))
      asset_.stats.warnings.push_back(reader_.file() + ": " + std::to_string(singular) +
                                      " node(s) with a singular transform (scale 0) place nothing");
  }

 private:
  static constexpr std::size_t kNone = ~std::size_t(0);

  // Every child index valid and every node with at most one parent.
  void link_children() {
    for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
      const std::vector<int>& children = model_.nodes[n].children;
      for (std::size_t c = 0; c < children.size(); ++c) {
        const std::string path = node_path(int(n)) + ".children[" + std::to_string(c) + "]";
        const int child = children[c];
        if (child < 0 || std::size_t(child) >= model_.nodes.size())
          reader_.fail(path, "node " + std::to_string(child) + " does not exist");
        if (parent_[std::size_t(child)] != kNone)
          reader_.fail(path, "node " + std::to_string(child) + " already has a parent (" +
                                 node_path(int(parent_[std::size_t(child)])) + "); glTF nodes form trees");
        parent_[std::size_t(child)] = n;
      }
    }
    reject_cycles();
  }

  // With one parent each, the nodes form trees plus possibly cycles that no root reaches; find
  // one by following parents, marking what is known to end at a root.
  void reject_cycles() const {
    enum : std::uint8_t { kUnseen, kOnChain, kEndsAtRoot };
    std::vector<std::uint8_t> state(model_.nodes.size(), kUnseen);
    std::vector<std::size_t> chain;
    for (std::size_t start = 0; start < model_.nodes.size(); ++start) {
      chain.clear();
      std::size_t n = start;
      while (n != kNone && state[n] == kUnseen) {
        state[n] = kOnChain;
        chain.push_back(n);
        n = parent_[n];
      }
      if (n != kNone && state[n] == kOnChain) {
        std::string cycle = node_path(int(n));
        for (std::size_t m = parent_[n]; m != n; m = parent_[m]) cycle = node_path(int(m)) + " -> " + cycle;
        reader_.fail(node_path(int(n)), "is its own ancestor (a cycle: " + node_path(int(n)) + " -> " + cycle + ")");
      }
      for (std::size_t m : chain) state[m] = kEndsAtRoot;
    }
  }

  // Parents before children, every node (joints may lie outside the scene).
  void order_nodes() {
    std::vector<std::uint32_t>& order = asset_.node_order;
    for (std::size_t n = 0; n < model_.nodes.size(); ++n)
      if (parent_[n] == kNone) order.push_back(std::uint32_t(n));
    for (std::size_t i = 0; i < order.size(); ++i)
      for (const int child : model_.nodes[order[i]].children) order.push_back(std::uint32_t(child));
  }

  // Every skinned mesh's joint indices within the skin of each node that draws it.
  void check_skins() const {
    for (const std::uint32_t n : asset_.scene_nodes) {
      const GltfNode& node = asset_.nodes[n];
      if (node.mesh < 0 || node.skin < 0) continue;
      const MeshDeformation& d = asset_.deformations[std::size_t(node.mesh)];
      const std::size_t joints = asset_.skins[std::size_t(node.skin)].joints.size();
      if (d.skinned() && d.max_joint >= joints)
        reader_.fail(d.max_joint_path, "joint " + std::to_string(d.max_joint) + ", but " + node_path(int(n)) +
                                           " skins the mesh with skins[" + std::to_string(node.skin) + "], which has " +
                                           std::to_string(joints) + " joints");
    }
  }

  std::vector<int> scene_roots() {
    std::vector<int> roots;
    if (model_.scenes.empty()) {
      for (std::size_t n = 0; n < model_.nodes.size(); ++n)
        if (parent_[n] == kNone) roots.push_back(int(n));
      if (!roots.empty())
        asset_.stats.warnings.push_back(reader_.file() + ": the file has no scenes; every root node is placed");
      return roots;
    }
    const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (std::size_t(scene) >= model_.scenes.size())
      reader_.fail("scene", "scene " + std::to_string(scene) + " does not exist");
    std::vector<bool> listed(model_.nodes.size(), false);
    const std::vector<int>& nodes = model_.scenes[std::size_t(scene)].nodes;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const std::string path = "scenes[" + std::to_string(scene) + "].nodes[" + std::to_string(i) + "]";
      const int node = nodes[i];
      if (node < 0 || std::size_t(node) >= model_.nodes.size())
        reader_.fail(path, "node " + std::to_string(node) + " does not exist");
      if (parent_[std::size_t(node)] != kNone)
        reader_.fail(path, "node " + std::to_string(node) + " is not a root: it is a child of " +
                               node_path(int(parent_[std::size_t(node)])));
      if (listed[std::size_t(node)]) reader_.fail(path, "node " + std::to_string(node) + " is listed twice");
      listed[std::size_t(node)] = true;
      roots.push_back(node);
    }
    return roots;
  }

  // Depth first with an explicit stack, into asset.scene_nodes. With one parent per node and roots
  // that have none, a cycle can only be met as a node already on the path.
  void walk(int root) {
    struct Frame {
      int node;
      std::size_t next_child;
    };
    std::vector<Frame> stack;
    std::vector<bool> on_path(model_.nodes.size(), false);
    stack.push_back({root, 0});
    on_path[std::size_t(root)] = true;
    asset_.scene_nodes.push_back(std::uint32_t(root));
    while (!stack.empty()) {
      Frame& frame = stack.back();
      const tinygltf::Node& node = model_.nodes[std::size_t(frame.node)];
      if (frame.next_child == node.children.size()) {
        on_path[std::size_t(frame.node)] = false;
        stack.pop_back();
        continue;
      }
      const std::size_t c = frame.next_child++;
      const int child = node.children[c];
      const std::string path = node_path(frame.node) + ".children[" + std::to_string(c) + "]";
      if (on_path[std::size_t(child)])
        reader_.fail(path, "node " + std::to_string(child) + " is its own ancestor (a cycle)");
      if (stack.size() >= kMaxGltfNodeDepth)
        reader_.fail(path, "nodes nest deeper than " + std::to_string(kMaxGltfNodeDepth) + " levels");
      on_path[std::size_t(child)] = true;
      stack.push_back({child, 0});
      asset_.scene_nodes.push_back(std::uint32_t(child));
    }
  }

  // The node's camera and light (its mesh is placed by place_meshes).
  void visit(int index, const Affine& world) {
    const tinygltf::Node& node = model_.nodes[std::size_t(index)];
    if (node.camera >= 0) add_camera(node, index, world);
    const int light = light_of(node);
    if (light != -1) add_light(light, index, world);
  }

  void add_camera(const tinygltf::Node& node, int index, const Affine& world) {
    const std::string path = node_path(index);
    if (std::size_t(node.camera) >= model_.cameras.size())
      reader_.fail(path + ".camera", "camera " + std::to_string(node.camera) + " does not exist");
    const tinygltf::Camera& camera = model_.cameras[std::size_t(node.camera)];
    const bool orthographic = camera.type == "orthographic";
    if (camera.type != "perspective" && !orthographic) {
      asset_.stats.warnings.push_back(reader_.file() + ": cameras[" + std::to_string(node.camera) +
                                      "]: " + ascii::quoted(camera.type) + " cameras are not supported; skipped");
      return;
    }
    const double yfov = camera.perspective.yfov * kRadiansToDegrees;
    const double ymag = std::fabs(camera.orthographic.ymag), xmag = std::fabs(camera.orthographic.xmag);
    GltfCamera placed{std::uint32_t(index),
                      std::uint32_t(node.camera),
                      {},
                      {},
                      {},
                      float(yfov),
                      0.0f,
                      orthographic ? float(ymag) : 0.0f};
    const bool usable = orthographic
                            ? ymag > 0.0 && std::isfinite(placed.ortho_half_height) && xmag > 0.0 && std::isfinite(xmag)
                            : yfov > 0.0 && yfov < 180.0;
    if (!usable || !place_camera(placed, world)) {
      asset_.stats.warnings.push_back(reader_.file() + ": cameras[" + std::to_string(node.camera) + "]: unusable " +
                                      (orthographic ? "xmag or ymag" : "field of view") + " or placement; skipped");
      return;
    }
    // The image is 640 pixels wide and as high as the aspect ratio makes it (0.0011 would make it
    // 65,536 high): ratios beyond 1:16 are clamped (with a warning), an image at most 10,240 high.
    // An orthographic camera's is xmag / ymag, as Blender's importer fits its view.
    double aspect = orthographic ? xmag / ymag : camera.perspective.aspectRatio;
    if (!std::isfinite(aspect) || aspect < 0.0) aspect = 0.0;  // none: the default size
    if (aspect > 0.0 && (aspect < kMinCameraAspect || aspect > kMaxCameraAspect)) {
      const double clamped = std::clamp(aspect, kMinCameraAspect, kMaxCameraAspect);
      asset_.stats.warnings.push_back(reader_.file() + ": cameras[" + std::to_string(node.camera) +
                                      (orthographic ? "]: xmag / ymag " : "].perspective.aspectRatio ") +
                                      std::to_string(aspect) + " is outside 1/16..16; " + std::to_string(clamped) +
                                      " is used");
      aspect = clamped;
    }
    placed.aspect_ratio = float(aspect);
    asset_.cameras.push_back(placed);
  }

  void add_light(int index, int node, const Affine& world) {
    const std::string where = node_path(node) + ".extensions.KHR_lights_punctual.light";
    if (index < 0 || std::size_t(index) >= model_.lights.size())
      reader_.fail(where, "light " + std::to_string(index) + " does not exist");
    const tinygltf::Light& light = model_.lights[std::size_t(index)];
    GltfLight out{};
    out.node = std::uint32_t(node);
    out.light = std::uint32_t(index);
    if (light.type == "point") out.kind = GltfLight::Kind::kPoint;
    else if (light.type == "directional") out.kind = GltfLight::Kind::kDirectional;
    else if (light.type == "spot") out.kind = GltfLight::Kind::kSpot;
    else
      reader_.fail("extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "].type",
                   "unknown light type " + ascii::quoted(light.type));
    place_light(out, world);
    out.color = Color(1.0f, 1.0f, 1.0f);
    // Refused, not clamped: a channel clamped to 0 changes the light's hue without a word.
    if (!light.color.empty()) {
      const bool valid = light.color.size() == 3 && all_finite(light.color) &&
                         std::all_of(light.color.begin(), light.color.end(),
                                     [](double c) { return c >= 0.0 && c <= kMaxLightIntensity; });
      if (!valid)
        reader_.fail("extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "].color",
                     "must be three finite numbers from 0 to 1e9 (linear RGB)");
      out.color = Color(float(light.color[0]), float(light.color[1]), float(light.color[2]));
    }
    // Refused, not zeroed: a light that silently goes out leaves a black image and exit 0.
    if (!(light.intensity >= 0.0 && light.intensity <= kMaxLightIntensity))
      reader_.fail("extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "].intensity",
                   "is " + shown(light.intensity) + "; it must be a finite number from 0 to 1e9 (" +
                       (out.kind == GltfLight::Kind::kDirectional ? "lux" : "candela") + ")");
    out.intensity = float(light.intensity);
    if (out.kind == GltfLight::Kind::kSpot) read_spot_cone(light.spot, index, out);
    asset_.lights.push_back(out);
  }

  // The glTF rule 0 <= innerConeAngle < outerConeAngle <= π/2, with equal angles allowed (a hard
  // edge) and rounding past a limit read as the limit.
  void read_spot_cone(const tinygltf::SpotLight& spot, int index, GltfLight& out) const {
    const std::string path = "extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "].spot.";
    const double outer = spot.outerConeAngle, inner = spot.innerConeAngle;
    if (!(outer > 0.0 && outer <= kHalfPi + kConeAngleSlack))
      reader_.fail(path + "outerConeAngle", "is " + std::to_string(outer) + "; it must be > 0 and at most π/2 radians");
    out.outer_cone_angle = float(std::min(outer, kHalfPi));
    if (!(inner >= 0.0 && inner <= outer + kConeAngleSlack))
      reader_.fail(path + "innerConeAngle", "is " + std::to_string(inner) +
                                                "; it must be >= 0 and at most outerConeAngle (" +
                                                std::to_string(outer) + ")");
    out.inner_cone_angle = std::min(float(inner), out.outer_cone_angle);
  }

  const tinygltf::Model& model_;
  const AccessorReader& reader_;
  GltfAsset& asset_;
  std::vector<std::size_t> parent_;
};

}  // namespace

void place_nodes(const tinygltf::Model& model, const AccessorReader& reader, GltfAsset& asset) {
  NodeWalker(model, reader, asset).run();
}

}  // namespace rtpro::gltf
