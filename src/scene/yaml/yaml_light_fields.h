#pragma once
// The fields several kinds of light share in a scene file, read the same way for each
// (each kind's reader is its own file: yaml_point_light.cpp and its neighbours).
#include "yaml_reader.h"

namespace rtpro {

// `color` and `intensity`, which every kind of light has.
template <typename Desc>
void read_color_and_intensity(const MappingReader& light, Desc& desc) {
  if (const YamlNode* color = light.optional("color")) desc.color = read_color(*color, light.field("color"));
  if (const YamlNode* intensity = light.optional("intensity"))
    desc.intensity = read_non_negative(*intensity, light.field("intensity"));
}

// Shadow rays per axis of an area light: samples² per light per shading point.
int read_light_samples(const MappingReader& light, int fallback);

}  // namespace rtpro
