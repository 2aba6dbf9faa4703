#include "yaml_subdivision.h"

#include "rtpro/core/special_file_kind.h"

#include <cmath>

namespace rtpro {

namespace {

// Sharpness as OpenSubdiv takes it: 0 smooth, 10 and more infinitely sharp.
constexpr double kMaxSharpness = 10.0;
// Adaptive levels aim at edges of at least a hundredth of a pixel: finer is never visible.
constexpr double kMinEdgeLength = 0.01;

std::uint32_t read_vertex(const YamlNode& node, const std::string& name) {
  const std::uint64_t v = read_unsigned(node, name);
  if (v >= std::uint64_t(kMaxMeshElements)) fail_at(node, name + ": " + std::to_string(v) + " is not a vertex index");
  return std::uint32_t(v);
}

float read_sharpness(const YamlNode& node, const std::string& name) {
  const double s = read_number(node, name);
  if (!(s >= 0.0 && s <= kMaxSharpness))
    fail_at(node,
            name + ": sharpness must be from 0 (smooth) to 10 (infinitely sharp), got " + std::string(node.scalar()));
  return float(s);
}

// A list of `count`-item lists (`shape` names one in messages), each handed to `read` with its
// field name and place.
template <typename Read>
void read_tuples(const YamlNode& node, const std::string& name, std::size_t count, std::string_view shape,
                 Read&& read) {
  if (!node.is_sequence())
    fail_at(node, name + ": expected a list of " + std::string(shape) + ", got " + node.describe());
  for (std::size_t i = 0; i < node.items().size(); ++i) {
    const YamlNode& item = *node.items()[i];
    const std::string field = name + "[" + std::to_string(i) + "]";
    read(read_list(item, field, count, shape), field, item.at.location());
  }
}

void read_creases(const YamlNode& node, const std::string& name, SubdivisionDesc& desc) {
  read_tuples(node, name, 3, "[v0, v1, sharpness]", [&](YamlNodeList v, const std::string& field, SourceLocation at) {
    desc.creases.push_back({read_vertex(*v[0], field + "[0]"), read_vertex(*v[1], field + "[1]"),
                            read_sharpness(*v[2], field + "[2]"), std::move(at)});
  });
}

void read_corners(const YamlNode& node, const std::string& name, SubdivisionDesc& desc) {
  read_tuples(node, name, 2, "[v, sharpness]", [&](YamlNodeList v, const std::string& field, SourceLocation at) {
    desc.corners.push_back({read_vertex(*v[0], field + "[0]"), read_sharpness(*v[1], field + "[1]"), std::move(at)});
  });
}

float read_finite(const YamlNode& node, const std::string& name) {
  const double value = read_number(node, name);
  if (std::abs(value) > kMaxSceneNumber) fail_at(node, name + ": beyond ±1e9");
  return float(value);
}

}  // namespace

SubdivisionDesc read_subdivision(const YamlNode& node, const std::string& name) {
  const MappingReader entry(node, name, {"scheme", "level", "edge_length", "creases", "corners"});
  SubdivisionDesc desc;
  desc.where = node.at.location();
  if (const YamlNode* scheme = entry.optional("scheme"))
    desc.scheme = read_keyword<SubdivisionScheme>(
        *scheme, entry.field("scheme"),
        {{"catmull-clark", SubdivisionScheme::kCatmullClark}, {"loop", SubdivisionScheme::kLoop}});
  if (const YamlNode* level = entry.optional("level")) {
    const std::int64_t n = read_integer(*level, entry.field("level"));
    if (n < 0 || n > kMaxSubdivisionLevel)
      fail_at(*level, entry.field("level") + ": must be from 0 to " + std::to_string(kMaxSubdivisionLevel) + ", got " +
                          std::to_string(n));
    desc.level = int(n);
    desc.level_given = true;
  }
  if (const YamlNode* edge = entry.optional("edge_length")) {
    const double pixels = read_number(*edge, entry.field("edge_length"));
    if (!(pixels >= kMinEdgeLength && pixels <= kMaxSceneNumber))
      fail_at(*edge, entry.field("edge_length") + ": must be a length in pixels of at least 0.01");
    desc.edge_length = float(pixels);
    if (!desc.level_given) desc.level = kDefaultAdaptiveLevelCap;
  }
  if (!entry.optional("level") && !entry.optional("edge_length"))
    fail_at(node, name + ": needs a `level:` or an `edge_length:` (pixels)");
  if (const YamlNode* creases = entry.optional("creases")) read_creases(*creases, entry.field("creases"), desc);
  if (const YamlNode* corners = entry.optional("corners")) read_corners(*corners, entry.field("corners"), desc);
  return desc;
}

DisplacementDesc read_displacement(const YamlNode& node, const std::string& name, const std::filesystem::path& folder) {
  const MappingReader entry(node, name, {"texture", "value", "scale", "bound"});
  DisplacementDesc desc;
  desc.where = node.at.location();
  const YamlNode* texture = entry.optional("texture");
  const YamlNode* value = entry.optional("value");
  if ((texture != nullptr) == (value != nullptr))
    fail_at(node, name + ": needs exactly one of `texture:` (an image) and `value:` (a constant)");
  if (texture) {
    const std::string written = read_string(*texture, entry.field("texture"));
    if (written.empty()) fail_at(*texture, entry.field("texture") + " must name an image file");
    desc.texture = folder / written;
    if (const std::string problem = unreadable_file_problem(desc.texture); !problem.empty())
      fail_at(*texture, entry.field("texture") + ": image file '" + desc.texture.string() + "' " + problem);
  }
  if (value) desc.value = read_finite(*value, entry.field("value"));
  if (const YamlNode* scale = entry.optional("scale")) desc.scale = read_finite(*scale, entry.field("scale"));
  if (const YamlNode* bound = entry.optional("bound")) {
    desc.bound = read_non_negative(*bound, entry.field("bound"));
    if (*desc.bound > kMaxSceneNumber) fail_at(*bound, entry.field("bound") + ": beyond 1e9");
  }
  if (!value) return desc;
  const float moved = std::abs(desc.scale * desc.value);
  if (desc.bound && moved > *desc.bound)
    fail_at(node, name + ": scale × value moves points " + std::to_string(moved) + ", beyond bound " +
                      std::to_string(*desc.bound));
  return desc;
}

}  // namespace rtpro
