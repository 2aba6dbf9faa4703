#include "yaml_camera.h"

#include "rtpro/scene/render_camera.h"
#include "yaml_motion.h"
#include "yaml_reader.h"

#include <cmath>
#include <cstdint>
#include <string>

namespace rtpro {

namespace {

constexpr std::int64_t kMaxImageSide = 65536;
constexpr std::int64_t kMaxImagePixels = std::int64_t{1} << 28;
// Below this sine of the angle between them, up and the view direction give no usable basis.
constexpr float kMinUpViewSine = 1e-3f;

int read_image_side(const YamlNode& node, const std::string& name) {
  const std::int64_t side = read_integer(node, name);
  if (side < 1 || side > kMaxImageSide)
    fail_at(node, name + ": each side must be from 1 to " + std::to_string(kMaxImageSide) + " pixels, got " +
                      std::string(node.scalar()));
  return static_cast<int>(side);
}

void read_resolution(const YamlNode& node, CameraDesc& camera) {
  const auto& items = read_list(node, "camera.resolution", 2, "[width, height] in pixels");
  camera.width = read_image_side(*items[0], "camera.resolution");
  camera.height = read_image_side(*items[1], "camera.resolution");
  const std::int64_t pixels = std::int64_t{camera.width} * camera.height;
  if (pixels > kMaxImagePixels) {
    fail_at(node, "camera.resolution: " + std::to_string(camera.width) + "x" + std::to_string(camera.height) + " is " +
                      std::to_string(pixels) + " pixels; the limit is " + std::to_string(kMaxImagePixels) +
                      " (2^28, e.g. 16384x16384)");
  }
}

// `camera.shutter: [open, close]`, in frames relative to the frame's time.
Shutter read_shutter(const YamlNode& node) {
  const auto& items = read_list(node, "camera.shutter", 2, "[open, close] in frames relative to the frame");
  const double open = read_number(*items[0], "camera.shutter");
  const double close = read_number(*items[1], "camera.shutter");
  if (!(close >= open))
    fail_at(node, "camera.shutter: the shutter must close no earlier than it opens ([open, close] in frames), got [" +
                      std::string(items[0]->scalar()) + ", " + std::string(items[1]->scalar()) + "]");
  return {static_cast<float>(open), static_cast<float>(close)};
}

// `camera.shutter_opening: [opening, closing]`: fractions of the shutter, 0 <= opening <= closing <= 1.
void read_shutter_opening(const YamlNode& node, Shutter& shutter) {
  const auto& items = read_list(node, "camera.shutter_opening", 2,
                                "[opening, closing]: the fractions of the shutter at which it is fully open and "
                                "from which it closes");
  const double opening = read_number(*items[0], "camera.shutter_opening");
  const double closing = read_number(*items[1], "camera.shutter_opening");
  if (!(0.0 <= opening && opening <= closing && closing <= 1.0))
    fail_at(node,
            "camera.shutter_opening: [opening, closing] must satisfy 0 <= opening <= closing <= 1 (fractions "
            "of the shutter; [0, 1] is a box, [0.5, 0.5] a triangle), got [" +
                std::string(items[0]->scalar()) + ", " + std::string(items[1]->scalar()) + "]");
  shutter.opening = static_cast<float>(opening);
  shutter.closing = static_cast<float>(closing);
}

}  // namespace

CameraDesc read_camera(const YamlNode& node) {
  const MappingReader camera(node, "camera",
                             {"position", "look_at", "up", "projection", "fov", "ortho_height", "resolution",
                              "aperture", "focus_distance", "shutter", "shutter_opening"});
  CameraDesc desc;
  desc.position = read_position(camera.required("position"), "camera.position");
  const YamlNode& look_at = camera.required("look_at");
  desc.look_at = read_position(look_at, "camera.look_at");
  const Vec3 view = desc.look_at - desc.position;
  if (!(length(view) > 0.0f))
    fail_at(look_at, "camera.look_at must differ from camera.position: the camera needs a direction to look in");

  const YamlNode* up = camera.optional("up");
  if (up) {
    desc.up = read_vec3(*up, "camera.up");
    if (!(length(desc.up) > 0.0f)) fail_at(*up, "camera.up must not be zero-length");
  }
  if (length(cross(normalize(view), normalize(desc.up))) < kMinUpViewSine) {
    fail_at(up ? *up : look_at, std::string("camera.up") + (up ? "" : " (default [0, 1, 0])") +
                                    " is parallel to the view direction (look_at - position); choose another up");
  }

  if (const YamlNode* projection = camera.optional("projection"))
    desc.projection = read_keyword<CameraProjection>(
        *projection, "camera.projection",
        {{"perspective", CameraProjection::kPerspective}, {"orthographic", CameraProjection::kOrthographic}});
  if (const YamlNode* height = camera.optional("ortho_height")) {
    const double extent = read_number(*height, "camera.ortho_height");
    if (!(extent > 0.0) || !std::isfinite(static_cast<float>(extent)))
      fail_at(*height, "camera.ortho_height is the orthographic view's height in scene units: a positive number, got " +
                           std::string(height->scalar()));
    desc.ortho_height = static_cast<float>(extent);
  }
  if (const YamlNode* fov = camera.optional("fov")) {
    const double degrees = read_number(*fov, "camera.fov");
    if (!(degrees > 0.0 && degrees < 180.0))
      fail_at(*fov, "camera.fov must be between 0 and 180 degrees (exclusive), got " + std::string(fov->scalar()));
    desc.fov_degrees = static_cast<float>(degrees);
  }
  if (const YamlNode* resolution = camera.optional("resolution")) read_resolution(*resolution, desc);
  if (const YamlNode* aperture = camera.optional("aperture")) {
    const double radius = read_number(*aperture, "camera.aperture");
    if (!(radius >= 0.0) || !std::isfinite(radius))
      fail_at(*aperture, "camera.aperture is the lens radius in scene units: 0 (a pinhole) or more, got " +
                             std::string(aperture->scalar()));
    desc.aperture = static_cast<float>(radius);
    // Parallel rays have no point to focus through: depth of field needs a perspective camera.
    if (radius > 0.0 && desc.projection == CameraProjection::kOrthographic)
      fail_at(*aperture,
              "camera.aperture (depth of field) needs a perspective camera; this one is orthographic "
              "(camera.projection)");
  }
  if (const YamlNode* shutter = camera.optional("shutter")) desc.shutter = read_shutter(*shutter);
  if (const YamlNode* opening = camera.optional("shutter_opening")) read_shutter_opening(*opening, desc.shutter);
  if (const YamlNode* focus = camera.optional("focus_distance")) {
    const double distance = read_number(*focus, "camera.focus_distance");
    if (!(distance > 0.0) || !std::isfinite(static_cast<float>(distance)))
      fail_at(*focus,
              "camera.focus_distance must be a positive distance in scene units, got " + std::string(focus->scalar()));
    desc.focus_distance = static_cast<float>(distance);
  }
  return desc;
}

std::vector<Affine> camera_frame_steps(const YamlDocument& document, const YamlNode& node, const Shutter& shutter) {
  return YamlMotion(document, shutter).transform_steps(node, [](const YamlNode& at) {
    const CameraDesc camera = read_camera(at);
    return camera_frame(camera.position, camera.look_at - camera.position, camera.up);
  });
}

}  // namespace rtpro
