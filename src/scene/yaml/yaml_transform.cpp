#include "yaml_transform.h"

#include "yaml_reader.h"

#include <cmath>
#include <sstream>

namespace rtpro {

namespace {

// The backing array of a namespace-scope initializer_list lives as long as the program.
const std::initializer_list<std::string_view> kStepKeys = {"translate", "rotate", "scale", "matrix"};

Affine read_scale(const YamlNode& node, const std::string& name) {
  Vec3 factors;
  if (node.is_sequence()) {
    factors = read_vec3(node, name);
  } else if (node.is_scalar()) {
    factors = Vec3(static_cast<float>(read_number(node, name)));
  } else {
    fail_at(node, name + ": expected a number or [sx, sy, sz], got " + node.describe());
  }
  if (factors.x == 0.0f || factors.y == 0.0f || factors.z == 0.0f)
    fail_at(node, name + ": scale factors must be non-zero (a zero scale flattens the object)");
  return Affine::scale(factors);
}

Affine read_matrix(const YamlNode& node, const std::string& name) {
  const auto& items = read_list(node, name, 16, "16 numbers (a row-major 4x4 matrix)");
  Affine matrix;
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) {
      const YamlNode& item = *items[row * 4 + column];
      // The last column is the translation: a position, not a factor.
      const double value = column == 3 ? read_coordinate(item, name) : read_number(item, name);
      if (row < 3) {
        matrix.m[row][column] = static_cast<float>(value);
      } else if (value != (column == 3 ? 1.0 : 0.0)) {
        fail_at(item, name + ": the last row must be 0 0 0 1 (an affine transform), got " + std::string(item.scalar()));
      }
    }
  }
  return matrix;
}

Affine read_step(std::string_view key, const YamlNode& value, const std::string& name) {
  if (key == "translate") return Affine::translate(read_position(value, name));
  if (key == "rotate") return read_rotation(value, name);
  if (key == "scale") return read_scale(value, name);
  return read_matrix(value, name);
}

Affine read_step_list(const YamlNode& node, const std::string& name) {
  Affine transform;
  for (const YamlNodePtr& step : node.items()) {
    if (!step->is_mapping() || step->entries().size() != 1) {
      fail_at(*step,
              name + ": expected a step with one key (translate, rotate, scale or matrix), got " + step->describe());
    }
    const MappingReader reader(*step, name, kStepKeys);
    const YamlEntry& entry = step->entries().front();
    transform = compose(read_step(entry.key, *entry.value, reader.field(entry.key)), transform);
  }
  return transform;
}

Affine read_transform_mapping(const YamlNode& node, const std::string& name) {
  const MappingReader reader(node, name, kStepKeys);
  if (const YamlNode* matrix = reader.optional("matrix")) {
    if (node.entries().size() > 1)
      fail_at(*matrix, name + ": 'matrix' cannot be combined with translate, rotate or scale");
    return read_matrix(*matrix, reader.field("matrix"));
  }
  Affine transform;
  for (const char* key : {"scale", "rotate", "translate"}) {
    if (const YamlNode* value = reader.optional(key))
      transform = compose(read_step(key, *value, reader.field(key)), transform);
  }
  return transform;
}

std::string determinant_text(const Affine& transform) {
  std::ostringstream text;
  text << transform.determinant();
  return text.str();
}

}  // namespace

Affine read_rotation(const YamlNode& node, const std::string& name) {
  if (node.is_sequence()) {
    const Vec3 degrees = read_vec3(node, name);
    return compose(Affine::rotate({0, 0, 1}, degrees.z),
                   compose(Affine::rotate({0, 1, 0}, degrees.y), Affine::rotate({1, 0, 0}, degrees.x)));
  }
  if (!node.is_mapping()) {
    fail_at(node,
            name + ": expected {axis: [x, y, z], angle: degrees} or Euler angles [x, y, z], got " + node.describe());
  }
  const MappingReader rotate(node, name, {"axis", "angle"});
  const YamlNode& axis_node = rotate.required("axis");
  const Vec3 axis = read_vec3(axis_node, rotate.field("axis"));
  if (!(length(axis) > 0.0f)) fail_at(axis_node, rotate.field("axis") + ": the rotation axis must not be zero");
  return Affine::rotate(axis, static_cast<float>(read_number(rotate.required("angle"), rotate.field("angle"))));
}

Affine read_transform(const YamlNode& node, const std::string& name) {
  const Affine transform = node.is_sequence() ? read_step_list(node, name) : read_transform_mapping(node, name);
  for (const auto& row : transform.m) {
    for (std::size_t column = 0; column < row.size(); ++column) {
      const double bound = column == 3 ? kMaxSceneCoordinate : kMaxSceneNumber;
      if (!std::isfinite(row[column]) || std::fabs(row[column]) > bound) {
        fail_at(node, name + ": the combined transform has entries beyond ±1e9 (±1e16 for its translation, " +
                          "the last column)");
      }
    }
  }
  if (!inverse(transform)) {
    fail_at(node, name + ": the transform is singular or nearly so (determinant " + determinant_text(transform) +
                      "); it must not flatten space");
  }
  return transform;
}

}  // namespace rtpro
