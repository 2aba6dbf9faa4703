#include "rtpro/scene/curve_geometry.h"

#include "yaml_light_linking.h"
#include "yaml_shape_entry.h"
#include "yaml_transform.h"

#include <cmath>
#include <string>
#include <vector>

namespace rtpro {

namespace {

float read_radius(const YamlNode& node, const std::string& field) {
  const double value = read_number(node, field);
  if (!(value > 0.0) || !std::isfinite(float(value)))
    fail_at(node, field + " must be > 0, got " + std::string(node.is_scalar() ? node.scalar() : node.describe()));
  return static_cast<float>(value);
}

// `points`, `radius` (one for all or one per point) and `strands` (points per strand).
void read_inline_points(const MappingReader& entry, CurvesDesc& desc) {
  const YamlNode& points = entry.required("points");
  if (!points.is_sequence() || points.items().size() < 2)
    fail_at(points,
            entry.field("points") + ": expected a list of at least 2 points [x, y, z], got " + points.describe());
  for (std::size_t i = 0; i < points.items().size(); ++i)
    desc.points.push_back(
        {read_position(*points.items()[i], entry.field("points") + "[" + std::to_string(i) + "]"), 1.0f});
  if (const YamlNode* radius = entry.optional("radius")) {
    if (radius->is_sequence()) {
      if (radius->items().size() != desc.points.size())
        fail_at(*radius, entry.field("radius") + ": expected one radius per point (" +
                             std::to_string(desc.points.size()) + "), got " + radius->describe());
      for (std::size_t i = 0; i < desc.points.size(); ++i)
        desc.points[i].radius = read_radius(*radius->items()[i], entry.field("radius") + "[" + std::to_string(i) + "]");
    } else {
      const float r = read_radius(*radius, entry.field("radius"));
      for (CurvePoint& p : desc.points) p.radius = r;
    }
  }
  if (const YamlNode* strands = entry.optional("strands")) {
    if (!strands->is_sequence() || strands->items().empty())
      fail_at(*strands, entry.field("strands") + ": expected a list of point counts, got " + strands->describe());
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < strands->items().size(); ++i) {
      const YamlNode& count = *strands->items()[i];
      const std::uint64_t n = read_unsigned(count, entry.field("strands") + "[" + std::to_string(i) + "]");
      if (n < 2)
        fail_at(count, entry.field("strands") + "[" + std::to_string(i) + "]: a strand needs at least 2 points");
      total += n;
      if (total > desc.points.size()) break;
      desc.strands.push_back(static_cast<std::uint32_t>(n));
    }
    if (total != desc.points.size())
      fail_at(*strands, entry.field("strands") + ": the strands' point counts must add up to the " +
                            std::to_string(desc.points.size()) + " points");
  }
}

}  // namespace

void read_shape_entry(const YamlNode& node, ShapeEntryReader& reader, std::vector<CurvesDesc>& curves) {
  const MappingReader entry(node, "curves",
                            {"type", "file", "points", "radius", "strands", "basis", "shape", "radius_scale",
                             "transform", "material", kLightLinkingKey, kShadowLinkingKey});
  CurvesDesc desc;
  desc.where = node.at.location();
  const YamlNode* file = entry.optional("file");
  if (file && entry.optional("points")) fail_at(*file, "curves: give either a file or points, not both");
  if (file) {
    desc.file = reader.input_file(*file, entry.field("file"), {".hair"}, "Cem Yuksel's .hair", "hair");
    if (const YamlNode* radius = entry.optional("radius"))
      fail_at(*radius, entry.field("radius") + ": a hair file gives its own thickness; scale it with radius_scale");
    if (const YamlNode* strands = entry.optional("strands"))
      fail_at(*strands, entry.field("strands") + ": a hair file gives its own strands");
  } else if (entry.optional("points")) {
    read_inline_points(entry, desc);
  } else {
    fail_at(node, "curves: needs a file (.hair) or a list of points");
  }
  if (const YamlNode* basis = entry.optional("basis"))
    desc.basis = read_keyword<CurveBasis>(*basis, entry.field("basis"),
                                          {{"catmull-rom", CurveBasis::kCatmullRom},
                                           {"b-spline", CurveBasis::kBSpline},
                                           {"bezier", CurveBasis::kBezier},
                                           {"linear", CurveBasis::kLinear}});
  if (const YamlNode* shape = entry.optional("shape"))
    desc.shape = read_keyword<CurveShape>(*shape, entry.field("shape"),
                                          {{"round", CurveShape::kRound}, {"flat", CurveShape::kFlat}});
  if (const YamlNode* scale = entry.optional("radius_scale"))
    desc.radius_scale = read_radius(*scale, entry.field("radius_scale"));
  if (const YamlNode* transform = entry.optional("transform"))
    desc.transform = read_transform(*transform, entry.field("transform"));
  if (const YamlNode* material = entry.optional("material"))
    desc.material = reader.material_index(*material, entry.field("material"));
  desc.linking = reader.read_linking(entry);
  if (desc.basis == CurveBasis::kBezier && desc.strands.empty() && !desc.points.empty() &&
      (desc.points.size() - 1) % 3 != 0)
    fail_at(*entry.optional("points"), entry.field("points") + ": a Bezier strand needs 3k + 1 points (4, 7, 10, ...)");
  curves.push_back(std::move(desc));
}

}  // namespace rtpro
