#include "yaml_light_fields.h"

#include <cmath>
#include <string>

namespace rtpro {

int read_light_samples(const MappingReader& light, int fallback) {
  const YamlNode* node = light.optional("samples");
  if (!node) return fallback;
  const double n = read_number(*node, light.field("samples"));
  if (!(n >= 1.0 && n <= 64.0) || n != std::floor(n))
    fail_at(*node, light.field("samples") +
                       " is shadow rays per axis (samples² per point): a whole number from 1 to 64, got " +
                       std::string(node->scalar()));
  return static_cast<int>(n);
}

}  // namespace rtpro
